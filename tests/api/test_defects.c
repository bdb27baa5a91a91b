/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Regression tests, through the public header, for defects found when the library was tried
 * as a new user would, fuzzed and run on extreme scenes: warm starts that stalled, solves that
 * said "converged" with NaN or nonsense, non-finite results returned with ASP_OK, and a
 * too-large grid reported as an internal error. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "check.h"

#define EXPECT(c) CHECK(c)

/* The smallest gap of the system's state. */
static double min_gap(const asp_system *system, int64_t n) {
  double *g = malloc((size_t)n * sizeof *g), m = HUGE_VAL;
  int64_t i;
  asp_system_get_field(system, ASP_FIELD_GAP, g, n);
  for (i = 0; i < n; ++i) m = g[i] < m ? g[i] : m;
  free(g);
  return m;
}

/* A load sweep, doubling the mean pressure from `first` to `last`, each solve warm-started
 * from the previous one. Every step must converge with no interpenetration beyond what the
 * tolerance allows (the error is the gap violation times the pixel stiffness over the
 * reference pressure, so with tolerance 1e-10 any gap below -1e-8 is far outside it). */
static void sweep(asp_grid *grid, const double *h, int64_t n, double first, double last,
                  const char *scene) {
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double load;
  int steps = 0, good = 0;
  EXPECT(asp_system_create(grid, 1.0, &system) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, n) == ASP_OK);
  EXPECT(asp_solver_create("pk", &solver) == ASP_OK);
  EXPECT(asp_solver_set_tolerance(solver, 1e-10) == ASP_OK);
  for (load = first; load <= last; load *= 2) {
    int converged = 0;
    asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, load);
    asp_solver_converged(solver, &converged);
    ++steps;
    if (converged && min_gap(system, n) > -1e-8)
      ++good;
    else
      fprintf(stderr, "  %s: warm start at load %g: converged %d, min gap %g\n", scene, load,
              converged, min_gap(system, n));
  }
  EXPECT(good == steps);
  asp_solver_destroy(solver);
  asp_system_destroy(system);
}

static void test_warm_start_sweeps(void) {
  asp_grid *grid = NULL;
  double *h = malloc(64 * 64 * sizeof *h);
  /* A sphere of radius 0.5 on a unit box, 64 x 64 (the one-pixel contact of light loads). */
  EXPECT(asp_grid_create_2d(64, 64, 1.0, 1.0, &grid) == ASP_OK);
  EXPECT(asp_topography_sphere(grid, 0.5, h, 64 * 64) == ASP_OK);
  sweep(grid, h, 64 * 64, 1e-7, 3.2e-3, "sphere 64x64");
  asp_grid_destroy(grid);
  /* A 2 x 1 grid. */
  EXPECT(asp_grid_create_2d(2, 1, 1.0, 1.0, &grid) == ASP_OK);
  h[0] = 0.1;
  h[1] = -0.1;
  sweep(grid, h, 2, 1e-7, 3.2e-3, "2x1");
  asp_grid_destroy(grid);
  /* A 256 x 1 sinusoid. */
  EXPECT(asp_grid_create_2d(256, 1, 1.0, 1.0, &grid) == ASP_OK);
  EXPECT(asp_topography_sinusoid(grid, 0.01, 1, 0, h, 256) == ASP_OK);
  sweep(grid, h, 256, 1e-7, 3.2e-3, "sinusoid 256x1");
  asp_grid_destroy(grid);
  free(h);
}

/* Everything a solve reports is finite, and "converged" only with a finite error. */
static void expect_finite_outcome(const asp_system *system, const asp_solver *solver,
                                  int64_t n, int line) {
  static const int keys[] = {ASP_CONTACT_FRACTION, ASP_MEAN_PRESSURE, ASP_MEAN_GAP,
                             ASP_ELASTIC_ENERGY,   ASP_PENETRATION,   ASP_TOTAL_FORCE, ASP_K0};
  double v = 0, *f = malloc((size_t)n * sizeof *f);
  int converged = 0, k, field, finite = 1;
  int64_t i;
  if (asp_solver_final_error(solver, &v) == ASP_OK && !isfinite(v)) finite = 0;
  if (asp_solver_converged(solver, &converged) == ASP_OK && converged && !isfinite(v)) finite = 0;
  for (k = 0; k < (int)(sizeof keys / sizeof keys[0]); ++k)
    if (asp_system_get(system, keys[k], &v) == ASP_OK && !isfinite(v)) finite = 0;
  for (field = ASP_FIELD_PRESSURE; field <= ASP_FIELD_DISPLACEMENT; ++field) {
    if (asp_system_get_field(system, field, f, n) != ASP_OK) continue;
    for (i = 0; i < n; ++i)
      if (!isfinite(f[i])) finite = 0;
  }
  free(f);
  check_record(finite, __FILE__, line, "every output finite");
}

