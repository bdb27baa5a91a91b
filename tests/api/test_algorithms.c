/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Every algorithm of the hard wall the build lists (asp_algorithms) works through the C API as
 * the header says for all of them: it solves a small rough scene under the controls it offers
 * to the same state as every other algorithm, records its history, reports progress and can
 * be cancelled. Every algorithm offers penetration control; all but lbfgsb offer load control
 * with their default options, which lbfgsb refuses on the pressure (it keeps bounds, not a
 * mean; on the gap the load is a work term: tests/api/test_load_control.c). The unconstrained
 * solvers of soft
 * potentials refuse the hard wall, which this checks; tests/api/test_unconstrained.c runs them
 * on their own scenes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "check.h"

enum { nx = 48, ny = 40, n = nx * ny };

static int cancel_at_two(int64_t iteration, double seconds, double error, void *user_data) {
  (void)seconds;
  (void)error;
  ++*(int *)user_data;
  return iteration >= 2;
}

/* The same state as the reference: a unique optimum, both solved to 1e-11, so 1e-8 of the
 * peak values leaves room for the condition number of this grid (measured differences near
 * 1e-12). */
static void check_same_state(const double *p, const double *g, const double *p0,
                             const double *g0) {
  double dp = 0, dg = 0, p_max = 0, g_max = 0;
  int64_t i;
  for (i = 0; i < n; ++i) {
    dp = fmax(dp, fabs(p[i] - p0[i]));
    dg = fmax(dg, fabs(g[i] - g0[i]));
    p_max = fmax(p_max, fabs(p0[i]));
    g_max = fmax(g_max, fabs(g0[i]));
  }
  CHECK(dp <= 1e-8 * p_max);
  CHECK(dg <= 1e-8 * g_max);
}

/* Solves the scene with `algorithm` and leaves pressure and gap in p and g. */
static void solve(const char *algorithm, asp_system *system, int control, double value,
                  double *p, double *g, double *contact) {
  asp_solver *solver = NULL;
  int converged = 0;
  CHECK_OK(asp_solver_create(algorithm, &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-11));
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_solve(solver, system, control, value));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, g, n));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, contact));
  asp_solver_destroy(solver);
}

/* Whether the algorithm solves the hard wall (the header's list). */
static int handles_hard_wall(const char *algorithm) {
  return strcmp(algorithm, "pk") == 0 || strcmp(algorithm, "bugnicourt") == 0 ||
         strcmp(algorithm, "lbfgsb") == 0;
}

/* Whether the algorithm offers mean-pressure control (the header's list). */
static int offers_load_control(const char *algorithm) {
  return strcmp(algorithm, "lbfgsb") != 0;
}

/* History and cancellation, as for every solver, under the given control. */
static void check_monitor(const char *algorithm, asp_system *system, int control,
                          double value) {
  asp_solver *solver = NULL;
  int calls = 0, reason = 0;
  int64_t length = 0, i;
  double iterations[8], errors[8];
  CHECK_OK(asp_solver_create(algorithm, &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_solver_set_progress(solver, cancel_at_two, &calls));
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_solve(solver, system, control, value));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CANCELLED);
  CHECK(calls == 3);
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK(length == 3);
  if (length == 3) {
    CHECK_OK(asp_solver_get_history(solver, ASP_HISTORY_ITERATION, iterations, length));
    CHECK_OK(asp_solver_get_history(solver, ASP_HISTORY_ERROR, errors, length));
    for (i = 0; i < length; ++i) {
      CHECK(iterations[i] == (double)i);
      CHECK(isfinite(errors[i]) && errors[i] >= 0.0);
    }
  }
  asp_solver_destroy(solver);
}

/* bugnicourt on the gap, under penetration, mean-gap and mean-pressure control, against the
 * reference. */
static void check_primal(asp_system *system, double penetration, double mean_gap,
                         const double *p0, const double *g0) {
  static double p[n], g[n];
  int control;
  for (control = ASP_CONTROL_PENETRATION; control <= ASP_CONTROL_MEAN_GAP; ++control) {
    asp_solver *solver = NULL;
    int converged = 0;
    CHECK_OK(asp_solver_create("bugnicourt", &solver));
    CHECK_OK(asp_solver_set_option_string(solver, "variable", "gap"));
    CHECK_OK(asp_solver_set_tolerance(solver, 1e-11));
    CHECK_OK(asp_system_reset(system));
    CHECK_OK(asp_solver_solve(solver, system, control,
                              control == ASP_CONTROL_PENETRATION ? penetration : mean_gap));
    CHECK_OK(asp_solver_converged(solver, &converged));
    CHECK(converged == 1);
    CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n));
    CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, g, n));
    check_same_state(p, g, p0, g0);
    /* Mean-pressure control on the gap, at this state's load, from rest: the same state. */
    {
      double load = 0.0;
      CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &load));
      CHECK_OK(asp_system_reset(system));
      CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, load));
      CHECK_OK(asp_solver_converged(solver, &converged));
      CHECK(converged == 1);
      CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n));
      CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, g, n));
      check_same_state(p, g, p0, g0);
    }
    asp_solver_destroy(solver);
  }
}

