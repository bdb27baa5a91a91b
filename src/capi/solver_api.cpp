// SPDX-License-Identifier: GPL-2.0-or-later
// asp_algorithms and asp_solver_*: algorithms, their options, solves, reports and histories.
#include <string>
#include <vector>

#include "capi/constants.hpp"
#include "capi/firewall.hpp"
#include "capi/handles.hpp"
#include "capi/text.hpp"
#include "core/checks.hpp"
#include "physics/normal_stiffness.hpp"

using asp::capi::Agreement;
using asp::capi::guarded;
using asp::capi::guarded_on;

namespace {
const asp::SolveReport &report_of(const asp_solver *solver) {
  asp::capi::require_handle(solver, "solver");
  const asp::SolveReport &r = solver->solver->report();
  if (!r.available)
    throw asp::Error(asp::Status::invalid_state,
                     "the solver has no report: no solve has run, or the last one failed");
  return r;
}

asp::Control control_of(int control) {
  asp::capi::require_member(control, asp::capi::Family::control, "control");
  switch (control) {
    case ASP_CONTROL_MEAN_PRESSURE: return asp::Control::mean_pressure;
    case ASP_CONTROL_PENETRATION: return asp::Control::penetration;
    default: return asp::Control::mean_gap;
  }
}

int termination_code(asp::Termination termination) {
  switch (termination) {
    case asp::Termination::converged: return ASP_TERMINATION_CONVERGED;
    case asp::Termination::iteration_limit: return ASP_TERMINATION_ITERATION_LIMIT;
    case asp::Termination::cancelled: return ASP_TERMINATION_CANCELLED;
    case asp::Termination::stalled: return ASP_TERMINATION_STALLED;
    case asp::Termination::breakdown: return ASP_TERMINATION_BREAKDOWN;
    case asp::Termination::separated: return ASP_TERMINATION_SEPARATED;
  }
  throw asp::Error(asp::Status::internal, "termination reason without a code");
}
}  // namespace

extern "C" {

int asp_algorithms(char *buffer, int64_t size, int64_t *length) {
  return guarded("asp_algorithms", [&] {
    std::string text;
    for (const asp::AlgorithmSpec &a : asp::algorithms()) text += a.name + "\n";
    asp::capi::copy_text(text, buffer, size, length);
  });
}

int asp_solver_create(const char *algorithm, asp_solver **out) {
  if (out != nullptr) *out = nullptr;
  return guarded("asp_solver_create", [&] {
    asp::require_not_null(algorithm, "algorithm");
    asp::require_not_null(out, "out");
    std::unique_ptr<asp_solver> handle(new asp_solver);
    handle->solver.reset(new asp::Solver(algorithm));
    *out = handle.release();
  });
}

void asp_solver_destroy(asp_solver *solver) {
  // A solver in use by a running call (destroyed from its callback) is left alone, and the
  // reason is the last error message.
  guarded("asp_solver_destroy", [&] {
    if (solver != nullptr) asp::capi::require_handle(solver, "solver");
    delete solver;
  });
}

int asp_solver_describe(const asp_solver *solver, char *buffer, int64_t size, int64_t *length) {
  return guarded("asp_solver_describe", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::capi::copy_text(asp::describe(solver->solver->algorithm()), buffer, size, length);
  });
}

int asp_solver_set_option(asp_solver *solver, const char *name, double value) {
  return guarded("asp_solver_set_option", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::require_not_null(name, "name");
    solver->solver->set_option(name, value);
  });
}

int asp_solver_set_option_string(asp_solver *solver, const char *name, const char *value) {
  return guarded("asp_solver_set_option_string", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::require_not_null(name, "name");
    asp::require_not_null(value, "value");
    solver->solver->set_option(name, std::string(value));
  });
}

int asp_solver_get_option(const asp_solver *solver, const char *name, double *value) {
  return guarded("asp_solver_get_option", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::require_not_null(name, "name");
    asp::require_not_null(value, "value");
    *value = solver->solver->option(name);
  });
}

int asp_solver_get_option_string(const asp_solver *solver, const char *name, char *buffer,
                                 int64_t size, int64_t *length) {
  return guarded("asp_solver_get_option_string", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::require_not_null(name, "name");
    asp::capi::copy_text(solver->solver->option_text(name), buffer, size, length);
  });
}

