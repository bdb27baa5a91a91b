/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Whatever way a solve ends, and whatever the algorithm, what it leaves adds up:
 *  - its history has one row per iteration from iteration 0, so iterations + 1 rows, the last
 *    one with the reported iteration, work counters and final error, every number finite:
 *    every algorithm converged, at the iteration limit, cancelled by the progress callback and
 *    with a stall window of 2; and "fire" broken down, on a potential whose energy below a
 *    gap of -0.1 is so large that the energy of a few pixels there overflows a double (the
 *    breakdown once left the history a row short);
 *  - the dynamics solvers ("fire", "fire_mass_weighted", "gfmd") on a soft wall so narrow
 *    (range 1e-300) that its curvature overflows a double end as broken down, with their
 *    history of one row, where "fire" once failed with ASP_ERR_INTERNAL for want of a time
 *    step;
 *  - asp_last_error_message() is empty after a solve that returned ASP_OK, also when the
 *    progress or the potential callback made a call of its own that the library refused (the
 *    message of that call was once left behind). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "check.h"

enum { nx = 32, n = nx * nx };

/* Two scenes on one rough surface of 32 x 32 pixels of unit size (rms slope 0.1): the hard
 * wall, which the constrained solvers take, and a soft wall (range 0.3, its well at 0.69),
 * which the unconstrained ones take. Each algorithm is solved on the first it serves. */
typedef struct {
  asp_grid *grid;
  asp_system *hard, *soft;
  double heights[n];
} Scenes;

static void make_scenes(Scenes *s) {
  CHECK_OK(asp_grid_create_2d(nx, nx, 32.0, 32.0, &s->grid));
  CHECK_OK(asp_topography_self_affine(s->grid, 0.8, 32.0, 16.0, 2.0, ASP_RMS_SLOPE, 0.1, 5,
                                      s->heights, n));
  CHECK_OK(asp_system_create(s->grid, 1.0, &s->hard));
  CHECK_OK(asp_system_set_topography(s->hard, s->heights, n));
  CHECK_OK(asp_system_create(s->grid, 1.0, &s->soft));
  CHECK_OK(asp_system_set_topography(s->soft, s->heights, n));
  CHECK_OK(asp_system_set_soft_wall(s->soft, 0.05, 0.3, 0.01, 0.3));
}

/* The system, control and value the solver serves: on the hard wall a mean pressure of
 * 0.005 or a penetration of 0.3, on the soft wall a mean pressure of 3e-4 or the crest 0.45
 * from the wall. 0 if none. */
static int served(const Scenes *s, const asp_solver *solver, asp_system **system, int *control,
                  double *value) {
  asp_system *const systems[2] = {s->hard, s->soft};
  const double pressures[2] = {0.005, 3e-4}, penetrations[2] = {0.3, -0.45};
  int k;
  for (k = 0; k < 2; ++k) {
    *system = systems[k];
    *control = ASP_CONTROL_MEAN_PRESSURE;
    *value = pressures[k];
    if (asp_solver_supports(solver, *system, *control) == ASP_OK) return 1;
    *control = ASP_CONTROL_PENETRATION;
    *value = penetrations[k];
    if (asp_solver_supports(solver, *system, *control) == ASP_OK) return 1;
  }
  return 0;
}

/* The history of the solver's last solve against its report. */
static void check_rows(const asp_solver *solver, const char *what, int line) {
  static const int columns[7] = {ASP_HISTORY_ITERATION,  ASP_HISTORY_EVALUATIONS,
                                 ASP_HISTORY_TRANSFORMS, ASP_HISTORY_SECONDS,
                                 ASP_HISTORY_ERROR,      ASP_HISTORY_OBJECTIVE,
                                 ASP_HISTORY_CONTACT_FRACTION};
  double *column[7] = {NULL};
  int64_t rows = -1, iterations = -1, evaluations = -1, transforms = -1, i;
  double error = -1.0;
  int c, ok = 1, finite = 1, numbered = 1;
  ok &= asp_solver_history_length(solver, &rows) == ASP_OK;
  ok &= asp_solver_iterations(solver, &iterations) == ASP_OK;
  ok &= asp_solver_evaluations(solver, &evaluations) == ASP_OK;
  ok &= asp_solver_transforms(solver, &transforms) == ASP_OK;
  ok &= asp_solver_final_error(solver, &error) == ASP_OK;
  if (!check_record(ok && rows == iterations + 1, __FILE__, line,
                    "one history row per iteration from iteration 0")) {
    fprintf(stderr, "  %s: %lld rows after %lld iterations\n", what, (long long)rows,
            (long long)iterations);
    return;
  }
  for (c = 0; c < 7; ++c) {
    column[c] = malloc((size_t)rows * sizeof(double));
    ok &= column[c] != NULL && asp_solver_get_history(solver, columns[c], column[c], rows) ==
                                   ASP_OK;
  }
  if (check_record(ok, __FILE__, line, "the history can be read")) {
    for (i = 0; i < rows; ++i) {
      numbered &= column[0][i] == (double)i;
      for (c = 0; c < 7; ++c) finite &= isfinite(column[c][i]);
    }
    check_record(numbered, __FILE__, line, "the rows are iterations 0, 1, 2, ...");
    check_record(finite, __FILE__, line, "every number of the history is finite");
    if (!check_record(column[1][rows - 1] == (double)evaluations &&
                          column[2][rows - 1] == (double)transforms &&
                          column[4][rows - 1] == error,
                      __FILE__, line, "the last row has the report's counters and error"))
      fprintf(stderr, "  %s: last row %g %g %g, report %lld %lld %g\n", what, column[1][rows - 1],
              column[2][rows - 1], column[4][rows - 1], (long long)evaluations,
              (long long)transforms, error);
  }
  for (c = 0; c < 7; ++c) free(column[c]);
}
#define CHECK_ROWS(solver, what) check_rows((solver), (what), __LINE__)

