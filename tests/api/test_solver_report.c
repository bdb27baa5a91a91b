/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The solver's report by key (asperity.h, asp_solver_get): after solves that end in different
 * ways (converged with a history, at the iteration limit without one, cancelled by the
 * progress callback; on the pressure and on the displacement), every ASP_REPORT_* key gives
 * exactly what its getter of its own gives, the counts as doubles that hold them exactly; and
 * what the keyed getter refuses is refused with a message naming it: a key of no family, a key
 * of another family, a NULL solver or value, and a solver without a report. */
#include <stdint.h>

#include "check.h"

#define NX 32
#define N (NX * NX)

/* Every key agrees with the getter of its own, exactly: the values are copied, not computed. */
static void check_keys_agree(const asp_solver *solver, const char *what) {
  int reason = 0, converged = -1;
  int64_t iterations = -1, evaluations = -1, transforms = -1, length = -1;
  double error = -1.0, seconds = -1.0, value = -1.0;
  printf("the report after %s\n", what);
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_TERMINATION, &value));
  CHECK(value == (double)reason && (int)value == reason);
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_CONVERGED, &value));
  CHECK(value == (double)converged && (value == 0.0 || value == 1.0));
  CHECK(converged == (reason == ASP_TERMINATION_CONVERGED));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_ITERATIONS, &value));
  CHECK((int64_t)value == iterations && value == (double)iterations);
  CHECK_OK(asp_solver_evaluations(solver, &evaluations));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_EVALUATIONS, &value));
  CHECK((int64_t)value == evaluations && value == (double)evaluations);
  CHECK_OK(asp_solver_transforms(solver, &transforms));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_TRANSFORMS, &value));
  CHECK((int64_t)value == transforms && value == (double)transforms);
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_FINAL_ERROR, &value));
  CHECK(value == error);
  CHECK_OK(asp_solver_elapsed_seconds(solver, &seconds));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_ELAPSED_SECONDS, &value));
  CHECK(value == seconds);
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK_OK(asp_solver_get(solver, ASP_REPORT_HISTORY_LENGTH, &value));
  CHECK((int64_t)value == length && value == (double)length);
  /* The figures are those of a solve that ran (so that agreeing is not agreeing on zeros). */
  CHECK(iterations > 0 && evaluations > 0 && transforms > 0 && seconds >= 0.0);
}

/* Every key refused as before any solve, with the state named. */
static void check_no_report(const asp_solver *solver) {
  static const int keys[] = {ASP_REPORT_TERMINATION,     ASP_REPORT_CONVERGED,
                             ASP_REPORT_ITERATIONS,      ASP_REPORT_EVALUATIONS,
                             ASP_REPORT_TRANSFORMS,      ASP_REPORT_FINAL_ERROR,
                             ASP_REPORT_ELAPSED_SECONDS, ASP_REPORT_HISTORY_LENGTH};
  size_t k;
  double value = -1.0;
  for (k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
    CHECK_ERROR(asp_solver_get(solver, keys[k], &value), ASP_ERR_INVALID_STATE, "no report");
    CHECK_MESSAGE_HAS("asp_solver_get");
  }
  CHECK(value == -1.0);
}

static int stop_at_three(int64_t iteration, double seconds, double error, void *user_data) {
  (void)seconds;
  (void)error;
  (void)user_data;
  return iteration >= 3;
}

