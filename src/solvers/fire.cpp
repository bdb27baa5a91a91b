// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/fire.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "solvers/monitor.hpp"

namespace asp {
namespace {

// An energy rise larger than this fraction of the energy is a rise (smaller ones may be
// rounding of the sums that make the energy).
constexpr double rise_resolved = 1e-6;

}  // namespace

double automatic_time_step(Formulation &f) {
  const double curvature = f.largest_curvature();
  return curvature > 0.0 && std::isfinite(curvature) ? 1.0 / std::sqrt(curvature) : 0.0;
}

void fire(Formulation &f, Monitor &monitor, const FireParameters &parameters) {
  const std::int64_t n = f.size();
  const Reductions &reductions = f.reductions();
  double *x = f.variable().data();
  Field force(static_cast<std::size_t>(n)), velocity(static_cast<std::size_t>(n), 0.0);
  double *F = force.data(), *v = velocity.data();

  // The gradient is the negative force; the solver keeps the gradient and flips signs.
  double value = f.value_and_gradient(x, F);
  if (monitor.should_stop(0, observe(f, x, F, value, monitor))) return;

  double dt = parameters.time_step > 0.0 ? parameters.time_step : automatic_time_step(f);
  if (dt == 0.0) {
    // A curvature that overflows (a wall whose stiffness is not a double) allows no step.
    monitor.declare_breakdown();
    return;
  }
  // Bitzek et al.'s largest step is ten times a stable molecular-dynamics step; the step the
  // elastic modes alone allow is taken as that, not the first step, which a start deep inside
  // a stiff wall can make orders of magnitude smaller.
  const double largest = parameters.largest_step > 0.0
                             ? parameters.largest_step
                             : 10.0 * std::max(dt, 1.0 / std::sqrt(f.largest_curvature(false)));
  double alpha = parameters.mixing;
  int positive_steps = 0;

  double previous_value = value;  // before the last step
  double last_step = 0.0;         // the time step of the last move, x += last_step v
  for (std::int64_t iteration = 1;; ++iteration) {
    // P = F.v with F = -gradient.
    const double power = -f.dot(F, v);
    if (!std::isfinite(power)) {
      monitor.declare_breakdown();
      return;
    }
    // Moving with positive power lowers the energy; an energy that rose clearly all the same
    // means the last step went beyond the stability of the stiffest modes (a stiff wall the
    // largest step does not account for). That step is undone, as ASE's FIRE does with its
    // downhill check, and the motion restarts with a smaller step: a half step back (below)
    // would leave the state where the energy exploded. Rises within rounding do not count.
    const bool rose = value - previous_value > rise_resolved * std::fabs(previous_value);
    if (rose) {
      loops::for_each(n, [&](std::int64_t i) {
        x[i] -= last_step * v[i];
        v[i] = 0.0;
      });
      positive_steps = 0;
      dt = last_step * parameters.shrink;
      alpha = parameters.mixing;
      value = f.value_and_gradient(x, F);
    } else if (power > 0.0) {
      if (++positive_steps > parameters.delay) {
        dt = std::min(dt * parameters.growth, largest);
        alpha *= parameters.mixing_decay;
      }
    } else {
      // Overshot: half a step back, stop, and start again more carefully.
      positive_steps = 0;
      const double back = 0.5 * dt;
      loops::for_each(n, [&](std::int64_t i) {
        x[i] -= back * v[i];
        v[i] = 0.0;
      });
      dt *= parameters.shrink;
      alpha = parameters.mixing;
    }
    // Semi-implicit Euler with the mixing: v += dt F, v <- (1 - alpha) v + alpha |v| F/|F|,
    // x += dt v.
    const auto norms = loops::sums<2>(reductions, n, [&](std::int64_t i, double *sum) {
      v[i] -= dt * F[i];
      sum[0] += v[i] * v[i];
      sum[1] += F[i] * F[i];
    });
    const double mix = norms[1] > 0.0 ? alpha * std::sqrt(norms[0] / norms[1]) : 0.0;
    const double keep = 1.0 - alpha;
    loops::for_each(n, [&](std::int64_t i) {
      v[i] = keep * v[i] - mix * F[i];
      x[i] += dt * v[i];
    });
    previous_value = value;
    last_step = dt;
    value = f.value_and_gradient(x, F);
    if (monitor.should_stop(iteration, observe(f, x, F, value, monitor))) return;
  }
}

}  // namespace asp
