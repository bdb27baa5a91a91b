/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The option "levels" (nested grids) through the public header: a count or the string
 * "auto", read back by both getters as documented; a count the grid cannot take refused by
 * asp_solver_supports and asp_solver_solve with ASP_ERR_UNSUPPORTED naming the option; and a
 * nested solve that ends where the plain one does. */
#include <math.h>
#include <stdlib.h>

#include "check.h"

enum { nx = 128, ny = 128, n = nx * ny };

static double heights[n];
static double plain_pressure[n];
static double nested_pressure[n];

int main(void) {
  asp_grid *grid = NULL, *odd = NULL;
  asp_system *system = NULL, *odd_system = NULL;
  asp_solver *solver = NULL;
  char text[64];
  int64_t length = 0, plain_iterations = 0, nested_iterations = 0;
  double value = 0.0, peak = 0.0, difference = 0.0, plain_fraction = 0.0, nested_fraction = 0.0;
  int converged = 0, i;

  /* The constrained solvers nest grids by default ("auto", read as -1); the solvers of soft
     walls do not. */
  CHECK_OK(asp_solver_create("lbfgsb", &solver));
  CHECK_OK(asp_solver_get_option(solver, "levels", &value));
  CHECK(value == -1.0);
  asp_solver_destroy(solver);
  CHECK_OK(asp_solver_create("lbfgs", &solver));
  CHECK_OK(asp_solver_get_option(solver, "levels", &value));
  CHECK(value == 0.0);
  asp_solver_destroy(solver);
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_get_option(solver, "levels", &value));
  CHECK(value == -1.0);
  CHECK_OK(asp_solver_set_option(solver, "levels", 0.0));
  CHECK_OK(asp_solver_get_option(solver, "levels", &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_solver_set_option_string(solver, "levels", "auto"));
  CHECK_OK(asp_solver_get_option(solver, "levels", &value));
  CHECK(value == -1.0);
  CHECK_OK(asp_solver_get_option_string(solver, "levels", text, sizeof text, &length));
  CHECK(strcmp(text, "auto") == 0 && length == 4);
  CHECK_ERROR(asp_solver_set_option_string(solver, "levels", "deep"), ASP_ERR_INVALID_ARGUMENT,
              "'auto'");
  CHECK_ERROR(asp_solver_set_option(solver, "levels", -1.0), ASP_ERR_INVALID_ARGUMENT,
              "levels");
  CHECK_ERROR(asp_solver_set_option(solver, "levels", 17.0), ASP_ERR_INVALID_ARGUMENT,
              "levels");
  CHECK_OK(asp_solver_set_option(solver, "levels", 2.0));
  CHECK_ERROR(asp_solver_get_option_string(solver, "levels", text, sizeof text, &length),
              ASP_ERR_INVALID_ARGUMENT, "asp_solver_get_option");

  /* An odd size cannot be halved. */
  CHECK_OK(asp_grid_create_2d(nx + 2, 33, 1.0, 1.0, &odd));
  CHECK_OK(asp_grid_set_fft_planning(odd, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_system_create(odd, 1.0, &odd_system));
  CHECK_OK(asp_topography_flat(odd, nested_pressure, (nx + 2) * 33));
  CHECK_OK(asp_system_set_topography(odd_system, nested_pressure, (nx + 2) * 33));
  CHECK_ERROR(asp_solver_supports(solver, odd_system, ASP_CONTROL_MEAN_PRESSURE),
              ASP_ERR_UNSUPPORTED, "option 'levels'");
  CHECK_ERROR(asp_solver_solve(solver, odd_system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
              ASP_ERR_UNSUPPORTED, "odd size");
  /* auto takes what the grid allows: none here. */
  CHECK_OK(asp_solver_set_option_string(solver, "levels", "auto"));
  CHECK_OK(asp_solver_supports(solver, odd_system, ASP_CONTROL_MEAN_PRESSURE));

  /* A rough surface, plain and nested (auto: one level, 64^2), to the tolerance 1e-10. */
  CHECK_OK(asp_grid_create_2d(nx, ny, 1.0, 1.0, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 8.0 / nx, ASP_RMS_SLOPE, 0.1, 5,
                                      heights, n));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, heights, n));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-10));
  CHECK_OK(asp_solver_set_option(solver, "levels", 0.0));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_solver_iterations(solver, &plain_iterations));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &plain_fraction));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, plain_pressure, n));

  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_set_option_string(solver, "levels", "auto"));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_solver_iterations(solver, &nested_iterations));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &nested_fraction));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, nested_pressure, n));
  for (i = 0; i < n; ++i) {
    if (fabs(plain_pressure[i]) > peak) peak = fabs(plain_pressure[i]);
    if (fabs(plain_pressure[i] - nested_pressure[i]) > difference)
      difference = fabs(plain_pressure[i] - nested_pressure[i]);
  }
  printf("plain %lld iterations, nested %lld; max dp/p %.1e\n", (long long)plain_iterations,
         (long long)nested_iterations, difference / peak);
  /* Both meet the tolerance 1e-10: the same contact set, pressures within 100 times it of
   * the peak (as in tests/unit/test_nested_grids.cpp). */
  CHECK(nested_fraction == plain_fraction);
  CHECK(difference <= 1e-8 * peak);

  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_system_destroy(odd_system);
  asp_grid_destroy(grid);
  asp_grid_destroy(odd);
  return check_summary("test_nested_grids");
}
