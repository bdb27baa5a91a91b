/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Caller arrays at any address. A NumPy slice a[1:] or a Fortran array section starts where
 * its parent's element does, not where an allocator would start a new block, so it may lack
 * the alignment FFTW planned its transforms for (running a plan on such memory crashes).
 * Every public entry that reads or writes a caller's array is called twice: once on malloc'd
 * blocks, once on arrays that start one double past the start of malloc'd blocks. Both calls
 * must succeed and give the same result bit for bit. Prints "N passed, N failed" and exits
 * non-zero on any failure. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"

static int passed = 0;
static int failed = 0;

static void expect(int condition, const char *what, const char *grid, int line) {
  if (condition) {
    ++passed;
  } else {
    ++failed;
    fprintf(stderr, "FAILED line %d on %s: %s (last error: '%s')\n", line, grid, what,
            asp_last_error_message());
  }
}
#define EXPECT(c) expect((c), #c, context, __LINE__)

/* The same n doubles twice: `aligned` is a malloc'd block, `shifted` starts one double into
 * another block. Both start with the same contents, so that entries a call leaves alone
 * compare equal too. */
typedef struct {
  double *aligned;
  double *block;
  double *shifted;
  int64_t n;
} array_pair;

static array_pair make_pair(int64_t n) {
  array_pair p;
  int64_t i;
  p.n = n;
  p.aligned = (double *)malloc((size_t)n * sizeof(double));
  p.block = (double *)malloc((size_t)(n + 1) * sizeof(double));
  if (p.aligned == NULL || p.block == NULL) {
    fprintf(stderr, "cannot allocate %ld doubles\n", (long)n);
    exit(1);
  }
  p.shifted = p.block + 1;
  for (i = 0; i < n; ++i) p.aligned[i] = p.shifted[i] = -1.0 - (double)i;
  return p;
}

static void free_pair(array_pair *p) {
  free(p->aligned);
  free(p->block);
}

static int same(const array_pair *p) {
  return memcmp(p->aligned, p->shifted, (size_t)p->n * sizeof(double)) == 0;
}

/* Both calls returned ASP_OK and left the same bits in the pair. */
static void expect_same(int status_aligned, int status_shifted, const array_pair *p,
                        const char *function, const char *grid, int line) {
  char what[160];
  sprintf(what, "%s: status %d (aligned) and %d (shifted), same bits", function, status_aligned,
          status_shifted);
  expect(status_aligned == ASP_OK && status_shifted == ASP_OK && same(p), what, grid, line);
}
#define EXPECT_SAME(call_aligned, call_shifted, pair, function) \
  expect_same((call_aligned), (call_shifted), (pair), (function), context, __LINE__)

/* Generators, statistics and the power spectrum; leaves a self-affine surface in h. */
static void test_topographies(const asp_grid *grid, array_pair *h, const char *context) {
  const int64_t n = h->n, n_bins = 64;
  array_pair stats = make_pair(3), q = make_pair(n_bins), c = make_pair(n_bins);
  int64_t nx = 0;
  int dimension = 0;
  asp_grid_get_shape(grid, &dimension, &nx, NULL, NULL);

  EXPECT_SAME(asp_topography_flat(grid, h->aligned, n), asp_topography_flat(grid, h->shifted, n),
              h, "asp_topography_flat");
  EXPECT_SAME(asp_topography_sphere(grid, 0.3, h->aligned, n),
              asp_topography_sphere(grid, 0.3, h->shifted, n), h, "asp_topography_sphere");
  EXPECT_SAME(asp_topography_paraboloid(grid, 0.3, h->aligned, n),
              asp_topography_paraboloid(grid, 0.3, h->shifted, n), h,
              "asp_topography_paraboloid");
  EXPECT_SAME(asp_topography_sinusoid(grid, 0.1, 3, dimension == 2 ? 2 : 0, h->aligned, n),
              asp_topography_sinusoid(grid, 0.1, 3, dimension == 2 ? 2 : 0, h->shifted, n), h,
              "asp_topography_sinusoid");
  EXPECT_SAME(asp_topography_double_sinewave(grid, 1.0, 0.05, 32, h->aligned, n),
              asp_topography_double_sinewave(grid, 1.0, 0.05, 32, h->shifted, n), h,
              "asp_topography_double_sinewave");
  EXPECT_SAME(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / (double)nx, ASP_RMS_SLOPE,
                                         0.1, 7, h->aligned, n),
              asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / (double)nx, ASP_RMS_SLOPE,
                                         0.1, 7, h->shifted, n),
              h, "asp_topography_self_affine");

  EXPECT_SAME(asp_topography_statistics(grid, h->aligned, n, &stats.aligned[0],
                                        &stats.aligned[1], &stats.aligned[2]),
              asp_topography_statistics(grid, h->shifted, n, &stats.shifted[0],
                                        &stats.shifted[1], &stats.shifted[2]),
              &stats, "asp_topography_statistics");
  EXPECT(stats.aligned[1] > 0.099 && stats.aligned[1] < 0.101);

  EXPECT_SAME(asp_topography_power_spectrum(grid, h->aligned, n, n_bins, q.aligned, c.aligned),
              asp_topography_power_spectrum(grid, h->shifted, n, n_bins, q.shifted, c.shifted),
              &q, "asp_topography_power_spectrum (q)");
  EXPECT(same(&c));
  free_pair(&stats);
  free_pair(&q);
  free_pair(&c);
}

