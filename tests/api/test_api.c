/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The public C interface, from C: every bad-input path returns its status and a message that
 * names the argument, leaves the handles usable, and the good paths give sane results.
 * Prints "N passed, N failed" and exits non-zero on any failure. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"

static int passed = 0;
static int failed = 0;

static void expect(int condition, const char *what, int line) {
  if (condition) {
    ++passed;
  } else {
    ++failed;
    fprintf(stderr, "FAILED line %d: %s (last error: '%s')\n", line, what,
            asp_last_error_message());
  }
}
#define EXPECT(c) expect((c), #c, __LINE__)

/* A call failed with `status` and its message names `argument`. */
static void expect_error(int got, int status, const char *argument, int line) {
  char what[256];
  sprintf(what, "status %d (want %d), message naming '%s'", got, status, argument);
  expect(got == status && strstr(asp_last_error_message(), argument) != NULL, what, line);
}
#define EXPECT_ERROR(call, status, argument) expect_error((call), (status), (argument), __LINE__)

#define N 64

static void test_status_and_version(void) {
  int s;
  EXPECT(strcmp(asp_version_string(), ASP_VERSION_STRING) == 0);
  EXPECT(asp_abi_version() == ASP_ABI_VERSION);
  for (s = ASP_OK; s <= ASP_ERR_IO; ++s) {
    EXPECT(asp_status_string(s) != NULL && strlen(asp_status_string(s)) > 0);
    EXPECT(strcmp(asp_status_string(s), "unknown status") != 0);
  }
  EXPECT(strcmp(asp_status_string(-1), "unknown status") == 0);
  EXPECT(strcmp(asp_status_string(1000), "unknown status") == 0);
  asp_grid_destroy(NULL);
  asp_system_destroy(NULL);
  asp_solver_destroy(NULL);
}