/* The unit scene (a sinusoidal egg box on a 32 x 32 unit box, E* = 1, mean pressure 0.05)
 * scaled in length by `length` and in modulus by `modulus`: its contact fraction and its
 * pressure over the modulus must be those of the unit scene. */
static void scaled_scene(double length, double modulus, double *fraction, double *pressure) {
  enum { n = 32 * 32 };
  double h[n];
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  int converged = 0;
  int64_t i;
  *fraction = -1;
  EXPECT(asp_grid_create_2d(32, 32, length, length, &grid) == ASP_OK);
  EXPECT(asp_topography_sinusoid(grid, 0.05 * length, 2, 3, h, n) == ASP_OK);
  EXPECT(asp_system_create(grid, modulus, &system) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, n) == ASP_OK);
  EXPECT(asp_solver_create("pk", &solver) == ASP_OK);
  EXPECT(asp_solver_set_tolerance(solver, 1e-12) == ASP_OK);
  EXPECT(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.05 * modulus) == ASP_OK);
  EXPECT(asp_solver_converged(solver, &converged) == ASP_OK && converged);
  expect_finite_outcome(system, solver, n, __LINE__);
  EXPECT(asp_system_get(system, ASP_CONTACT_FRACTION, fraction) == ASP_OK);
  EXPECT(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, n) == ASP_OK);
  for (i = 0; i < n; ++i) pressure[i] /= modulus;
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
}

static void test_scale_invariance(void) {
  static const double scales[][2] = {{1e100, 1}, {1e-100, 1}, {1, 1e100}, {1, 1e-100},
                                     {1e100, 1e-100}};
  static double unit[32 * 32], other[32 * 32];
  double f_unit = 0, f_other = 0;
  int s, i;
  scaled_scene(1, 1, &f_unit, unit);
  for (s = 0; s < 5; ++s) {
    double worst = 0;
    scaled_scene(scales[s][0], scales[s][1], &f_other, other);
    EXPECT(f_other == f_unit);
    /* Same dimensionless arithmetic up to the rounding of the scale factors themselves. */
    for (i = 0; i < 32 * 32; ++i)
      worst = fabs(other[i] - unit[i]) > worst ? fabs(other[i] - unit[i]) : worst;
    EXPECT(worst <= 1e-12);
  }
}

/* A call that must fail cleanly: not OK, not INTERNAL, a message, and *out left NULL. */
#define EXPECT_REFUSED(call)                                                           \
  do {                                                                                 \
    int status_ = (call);                                                              \
    EXPECT(status_ == ASP_ERR_INVALID_ARGUMENT || status_ == ASP_ERR_OUT_OF_MEMORY);   \
    EXPECT(strlen(asp_last_error_message()) > 0);                                      \
  } while (0)

