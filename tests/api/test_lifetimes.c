/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Handle lifetimes (asperity.h, "Handles and lifetimes"): a system keeps its grid alive, so
 * handles may be destroyed in any order and a system stays fully usable after its grid's
 * handle is gone; every destroy function accepts NULL.
 *
 * A use after free shows here only as wrong numbers or a crash by luck; build with
 * -DASPERITY_SANITIZE=ON to have AddressSanitizer report it. The test uses only calls that
 * asperity has had from its first release, so that it also builds against old versions. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define NX 32
#define N (NX * NX)

static const double pi = 3.14159265358979323846;

/* h = amplitude cos(2 pi x) cos(2 pi y) on the unit box, written without a grid handle so that
 * it can be made after the grid's handle is gone. */
static void sinusoid(double amplitude, double *h) {
  int i, j;
  for (j = 0; j < NX; ++j)
    for (i = 0; i < NX; ++i)
      h[i + NX * j] = amplitude * cos(2.0 * pi * i / NX) * cos(2.0 * pi * j / NX);
}

/* The system works: a topography can be set, a solve converges, and what it reports is the
 * solution (mean pressure on target, fields finite, the topography the one set). */
static void use_system(asp_system *system, asp_solver *solver, double amplitude, int line) {
  static double h[N], field[N];
  double mean = -1.0, fraction = -1.0;
  int converged = 0, ok = 1, i;
  sinusoid(amplitude, h);
  ok &= asp_system_set_topography(system, h, N) == ASP_OK;
  ok &= asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01 * amplitude) == ASP_OK;
  ok &= asp_solver_converged(solver, &converged) == ASP_OK && converged == 1;
  ok &= asp_system_get(system, ASP_MEAN_PRESSURE, &mean) == ASP_OK &&
        fabs(mean - 0.01 * amplitude) <= 1e-12 * amplitude;
  ok &= asp_system_get(system, ASP_CONTACT_FRACTION, &fraction) == ASP_OK && fraction > 0.0 &&
        fraction < 1.0;
  ok &= asp_system_get_field(system, ASP_FIELD_PRESSURE, field, N) == ASP_OK;
  for (i = 0; i < N; ++i) ok &= isfinite(field[i]) && field[i] >= 0.0;
  ok &= asp_system_get_field(system, ASP_FIELD_GAP, field, N) == ASP_OK;
  for (i = 0; i < N; ++i) ok &= isfinite(field[i]);
  ok &= asp_system_get_field(system, ASP_FIELD_TOPOGRAPHY, field, N) == ASP_OK;
  for (i = 0; i < N; ++i) ok &= field[i] == h[i];
  if (!ok) fprintf(stderr, "  last error: '%s'\n", asp_last_error_message());
  check_record(ok, __FILE__, line, "the system works: topography, solve, results");
}
#define USE_SYSTEM(system, solver, amplitude) use_system((system), (solver), (amplitude), __LINE__)

static void test_destroy_null(void) {
  asp_grid_destroy(NULL);
  asp_system_destroy(NULL);
  asp_solver_destroy(NULL);
  CHECK(1);
}

/* The grid's handle goes first, before the system has planned any FFT; the system then does
 * everything a system does. */
static void test_grid_destroyed_first(void) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_solver_create("pk", &solver));
  asp_grid_destroy(grid);
  USE_SYSTEM(system, solver, 0.01);
  USE_SYSTEM(system, solver, 0.02);
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_system_set_k0(system, 5.0));
  USE_SYSTEM(system, solver, 0.01);
  asp_system_destroy(system);
  asp_solver_destroy(solver);
}

/* Two systems on one grid outlive its handle, and each other. */
static void test_shared_grid(void) {
  asp_grid *grid = NULL;
  asp_system *first = NULL, *second = NULL;
  asp_solver *solver = NULL;
  CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
  CHECK_OK(asp_system_create(grid, 1.0, &first));
  CHECK_OK(asp_system_create(grid, 2.0, &second));
  CHECK_OK(asp_solver_create("pk", &solver));
  USE_SYSTEM(first, solver, 0.01);
  asp_grid_destroy(grid);
  USE_SYSTEM(second, solver, 0.01);
  asp_system_destroy(first);
  USE_SYSTEM(second, solver, 0.03);
  asp_solver_destroy(solver);
  asp_system_destroy(second);
}

/* A grid destroyed with no system on it, and one whose system was destroyed first. */
static void test_grid_alone(void) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  int64_t n = 0;
  CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
  asp_grid_destroy(grid);
  CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  asp_system_destroy(system);
  CHECK_OK(asp_grid_get_shape(grid, NULL, NULL, NULL, &n));
  CHECK(n == N);
  asp_grid_destroy(grid);
}

/* After a solve, the three handles destroyed in each of the six orders; between the
 * destructions, the handles still alive keep working. */
static void test_every_order(void) {
  static const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int o, k;
  for (o = 0; o < 6; ++o) {
    asp_grid *grid = NULL;
    asp_system *system = NULL;
    asp_solver *solver = NULL;
    int64_t n = 0;
    double expected_mean = 1e-4;
    CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
    CHECK_OK(asp_system_create(grid, 1.0, &system));
    CHECK_OK(asp_solver_create("pk", &solver));
    USE_SYSTEM(system, solver, 0.01);
    for (k = 0; k < 3; ++k) {
      switch (orders[o][k]) {
        case 0: asp_grid_destroy(grid); grid = NULL; break;
        case 1: asp_system_destroy(system); system = NULL; break;
        default: asp_solver_destroy(solver); solver = NULL; break;
      }
      if (grid != NULL) {
        CHECK_OK(asp_grid_get_shape(grid, NULL, NULL, NULL, &n));
        CHECK(n == N);
      }
      if (system != NULL) {
        double mean = 0.0;
        CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &mean));
        CHECK(fabs(mean - expected_mean) <= 1e-15);
      }
      if (system != NULL && solver != NULL) {
        USE_SYSTEM(system, solver, 0.02);
        expected_mean = 2e-4;
      }
    }
  }
}

/* A solver is independent of any system: it outlives the systems it solved, and solves
 * systems on other grids. */
static void test_solver_outlives_systems(void) {
  asp_solver *solver = NULL;
  int round;
  CHECK_OK(asp_solver_create("pk", &solver));
  for (round = 0; round < 3; ++round) {
    asp_grid *grid = NULL;
    asp_system *system = NULL;
    CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
    CHECK_OK(asp_system_create(grid, 1.0 + round, &system));
    if (round % 2 == 0) asp_grid_destroy(grid);
    USE_SYSTEM(system, solver, 0.01);
    asp_system_destroy(system);
    if (round % 2 == 1) asp_grid_destroy(grid);
  }
  {
    int converged = 0;
    CHECK_OK(asp_solver_converged(solver, &converged));
    CHECK(converged == 1);
  }
  asp_solver_destroy(solver);
}

int main(void) {
  test_destroy_null();
  test_grid_destroyed_first();
  test_shared_grid();
  test_grid_alone();
  test_every_order();
  test_solver_outlives_systems();
  return check_summary("api.lifetimes");
}