static void test_grid_errors(void) {
  asp_grid *grid = (asp_grid *)&passed; /* garbage that must be reset to NULL */
  EXPECT_ERROR(asp_grid_create_1d(0, 1.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'nx'");
  EXPECT(grid == NULL);
  EXPECT_ERROR(asp_grid_create_1d(-5, 1.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'nx'");
  EXPECT_ERROR(asp_grid_create_1d(8, 0.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'lx'");
  EXPECT_ERROR(asp_grid_create_1d(8, -1.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'lx'");
  EXPECT_ERROR(asp_grid_create_1d(8, NAN, &grid), ASP_ERR_INVALID_ARGUMENT, "'lx'");
  EXPECT_ERROR(asp_grid_create_1d(8, INFINITY, &grid), ASP_ERR_INVALID_ARGUMENT, "'lx'");
  EXPECT_ERROR(asp_grid_create_1d(8, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  EXPECT_ERROR(asp_grid_create_2d(8, 0, 1.0, 1.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'ny'");
  EXPECT_ERROR(asp_grid_create_2d(8, 8, 1.0, -2.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'ly'");
  EXPECT_ERROR(asp_grid_create_2d(8, 8, NAN, 1.0, &grid), ASP_ERR_INVALID_ARGUMENT, "'lx'");
  EXPECT_ERROR(asp_grid_create_2d(INT64_MAX / 2, INT64_MAX / 2, 1.0, 1.0, &grid),
               ASP_ERR_INVALID_ARGUMENT, "'nx'");
  EXPECT(grid == NULL);
  EXPECT_ERROR(asp_grid_get_shape(NULL, NULL, NULL, NULL, NULL), ASP_ERR_NULL_POINTER,
               "'grid'");
  EXPECT_ERROR(asp_grid_get_box(NULL, NULL, NULL), ASP_ERR_NULL_POINTER, "'grid'");
  EXPECT_ERROR(asp_grid_set_fft_planning(NULL, ASP_FFT_MEASURE), ASP_ERR_NULL_POINTER, "'grid'");
}

static void test_grid_queries(void) {
  asp_grid *grid = NULL;
  int dimension = 0;
  int64_t nx = 0, ny = 0, n = 0;
  double lx = 0, ly = 0;
  EXPECT(asp_grid_create_2d(13, 7, 2.0, 3.0, &grid) == ASP_OK);
  EXPECT(strcmp(asp_last_error_message(), "") == 0);
  EXPECT(asp_grid_get_shape(grid, &dimension, &nx, &ny, &n) == ASP_OK);
  EXPECT(dimension == 2 && nx == 13 && ny == 7 && n == 91);
  EXPECT(asp_grid_get_box(grid, &lx, &ly) == ASP_OK && lx == 2.0 && ly == 3.0);
  EXPECT_ERROR(asp_grid_set_fft_planning(grid, 7), ASP_ERR_INVALID_ARGUMENT, "'planning'");
  EXPECT(asp_grid_set_fft_planning(grid, ASP_FFT_MEASURE) == ASP_OK);
  asp_grid_destroy(grid);

  EXPECT(asp_grid_create_1d(10, 5.0, &grid) == ASP_OK);
  EXPECT(asp_grid_get_shape(grid, &dimension, &nx, &ny, &n) == ASP_OK);
  EXPECT(dimension == 1 && nx == 10 && ny == 1 && n == 10);
  EXPECT(asp_grid_get_box(grid, &lx, &ly) == ASP_OK && lx == 5.0 && ly == 1.0);
  asp_grid_destroy(grid);
}

static void test_topography_errors(asp_grid *grid) {
  double h[N], q[4], c[4];
  EXPECT_ERROR(asp_topography_flat(NULL, h, N), ASP_ERR_NULL_POINTER, "'grid'");
  EXPECT_ERROR(asp_topography_flat(grid, NULL, N), ASP_ERR_NULL_POINTER, "'heights'");
  EXPECT_ERROR(asp_topography_flat(grid, h, N - 1), ASP_ERR_SIZE_MISMATCH, "'heights'");
  EXPECT_ERROR(asp_topography_flat(grid, h, -1), ASP_ERR_SIZE_MISMATCH, "'heights'");
  EXPECT_ERROR(asp_topography_sphere(grid, 0.0, h, N), ASP_ERR_INVALID_ARGUMENT, "'radius'");
  EXPECT_ERROR(asp_topography_sphere(grid, NAN, h, N), ASP_ERR_INVALID_ARGUMENT, "'radius'");
  EXPECT_ERROR(asp_topography_paraboloid(grid, -1.0, h, N), ASP_ERR_INVALID_ARGUMENT,
               "'radius'");
  EXPECT_ERROR(asp_topography_sinusoid(grid, NAN, 1, 0, h, N), ASP_ERR_INVALID_ARGUMENT,
               "'amplitude'");
  EXPECT_ERROR(asp_topography_sinusoid(grid, 1.0, 0, 0, h, N), ASP_ERR_INVALID_ARGUMENT,
               "'periods_x'");
  EXPECT_ERROR(asp_topography_sinusoid(grid, 1.0, 1, -1, h, N), ASP_ERR_INVALID_ARGUMENT,
               "'periods_y'");
  EXPECT_ERROR(asp_topography_double_sinewave(grid, 1.0, INFINITY, 4, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'ripple_amplitude'");
  EXPECT_ERROR(asp_topography_double_sinewave(grid, 1.0, 0.1, 0, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'ripple_periods'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 1.5, 1.0, 0.5, 0.1, ASP_RMS_SLOPE, 1.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'hurst'");
  EXPECT_ERROR(asp_topography_self_affine(grid, NAN, 1.0, 0.5, 0.1, ASP_RMS_SLOPE, 1.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'hurst'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 0.8, -1.0, 0.5, 0.1, ASP_RMS_SLOPE, 1.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'long_cutoff'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 0.8, 1.0, 2.0, 0.1, ASP_RMS_SLOPE, 1.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'rolloff'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 0.6, ASP_RMS_SLOPE, 1.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'short_cutoff'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 0.1, 3, 1.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'normalise'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 0.1, ASP_RMS_HEIGHT, 0.0, 1, h, N),
               ASP_ERR_INVALID_ARGUMENT, "'target'");
  EXPECT_ERROR(asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 0.1, ASP_RMS_HEIGHT, 1.0, 1, h, 3),
               ASP_ERR_SIZE_MISMATCH, "'heights'");

  asp_topography_flat(grid, h, N);
  h[5] = NAN;
  EXPECT_ERROR(asp_topography_statistics(grid, h, N, NULL, NULL, NULL), ASP_ERR_INVALID_ARGUMENT,
               "'heights'");
  h[5] = 0.0;
  EXPECT_ERROR(asp_topography_power_spectrum(grid, h, N, 0, q, c), ASP_ERR_INVALID_ARGUMENT,
               "'n_bins'");
  EXPECT_ERROR(asp_topography_power_spectrum(grid, h, N, 4, NULL, c), ASP_ERR_NULL_POINTER, "'q'");
  EXPECT_ERROR(asp_topography_power_spectrum(grid, h, N, 4, q, NULL), ASP_ERR_NULL_POINTER, "'c'");
}

static void test_topography_on_1d(void) {
  asp_grid *line = NULL;
  double h[32], rms = 0, slope = 0, curvature = 0;
  EXPECT(asp_grid_create_1d(32, 1.0, &line) == ASP_OK);
  EXPECT_ERROR(asp_topography_sinusoid(line, 1.0, 1, 2, h, 32), ASP_ERR_INVALID_ARGUMENT,
               "'periods_y'");
  EXPECT(asp_topography_sinusoid(line, 2.0, 1, 0, h, 32) == ASP_OK);
  EXPECT(asp_topography_statistics(line, h, 32, &rms, &slope, &curvature) == ASP_OK);
  EXPECT(fabs(rms - 2.0 / sqrt(2.0)) < 1e-12);
  asp_grid_destroy(line);
}

static void test_system_errors(asp_grid *grid) {
  asp_system *system = (asp_system *)&passed;
  double h[N], v = 0;
  int i;
  EXPECT_ERROR(asp_system_create(NULL, 1.0, &system), ASP_ERR_NULL_POINTER, "'grid'");
  EXPECT(system == NULL);
  EXPECT_ERROR(asp_system_create(grid, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  EXPECT_ERROR(asp_system_create(grid, -1.0, &system), ASP_ERR_INVALID_ARGUMENT,
               "'contact_modulus'");
  EXPECT_ERROR(asp_system_create(grid, 0.0, &system), ASP_ERR_INVALID_ARGUMENT,
               "'contact_modulus'");
  EXPECT_ERROR(asp_system_create(grid, NAN, &system), ASP_ERR_INVALID_ARGUMENT,
               "'contact_modulus'");
  EXPECT(system == NULL);

  EXPECT(asp_system_create(grid, 1.0, &system) == ASP_OK);
  EXPECT(asp_topography_sinusoid(grid, 0.01, 1, 1, h, N) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, N) == ASP_OK);

  EXPECT_ERROR(asp_system_set_topography(NULL, h, N), ASP_ERR_NULL_POINTER, "'system'");
  EXPECT_ERROR(asp_system_set_topography(system, NULL, N), ASP_ERR_NULL_POINTER, "'heights'");
  EXPECT_ERROR(asp_system_set_topography(system, h, N + 1), ASP_ERR_SIZE_MISMATCH, "'heights'");
  h[3] = NAN;
  EXPECT_ERROR(asp_system_set_topography(system, h, N), ASP_ERR_INVALID_ARGUMENT, "'heights'");
  h[3] = -INFINITY;
  EXPECT_ERROR(asp_system_set_topography(system, h, N), ASP_ERR_INVALID_ARGUMENT, "'heights'");
  EXPECT_ERROR(asp_system_set_k0(system, 0.0), ASP_ERR_INVALID_ARGUMENT, "'k0'");
  EXPECT_ERROR(asp_system_set_k0(system, NAN), ASP_ERR_INVALID_ARGUMENT, "'k0'");
  EXPECT_ERROR(asp_system_set_k0(NULL, 1.0), ASP_ERR_NULL_POINTER, "'system'");
  EXPECT_ERROR(asp_system_set_reference_pressure(system, -1.0), ASP_ERR_INVALID_ARGUMENT,
               "'reference_pressure'");
  EXPECT_ERROR(asp_system_reset(NULL), ASP_ERR_NULL_POINTER, "'system'");
  EXPECT_ERROR(asp_system_get(system, 999, &v), ASP_ERR_INVALID_ARGUMENT, "'key'");
  EXPECT_ERROR(asp_system_get(system, ASP_MEAN_PRESSURE, NULL), ASP_ERR_NULL_POINTER, "'value'");
  EXPECT_ERROR(asp_system_get(NULL, ASP_MEAN_PRESSURE, &v), ASP_ERR_NULL_POINTER, "'system'");
  EXPECT_ERROR(asp_system_get_field(system, 999, h, N), ASP_ERR_INVALID_ARGUMENT, "'field'");
  EXPECT_ERROR(asp_system_get_field(system, ASP_FIELD_GAP, h, 2), ASP_ERR_SIZE_MISMATCH,
               "'values'");
  EXPECT_ERROR(asp_system_get_field(system, ASP_FIELD_GAP, NULL, N), ASP_ERR_NULL_POINTER,
               "'values'");

  /* The failed calls left the system as it was: the sinusoid is still there. */
  EXPECT(asp_system_get_field(system, ASP_FIELD_TOPOGRAPHY, h, N) == ASP_OK);
  for (i = 0; i < N; ++i) EXPECT(isfinite(h[i]));
  EXPECT(asp_system_get(system, ASP_K0, &v) == ASP_OK && v > 0);
  asp_system_destroy(system);
}

static void test_solver_errors(asp_grid *grid) {
  asp_solver *solver = (asp_solver *)&passed;
  asp_system *system = NULL;
  double h[N], v = 0;
  int64_t iterations = -1;
  int converged = -1;

  EXPECT_ERROR(asp_solver_create("no-such-solver", &solver), ASP_ERR_UNSUPPORTED, "'algorithm'");
  EXPECT(solver == NULL);
  EXPECT_ERROR(asp_solver_create(NULL, &solver), ASP_ERR_NULL_POINTER, "'algorithm'");
  EXPECT_ERROR(asp_solver_create("pk", NULL), ASP_ERR_NULL_POINTER, "'out'");
  EXPECT(asp_solver_create("pk", &solver) == ASP_OK);

  EXPECT_ERROR(asp_solver_set_tolerance(solver, 0.0), ASP_ERR_INVALID_ARGUMENT, "'tolerance'");
  EXPECT_ERROR(asp_solver_set_tolerance(solver, NAN), ASP_ERR_INVALID_ARGUMENT, "'tolerance'");
  EXPECT_ERROR(asp_solver_set_tolerance(NULL, 1e-6), ASP_ERR_NULL_POINTER, "'solver'");
  EXPECT_ERROR(asp_solver_set_max_iterations(solver, 0), ASP_ERR_INVALID_ARGUMENT,
               "'max_iterations'");
  EXPECT_ERROR(asp_solver_iterations(solver, &iterations), ASP_ERR_INVALID_STATE, "no solve has run");
  EXPECT_ERROR(asp_solver_final_error(solver, &v), ASP_ERR_INVALID_STATE, "no solve has run");
  EXPECT_ERROR(asp_solver_converged(solver, NULL), ASP_ERR_NULL_POINTER, "'converged'");

  EXPECT(asp_system_create(grid, 1.0, &system) == ASP_OK);
  EXPECT(asp_topography_sinusoid(grid, 0.01, 1, 1, h, N) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, N) == ASP_OK);
  EXPECT_ERROR(asp_solver_solve(NULL, system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
               ASP_ERR_NULL_POINTER, "'solver'");
  EXPECT_ERROR(asp_solver_solve(solver, NULL, ASP_CONTROL_MEAN_PRESSURE, 0.01),
               ASP_ERR_NULL_POINTER, "'system'");
  EXPECT_ERROR(asp_solver_solve(solver, system, 42, 0.01), ASP_ERR_INVALID_ARGUMENT, "'control'");
  EXPECT_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_GAP, 0.01), ASP_ERR_UNSUPPORTED,
               "mean_gap");
  EXPECT_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, -0.01),
               ASP_ERR_INVALID_ARGUMENT, "'value'");
  EXPECT_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, NAN),
               ASP_ERR_INVALID_ARGUMENT, "'value'");
  EXPECT_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, INFINITY),
               ASP_ERR_INVALID_ARGUMENT, "'value'");
  EXPECT_ERROR(asp_solver_iterations(solver, &iterations), ASP_ERR_INVALID_STATE, "no solve has run");

  /* After all that, both handles still work. */
  EXPECT(asp_solver_set_tolerance(solver, 1e-10) == ASP_OK);
  EXPECT(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.001) == ASP_OK);
  EXPECT(strcmp(asp_last_error_message(), "") == 0);
  EXPECT(asp_solver_converged(solver, &converged) == ASP_OK && converged == 1);
  EXPECT(asp_solver_iterations(solver, &iterations) == ASP_OK && iterations > 0);
  EXPECT(asp_solver_final_error(solver, &v) == ASP_OK && v <= 1e-10);
  EXPECT(asp_system_get(system, ASP_MEAN_PRESSURE, &v) == ASP_OK && fabs(v - 0.001) < 1e-15);

  /* An iteration limit is an outcome, not an error. */
  EXPECT(asp_system_reset(system) == ASP_OK);
  EXPECT(asp_solver_set_max_iterations(solver, 1) == ASP_OK);
  EXPECT(asp_solver_set_tolerance(solver, 1e-15) == ASP_OK);
  EXPECT(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.001) == ASP_OK);
  EXPECT(asp_solver_converged(solver, &converged) == ASP_OK && converged == 0);
  EXPECT(asp_solver_final_error(solver, &v) == ASP_OK && isfinite(v) && v > 1e-15);

  asp_system_destroy(system);
  asp_solver_destroy(solver);
}

/* A full solve through the API: Westergaard's sinusoid at a quarter of the full-contact load,
 * with contact half-width a from p/p* = sin^2(pi a/l). */
static void test_westergaard_through_the_api(void) {
  enum { n = 1024 };
  const double pi = 3.14159265358979323846, h0 = 0.01, modulus = 2.0;
  static double h[n], p[n], g[n], u[n];
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double fraction = 0, energy = 0, mean_mode = 0, mean_gap = 0, force = 0, sum = 0;
  const double p_star = pi * modulus * h0, mean = 0.25 * p_star;
  int i, converged = 0;

  EXPECT(asp_grid_create_1d(n, 1.0, &grid) == ASP_OK);
  EXPECT(asp_topography_sinusoid(grid, h0, 1, 0, h, n) == ASP_OK);
  EXPECT(asp_system_create(grid, modulus, &system) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, n) == ASP_OK);
  EXPECT(asp_solver_create("pk", &solver) == ASP_OK);
  EXPECT(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean) == ASP_OK);
  EXPECT(asp_solver_converged(solver, &converged) == ASP_OK && converged);
  EXPECT(asp_system_get(system, ASP_CONTACT_FRACTION, &fraction) == ASP_OK);
  /* 2a/l = 2 asin(1/2)/pi = 1/3, to within two pixels. */
  EXPECT(fabs(fraction - 1.0 / 3.0) <= 2.0 / n);
  EXPECT(asp_system_get(system, ASP_TOTAL_FORCE, &force) == ASP_OK && fabs(force - mean) < 1e-14);
  EXPECT(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n) == ASP_OK);
  EXPECT(asp_system_get_field(system, ASP_FIELD_GAP, g, n) == ASP_OK);
  EXPECT(asp_system_get_field(system, ASP_FIELD_DISPLACEMENT, u, n) == ASP_OK);
  EXPECT(asp_system_get(system, ASP_ELASTIC_ENERGY, &energy) == ASP_OK);
  EXPECT(asp_system_get(system, ASP_MEAN_MODE_ENERGY, &mean_mode) == ASP_OK);
  EXPECT(asp_system_get(system, ASP_MEAN_GAP, &mean_gap) == ASP_OK);
  /* The q != 0 energy and the q = 0 term add up to (a/2) sum p u. */
  for (i = 0; i < n; ++i) sum += p[i] * u[i];
  EXPECT(fabs(energy + mean_mode - 0.5 * sum / n) <= 1e-12 * (energy + mean_mode));
  sum = 0;
  for (i = 0; i < n; ++i) sum += g[i];
  EXPECT(fabs(mean_gap - sum / n) <= 1e-14);
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
}

int main(void) {
  asp_grid *grid = NULL;
  test_status_and_version();
  test_grid_errors();
  test_grid_queries();
  test_topography_on_1d();
  if (asp_grid_create_2d(8, 8, 1.0, 1.0, &grid) != ASP_OK) {
    fprintf(stderr, "cannot create a grid: %s\n", asp_last_error_message());
    return 1;
  }
  test_topography_errors(grid);
  test_system_errors(grid);
  test_solver_errors(grid);
  asp_grid_destroy(grid);
  test_westergaard_through_the_api();
  printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
