// SPDX-License-Identifier: GPL-2.0-or-later
// The monitor watches every solve the same way, whatever the algorithm: it compares the error
// with the tolerance, counts iterations, guards against non-finite numbers, detects stalls,
// calls the user's progress callback, records the history when asked, and says why the solve
// ended. A solver asks it once per iteration whether to stop.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/reductions.hpp"
#include "formulations/formulation.hpp"
#include "physics/system.hpp"

namespace asp {

enum class Termination { converged, iteration_limit, cancelled, stalled, breakdown, separated };
const char *termination_name(Termination termination);

// The C signature of asp_progress_fn: non-zero return cancels.
using ProgressFunction = int (*)(std::int64_t iteration, double seconds, double error,
                                 void *user_data);

struct MonitorSettings {
  double tolerance = 1e-8;
  std::int64_t max_iterations = 10000;
  // Stalled: the smallest error seen has not fallen below 99 % of itself within this many
  // iterations (0: never).
  std::int64_t stall_window = 1000;
  bool record_history = false;
  ProgressFunction progress = nullptr;
  void *progress_data = nullptr;
  // The processes of a distributed solve, which must stop together: a cancel asked on one
  // stops all. Null on one process.
  const Reductions *reductions = nullptr;
};

// What an iteration reached, as the solver knows it.
struct IterationState {
  double error = 0.0;
  double objective = 0.0;  // only read when the monitor wants it
  double contact_fraction = 0.0;
  std::int64_t evaluations = 0;
  std::int64_t transforms = 0;
  // The formulation's word that the load pulls the surfaces apart (Formulation::separates).
  bool separated = false;
};

// One row per iteration; columns in the order of the ASP_HISTORY_* constants.
enum class HistoryColumn {
  iteration,
  evaluations,
  transforms,
  seconds,
  error,
  objective,
  contact_fraction,
};
constexpr int history_columns = 7;
using History = std::vector<std::array<double, history_columns>>;

class Monitor {
 public:
  explicit Monitor(const MonitorSettings &settings);

  // Whether the solver should compute its objective (only the history records it).
  bool wants_objective() const { return settings_.record_history; }
  double tolerance() const { return settings_.tolerance; }

  // Iteration `iteration` (0: the starting point) has reached `state`. Returns true when the
  // solve must stop now; termination() then says why. With the history on, every iteration
  // asked about has its row, the one that breaks down included, so that a history has
  // iterations() + 1 rows however the solve ends.
  bool should_stop(std::int64_t iteration, const IterationState &state);

  // The solver found a non-finite value the monitor could not see (e.g. in physical units).
  void declare_breakdown() { termination_ = Termination::breakdown; }
  // The algorithm has no step left to take (no descent direction) short of the tolerance.
  void declare_stalled() { termination_ = Termination::stalled; }
  // Transforms made for this solve before its first iteration (the coarse levels of nested
  // grids): counted in every row of the history and in transforms(), as the solve's work.
  void count_prior_transforms(std::int64_t transforms) { prior_transforms_ = transforms; }
  // A solve in stages on the system's grid (range_continuation.hpp): the first stage, about
  // to run, stops at `tolerance`. A cancel asked at an iteration that also meets it stops the
  // solve (it would only stop the stage).
  void begin_first_stage(double tolerance);
  // The stage that ran is over and the next, to `tolerance`, starts from its state. The next
  // stage's iterations, evaluations and transforms continue the counts; its starting point
  // is numbered as the stage's last iteration and takes that iteration's row of the history
  // (the same state, measured against the next stage's objective), so that a history still
  // has iterations() + 1 rows; the progress callback, which saw that iteration, is not
  // called for it again. max_iterations bounds the stages together; the stall window starts
  // again. The termination is cleared: the caller decides which endings of a stage it
  // continues from (range_continuation.hpp: all but a cancel and the iteration limit).
  void continue_with_next_stage(double tolerance);

  Termination termination() const { return termination_; }
  std::int64_t iterations() const { return iterations_; }
  // The work counters of the last iteration the solver reported.
  std::int64_t evaluations() const { return evaluations_; }
  std::int64_t transforms() const { return transforms_; }
  // The error of the last iteration with a finite one.
  double error() const { return error_; }
  double seconds() const;
  History &history() { return history_; }

 private:
  void record(std::int64_t iteration, const IterationState &state, double elapsed, double error,
              double objective, double contact_fraction, bool replace_last);

  MonitorSettings settings_;
  std::chrono::steady_clock::time_point start_;
  Termination termination_ = Termination::iteration_limit;
  std::int64_t iterations_ = 0;
  std::int64_t evaluations_ = 0;
  std::int64_t transforms_ = 0;
  std::int64_t prior_transforms_ = 0;
  // The work of the stages before this one (continue_with_next_stage).
  std::int64_t prior_iterations_ = 0;
  std::int64_t prior_evaluations_ = 0;
  bool stage_starts_ = false;  // the next should_stop is a later stage's starting point
  bool first_stage_ = false;   // a stage before the last runs
  // The last finite error seen; DBL_MAX until there is one (a start that is not finite).
  double error_ = std::numeric_limits<double>::max();
  double stall_reference_ = 0.0;  // the error the next iterations must beat by 1 %
  std::int64_t stall_since_ = 0;  // iteration at which stall_reference_ was set
  History history_;
};

// The state the monitor sees at x with the gradient g (before any projection) and the
// objective's value there: the error, the counters, and the reported objective and contact
// fraction when the history is recorded.
IterationState observe(const Formulation &f, const double *x, const double *g, double value,
                       const Monitor &monitor);
// The same with the error already known (a solver that gathers it in a pass of its own).
IterationState observe(const Formulation &f, const double *x, const double *g, double error,
                       double value, const Monitor &monitor);

// The end of every algorithm's run: writes the formulation's iterate back into the system, or,
// after a breakdown (seen by the monitor or in the physical values), resets the system to zero
// pressure and records the breakdown.
void conclude(Formulation &formulation, System &system, Monitor &monitor);

}  // namespace asp