static int cancel_at_two(int64_t iteration, double seconds, double error, void *user_data) {
  (void)seconds;
  (void)error;
  (void)user_data;
  return iteration == 2;
}

/* Every algorithm the library lists, in four endings. */
static void test_every_algorithm_every_ending(const Scenes *s) {
  char names[4096];
  char *name;
  int endings_seen[5] = {0};
  CHECK_OK(asp_algorithms(names, sizeof names, NULL));
  for (name = strtok(names, "\n"); name != NULL; name = strtok(NULL, "\n")) {
    int ending;
    for (ending = 0; ending < 4; ++ending) {
      asp_solver *solver = NULL;
      asp_system *system = NULL;
      int control = 0, reason = 0;
      double value = 0.0;
      char what[128];
      snprintf(what, sizeof what, "%s, ending %d", name, ending);
      CHECK_OK(asp_solver_create(name, &solver));
      CHECK_OK(asp_solver_set_history(solver, 1));
      if (!CHECK(served(s, solver, &system, &control, &value))) {
        fprintf(stderr, "  %s serves neither scene\n", name);
        asp_solver_destroy(solver);
        break;
      }
      if (ending == 1) CHECK_OK(asp_solver_set_max_iterations(solver, 3));
      if (ending == 2) CHECK_OK(asp_solver_set_progress(solver, cancel_at_two, NULL));
      if (ending == 3) {
        CHECK_OK(asp_solver_set_tolerance(solver, 1e-30));
        CHECK_OK(asp_solver_set_option(solver, "stall_window", 2));
      }
      CHECK_OK(asp_system_reset(system));
      CHECK_OK(asp_solver_solve(solver, system, control, value));
      CHECK_OK(asp_solver_termination(solver, &reason));
      if (reason >= ASP_TERMINATION_CONVERGED && reason <= ASP_TERMINATION_BREAKDOWN)
        endings_seen[reason - ASP_TERMINATION_CONVERGED] = 1;
      if (ending == 1)
        CHECK(reason == ASP_TERMINATION_ITERATION_LIMIT || reason == ASP_TERMINATION_CONVERGED);
      if (ending == 2)
        CHECK(reason == ASP_TERMINATION_CANCELLED || reason == ASP_TERMINATION_CONVERGED);
      CHECK_ROWS(solver, what);
      asp_solver_destroy(solver);
    }
  }
  CHECK(endings_seen[0] && endings_seen[1] && endings_seen[2] && endings_seen[3]);
}

/* A repulsive wall 0.05 exp(-2g/0.3) whose energy jumps to 1e305 below the gap -0.1, its force
 * going on unchanged. Under a mean pressure of 0.5 the iterate goes below -0.1 on a few pixels,
 * where the energy (finite on each pixel) sums to more than a double holds. */
static int cliff(int64_t count, const double *gap, double *phi, double *dphi, double *d2phi,
                 void *user_data) {
  int64_t i;
  (void)user_data;
  for (i = 0; i < count; ++i) {
    const double r = 0.05 * exp(-2.0 * gap[i] / 0.3);
    phi[i] = gap[i] < -0.1 ? 1e305 : r;
    dphi[i] = -2.0 * r / 0.3;
    if (d2phi != NULL) d2phi[i] = 4.0 * r / 0.09;
  }
  return 0;
}

/* A cold solve of `name` on `system` under the mean pressure `pressure` that ends broken down,
 * with the history of its rows. */
