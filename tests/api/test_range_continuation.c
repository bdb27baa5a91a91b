/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The option "range_continuation" (a first solve with the exponential adhesion's range times
 * a factor) through the public header: "auto" set with asp_solver_set_option_string and a
 * factor with asp_solver_set_option, read back by both getters; the default "auto" of
 * bugnicourt and 0 of the others; an explicit factor on the plain hard wall refused by
 * asp_solver_solve with ASP_ERR_UNSUPPORTED and a factor below 1 with
 * ASP_ERR_INVALID_ARGUMENT, each naming the option in asp_last_error_message(), with the
 * handles usable afterwards; and a continued solve of an unresolved adhesive scene that
 * converges and leaves the system's adhesion as it was set. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

enum { nx = 64, ny = 64, n = nx * ny };

static double heights[n];
static double pressure[n];
static char sentence[1024];

int main(void) {
  /* The adhesion: w/rho = 0.05 E* (about E* h'_rms/2), rho = 1e-4 of the box; its cohesive
   * zone (pi/4) E* rho^2/w is 1.6e-3, a tenth of a pixel (1/64): unresolved. */
  const double work = 5e-6, range = 1e-4;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  char text[64];
  int64_t length = 0, iterations = 0;
  double value = 0.0, ratio = 0.0, height_range = 0.0, lowest = 0.0, highest = 0.0;
  int converged = 0, resolved = -1, finite = 1, i;

  /* ---- the option's values ---- */
  CHECK_OK(asp_solver_create("lbfgsb", &solver));
  CHECK_OK(asp_solver_get_option(solver, "range_continuation", &value));
  CHECK(value == 0.0);
  asp_solver_destroy(solver);
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_get_option(solver, "range_continuation", &value));
  CHECK(value == 0.0);
  asp_solver_destroy(solver);
  CHECK_OK(asp_solver_create("bugnicourt", &solver));
  CHECK_OK(asp_solver_get_option(solver, "range_continuation", &value));
  CHECK(value == -1.0);
  CHECK_OK(asp_solver_get_option_string(solver, "range_continuation", text, sizeof text,
                                        &length));
  CHECK(strcmp(text, "auto") == 0 && length == 4);
  CHECK_OK(asp_solver_set_option(solver, "range_continuation", 4.0));
  CHECK_OK(asp_solver_get_option(solver, "range_continuation", &value));
  CHECK(value == 4.0);
  CHECK_ERROR(asp_solver_get_option_string(solver, "range_continuation", text, sizeof text,
                                           &length),
              ASP_ERR_INVALID_ARGUMENT, "range_continuation");
  CHECK_OK(asp_solver_set_option_string(solver, "range_continuation", "auto"));
  CHECK_OK(asp_solver_get_option(solver, "range_continuation", &value));
  CHECK(value == -1.0);
  CHECK_OK(asp_solver_get_option_string(solver, "range_continuation", text, sizeof text,
                                        &length));
  CHECK(strcmp(text, "auto") == 0 && length == 4);
  CHECK_ERROR(asp_solver_set_option(solver, "range_continuation", -1.0),
              ASP_ERR_INVALID_ARGUMENT, "range_continuation");
  CHECK_ERROR(asp_solver_set_option_string(solver, "range_continuation", "long"),
              ASP_ERR_INVALID_ARGUMENT, "'auto'");
  CHECK_OK(asp_solver_get_option(solver, "range_continuation", &value));
  CHECK(value == -1.0); /* a refused value changes nothing */

  /* ---- the plain hard wall: an explicit factor is refused at the solve ---- */
  CHECK_OK(asp_grid_create_2d(nx, ny, 1.0, 1.0, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / nx, ASP_RMS_SLOPE, 0.1, 9,
                                      heights, n));
  lowest = highest = heights[0];
  for (i = 0; i < n; ++i) {
    if (heights[i] < lowest) lowest = heights[i];
    if (heights[i] > highest) highest = heights[i];
  }
  height_range = highest - lowest;
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, heights, n));
  CHECK_OK(asp_solver_set_option_string(solver, "variable", "gap"));
  CHECK_OK(asp_solver_set_option(solver, "range_continuation", 4.0));
  CHECK_ERROR(asp_solver_supports(solver, system, ASP_CONTROL_PENETRATION), ASP_ERR_UNSUPPORTED,
              "'range_continuation'");
  CHECK_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.3 * height_range),
              ASP_ERR_UNSUPPORTED, "'range_continuation'");
  /* The handles stay usable: "auto" does nothing on the hard wall, and 0 is none. */
  CHECK_OK(asp_solver_set_option_string(solver, "range_continuation", "auto"));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.3 * height_range));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_set_option(solver, "range_continuation", 0.0));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.3 * height_range));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);

  /* ---- the unresolved adhesive scene ---- */
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_system_set_adhesion(system, work, range));
  CHECK_OK(asp_system_check_resolution(system, &ratio, &resolved, sentence, sizeof sentence,
                                       &length));
  CHECK(resolved == 0 && ratio > 0.05 && ratio < 0.2);
  CHECK_OK(asp_solver_set_option(solver, "range_continuation", 0.5));
  CHECK_ERROR(asp_solver_supports(solver, system, ASP_CONTROL_PENETRATION),
              ASP_ERR_INVALID_ARGUMENT, "'range_continuation'");
  CHECK_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.3 * height_range),
              ASP_ERR_INVALID_ARGUMENT, "'range_continuation'");
  CHECK_OK(asp_solver_set_option(solver, "range_continuation", 4.0));
  CHECK_OK(asp_solver_supports(solver, system, ASP_CONTROL_PENETRATION));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.3 * height_range));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(iterations > 0);
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, n));
  for (i = 0; i < n; ++i) finite = finite && isfinite(pressure[i]);
  CHECK(finite);
  /* The adhesion is the one set, exactly. */
  CHECK_OK(asp_system_get(system, ASP_WORK_OF_ADHESION, &value));
  CHECK(value == work);
  CHECK_OK(asp_system_get(system, ASP_ADHESION_RANGE, &value));
  CHECK(value == range);
  printf("range_continuation 4: %lld iterations (zone %.3f pixels)\n", (long long)iterations,
         ratio);

  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  return check_summary("test_range_continuation");
}
