/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A system's topography (asperity.h, asp_system_create and asp_solver_solve): a solve on a
 * system whose topography was never set is refused with ASP_ERR_INVALID_STATE, naming the
 * system and asp_system_set_topography, with no report (a forgotten topography would
 * otherwise be solved as the zeros of a flat surface and reported as converged), on a
 * periodic and on a free system; the same solve runs once heights are set, zeros included
 * (the flat surface is a topography like any other). A height that is NaN or infinite is
 * refused by asp_system_set_topography and the asp_topography_* functions that read heights,
 * naming its pixel (x, y) and its index in the array, on 2D and 1D grids. */
#include <stdint.h>

#include "check.h"

#define NX 8
#define NY 4
#define N (NX * NY)

static void solve_needs_topography(asp_grid *grid, int free_substrate) {
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double heights[N];
  int reason = 0;
  int64_t i;
  printf("a solve on a %s system\n", free_substrate ? "free" : "periodic");
  CHECK_OK(free_substrate ? asp_system_create_free(grid, 1.0, &system)
                          : asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
              ASP_ERR_INVALID_STATE, "argument 'system' has no topography");
  CHECK_MESSAGE_HAS("asp_system_set_topography");
  /* Refused before it ran: no report. */
  CHECK_ERROR(asp_solver_termination(solver, &reason), ASP_ERR_INVALID_STATE, NULL);

  /* Zeros are a flat surface, solved like any other. */
  CHECK_OK(asp_topography_flat(grid, heights, N));
  CHECK_OK(asp_system_set_topography(system, heights, N));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);

  /* A refused topography after a good one leaves the good one in place. */
  for (i = 0; i < N; ++i) heights[i] = 0.01 * (double)(i % 3);
  heights[5] = NAN;
  CHECK_ERROR(asp_system_set_topography(system, heights, N), ASP_ERR_INVALID_ARGUMENT, NULL);
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01));
  asp_solver_destroy(solver);
  asp_system_destroy(system);
}

/* Pixel 13 of an 8-pixel-wide grid is (x = 5, y = 1). */
static void bad_height_located(asp_grid *grid) {
  asp_system *system = NULL;
  double heights[N], rms_height, rms_slope, rms_curvature, q[2], c[2];
  int64_t i;
  printf("a NaN or infinite height, located\n");
  for (i = 0; i < N; ++i) heights[i] = 0.01 * (double)(i % 5);
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  heights[13] = NAN;
  CHECK_ERROR(asp_system_set_topography(system, heights, N), ASP_ERR_INVALID_ARGUMENT,
              "at pixel (x = 5, y = 1), index 13");
  CHECK_MESSAGE_HAS("'heights'");
  heights[13] = -INFINITY;
  CHECK_ERROR(asp_system_set_topography(system, heights, N), ASP_ERR_INVALID_ARGUMENT,
              "-inf at pixel (x = 5, y = 1), index 13");
  CHECK_ERROR(asp_topography_statistics(grid, heights, N, &rms_height, &rms_slope,
                                        &rms_curvature),
              ASP_ERR_INVALID_ARGUMENT, "at pixel (x = 5, y = 1), index 13");
  CHECK_ERROR(asp_topography_power_spectrum(grid, heights, N, 2, q, c),
              ASP_ERR_INVALID_ARGUMENT, "at pixel (x = 5, y = 1), index 13");
  CHECK_ERROR(asp_topography_detrend(grid, ASP_DETREND_PLANE, heights, N),
              ASP_ERR_INVALID_ARGUMENT, "at pixel (x = 5, y = 1), index 13");
  asp_system_destroy(system);
}

/* On a 1D grid the pixel is its x alone. */
static void bad_height_on_a_line(void) {
  asp_grid *line = NULL;
  asp_system *system = NULL;
  double heights[16] = {0.0};
  printf("a NaN height on a line\n");
  CHECK_OK(asp_grid_create_1d(16, 1.0, &line));
  CHECK_OK(asp_system_create(line, 1.0, &system));
  heights[11] = NAN;
  CHECK_ERROR(asp_system_set_topography(system, heights, 16), ASP_ERR_INVALID_ARGUMENT,
              "at pixel (x = 11), index 11");
  asp_system_destroy(system);
  asp_grid_destroy(line);
}

int main(void) {
  asp_grid *grid = NULL;
  CHECK_OK(asp_grid_create_2d(NX, NY, 2.0, 1.0, &grid));
  solve_needs_topography(grid, 0);
  solve_needs_topography(grid, 1);
  bad_height_located(grid);
  bad_height_on_a_line();
  asp_grid_destroy(grid);
  return check_summary("test_topography_required");
}
