/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Adhesion through the public header (asp_system_set_adhesion and the ASP_ATTRACTIVE_*,
 * ASP_COMPRESSIVE_FRACTION, ASP_REPULSIVE_FORCE, ASP_INTERACTION_ENERGY, ASP_WORK_OF_ADHESION
 * and ASP_ADHESION_RANGE keys): bad arguments refused by name with nothing changed; solvers without adhesion
 * refusing it with a message naming the interaction and the option; a paraboloid pulled by
 * adhesion solved by "bugnicourt" on the gap, with observables that agree with the fields;
 * and work 0 back to the plain hard wall. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define N 64

int main(void) {
  const double box = 1.0, radius = 1.0, modulus = 1.0, work = 1e-4, range = 2e-3;
  const double pixel_area = box * box / (N * N);
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *pk = NULL, *dual = NULL, *primal = NULL;
  double *heights = malloc(N * N * sizeof(double));
  double *gap = malloc(N * N * sizeof(double));
  double *pressure = malloc(N * N * sizeof(double));
  double value = 0.0, repulsive = 0.0, attractive = 0.0, total = 0.0, energy = 0.0;
  double fraction = 0.0, attractive_fraction = 0.0, compressive_fraction = 0.0, sum = 0.0;
  int converged = 0, i = 0, negative = 0, positive = 0, on_wall = 0, too_tensile = 0;

  CHECK_OK(asp_grid_create_2d(N, N, box, box, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_paraboloid(grid, radius, heights, N * N));
  CHECK_OK(asp_system_create(grid, modulus, &system));
  CHECK_OK(asp_system_set_topography(system, heights, N * N));

  /* ---- bad arguments, each named; the interaction stays the plain hard wall ---- */
  CHECK_ERROR(asp_system_set_adhesion(NULL, work, range), ASP_ERR_NULL_POINTER, "system");
  CHECK_ERROR(asp_system_set_adhesion(system, -work, range), ASP_ERR_INVALID_ARGUMENT,
              "work_of_adhesion");
  CHECK_ERROR(asp_system_set_adhesion(system, NAN, range), ASP_ERR_INVALID_ARGUMENT,
              "work_of_adhesion");
  CHECK_ERROR(asp_system_set_adhesion(system, INFINITY, range), ASP_ERR_INVALID_ARGUMENT,
              "work_of_adhesion");
  CHECK_ERROR(asp_system_set_adhesion(system, work, 0.0), ASP_ERR_INVALID_ARGUMENT, "range");
  CHECK_ERROR(asp_system_set_adhesion(system, work, -range), ASP_ERR_INVALID_ARGUMENT, "range");
  CHECK_ERROR(asp_system_set_adhesion(system, work, INFINITY), ASP_ERR_INVALID_ARGUMENT, "range");
  CHECK_ERROR(asp_system_set_adhesion(system, 0.0, NAN), ASP_ERR_INVALID_ARGUMENT, "range");
  /* w/rho overflows, or is subnormal. */
  CHECK_ERROR(asp_system_set_adhesion(system, 1e300, 1e-300), ASP_ERR_INVALID_ARGUMENT, "w/rho");
  CHECK_MESSAGE_HAS("work_of_adhesion");
  CHECK_ERROR(asp_system_set_adhesion(system, 1e-300, 1e300), ASP_ERR_INVALID_ARGUMENT, "w/rho");
  CHECK_OK(asp_system_get(system, ASP_WORK_OF_ADHESION, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_system_get(system, ASP_ADHESION_RANGE, &value));
  CHECK(value == 0.0);

  /* ---- adhesion set: the keys read it back ---- */
  CHECK_OK(asp_system_set_adhesion(system, work, range));
  CHECK_OK(asp_system_get(system, ASP_WORK_OF_ADHESION, &value));
  CHECK(value == work);
  CHECK_OK(asp_system_get(system, ASP_ADHESION_RANGE, &value));
  CHECK(value == range);

  /* ---- solvers without adhesion refuse it, naming the interaction and the option ---- */
  CHECK_OK(asp_solver_create("pk", &pk));
  CHECK_ERROR(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, 0.0), ASP_ERR_UNSUPPORTED,
              "does not handle an adhesive hard wall");
  CHECK_MESSAGE_HAS("'pk'");
  CHECK_OK(asp_solver_create("bugnicourt", &dual));
  CHECK_ERROR(asp_solver_solve(dual, system, ASP_CONTROL_MEAN_PRESSURE, 0.0),
              ASP_ERR_UNSUPPORTED,
              "with variable = pressure does not handle an adhesive hard wall");
  CHECK_ERROR(asp_solver_solve(dual, system, ASP_CONTROL_PENETRATION, 0.0), ASP_ERR_UNSUPPORTED,
              "variable = pressure");

  /* ---- the paraboloid held at delta = 0, pulled by adhesion, on the gap ---- */
  CHECK_OK(asp_solver_create("bugnicourt", &primal));
  CHECK_OK(asp_solver_set_option_string(primal, "variable", "gap"));
  CHECK_OK(asp_solver_set_tolerance(primal, 1e-9));
  CHECK_OK(asp_solver_solve(primal, system, ASP_CONTROL_PENETRATION, 0.0));
  CHECK_OK(asp_solver_converged(primal, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get(system, ASP_REPULSIVE_FORCE, &repulsive));
  CHECK_OK(asp_system_get(system, ASP_ATTRACTIVE_FORCE, &attractive));
  CHECK_OK(asp_system_get(system, ASP_TOTAL_FORCE, &total));
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &energy));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &fraction));
  CHECK_OK(asp_system_get(system, ASP_ATTRACTIVE_FRACTION, &attractive_fraction));
  CHECK(repulsive > 0.0);
  CHECK(attractive < 0.0);
  CHECK(total < 0.0); /* at delta = 0 adhesion wins: the sphere is pulled */
  CHECK_NEAR(repulsive + attractive, total, 1e-12 * (repulsive - attractive));
  CHECK_OK(asp_system_get(system, ASP_COMPRESSIVE_FRACTION, &compressive_fraction));
  /* The contact (g = 0) holds the compressive core and the tensile ring around it. */
  CHECK(compressive_fraction > 0.0 && compressive_fraction < fraction);
  CHECK(attractive_fraction > 0.0 && compressive_fraction + attractive_fraction <= 1.0);
  /* The observables against the fields: a sum phi(g), the signed sums, the counts. The
   * energy's terms are all negative, so 1e-12 of it bounds the rounding. */
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, gap, N * N));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, N * N));
  sum = 0.0;
  for (i = 0; i < N * N; ++i) {
    sum += -work * exp(-(gap[i] > 0.0 ? gap[i] : 0.0) / range);
    negative += pressure[i] < 0.0;
    positive += pressure[i] > 0.0;
    on_wall += gap[i] == 0.0;
    /* the wall pulls no harder than adhesion can */
    too_tensile += !(pressure[i] >= -work / range * (1 + 1e-12));
  }
  CHECK(too_tensile == 0);
  CHECK_NEAR(energy, pixel_area * sum, 1e-12 * fabs(energy));
  CHECK(energy < 0.0);
  CHECK(fraction == (double)on_wall / (N * N));
  CHECK(compressive_fraction == (double)positive / (N * N));
  CHECK(attractive_fraction == (double)negative / (N * N));

  /* ---- work 0: the plain hard wall again; the state is kept (no longer an equilibrium) ---- */
  CHECK_OK(asp_system_set_adhesion(system, 0.0, range));
  CHECK_OK(asp_system_get(system, ASP_WORK_OF_ADHESION, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_system_get(system, ASP_ATTRACTIVE_FORCE, &value));
  CHECK(value == attractive);
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, 0.01));
  CHECK_OK(asp_system_get(system, ASP_ATTRACTIVE_FRACTION, &value));
  CHECK(value == 0.0);

  asp_solver_destroy(pk);
  asp_solver_destroy(dual);
  asp_solver_destroy(primal);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(heights);
  free(gap);
  free(pressure);
  return check_summary("api.adhesion");
}