int main(void) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  double *h = malloc(n * sizeof *h), *p0 = malloc(n * sizeof *p0), *g0 = malloc(n * sizeof *g0),
         *p = malloc(n * sizeof *p), *g = malloc(n * sizeof *g);
  char names[256], *name;
  int64_t length = 0;
  double contact0 = 0, contact = 0, penetration = 0;
  int control;

  CHECK(h && p0 && g0 && p && g);
  CHECK_OK(asp_grid_create_2d(nx, ny, 1.0, 1.0 * ny / nx, &grid));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / nx, ASP_RMS_SLOPE, 0.1, 3,
                                      h, n));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, h, n));
  CHECK_OK(asp_algorithms(names, sizeof names, &length));
  CHECK(strstr(names, "pk") != NULL && strstr(names, "bugnicourt") != NULL &&
        strstr(names, "lbfgsb") != NULL);

  for (control = ASP_CONTROL_MEAN_PRESSURE; control <= ASP_CONTROL_PENETRATION; ++control) {
    /* The reference: pk under load control, and its penetration for penetration control. */
    solve("pk", system, ASP_CONTROL_MEAN_PRESSURE, 0.01, p0, g0, &contact0);
    CHECK_OK(asp_system_get(system, ASP_PENETRATION, &penetration));
    for (name = strtok(names, "\n"); name != NULL; name = strtok(NULL, "\n")) {
      if (!handles_hard_wall(name)) {
        asp_solver *solver = NULL;
        CHECK_OK(asp_solver_create(name, &solver));
        /* asp_solver_supports answers as the solve does, without solving. */
        CHECK_ERROR(asp_solver_supports(solver, system, control), ASP_ERR_UNSUPPORTED,
                    "hard wall");
        CHECK_ERROR(asp_solver_solve(solver, system, control, 0.01), ASP_ERR_UNSUPPORTED,
                    "hard wall");
        asp_solver_destroy(solver);
        continue;
      }
      if (control == ASP_CONTROL_MEAN_PRESSURE && !offers_load_control(name)) {
        asp_solver *solver = NULL;
        CHECK_OK(asp_solver_create(name, &solver));
        CHECK_ERROR(asp_solver_supports(solver, system, control), ASP_ERR_UNSUPPORTED,
                    "mean_pressure");
        CHECK_ERROR(asp_solver_solve(solver, system, control, 0.01), ASP_ERR_UNSUPPORTED,
                    "mean_pressure");
        asp_solver_destroy(solver);
        check_monitor(name, system, ASP_CONTROL_PENETRATION, penetration);
        continue;
      }
      {
        asp_solver *solver = NULL;
        CHECK_OK(asp_solver_create(name, &solver));
        CHECK_OK(asp_solver_supports(solver, system, control));
        CHECK_ERROR(asp_solver_supports(solver, system, 0), ASP_ERR_INVALID_ARGUMENT, "control");
        CHECK_ERROR(asp_solver_supports(NULL, system, control), ASP_ERR_NULL_POINTER, "solver");
        CHECK_ERROR(asp_solver_supports(solver, NULL, control), ASP_ERR_NULL_POINTER, "system");
        asp_solver_destroy(solver);
      }
      solve(name, system, control,
            control == ASP_CONTROL_MEAN_PRESSURE ? 0.01 : penetration, p, g, &contact);
      check_same_state(p, g, p0, g0);
      CHECK(contact == contact0);
      if (control == ASP_CONTROL_MEAN_PRESSURE)
        check_monitor(name, system, ASP_CONTROL_MEAN_PRESSURE, 0.01);
    }
    if (control == ASP_CONTROL_MEAN_PRESSURE) {
      double mean_gap = 0;
      solve("pk", system, ASP_CONTROL_MEAN_PRESSURE, 0.01, p0, g0, &contact0);
      CHECK_OK(asp_system_get(system, ASP_MEAN_GAP, &mean_gap));
      check_primal(system, penetration, mean_gap, p0, g0);
    }
    /* strtok cut the list: list the names again for the next control. */
    CHECK_OK(asp_algorithms(names, sizeof names, &length));
  }

  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(h);
  free(p0);
  free(g0);
  free(p);
  free(g);
  return check_summary("api.algorithms");
}
