/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The "preconditioner" option of "pk" through the C API: "auto" by default, "none" and
 * "fourier" set and read back by asp_solver_get_option_string, other values refused with
 * ASP_ERR_INVALID_ARGUMENT naming the option and its values, and a preconditioned solve
 * reaching the plain one's state. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"

#define NX 64
#define N (NX * NX)

static int read_option(asp_solver *solver, const char *expected) {
  char text[32];
  int64_t length = -1;
  if (!CHECK_OK(asp_solver_get_option_string(solver, "preconditioner", text, sizeof text,
                                             &length)))
    return 0;
  return CHECK(strcmp(text, expected) == 0) && CHECK(length == (int64_t)strlen(expected));
}

int main(void) {
  static double h[N], plain[N], p[N];
  asp_grid *grid = NULL;
  asp_system *scene = NULL;
  asp_solver *solver = NULL;
  int converged = 0, i;
  int64_t iterations_plain = 0, iterations_fourier = 0;
  double largest = 0.0, difference = 0.0;

  CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / NX, ASP_RMS_SLOPE, 0.1, 3, h,
                                      N));
  CHECK_OK(asp_system_create(grid, 1.0, &scene));
  CHECK_OK(asp_system_set_topography(scene, h, N));
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-10));

  read_option(solver, "auto");
  CHECK_OK(asp_solver_set_option_string(solver, "preconditioner", "none"));
  read_option(solver, "none");
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_iterations(solver, &iterations_plain));
  CHECK_OK(asp_system_get_field(scene, ASP_FIELD_PRESSURE, plain, N));

  CHECK_OK(asp_solver_set_option_string(solver, "preconditioner", "fourier"));
  read_option(solver, "fourier");
  CHECK_ERROR(asp_solver_set_option_string(solver, "preconditioner", "jacobi"),
              ASP_ERR_INVALID_ARGUMENT, "'preconditioner'");
  CHECK_MESSAGE_HAS("fourier");
  CHECK_ERROR(asp_solver_set_option(solver, "preconditioner", 1.0), ASP_ERR_INVALID_ARGUMENT,
              "'preconditioner'");
  read_option(solver, "fourier"); /* a refusal changes nothing */

  CHECK_OK(asp_system_reset(scene));
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged);
  CHECK_OK(asp_solver_iterations(solver, &iterations_fourier));
  CHECK(iterations_fourier < iterations_plain);
  CHECK_OK(asp_system_get_field(scene, ASP_FIELD_PRESSURE, p, N));
  for (i = 0; i < N; ++i) {
    largest = fmax(largest, fabs(plain[i]));
    difference = fmax(difference, fabs(p[i] - plain[i]));
  }
  /* Both states meet the tolerance 1e-10 on the gap residual; their pressures differ by a
   * few pixel stiffnesses times that (test_fourier_preconditioner.cpp), far below 1e-8. */
  CHECK(largest > 0.0 && difference <= 1e-8 * largest);

  asp_solver_destroy(solver);
  asp_system_destroy(scene);
  asp_grid_destroy(grid);
  return check_summary("api.pk_preconditioner");
}
