// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/gfmd.hpp"

#include <algorithm>
#include <cmath>

#include "core/loops.hpp"
#include "solvers/fire.hpp"
#include "solvers/monitor.hpp"

namespace asp {
namespace {

// An energy rise larger than this fraction of the energy is a rise (smaller ones may be
// rounding of the sums that make the energy); FIRE's threshold.
constexpr double rise_resolved = 1e-6;
// The steps between two evaluations of the curvature bound for the automatic step.
constexpr std::int64_t curvature_interval = 10;

}  // namespace

void gfmd(Formulation &f, Monitor &monitor, const GfmdParameters &parameters) {
  const std::int64_t n = f.size();
  double *x = f.variable().data();
  Field gradient(static_cast<std::size_t>(n)), step(static_cast<std::size_t>(n), 0.0);
  double *g = gradient.data(), *s = step.data();
  const bool fixed = parameters.time_step > 0.0;
  // The automatic step never exceeds 1/sqrt of the elastic modes' curvature (1 on the Fourier
  // variable), the step of a Verlet run of the elastic modes alone.
  const double elastic_step = 1.0 / std::sqrt(f.largest_curvature(false));
  double value = f.value_and_gradient(x, g);
  if (monitor.should_stop(0, observe(f, x, g, value, monitor))) return;
  // s = x - x_old = dt_old v carries the velocity of the last accepted step (0: at rest);
  // scale halves the step after a step from rest raised the energy, and recovers.
  double last_step = 0.0, scale = 1.0, rule_step = 0.0;
  for (std::int64_t iteration = 1;; ++iteration) {
    double dt = parameters.time_step;
    if (!fixed && (last_step == 0.0 || iteration % curvature_interval == 1)) {
      // The stability bound of the iterate, not of the start: from a start deep inside a
      // stiff wall the start's curvature is orders of magnitude above the solution's. It is
      // taken again at every start from rest and every curvature_interval steps (its pass over
      // the potential cost 2.6 FFT pairs per iteration at 512^2 when taken at every step); a
      // stiffer wall met in between makes the motion unstable, the energy rise, and the
      // motion restart with a new bound.
      const double step = automatic_time_step(f);
      if (step == 0.0) {
        monitor.declare_breakdown();
        return;
      }
      rule_step = std::min(elastic_step, step);
    }
    if (!fixed) dt = rule_step;
    dt *= scale;
    // v <- (1 - damping dt) v - dt gradient, x += dt v, with v = s/dt_old: for a fixed step the
    // Verlet update x_new = 2x - x_old - damping dt (x - x_old) - dt^2 gradient. A damping that
    // would reverse the velocity within one step (damping dt > 1) stops it instead.
    const double keep = parameters.damping * dt < 1.0 ? 1.0 - parameters.damping * dt : 0.0;
    const double carry = last_step > 0.0 ? keep * dt / last_step : 0.0;
    const double dt2 = dt * dt;
    loops::for_each(n, [&](std::int64_t i) {
      s[i] = carry * s[i] - dt2 * g[i];
      x[i] += s[i];
    });
    const double previous_value = value;
    value = f.value_and_gradient(x, g);
    if (!std::isfinite(value)) {
      monitor.declare_breakdown();
      return;
    }
    if (value - previous_value > rise_resolved * std::fabs(previous_value)) {
      // The energy rose: the step went beyond the stiffest modes' stability, or the motion
      // carries kinetic energy uphill (the wall's kick from a start inside it). The step is
      // undone and the motion restarts from rest, as FIRE's downhill check does; a step from
      // rest that raises the energy is halved.
      if (last_step == 0.0) scale *= 0.5;
      loops::for_each(n, [&](std::int64_t i) {
        x[i] -= s[i];
        s[i] = 0.0;
      });
      last_step = 0.0;
      value = f.value_and_gradient(x, g);
    } else {
      last_step = dt;
      scale = std::min(1.0, 2.0 * scale);
    }
    if (monitor.should_stop(iteration, observe(f, x, g, value, monitor))) return;
  }
}

}  // namespace asp
