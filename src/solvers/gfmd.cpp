// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/gfmd.hpp"

#include "core/loops.hpp"
#include "solvers/fire.hpp"
#include "solvers/solver.hpp"

namespace asp {

void gfmd(Formulation &f, Monitor &monitor, const GfmdParameters &parameters) {
  const std::int64_t n = f.size();
  double *x = f.variable().data();
  Field gradient(static_cast<std::size_t>(n)), step(static_cast<std::size_t>(n), 0.0);
  double *g = gradient.data(), *s = step.data();
  const double dt = parameters.time_step > 0.0 ? parameters.time_step : automatic_time_step(f);
  // x_new - x = (x - x_old) (1 - damping dt) - dt^2 gradient: the step s = x - x_old carries
  // the velocity, so that no second copy of x is kept. A damping that would reverse the
  // velocity within one step (damping dt > 1) stops it instead.
  const double keep = parameters.damping * dt < 1.0 ? 1.0 - parameters.damping * dt : 0.0;
  const double dt2 = dt * dt;
  double value = f.value_and_gradient(x, g);
  if (monitor.should_stop(0, observe(f, x, g, value, monitor))) return;
  for (std::int64_t iteration = 1;; ++iteration) {
    loops::for_each(n, [&](std::int64_t i) {
      s[i] = keep * s[i] - dt2 * g[i];
      x[i] += s[i];
    });
    value = f.value_and_gradient(x, g);
    if (monitor.should_stop(iteration, observe(f, x, g, value, monitor))) return;
  }
}

}  // namespace asp
