/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asp_grid_set_threads and asp_grid_get_threads: the default count (OMP_NUM_THREADS when set,
 * else at least one), a count set before the plans exist, the refusals (a count below 1, a
 * count after the plans exist, NULL), and a solve on two threads that gives the one-thread
 * result to 1e-12 of the largest pressure.
 *
 * With an argument, the program checks that the default count is that number (the test
 * api.grid_threads_from_environment runs it with OMP_NUM_THREADS=3). */
#include <math.h>
#include <stdlib.h>

#include "check.h"

#define N 256

static double largest_difference(const double *a, const double *b, int64_t n, double *scale) {
  double d = 0.0, s = 0.0;
  int64_t i;
  for (i = 0; i < n; ++i) {
    if (fabs(a[i] - b[i]) > d) d = fabs(a[i] - b[i]);
    if (fabs(a[i]) > s) s = fabs(a[i]);
  }
  *scale = s;
  return d;
}

/* pk on a rough 256 x 256 surface with the given thread count; the pressure into p. */
static void solve(int threads, const double *h, double *p) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  int got = 0;
  CHECK_OK(asp_grid_create_2d(N, N, 1.0, 1.0, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_grid_set_threads(grid, threads));
  CHECK_OK(asp_grid_get_threads(grid, &got));
  CHECK(got == threads);
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, h, N * N));
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-12));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, N * N));
  /* The plans exist now: the count can no longer change, and stays as it was. */
  CHECK_ERROR(asp_grid_set_threads(grid, 1), ASP_ERR_INVALID_STATE, "plans");
  CHECK_OK(asp_grid_get_threads(grid, &got));
  CHECK(got == threads);
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
}

int main(int argc, char **argv) {
  asp_grid *grid = NULL;
  int threads = 0;
  double *h = malloc(N * N * sizeof *h), *one = malloc(N * N * sizeof *one),
         *two = malloc(N * N * sizeof *two), scale = 0.0;

  CHECK(h != NULL && one != NULL && two != NULL);
  CHECK_OK(asp_grid_create_2d(N, N, 1.0, 1.0, &grid));
  CHECK_OK(asp_grid_get_threads(grid, &threads));
  if (argc > 1)
    CHECK(threads == atoi(argv[1]));
  else
    CHECK(threads >= 1);
  CHECK_ERROR(asp_grid_set_threads(grid, 0), ASP_ERR_INVALID_ARGUMENT, "'threads'");
  CHECK_ERROR(asp_grid_set_threads(grid, -2), ASP_ERR_INVALID_ARGUMENT, "'threads'");
  CHECK_OK(asp_grid_get_threads(grid, &threads)); /* refusals change nothing */
  CHECK(threads >= 1);
  CHECK_ERROR(asp_grid_set_threads(NULL, 2), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_grid_get_threads(grid, NULL), ASP_ERR_NULL_POINTER, "'threads'");
  CHECK_ERROR(asp_grid_get_threads(NULL, &threads), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / N, ASP_RMS_SLOPE, 0.1, 5, h,
                                      N * N));
  asp_grid_destroy(grid);

  solve(1, h, one);
  solve(2, h, two);
  CHECK(largest_difference(one, two, N * N, &scale) <= 1e-12 * scale);

  free(h);
  free(one);
  free(two);
  return check_summary("api.grid_threads");
}
