// SPDX-License-Identifier: GPL-2.0-or-later
#include "solve.hpp"

#include <time.h>

#include <cmath>

namespace cli {

const std::vector<HistoryColumn> history_columns = {
    {ASP_HISTORY_ITERATION, "iteration"},   {ASP_HISTORY_EVALUATIONS, "evaluations"},
    {ASP_HISTORY_TRANSFORMS, "transforms"}, {ASP_HISTORY_SECONDS, "seconds"},
    {ASP_HISTORY_ERROR, "error"},           {ASP_HISTORY_OBJECTIVE, "objective"},
    {ASP_HISTORY_CONTACT_FRACTION, "contact_fraction"}};

bool SolveReport::converged() const { return termination == ASP_TERMINATION_CONVERGED; }

namespace {

// The processor time of the whole process so far (every thread's, the library's included).
double process_cpu_seconds() {
  timespec t{};
  if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0) return 0.0;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void require_finite(double value, const char *name, const SolveReport &r) {
  if (!std::isfinite(value))
    throw failure("the library reported a " + std::string(name) +
                  " that is not finite after a solve by " + r.algorithm + " that ended as '" +
                  termination_name(r.termination) +
                  "'; this is a bug in asperity, please report it");
}

}  // namespace

SolveReport solve(asp_solver *solver, const std::string &algorithm, Contact &contact,
                  int control, double value, ProgressLine &progress, bool record_history,
                  const std::string &where) {
  asp_system *system = contact.system.get();
  check(asp_solver_set_history(solver, record_history ? 1 : 0), "turning the history on");
  check(asp_solver_set_progress(solver, ProgressLine::callback, &progress),
        "setting the progress callback");
  // The callback is removed however the solve ends, and only after a refusal's message has
  // been read into the error thrown (the removal is a call of its own and empties it).
  struct ProgressRemoval {
    asp_solver *solver;
    ~ProgressRemoval() { asp_solver_set_progress(solver, nullptr, nullptr); }
  } removal{solver};
  const double cpu_start = process_cpu_seconds();
  const int status = asp_solver_solve(solver, system, control, value);
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  progress.clear();
  check_given(status, where);

  SolveReport r;
  r.algorithm = algorithm;
  r.cpu_seconds = cpu_seconds;
  check(asp_solver_termination(solver, &r.termination), "reading the report");
  check(asp_solver_iterations(solver, &r.iterations), "reading the report");
  check(asp_solver_evaluations(solver, &r.evaluations), "reading the report");
  check(asp_solver_transforms(solver, &r.transforms), "reading the report");
  check(asp_solver_elapsed_seconds(solver, &r.seconds), "reading the report");
  check(asp_solver_final_error(solver, &r.error), "reading the report");
  check(asp_solver_get_option(solver, "tolerance", &r.tolerance), "reading the report");
  r.mean_pressure = observable(system, ASP_MEAN_PRESSURE);
  r.penetration = observable(system, ASP_PENETRATION);
  r.mean_gap = observable(system, ASP_MEAN_GAP);
  r.contact_fraction = observable(system, ASP_CONTACT_FRACTION);
  r.compressive_fraction = observable(system, ASP_COMPRESSIVE_FRACTION);
  r.total_force = observable(system, ASP_TOTAL_FORCE);
  const struct {
    double value;
    const char *name;
  } numbers[] = {{r.seconds, "time"},
                 {r.error, "error"},
                 {r.mean_pressure, "mean pressure"},
                 {r.penetration, "penetration"},
                 {r.mean_gap, "mean gap"},
                 {r.contact_fraction, "contact fraction"},
                 {r.compressive_fraction, "compressive fraction"},
                 {r.total_force, "total force"}};
  for (const auto &n : numbers) require_finite(n.value, n.name, r);

  if (record_history) {
    int64_t rows = 0;
    check(asp_solver_history_length(solver, &rows), "reading the history");
    for (const HistoryColumn &column : history_columns) {
      std::vector<double> values(static_cast<size_t>(rows));
      check(asp_solver_get_history(solver, column.key, values.data(), rows),
            "reading the history");
      for (double v : values) require_finite(v, column.name, r);
      r.history.push_back(std::move(values));
    }
  }
  return r;
}

}  // namespace cli
