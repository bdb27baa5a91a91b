/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The report after a refused solve (asperity.h, asp_solver_solve and the report getters):
 * "Errors (a status other than ASP_OK) mean the solve did not run ...; the system keeps the
 * state it had before the call", and the report getters return ASP_ERR_INVALID_STATE "before
 * the first solve, or after a solve that returned an error: the report then describes
 * nothing". So after each refused solve, right after a good one, the termination, iterations,
 * final error, convergence and elapsed seconds are refused with ASP_ERR_INVALID_STATE, and the
 * history is not the previous solve's (its length is refused the same way or is 0); the
 * system's state is unchanged; and the next good solve reports normally. */
#include <stdint.h>

#include "check.h"

#define NX 32
#define N (NX * NX)

static asp_grid *grid = NULL;
static asp_system *scene = NULL;
static asp_solver *solver = NULL;
static double before[N]; /* the pressure after the last good solve */

/* A good solve with a history, so that there is a report to forget. It starts cold, so that
 * it takes iterations. */
static void good_solve(void) {
  int64_t iterations = 0, length = 0;
  CHECK_OK(asp_system_reset(scene));
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK(iterations > 0 && length == iterations + 1);
  CHECK_OK(asp_system_get_field(scene, ASP_FIELD_PRESSURE, before, N));
}

/* The report describes nothing. */
static void check_no_report(const char *what, int line) {
  int reason = -1, converged = -1, status, ok;
  int64_t iterations = -1, length = -1, count = -1;
  double error = -1.0, seconds = -1.0, values[4096];
  printf("after a solve refused for %s\n", what);
  check_error(asp_solver_termination(solver, &reason), ASP_ERR_INVALID_STATE, NULL, __FILE__,
              line, "asp_solver_termination refused after a refused solve");
  check_error(asp_solver_iterations(solver, &iterations), ASP_ERR_INVALID_STATE, NULL, __FILE__,
              line, "asp_solver_iterations refused after a refused solve");
  check_error(asp_solver_evaluations(solver, &count), ASP_ERR_INVALID_STATE, NULL, __FILE__,
              line, "asp_solver_evaluations refused after a refused solve");
  check_error(asp_solver_transforms(solver, &count), ASP_ERR_INVALID_STATE, NULL, __FILE__,
              line, "asp_solver_transforms refused after a refused solve");
  check_error(asp_solver_final_error(solver, &error), ASP_ERR_INVALID_STATE, NULL, __FILE__,
              line, "asp_solver_final_error refused after a refused solve");
  check_error(asp_solver_converged(solver, &converged), ASP_ERR_INVALID_STATE, NULL, __FILE__,
              line, "asp_solver_converged refused after a refused solve");
  check_error(asp_solver_elapsed_seconds(solver, &seconds), ASP_ERR_INVALID_STATE, NULL,
              __FILE__, line, "asp_solver_elapsed_seconds refused after a refused solve");
  status = asp_solver_history_length(solver, &length);
  ok = status == ASP_ERR_INVALID_STATE || (status == ASP_OK && length == 0);
  if (!ok)
    fprintf(stderr, "%s:%d: asp_solver_history_length gives status %d, length %lld\n", __FILE__,
            line, status, (long long)length);
  check_record(ok, __FILE__, line, "no history after a refused solve");
  if (status == ASP_OK && length > 0 && length <= 4096)
    check_record(asp_solver_get_history(solver, ASP_HISTORY_ITERATION, values, length) != ASP_OK,
                 __FILE__, line, "the previous solve's history cannot be read");
}
#define CHECK_NO_REPORT(what) check_no_report((what), __LINE__)

/* The refused call left the state as it was. */
static void check_state_unchanged(int line) {
  static double after[N];
  int i, same = 1;
  check_record(asp_system_get_field(scene, ASP_FIELD_PRESSURE, after, N) == ASP_OK, __FILE__,
               line, "the pressure can be read");
  for (i = 0; i < N; ++i) same &= before[i] == after[i];
  check_record(same, __FILE__, line, "the refused solve left the pressure as it was");
}

int main(void) {
  static double h[N];
  int reason = 0;
  if (asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid) != ASP_OK ||
      asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 4.0 / NX, ASP_RMS_SLOPE, 0.1, 3, h, N) !=
          ASP_OK ||
      asp_system_create(grid, 1.0, &scene) != ASP_OK ||
      asp_system_set_topography(scene, h, N) != ASP_OK ||
      asp_solver_create("pk", &solver) != ASP_OK || asp_solver_set_history(solver, 1) != ASP_OK) {
    fprintf(stderr, "cannot set up: %s\n", asp_last_error_message());
    return 1;
  }

  /* Before any solve: nothing (the documented case the library already handles). */
  CHECK_NO_REPORT("no solve yet");

  /* Each refusal, right after a good solve. */
  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, 42, 0.005), ASP_ERR_INVALID_ARGUMENT, "'control'");
  CHECK_NO_REPORT("a control of no family");
  check_state_unchanged(__LINE__);

  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTACT_FRACTION, 0.005),
              ASP_ERR_INVALID_ARGUMENT, "'control'");
  CHECK_NO_REPORT("a control of another family");
  check_state_unchanged(__LINE__);

  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_GAP, 0.005), ASP_ERR_UNSUPPORTED,
              "mean_gap");
  CHECK_NO_REPORT("a control the algorithm does not offer");
  check_state_unchanged(__LINE__);

  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, -0.005),
              ASP_ERR_INVALID_ARGUMENT, "'value'");
  CHECK_NO_REPORT("a negative mean pressure on a non-adhesive wall");
  check_state_unchanged(__LINE__);

  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTROL_PENETRATION, NAN),
              ASP_ERR_INVALID_ARGUMENT, "'value'");
  CHECK_NO_REPORT("a NaN target");
  check_state_unchanged(__LINE__);

  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, INFINITY),
              ASP_ERR_INVALID_ARGUMENT, "'value'");
  CHECK_NO_REPORT("an infinite target");
  check_state_unchanged(__LINE__);

  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, NULL, ASP_CONTROL_MEAN_PRESSURE, 0.005),
              ASP_ERR_NULL_POINTER, "'system'");
  CHECK_NO_REPORT("a NULL system");
  check_state_unchanged(__LINE__);

  /* A target the scene cannot represent in doubles. */
  good_solve();
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 1e300),
              ASP_ERR_INVALID_ARGUMENT, "'value'");
  CHECK_NO_REPORT("a target too large for doubles");
  check_state_unchanged(__LINE__);

  /* The next good solve reports as usual. */
  good_solve();
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);

  asp_solver_destroy(solver);
  asp_system_destroy(scene);
  asp_grid_destroy(grid);
  return check_summary("api.refused_solve_report");
}