static void expect_breakdown(asp_system *system, const char *name, double pressure,
                             const char *what) {
  asp_solver *solver = NULL;
  int reason = 0;
  CHECK_OK(asp_solver_create(name, &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, pressure));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_BREAKDOWN);
  CHECK_ROWS(solver, what);
  asp_solver_destroy(solver);
}

static void test_fire_breakdown(const Scenes *s) {
  asp_system *system = NULL;
  CHECK_OK(asp_system_create(s->grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, s->heights, n));
  CHECK_OK(asp_system_set_potential(system, cliff, NULL, 0));
  expect_breakdown(system, "fire", 0.5, "fire, breakdown");
  asp_system_destroy(system);
}

/* A soft wall whose curvature 4 gamma_r/rho_r^2 is not a double: no time step is stable. */
static void test_dynamics_without_a_time_step(const Scenes *s) {
  static const char *const names[3] = {"fire", "fire_mass_weighted", "gfmd"};
  asp_system *system = NULL;
  int k;
  CHECK_OK(asp_system_create(s->grid, 2.0, &system));
  CHECK_OK(asp_system_set_topography(system, s->heights, n));
  CHECK_OK(asp_system_set_soft_wall(system, 0.01, 1e-300, 0.001, 0.02));
  for (k = 0; k < 3; ++k) {
    char what[64];
    snprintf(what, sizeof what, "%s, no time step", names[k]);
    expect_breakdown(system, names[k], 0.91, what);
  }
  asp_system_destroy(system);
}

/* Callbacks that call the library about the system being solved: refused, and the solve goes
 * on. What each refused call said is kept for the checks. */
typedef struct {
  asp_system *system;
  int calls, refused;
  char message[512];
} Meddler;

static void meddle(Meddler *m) {
  double value = 0.0;
  const int status = asp_system_get(m->system, ASP_MEAN_PRESSURE, &value);
  ++m->calls;
  if (status == ASP_ERR_INVALID_STATE) {
    ++m->refused;
    strncpy(m->message, asp_last_error_message(), sizeof m->message - 1);
  }
}

static int meddling_progress(int64_t iteration, double seconds, double error, void *user_data) {
  (void)iteration;
  (void)seconds;
  (void)error;
  meddle((Meddler *)user_data);
  return 0;
}

static int meddling_wall(int64_t count, const double *gap, double *phi, double *dphi,
                         double *d2phi, void *user_data) {
  int64_t i;
  meddle((Meddler *)user_data);
  for (i = 0; i < count; ++i) {
    const double r = 0.05 * exp(-2.0 * gap[i] / 0.3), a = 0.01 * exp(-gap[i] / 0.3);
    phi[i] = r - a;
    dphi[i] = -2.0 * r / 0.3 + a / 0.3;
    if (d2phi != NULL) d2phi[i] = 4.0 * r / 0.09 - a / 0.09;
  }
  return 0;
}

static void test_message_empty_after_success(const Scenes *s) {
  static Meddler m;
  asp_solver *solver = NULL;
  asp_system *system = NULL;
  int converged = 0;
  /* The progress callback. */
  memset(&m, 0, sizeof m);
  m.system = s->hard;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_progress(solver, meddling_progress, &m));
  CHECK_OK(asp_system_reset(s->hard));
  CHECK(asp_solver_solve(solver, s->hard, ASP_CONTROL_MEAN_PRESSURE, 0.005) == ASP_OK);
  CHECK(strcmp(asp_last_error_message(), "") == 0);
  CHECK(m.calls > 0 && m.refused == m.calls && m.message[0] != '\0');
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  asp_solver_destroy(solver);

  /* The potential callback. */
  memset(&m, 0, sizeof m);
  CHECK_OK(asp_system_create(s->grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, s->heights, n));
  m.system = system;
  CHECK_OK(asp_system_set_potential(system, meddling_wall, &m, 0));
  CHECK_OK(asp_solver_create("lbfgs", &solver));
  CHECK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, -0.45) == ASP_OK);
  CHECK(strcmp(asp_last_error_message(), "") == 0);
  CHECK(m.calls > 0 && m.refused == m.calls && m.message[0] != '\0');
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  asp_solver_destroy(solver);
  asp_system_destroy(system);
}

int main(void) {
  static Scenes s;
  make_scenes(&s);
  test_every_algorithm_every_ending(&s);
  test_fire_breakdown(&s);
  test_dynamics_without_a_time_step(&s);
  test_message_empty_after_success(&s);
  asp_system_destroy(s.hard);
  asp_system_destroy(s.soft);
  asp_grid_destroy(s.grid);
  return check_summary("api.solve_endings");
}
