// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/range_continuation.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "physics/resolution.hpp"
#include "solvers/nested_grids.hpp"

namespace asp {

void check_range_continuation(const System &system, double option) {
  if (option == continuation_auto || option == 0.0) return;
  if (option < 1.0)
    throw Error(Status::invalid_argument,
                "option 'range_continuation' must be 0 (none), \"auto\" or a factor of the "
                "range of at least 1, got " + format_number(option));
  if (exponential_adhesion(system.interaction()) == nullptr)
    throw Error(Status::unsupported,
                "option 'range_continuation' is " + format_number(option) +
                    ", but it applies to the hard wall with exponential adhesion only, and the "
                    "system's interaction is the " +
                    interaction_name(system.interaction().kind()) +
                    " (set it to 0, or \"auto\", which does nothing there)");
}

double continuation_factor(const System &system, Control control, double value, double option) {
  check_range_continuation(system, option);
  if (option == 0.0 || exponential_adhesion(system.interaction()) == nullptr) return 0.0;
  if (option == continuation_auto) {
    if (control == Control::mean_pressure && value <= 0.0) return 0.0;
    const Resolution r = resolution(system);
    if (!(r.ratio <= continuation_largest_zone) || carries_pressure(system)) return 0.0;
    return std::sqrt(continuation_zone / r.ratio);
  }
  return carries_pressure(system) ? 0.0 : option;
}

namespace {

// The system's adhesion with its range times a factor while it lives; its own afterwards.
class LongerRange {
 public:
  LongerRange(System &system, double factor) : system_(system) {
    const ExponentialAdhesion &adhesion = *exponential_adhesion(system.interaction());
    work_ = adhesion.work();
    range_ = adhesion.range();
    system.set_adhesion(work_, factor * range_);
  }
  // Setting the values the system held cannot fail but for memory.
  ~LongerRange() {
    try {
      system_.set_adhesion(work_, range_);
    } catch (...) {
    }
  }
  LongerRange(const LongerRange &) = delete;
  LongerRange &operator=(const LongerRange &) = delete;

 private:
  System &system_;
  double work_ = 0.0, range_ = 0.0;
};

}  // namespace

bool solve_with_longer_range(const AlgorithmSpec &algorithm, const OptionValues &options,
                             System &system, Control control, double value, double factor,
                             double tolerance, Monitor &monitor) {
  if (!(factor > 1.0)) return true;
  // The longer range lowers the largest tension w/(F rho); where that would leave the
  // normal doubles, the stage is skipped rather than refused.
  const ExponentialAdhesion &adhesion = *exponential_adhesion(system.interaction());
  if (!(adhesion.work() / (factor * adhesion.range()) >= DBL_MIN)) return true;
  {
    const LongerRange longer(system, factor);
    monitor.begin_first_stage(first_stage_tolerance(tolerance));
    algorithm.run(system, control, value, options, monitor);
  }
  const Termination ended = monitor.termination();
  if (ended == Termination::cancelled || ended == Termination::iteration_limit) return false;
  // A breakdown left the state reset: the second stage starts cold. A stage that stalled or
  // separated leaves a state to start from, as any other.
  monitor.continue_with_next_stage(tolerance);
  return true;
}

}  // namespace asp
