/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asperity inside a host program that uses OpenMP itself, as an FEM or MD code does: solves
 * called from inside the host's own `#pragma omp parallel` region (each host thread with its
 * own system and solver on one shared grid, and each with a grid of its own of two threads)
 * and outside it give the pressure of a solve on one thread to 1e-12 of its largest value,
 * and the host's OpenMP still works after them. The library's threads are its own (sleeping
 * while they wait), so that neither side's threads spin against the other's; a solve started
 * while another thread of the process runs one uses its calling thread alone. */
#include <math.h>
#include <stdlib.h>

#include <omp.h>

#include "check.h"

#define N 128
#define HOST_THREADS 4

/* pk on the surface h on `grid` (N x N), with a system and a solver of its own; the pressure
 * into p. Returns the number of failed calls. */
static int solve(asp_grid *grid, const double *h, double *p) {
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  int failed = 0;
  failed += asp_system_create(grid, 1.0, &system) != ASP_OK;
  failed += asp_system_set_topography(system, h, N * N) != ASP_OK;
  failed += asp_solver_create("pk", &solver) != ASP_OK;
  failed += asp_solver_set_tolerance(solver, 1e-12) != ASP_OK;
  failed += asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.005) != ASP_OK;
  failed += asp_system_get_field(system, ASP_FIELD_PRESSURE, p, N * N) != ASP_OK;
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  return failed;
}

/* An N x N grid with estimated plans and `threads` threads (0: the default). */
static asp_grid *new_grid(int threads) {
  asp_grid *grid = NULL;
  if (asp_grid_create_2d(N, N, 1.0, 1.0, &grid) != ASP_OK) return NULL;
  if (asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE) != ASP_OK ||
      (threads > 0 && asp_grid_set_threads(grid, threads) != ASP_OK)) {
    asp_grid_destroy(grid);
    return NULL;
  }
  return grid;
}

static int agrees(const double *p, const double *reference) {
  double difference = 0.0, scale = 0.0;
  int i;
  for (i = 0; i < N * N; ++i) {
    if (!(fabs(p[i] - reference[i]) <= difference)) difference = fabs(p[i] - reference[i]);
    if (fabs(reference[i]) > scale) scale = fabs(reference[i]);
  }
  return scale > 0.0 && difference <= 1e-12 * scale;
}

int main(void) {
  double *h = malloc(N * N * sizeof *h), *reference = malloc(N * N * sizeof *reference);
  double *inside_shared = malloc(HOST_THREADS * N * N * sizeof *inside_shared);
  double *inside_own = malloc(HOST_THREADS * N * N * sizeof *inside_own);
  double *outside = malloc(N * N * sizeof *outside);
  int failed_shared[HOST_THREADS] = {0}, failed_own[HOST_THREADS] = {0}, ran[HOST_THREADS] = {0};
  asp_grid *one = new_grid(1), *shared = new_grid(0);
  long host_sum = 0;
  int t;

  CHECK(h != NULL && reference != NULL && inside_shared != NULL && inside_own != NULL &&
        outside != NULL && one != NULL && shared != NULL);
  CHECK_OK(asp_topography_self_affine(one, 0.8, 1.0, 0.25, 4.0 / N, ASP_RMS_SLOPE, 0.1, 3, h,
                                      N * N));
  CHECK(solve(one, h, reference) == 0);

#pragma omp parallel num_threads(HOST_THREADS)
  {
    const int me = omp_get_thread_num();
    asp_grid *own = new_grid(2);
    ran[me] = 1;
    failed_shared[me] = solve(shared, h, inside_shared + (size_t)me * N * N);
    failed_own[me] = own == NULL ? 1 : solve(own, h, inside_own + (size_t)me * N * N);
    asp_grid_destroy(own);
  }
  for (t = 0; t < HOST_THREADS; ++t) {
    CHECK(ran[t] == 1);
    CHECK(failed_shared[t] == 0);
    CHECK(failed_own[t] == 0);
    CHECK(agrees(inside_shared + (size_t)t * N * N, reference));
    CHECK(agrees(inside_own + (size_t)t * N * N, reference));
  }

  /* Outside the region, on the grid's default threads; then the host's OpenMP once more. */
  CHECK(solve(shared, h, outside) == 0);
  CHECK(agrees(outside, reference));
#pragma omp parallel for num_threads(HOST_THREADS) reduction(+ : host_sum)
  for (t = 0; t < 1000; ++t) host_sum += t;
  CHECK(host_sum == 999 * 1000 / 2);

  asp_grid_destroy(one);
  asp_grid_destroy(shared);
  free(h);
  free(reference);
  free(inside_shared);
  free(inside_own);
  free(outside);
  return check_summary("api.host_openmp");
}
