/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asp_topography_detrend through the public header: a 3 % tilt on a periodic rough surface
 * changes the contact at a given load, and removing the plane gives back the contact of the
 * surface without the tilt; bad arguments are refused by name and leave the heights as they
 * were. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "check.h"

enum { nx = 64, ny = 64, n = nx * ny };

static double contact_at_load(asp_grid *grid, const double *h, double load) {
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double contact = -1.0;
  int converged = 0;
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, h, n));
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-10));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, load));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &contact));
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  return contact;
}

int main(void) {
  asp_grid *grid = NULL;
  double *h = malloc(n * sizeof *h), *tilted = malloc(n * sizeof *tilted),
         *level = malloc(n * sizeof *level);
  double plain = 0, with_tilt = 0, detrended = 0, largest = 0;
  int64_t i;

  CHECK(h && tilted && level);
  CHECK_OK(asp_grid_create_2d(nx, ny, 1.0, 1.0, &grid));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / nx, ASP_RMS_SLOPE, 0.1, 7, h,
                                      n));
  /* The surface as the solver would see it without a tilt, its own plane removed. */
  memcpy(level, h, n * sizeof *h);
  CHECK_OK(asp_topography_detrend(grid, ASP_DETREND_PLANE, level, n));
  for (i = 0; i < n; ++i) tilted[i] = level[i] + 0.03 * ((double)(i % nx) + 0.5) / nx;

  plain = contact_at_load(grid, level, 2e-3);
  with_tilt = contact_at_load(grid, tilted, 2e-3);
  /* The tilt wraps into a ridge on the periodic substrate: far less of the surface touches. */
  CHECK(with_tilt < 0.8 * plain);
  CHECK_OK(asp_topography_detrend(grid, ASP_DETREND_PLANE, tilted, n));
  for (i = 0; i < n; ++i) largest = fmax(largest, fabs(tilted[i] - level[i]));
  CHECK(largest <= 1e-14);
  detrended = contact_at_load(grid, tilted, 2e-3);
  CHECK(detrended == plain);

  /* The mean mode leaves a zero mean. */
  CHECK_OK(asp_topography_detrend(grid, ASP_DETREND_MEAN, h, n));
  largest = 0;
  for (i = 0; i < n; ++i) largest += h[i] / n;
  CHECK(fabs(largest) <= 1e-16);

  /* Refusals name the argument and leave the heights. */
  CHECK_ERROR(asp_topography_detrend(NULL, ASP_DETREND_PLANE, h, n), ASP_ERR_NULL_POINTER,
              "'grid'");
  CHECK_ERROR(asp_topography_detrend(grid, ASP_DETREND_PLANE, h, n - 1), ASP_ERR_SIZE_MISMATCH,
              "'heights'");
  CHECK_ERROR(asp_topography_detrend(grid, ASP_RMS_SLOPE, h, n), ASP_ERR_INVALID_ARGUMENT,
              "'mode'");
  CHECK_MESSAGE_HAS("ASP_RMS_SLOPE");
  memcpy(level, h, n * sizeof *h);
  h[17] = NAN;
  CHECK_ERROR(asp_topography_detrend(grid, ASP_DETREND_CURVATURE, h, n),
              ASP_ERR_INVALID_ARGUMENT, "'heights'");
  CHECK(h[16] == level[16] && isnan(h[17]));

  asp_grid_destroy(grid);
  free(h);
  free(tilted);
  free(level);
  return check_summary("api.detrend");
}
