// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/monitor.hpp"

#include <cmath>

namespace asp {

const char *termination_name(Termination termination) {
  switch (termination) {
    case Termination::converged: return "converged";
    case Termination::iteration_limit: return "iteration limit";
    case Termination::cancelled: return "cancelled";
    case Termination::stalled: return "stalled";
    case Termination::breakdown: return "numerical breakdown";
    case Termination::separated:
      return "no stable state under this load: the surfaces separate (the tensile load "
             "exceeds the pull-off force)";
  }
  return "unknown";
}

Monitor::Monitor(const MonitorSettings &settings)
    : settings_(settings), start_(std::chrono::steady_clock::now()) {}

double Monitor::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Monitor::record(std::int64_t iteration, const IterationState &state, double elapsed,
                     double error, double objective, double contact_fraction,
                     bool replace_last) {
  if (replace_last && !history_.empty()) history_.pop_back();
  history_.push_back({static_cast<double>(iteration),
                      static_cast<double>(state.evaluations + prior_evaluations_),
                      static_cast<double>(state.transforms + prior_transforms_), elapsed,
                      error, objective, contact_fraction});
}

void Monitor::begin_first_stage(double tolerance) {
  settings_.tolerance = tolerance;
  first_stage_ = true;
}

void Monitor::continue_with_next_stage(double tolerance) {
  settings_.tolerance = tolerance;
  first_stage_ = false;
  prior_iterations_ = iterations_;
  prior_evaluations_ = evaluations_;
  prior_transforms_ = transforms_;
  stage_starts_ = true;
  termination_ = Termination::iteration_limit;
}

bool Monitor::should_stop(std::int64_t stage_iteration, const IterationState &state) {
  // The iteration of the solve; the stall window counts those of the stage.
  const std::int64_t iteration = prior_iterations_ + stage_iteration;
  const bool stage_start = stage_starts_;
  stage_starts_ = false;
  iterations_ = iteration;
  evaluations_ = state.evaluations + prior_evaluations_;
  transforms_ = state.transforms + prior_transforms_;
  // An error is a magnitude: one that is not finite, or negative (a maximum over no finite
  // value), says that the iterate broke down.
  if (!std::isfinite(state.error) || state.error < 0.0 ||
      (settings_.record_history && !std::isfinite(state.objective))) {
    termination_ = Termination::breakdown;
    // The iteration that broke down is counted, so it has its row, with its work and time;
    // its error, objective and contact fraction are not numbers to show, and the row repeats
    // those of the last finite state (the error the report gives), or DBL_MAX, 0 and 0 when
    // the starting point broke down. Every number of a history is finite.
    if (settings_.record_history) {
      const bool earlier = !history_.empty();
      record(iteration, state, seconds(), error_,
             earlier ? history_.back()[static_cast<int>(HistoryColumn::objective)] : 0.0,
             earlier ? history_.back()[static_cast<int>(HistoryColumn::contact_fraction)] : 0.0,
             stage_start);
    }
    return true;
  }
  error_ = state.error;

  const bool timed = settings_.record_history || settings_.progress != nullptr;
  const double elapsed = timed ? seconds() : 0.0;
  if (settings_.record_history)
    record(iteration, state, elapsed, state.error, state.objective, state.contact_fraction,
           stage_start);
  bool cancel = settings_.progress != nullptr && !stage_start &&
                settings_.progress(iteration, elapsed, state.error, settings_.progress_data) != 0;
  if (settings_.reductions != nullptr) {
    double asked = cancel ? 1.0 : 0.0;
    settings_.reductions->combine_maxima(&asked, 1);
    cancel = asked > 0.0;
  }

  // A state the load pulls apart is no equilibrium, whatever its error (and it has no
  // stable state ahead): it ends the solve before anything else is asked.
  if (state.separated) {
    termination_ = Termination::separated;
    return true;
  }
  // A state that met the tolerance is converged even if the callback also asked to stop,
  // but for a first stage's: converged, it would only end that stage.
  if (state.error <= settings_.tolerance && !(cancel && first_stage_)) {
    termination_ = Termination::converged;
    return true;
  }
  if (cancel) {
    termination_ = Termination::cancelled;
    return true;
  }
  if (iteration >= settings_.max_iterations) {
    termination_ = Termination::iteration_limit;
    return true;
  }
  if (stage_iteration == 0 || state.error < 0.99 * stall_reference_) {
    stall_reference_ = state.error;
    stall_since_ = iteration;
  } else if (settings_.stall_window > 0 && iteration - stall_since_ >= settings_.stall_window) {
    termination_ = Termination::stalled;
    return true;
  }
  return false;
}

IterationState observe(const Formulation &f, const double *x, const double *g, double value,
                       const Monitor &monitor) {
  return observe(f, x, g, f.error(x, g), value, monitor);
}

IterationState observe(const Formulation &f, const double *x, const double *g, double error,
                       double value, const Monitor &monitor) {
  IterationState state;
  state.error = error;
  state.objective =
      monitor.wants_objective() ? f.reported_objective(x, g, value) * f.energy_unit() : 0.0;
  state.contact_fraction = monitor.wants_objective() ? f.contact_fraction(x, g) : 0.0;
  state.evaluations = f.counters().evaluations;
  state.transforms = f.counters().transforms;
  state.separated = f.separates(x);
  return state;
}

void conclude(Formulation &formulation, System &system, Monitor &monitor) {
  if (monitor.termination() == Termination::breakdown || !formulation.finish()) {
    system.reset_state();
    monitor.declare_breakdown();
  }
}

}  // namespace asp