int asp_solver_set_tolerance(asp_solver *solver, double tolerance) {
  return guarded("asp_solver_set_tolerance", [&] {
    asp::capi::require_handle(solver, "solver");
    solver->solver->set_option("tolerance", tolerance);
  });
}

int asp_solver_set_max_iterations(asp_solver *solver, int64_t max_iterations) {
  return guarded("asp_solver_set_max_iterations", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::require_at_least(max_iterations, 1, "max_iterations");
    // Counts beyond 2^53 are not distinguishable as doubles; the option's range caps them.
    // Counts beyond the option's range (9.2e18) are no limit in practice: they mean the largest.
    const int64_t largest = 9200000000000000000;
    solver->solver->set_option(
        "max_iterations", static_cast<double>(max_iterations > largest ? largest : max_iterations));
  });
}

int asp_solver_set_progress(asp_solver *solver, asp_progress_fn progress, void *user_data) {
  return guarded("asp_solver_set_progress", [&] {
    asp::capi::require_handle(solver, "solver");
    solver->solver->set_progress(progress, user_data);
  });
}

int asp_solver_set_history(asp_solver *solver, int on) {
  return guarded("asp_solver_set_history", [&] {
    asp::capi::require_handle(solver, "solver");
    solver->solver->set_history(on != 0);
  });
}

int asp_solver_solve(asp_solver *solver, asp_system *system, int control, double value) {
  const asp::Grid *grid = system != nullptr ? &system->system->grid() : nullptr;
  return guarded_on("asp_solver_solve", grid, [&](Agreement &agreement) {
    asp::capi::require_handle(solver, "solver");
    solver->solver->forget_last_solve();
    solver->solved_revision = 0;
    asp::capi::require_handle(system, "system");
    asp::capi::require_topography(system);
    const asp::Control c = control_of(control);
    // The algorithm and its options as one number (their count differs between algorithms),
    // whether the history is kept (it adds sums to each iteration), the control and the value.
    const std::vector<double> scalars = {
        solver->solver->fingerprint(),
        solver->solver->history_on() ? 1.0 : 0.0, static_cast<double>(control), value};
    agreement.checks_passed(
        scalars, "arguments 'control' and 'value', or the solver's algorithm, options or history");
    const asp::capi::BusyScope busy(system, solver);
    solver->solver->solve(*system->system, c, value);
    solver->solved_revision = system->system->revision();
  });
}

int asp_solver_normal_stiffness(asp_solver *solver, asp_system *system, double *stiffness) {
  const asp::Grid *grid = system != nullptr ? &system->system->grid() : nullptr;
  return guarded_on("asp_solver_normal_stiffness", grid, [&](Agreement &agreement) {
    asp::capi::require_handle(solver, "solver");
    asp::capi::require_handle(system, "system");
    asp::require_not_null(stiffness, "stiffness");
    const asp::SolveReport &report = solver->solver->report();
    if (!report.available || solver->solved_revision == 0)
      throw asp::Error(asp::Status::invalid_state,
                       "the solver has no solve to take the stiffness of: no solve has run, or "
                       "the last one failed");
    if (solver->solved_revision != system->system->revision())
      throw asp::Error(asp::Status::invalid_state,
                       "argument 'system' is not the state the solver's last solve left: "
                       "that solve was of another system, or this one has changed since "
                       "(topography, interaction, K~(0), reference pressure or a reset); "
                       "solve it again first");
    if (!report.converged())
      throw asp::Error(asp::Status::invalid_state,
                       "the solver's last solve did not converge (its state is not an "
                       "equilibrium, and has no stiffness); solve it to convergence first");
    agreement.checks_passed();
    const asp::capi::BusyScope busy(system, solver);
    *stiffness = asp::normal_stiffness(*system->system).value;
  });
}

int asp_solver_supports(const asp_solver *solver, const asp_system *system, int control) {
  return guarded("asp_solver_supports", [&] {
    asp::capi::require_handle(solver, "solver");
    asp::capi::require_handle(system, "system");
    solver->solver->check_supported(*system->system, control_of(control));
  });
}