/* A system's topography from a caller's array, a few solver iterations, and every field and
 * history column copied back into caller arrays. */
static void test_system(const asp_grid *grid, const array_pair *h, const char *context) {
  static const int fields[] = {ASP_FIELD_PRESSURE, ASP_FIELD_GAP, ASP_FIELD_DISPLACEMENT,
                               ASP_FIELD_TOPOGRAPHY};
  /* ASP_HISTORY_SECONDS is wall-clock time, which differs between two solves. */
  static const int columns[] = {ASP_HISTORY_ITERATION,  ASP_HISTORY_EVALUATIONS,
                                ASP_HISTORY_TRANSFORMS, ASP_HISTORY_ERROR,
                                ASP_HISTORY_OBJECTIVE,  ASP_HISTORY_CONTACT_FRACTION};
  const int64_t n = h->n;
  asp_system *system_aligned = NULL, *system_shifted = NULL;
  asp_solver *solver = NULL;
  array_pair values = make_pair(n), scalar = make_pair(1);
  int64_t length = 0;
  size_t k;

  EXPECT(asp_system_create(grid, 1.0, &system_aligned) == ASP_OK);
  EXPECT(asp_system_create(grid, 1.0, &system_shifted) == ASP_OK);
  EXPECT(asp_solver_create("pk", &solver) == ASP_OK);
  EXPECT(asp_solver_set_max_iterations(solver, 3) == ASP_OK);
  EXPECT(asp_solver_set_history(solver, 1) == ASP_OK);
  EXPECT_SAME(asp_system_set_topography(system_aligned, h->aligned, n),
              asp_system_set_topography(system_shifted, h->shifted, n), h,
              "asp_system_set_topography");
  EXPECT(asp_solver_solve(solver, system_aligned, ASP_CONTROL_MEAN_PRESSURE, 0.005) == ASP_OK);

  /* The aligned solve's history, kept before the second solve replaces it. */
  EXPECT(asp_solver_history_length(solver, &length) == ASP_OK && length == 4);
  {
    array_pair history[sizeof columns / sizeof columns[0]];
    for (k = 0; k < sizeof columns / sizeof columns[0]; ++k) {
      history[k] = make_pair(length);
      EXPECT(asp_solver_get_history(solver, columns[k], history[k].aligned, length) == ASP_OK);
    }
    EXPECT(asp_solver_solve(solver, system_shifted, ASP_CONTROL_MEAN_PRESSURE, 0.005) == ASP_OK);
    for (k = 0; k < sizeof columns / sizeof columns[0]; ++k) {
      EXPECT_SAME(ASP_OK, asp_solver_get_history(solver, columns[k], history[k].shifted, length),
                  &history[k], "asp_solver_get_history");
      free_pair(&history[k]);
    }
  }
  for (k = 0; k < sizeof fields / sizeof fields[0]; ++k)
    EXPECT_SAME(asp_system_get_field(system_aligned, fields[k], values.aligned, n),
                asp_system_get_field(system_shifted, fields[k], values.shifted, n), &values,
                "asp_system_get_field");
  EXPECT_SAME(asp_system_get(system_aligned, ASP_ELASTIC_ENERGY, scalar.aligned),
              asp_system_get(system_shifted, ASP_ELASTIC_ENERGY, scalar.shifted), &scalar,
              "asp_system_get");

  asp_solver_destroy(solver);
  asp_system_destroy(system_aligned);
  asp_system_destroy(system_shifted);
  free_pair(&values);
  free_pair(&scalar);
}

static void test_on(int dimension, int64_t nx, int64_t ny) {
  char context[64];
  asp_grid *grid = NULL;
  array_pair h;
  int status;
  sprintf(context, "%dD %ldx%ld", dimension, (long)nx, (long)ny);
  status = dimension == 2 ? asp_grid_create_2d(nx, ny, 1.0, 1.0, &grid)
                          : asp_grid_create_1d(nx, 1.0, &grid);
  EXPECT(status == ASP_OK);
  if (status != ASP_OK) return;
  /* Estimated plans: measuring 1024^2 would cost seconds and change nothing tested here. */
  EXPECT(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE) == ASP_OK);
  h = make_pair(nx * ny);
  test_topographies(grid, &h, context);
  test_system(grid, &h, context);
  free_pair(&h);
  asp_grid_destroy(grid);
}

int main(void) {
  test_on(2, 256, 256);
  test_on(2, 1024, 1024);
  test_on(2, 255, 257);
  test_on(1, 65536, 1);
  printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
