// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/range_continuation.hpp"

#include <cfloat>
#include <cmath>
#include <memory>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "physics/resolution.hpp"

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
  // A tensile or zero load: the longer range's weaker largest tension w/(F rho) might not
  // hold the surfaces together, and a first stage that separates them is no start.
  if (control == Control::mean_pressure && value <= 0.0) return 0.0;
  double factor = option;
  if (option == continuation_auto) {
    const Resolution r = resolution(system);
    if (!(r.ratio <= continuation_largest_zone)) return 0.0;
    factor = std::sqrt(continuation_zone / r.ratio);
  }
  return system.carries_pressure() ? 0.0 : factor;
}

MonitorSettings coarse_level_settings(const MonitorSettings &settings, double factor) {
  MonitorSettings coarse = settings;
  if (factor > 1.0) coarse.tolerance = first_stage_tolerance(settings.tolerance);
  return coarse;
}

namespace {

// The system's adhesion with its range times a factor while it lives; its own afterwards.
// The interactions are exchanged, not made anew, so that putting the system's own back
// cannot fail.
class LongerRange {
 public:
  LongerRange(System &system, const ExponentialAdhesion &adhesion, double factor)
      : system_(system),
        held_(std::make_unique<ExponentialAdhesion>(adhesion.work(),
                                                    factor * adhesion.range())) {
    system_.exchange_interaction(held_);
  }
  ~LongerRange() { system_.exchange_interaction(held_); }
  LongerRange(const LongerRange &) = delete;
  LongerRange &operator=(const LongerRange &) = delete;

 private:
  System &system_;
  std::unique_ptr<Interaction> held_;  // the interaction the system does not hold now
};

}  // namespace

bool solve_with_longer_range(const AlgorithmSpec &algorithm, const OptionValues &options,
                             System &system, Control control, double value, double factor,
                             double tolerance, Monitor &monitor) {
  if (!(factor > 1.0)) return true;
  {
    const ExponentialAdhesion &adhesion = *exponential_adhesion(system.interaction());
    // The longer range lowers the largest tension w/(F rho); where that would leave the
    // normal doubles, the stage is skipped rather than refused.
    if (!(adhesion.work() / (factor * adhesion.range()) >= DBL_MIN)) return true;
    const LongerRange longer(system, adhesion, factor);
    monitor.begin_first_stage(first_stage_tolerance(tolerance));
    algorithm.run(system, control, value, options, monitor);
  }
  const Termination ended = monitor.termination();
  if (ended == Termination::cancelled || ended == Termination::iteration_limit) return false;
  // A breakdown left the state reset, and surfaces that separated are no start: the second
  // stage then starts cold. A stage that stalled leaves a state to start from, as any other.
  if (ended == Termination::separated) system.reset_state();
  monitor.continue_with_next_stage(tolerance);
  return true;
}

}  // namespace asp
