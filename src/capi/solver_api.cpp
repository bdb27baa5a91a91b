// asp_solver_*: algorithms, their options, solves and reports.
#include <string>

#include "capi/constants.hpp"
#include "capi/firewall.hpp"
#include "capi/handles.hpp"
#include "core/checks.hpp"

using asp::capi::guarded;

namespace {
const asp::SolveReport &report_of(const asp_solver *solver) {
  asp::require_not_null(solver, "solver");
  const asp::SolveReport &r = solver->solver->report();
  if (!r.available)
    throw asp::Error(asp::Status::invalid_state, "the solver has not run a solve yet");
  return r;
}
}  // namespace

extern "C" {

int asp_solver_create(const char *algorithm, asp_solver **out) {
  if (out != nullptr) *out = nullptr;
  return guarded("asp_solver_create", [&] {
    asp::require_not_null(algorithm, "algorithm");
    asp::require_not_null(out, "out");
    std::unique_ptr<asp_solver> handle(new asp_solver);
    handle->solver = asp::make_solver(algorithm);
    *out = handle.release();
  });
}

void asp_solver_destroy(asp_solver *solver) { delete solver; }

int asp_solver_set_tolerance(asp_solver *solver, double tolerance) {
  return guarded("asp_solver_set_tolerance", [&] {
    asp::require_not_null(solver, "solver");
    asp::require_positive(tolerance, "tolerance");
    solver->solver->options().tolerance = tolerance;
  });
}

int asp_solver_set_max_iterations(asp_solver *solver, int64_t max_iterations) {
  return guarded("asp_solver_set_max_iterations", [&] {
    asp::require_not_null(solver, "solver");
    asp::require_at_least(max_iterations, 1, "max_iterations");
    solver->solver->options().max_iterations = max_iterations;
  });
}

int asp_solver_solve(asp_solver *solver, asp_system *system, int control, double value) {
  return guarded("asp_solver_solve", [&] {
    asp::require_not_null(solver, "solver");
    asp::require_not_null(system, "system");
    asp::capi::require_member(control, asp::capi::Family::control, "control");
    const asp::Control c = control == ASP_CONTROL_MEAN_PRESSURE ? asp::Control::mean_pressure
                           : control == ASP_CONTROL_PENETRATION ? asp::Control::penetration
                                                                : asp::Control::mean_gap;
    solver->solver->solve(*system->system, c, value);
  });
}

int asp_solver_iterations(const asp_solver *solver, int64_t *iterations) {
  return guarded("asp_solver_iterations", [&] {
    asp::require_not_null(iterations, "iterations");
    *iterations = report_of(solver).iterations;
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
    *converged = report_of(solver).converged ? 1 : 0;
  });
}

int asp_solver_elapsed_seconds(const asp_solver *solver, double *seconds) {
  return guarded("asp_solver_elapsed_seconds", [&] {
    asp::require_not_null(seconds, "seconds");
    *seconds = report_of(solver).seconds;
  });
}

}  // extern "C"