int asp_solver_get(const asp_solver *solver, int key, double *value) {
  return guarded("asp_solver_get", [&] {
    asp::require_not_null(value, "value");
    asp::capi::require_member(key, asp::capi::Family::report_key, "key");
    const asp::SolveReport &r = report_of(solver);
    // Counts go out as doubles, exact below 2^53 (the header says so).
    switch (key) {
      case ASP_REPORT_TERMINATION: *value = termination_code(r.termination); break;
      case ASP_REPORT_CONVERGED: *value = r.converged() ? 1.0 : 0.0; break;
      case ASP_REPORT_ITERATIONS: *value = static_cast<double>(r.iterations); break;
      case ASP_REPORT_EVALUATIONS: *value = static_cast<double>(r.evaluations); break;
      case ASP_REPORT_TRANSFORMS: *value = static_cast<double>(r.transforms); break;
      case ASP_REPORT_FINAL_ERROR: *value = r.error; break;
      case ASP_REPORT_ELAPSED_SECONDS: *value = r.seconds; break;
      case ASP_REPORT_HISTORY_LENGTH:
        *value = static_cast<double>(solver->solver->history().size());
        break;
      default:
        throw asp::Error(asp::Status::internal,
                         "report key " + std::to_string(key) + " without a figure");
    }
  });
}

int asp_solver_termination(const asp_solver *solver, int *reason) {
  return guarded("asp_solver_termination", [&] {
    asp::require_not_null(reason, "reason");
    *reason = termination_code(report_of(solver).termination);
  });
}

int asp_solver_iterations(const asp_solver *solver, int64_t *iterations) {
  return guarded("asp_solver_iterations", [&] {
    asp::require_not_null(iterations, "iterations");
    *iterations = report_of(solver).iterations;
  });
}

int asp_solver_evaluations(const asp_solver *solver, int64_t *evaluations) {
  return guarded("asp_solver_evaluations", [&] {
    asp::require_not_null(evaluations, "evaluations");
    *evaluations = report_of(solver).evaluations;
  });
}

int asp_solver_transforms(const asp_solver *solver, int64_t *transforms) {
  return guarded("asp_solver_transforms", [&] {
    asp::require_not_null(transforms, "transforms");
    *transforms = report_of(solver).transforms;
  });
}

int asp_solver_final_error(const asp_solver *solver, double *error) {
  return guarded("asp_solver_final_error", [&] {
    asp::require_not_null(error, "error");
    *error = report_of(solver).error;
  });
}

int asp_solver_converged(const asp_solver *solver, int *converged) {
  return guarded("asp_solver_converged", [&] {
    asp::require_not_null(converged, "converged");
    *converged = report_of(solver).converged() ? 1 : 0;
  });
}

int asp_solver_elapsed_seconds(const asp_solver *solver, double *seconds) {
  return guarded("asp_solver_elapsed_seconds", [&] {
    asp::require_not_null(seconds, "seconds");
    *seconds = report_of(solver).seconds;
  });
}

int asp_solver_history_length(const asp_solver *solver, int64_t *length) {
  return guarded("asp_solver_history_length", [&] {
    asp::require_not_null(length, "length");
    report_of(solver);
    *length = static_cast<int64_t>(solver->solver->history().size());
  });
}

int asp_solver_get_history(const asp_solver *solver, int column, double *values, int64_t n) {
  return guarded("asp_solver_get_history", [&] {
    asp::capi::require_member(column, asp::capi::Family::history_column, "column");
    report_of(solver);
    const asp::History &history = solver->solver->history();
    const auto rows = static_cast<int64_t>(history.size());
    if (n != rows)
      throw asp::Error(asp::Status::size_mismatch, "array 'values' has count " + std::to_string(n) +
                                                       " but the history has " +
                                                       std::to_string(rows) + " rows");
    if (rows > 0) asp::require_not_null(values, "values");
    static_assert(ASP_HISTORY_CONTACT_FRACTION - ASP_HISTORY_ITERATION ==
                      static_cast<int>(asp::HistoryColumn::contact_fraction),
                  "history columns are numbered in the order of a row");
    const int k = column - ASP_HISTORY_ITERATION;
    for (int64_t i = 0; i < rows; ++i) values[i] = history[static_cast<std::size_t>(i)][k];
  });
}

}  // extern "C"