int main(void) {
  static double h[N];
  asp_grid *grid = NULL;
  asp_system *hard = NULL, *soft = NULL;
  asp_solver *pk = NULL, *lbfgs = NULL;
  double value = -1.0;
  int reason = 0;
  if (asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid) != ASP_OK ||
      asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 4.0 / NX, ASP_RMS_SLOPE, 0.1, 3, h, N) !=
          ASP_OK ||
      asp_system_create(grid, 1.0, &hard) != ASP_OK ||
      asp_system_set_topography(hard, h, N) != ASP_OK ||
      asp_system_create(grid, 1.0, &soft) != ASP_OK ||
      asp_system_set_topography(soft, h, N) != ASP_OK ||
      asp_system_set_soft_wall(soft, 1e-3, 0.01, 5e-4, 0.02) != ASP_OK ||
      asp_solver_create("pk", &pk) != ASP_OK || asp_solver_create("lbfgs", &lbfgs) != ASP_OK) {
    fprintf(stderr, "cannot set up: %s\n", asp_last_error_message());
    return 1;
  }

  /* Before any solve there is no report. */
  check_no_report(pk);

  /* Converged, with a history: the history length is its row count, iterations + 1. */
  CHECK_OK(asp_solver_set_history(pk, 1));
  CHECK_OK(asp_solver_solve(pk, hard, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_termination(pk, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);
  check_keys_agree(pk, "a converged solve with a history");
  CHECK_OK(asp_solver_get(pk, ASP_REPORT_HISTORY_LENGTH, &value));
  {
    double iterations = -1.0;
    CHECK_OK(asp_solver_get(pk, ASP_REPORT_ITERATIONS, &iterations));
    CHECK(value == iterations + 1.0);
  }

  /* At the iteration limit, without a history (length 0). */
  CHECK_OK(asp_solver_set_history(pk, 0));
  CHECK_OK(asp_solver_set_max_iterations(pk, 2));
  CHECK_OK(asp_system_reset(hard));
  CHECK_OK(asp_solver_solve(pk, hard, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_termination(pk, &reason));
  CHECK(reason == ASP_TERMINATION_ITERATION_LIMIT);
  check_keys_agree(pk, "a solve at its iteration limit");
  CHECK_OK(asp_solver_get(pk, ASP_REPORT_HISTORY_LENGTH, &value));
  CHECK(value == 0.0);

  /* Cancelled, by another algorithm on another formulation. */
  CHECK_OK(asp_solver_set_progress(lbfgs, stop_at_three, NULL));
  CHECK_OK(asp_solver_set_history(lbfgs, 1));
  CHECK_OK(asp_solver_solve(lbfgs, soft, ASP_CONTROL_PENETRATION, 0.05));
  CHECK_OK(asp_solver_termination(lbfgs, &reason));
  CHECK(reason == ASP_TERMINATION_CANCELLED);
  check_keys_agree(lbfgs, "a cancelled solve");

  /* Refusals, each naming what it refuses; the value is left alone. */
  value = -1.0;
  CHECK_ERROR(asp_solver_get(pk, 42, &value), ASP_ERR_INVALID_ARGUMENT, "'key'");
  CHECK_MESSAGE_HAS("42");
  CHECK_MESSAGE_HAS("ASP_REPORT_ITERATIONS");
  CHECK_ERROR(asp_solver_get(pk, 909, &value), ASP_ERR_INVALID_ARGUMENT, "'key'");
  CHECK_ERROR(asp_solver_get(pk, ASP_HISTORY_ITERATION, &value), ASP_ERR_INVALID_ARGUMENT,
              "'key'");
  CHECK_MESSAGE_HAS("ASP_HISTORY_ITERATION");
  CHECK_MESSAGE_HAS("a history column");
  CHECK_ERROR(asp_solver_get(pk, ASP_MEAN_PRESSURE, &value), ASP_ERR_INVALID_ARGUMENT,
              "ASP_MEAN_PRESSURE");
  CHECK(value == -1.0);
  CHECK_ERROR(asp_solver_get(NULL, ASP_REPORT_ITERATIONS, &value), ASP_ERR_NULL_POINTER,
              "'solver'");
  CHECK_ERROR(asp_solver_get(pk, ASP_REPORT_ITERATIONS, NULL), ASP_ERR_NULL_POINTER, "'value'");
  CHECK(value == -1.0);

  /* A refused solve leaves no report to read by key either. */
  CHECK_ERROR(asp_solver_solve(pk, hard, 42, 0.005), ASP_ERR_INVALID_ARGUMENT, "'control'");
  check_no_report(pk);

  asp_solver_destroy(lbfgs);
  asp_solver_destroy(pk);
  asp_system_destroy(soft);
  asp_system_destroy(hard);
  asp_grid_destroy(grid);
  return check_summary("test_solver_report");
}