static void test_scenes_doubles_cannot_hold(void) {
  enum { n = 64 * 64 };
  static double h[n];
  asp_grid *grid = NULL, *huge = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double v = 0;
  int status, converged = 0;

  EXPECT(asp_grid_create_2d(64, 64, 1.0, 1.0, &grid) == ASP_OK);
  EXPECT(asp_solver_create("pk", &solver) == ASP_OK);

  /* Moduli whose stiffness underflows or overflows. */
  EXPECT_REFUSED(asp_system_create(grid, 4.9e-324, &system));
  EXPECT(system == NULL);
  EXPECT_REFUSED(asp_system_create(grid, 1e308, &system));
  EXPECT(system == NULL);

  EXPECT(asp_system_create(grid, 1.0, &system) == ASP_OK);
  EXPECT(asp_topography_sinusoid(grid, 0.01, 1, 1, h, n) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, n) == ASP_OK);
  EXPECT_REFUSED(asp_system_set_k0(system, 4.9e-324));
  EXPECT_REFUSED(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, DBL_MAX));
  EXPECT_REFUSED(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, -DBL_MAX));
  EXPECT(asp_system_get(system, ASP_MEAN_GAP, &v) == ASP_OK && isfinite(v));

  /* A mean mode so soft that the mean displacement pbar/K~(0) of a load leaves the doubles:
   * refused, or solved with every output finite. */
  {
    static const double soft[] = {1e-300, 1e-200, 1e-150, 1e-100};
    double k0 = 0;
    int i;
    EXPECT(asp_system_get(system, ASP_K0, &k0) == ASP_OK);
    for (i = 0; i < 4; ++i) {
      EXPECT(asp_system_reset(system) == ASP_OK);
      EXPECT(asp_system_set_k0(system, soft[i]) == ASP_OK);
      status = asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.05);
      EXPECT(status == ASP_OK || status == ASP_ERR_INVALID_ARGUMENT);
      if (status == ASP_OK) expect_finite_outcome(system, solver, n, __LINE__);
    }
    EXPECT(asp_system_set_k0(system, k0) == ASP_OK);
  }

  /* Heights spanning more than a double. */
  h[0] = DBL_MAX;
  h[1] = -DBL_MAX;
  EXPECT_REFUSED(asp_system_set_topography(system, h, n));

  /* A box of 1e160 (area 1e320) and one of 1e200. */
  EXPECT_REFUSED(asp_grid_create_2d(64, 64, 1e160, 1e160, &huge));
  EXPECT_REFUSED(asp_grid_create_2d(64, 64, 1e200, 1e200, &huge));
  EXPECT(huge == NULL);

  /* A sinusoid of amplitude 1e154 under a proportional load: either refused, or solved with
   * the answer of amplitude 1 (it is the same dimensionless scene). */
  EXPECT(asp_topography_sinusoid(grid, 1e154, 1, 1, h, n) == ASP_OK);
  EXPECT(asp_system_set_topography(system, h, n) == ASP_OK);
  status = asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 1e154);
  if (status == ASP_OK) {
    double big = 0, unit = 0;
    EXPECT(asp_solver_converged(solver, &converged) == ASP_OK && converged);
    expect_finite_outcome(system, solver, n, __LINE__);
    EXPECT(asp_system_get(system, ASP_CONTACT_FRACTION, &big) == ASP_OK);
    EXPECT(asp_topography_sinusoid(grid, 1.0, 1, 1, h, n) == ASP_OK);
    EXPECT(asp_system_set_topography(system, h, n) == ASP_OK);
    EXPECT(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 1.0) == ASP_OK);
    EXPECT(asp_system_get(system, ASP_CONTACT_FRACTION, &unit) == ASP_OK);
    EXPECT(big == unit && big < 1.0);
  } else {
    EXPECT(status == ASP_ERR_INVALID_ARGUMENT);
  }

  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
}

/* Too large is OUT_OF_MEMORY or INVALID_ARGUMENT naming the argument, never INTERNAL. */
static void test_too_large(void) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  int status = asp_grid_create_2d(INT_MAX, INT_MAX, 1.0, 1.0, &grid);
  if (status == ASP_OK) {
    status = asp_system_create(grid, 1.0, &system);
    EXPECT(status == ASP_ERR_OUT_OF_MEMORY || status == ASP_ERR_INVALID_ARGUMENT);
    EXPECT(system == NULL);
  } else {
    EXPECT(status == ASP_ERR_INVALID_ARGUMENT);
  }
  EXPECT(strstr(asp_last_error_message(), "std::") == NULL);
  asp_grid_destroy(grid);
  EXPECT(asp_grid_create_2d(INT_MAX / 2, INT_MAX / 2, 1.0, 1.0, &grid) == ASP_OK);
  status = asp_system_create(grid, 1.0, &system);
  EXPECT(status == ASP_ERR_OUT_OF_MEMORY);
  EXPECT(strstr(asp_last_error_message(), "std::") == NULL);
  asp_grid_destroy(grid);
}

int main(void) {
  test_warm_start_sweeps();
  test_scale_invariance();
  test_scenes_doubles_cannot_hold();
  test_too_large();
  return check_summary("api.defects");
}
