/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The free (non-periodic) half-space through the public header (asp_system_create_free):
 * Hertz under penetration control, the energies it reports (ASP_ELASTIC_ENERGY the whole
 * (a/2) sum p u, ASP_MEAN_MODE_ENERGY 0), the solvers that work on it and the one that does
 * not, and what it refuses: a 1D grid, K~(0) (set and get), bad arguments, a grid too large
 * for memory. After every refusal the handles stay usable. */
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

enum { n = 40 }; /* a box of 2.5 a with a = 16 pixels */

static double get(const asp_system *system, int key) {
  double value = NAN;
  if (asp_system_get(system, key, &value) != ASP_OK)
    fprintf(stderr, "asp_system_get(%d): %s\n", key, asp_last_error_message());
  return value;
}

static int converged(const asp_solver *solver) {
  int c = 0;
  return asp_solver_converged(solver, &c) == ASP_OK && c == 1;
}

int main(void) {
  const double radius = 1.0, modulus = 2.0, a = 0.05, l = 2.5 * a, dx = l / n;
  const double delta = a * a / radius;
  const double force = 4.0 / 3.0 * modulus * sqrt(radius) * pow(delta, 1.5);
  asp_grid *grid = NULL, *line = NULL;
  asp_system *system = NULL, *refused = NULL;
  asp_solver *pk = NULL, *gap = NULL, *pressure_cg = NULL;
  double *h = calloc((size_t)(n * n), sizeof(double));
  double *p = calloc((size_t)(n * n), sizeof(double));
  double *u = calloc((size_t)(n * n), sizeof(double));
  double *q = calloc((size_t)(n * n), sizeof(double));
  double pu = 0.0, largest = 0.0, elastic, value = 0.0;
  char text[4096];
  int64_t i;
  if (h == NULL || p == NULL || u == NULL || q == NULL) return 2;

  CHECK_OK(asp_grid_create_2d(n, n, l, l, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_paraboloid(grid, radius, h, n * n));
  CHECK_OK(asp_system_create_free(grid, modulus, &system));
  CHECK_OK(asp_system_set_topography(system, h, n * n));
  CHECK_OK(asp_solver_create("pk", &pk));
  CHECK_OK(asp_solver_set_tolerance(pk, 1e-11));

  /* ---- Hertz: F = (4/3) E* sqrt(R) delta^(3/2), the penetration that of distant points ----
   * Second-order collocation error, 0.2 (dx/a)^2 = 7.8e-4 at a/dx = 16 (the unit test
   * FreeHalfSpace.HertzConvergesWithResolution derives it; measured 1.3e-4). */
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, delta));
  CHECK(converged(pk));
  CHECK_NEAR(get(system, ASP_TOTAL_FORCE), force, 0.2 * (dx / a) * (dx / a) * force);
  CHECK(get(system, ASP_PENETRATION) == delta);

  /* ---- energies: all of it is elastic, (a/2) sum p u, to round-off (the state's gap is
   * the one its pressure makes) ---- */
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n * n));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_DISPLACEMENT, u, n * n));
  for (i = 0; i < n * n; ++i) pu += p[i] * u[i];
  elastic = get(system, ASP_ELASTIC_ENERGY);
  CHECK_NEAR(elastic, 0.5 * dx * dx * pu, 1e-10 * elastic);
  CHECK(get(system, ASP_MEAN_MODE_ENERGY) == 0.0);

  /* ---- no K~(0) ---- */
  CHECK_ERROR(asp_system_get(system, ASP_K0, &value), ASP_ERR_UNSUPPORTED, "'key'");
  CHECK_MESSAGE_HAS("free half-space");
  CHECK_ERROR(asp_system_set_k0(system, 1.0), ASP_ERR_UNSUPPORTED, "'system'");
  CHECK_MESSAGE_HAS("free half-space");
  CHECK(get(system, ASP_PENETRATION) == delta);

  /* ---- the gap formulation refuses mean-gap control, naming the substrate; the state
   * stays ---- */
  CHECK_OK(asp_solver_create("bugnicourt", &gap));
  CHECK_OK(asp_solver_set_option_string(gap, "variable", "gap"));
  CHECK_ERROR(asp_solver_solve(gap, system, ASP_CONTROL_MEAN_GAP, 1e-4), ASP_ERR_UNSUPPORTED,
              "periodic substrate only");
  CHECK_MESSAGE_HAS("free half-space");
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, q, n * n));
  CHECK(memcmp(p, q, sizeof(double) * n * n) == 0);
  CHECK_OK(asp_solver_describe(gap, text, (int64_t)sizeof text, NULL));
  CHECK(strstr(text, "free half-space") != NULL);

  /* ---- under penetration control it solves the same problem as pk, on the displacement of
   * the padded surface: both stop at error 1e-11 of the reference pressure, the primal's a
   * pressure residual, pk's a gap residual times the pixel stiffness; 1e-9 of the peak
   * pressure allows for how the contact operator spreads the latter ---- */
  CHECK_OK(asp_solver_set_tolerance(gap, 1e-11));
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_solve(gap, system, ASP_CONTROL_PENETRATION, delta));
  CHECK(converged(gap));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, q, n * n));
  for (i = 0; i < n * n; ++i) largest = fmax(largest, p[i]);
  for (i = 0; i < n * n; ++i)
    if (fabs(p[i] - q[i]) > 1e-9 * largest) break;
  CHECK(i == n * n);
  CHECK_NEAR(get(system, ASP_ELASTIC_ENERGY), elastic, 1e-9 * elastic);

  /* ---- bugnicourt on the pressure works and agrees with pk: both stop at error 1e-11, a
   * gap residual worth 1e-11 of the reference pressure per pixel; 1e-9 of the peak pressure
   * allows for how the contact operator spreads it ---- */
  CHECK_OK(asp_solver_create("bugnicourt", &pressure_cg));
  CHECK_OK(asp_solver_set_tolerance(pressure_cg, 1e-11));
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_solve(pressure_cg, system, ASP_CONTROL_PENETRATION, delta));
  CHECK(converged(pressure_cg));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, q, n * n));
  for (i = 0; i < n * n; ++i)
    if (fabs(p[i] - q[i]) > 1e-9 * largest) break;
  CHECK(i == n * n);

  /* ---- refusals of creation ---- */
  CHECK_OK(asp_grid_create_1d(64, 1.0, &line));
  refused = (asp_system *)&value; /* not NULL, so that the reset to NULL shows */
  CHECK_ERROR(asp_system_create_free(line, 1.0, &refused), ASP_ERR_UNSUPPORTED, "'grid'");
  CHECK_MESSAGE_HAS("reference point");
  CHECK(refused == NULL);
  CHECK_ERROR(asp_system_create_free(NULL, 1.0, &refused), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_system_create_free(grid, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_system_create_free(grid, 0.0, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'contact_modulus'");
  CHECK_ERROR(asp_system_create_free(grid, NAN, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'contact_modulus'");
  CHECK_ERROR(asp_system_create_free(grid, 1e-310, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'contact_modulus'");
  CHECK(refused == NULL);
  asp_grid_destroy(line);
  line = NULL;

  /* A grid whose fields cannot be allocated: out of memory, nothing made. */
  CHECK_OK(asp_grid_create_2d(INT_MAX / 2, INT_MAX / 2, 1.0, 1.0, &line));
  CHECK_ERROR(asp_system_create_free(line, 1.0, &refused), ASP_ERR_OUT_OF_MEMORY, NULL);
  CHECK(refused == NULL);
  asp_grid_destroy(line);

  /* ---- the handles are still usable, and the system keeps its grid alive ---- */
  asp_grid_destroy(grid);
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_MEAN_PRESSURE, force / (l * l)));
  CHECK(converged(pk));
  CHECK_NEAR(get(system, ASP_MEAN_PRESSURE), force / (l * l), 1e-14 * force / (l * l));

  asp_solver_destroy(pk);
  asp_solver_destroy(gap);
  asp_solver_destroy(pressure_cg);
  asp_system_destroy(system);
  free(h);
  free(p);
  free(u);
  free(q);
  return check_summary("free_substrate");
}
