/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A warm solve from a state that is already converged, as a finite-element code makes one at
 * every integration point whose load did not change: it ends after its one evaluation, with
 * no iteration, termination "converged" and an error within the tolerance, and leaves the
 * contact set as it was. For pk, bugnicourt (on the pressure and on the gap, with and without
 * adhesion), lbfgsb (on the pressure and on the gap) and lbfgs_fourier (soft wall), under
 * each control they serve. */
#include <math.h>
#include <stdlib.h>

#include "check.h"

enum { nx = 32, ny = 32, n = nx * ny };

enum interaction { hard_wall, adhesive, soft_wall };

struct warm_case {
  const char *algorithm;
  const char *variable; /* NULL: the algorithm's default */
  enum interaction interaction;
  int control;
  double value;
};

static double heights[n];

/* Solves the case cold, then again from the state it left with the same control and value. */
static void check_warm_solve(const asp_grid *grid, const struct warm_case *c) {
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double first_fraction = -1.0, second_fraction = -2.0, error = 1.0, tolerance = 0.0;
  int64_t iterations = -1, evaluations = -1;
  int termination = 0, converged = 0;

  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, heights, n));
  if (c->interaction == adhesive) CHECK_OK(asp_system_set_adhesion(system, 2e-4, 0.01));
  if (c->interaction == soft_wall)
    CHECK_OK(asp_system_set_soft_wall(system, 1e-2, 2.0 / nx, 1e-4, 2.0 / nx));
  CHECK_OK(asp_solver_create(c->algorithm, &solver));
  if (c->variable != NULL) CHECK_OK(asp_solver_set_option_string(solver, "variable", c->variable));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &tolerance));

  CHECK_OK(asp_solver_solve(solver, system, c->control, c->value));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &first_fraction));

  CHECK_OK(asp_solver_solve(solver, system, c->control, c->value));
  CHECK_OK(asp_solver_termination(solver, &termination));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK_OK(asp_solver_evaluations(solver, &evaluations));
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &second_fraction));
  if (!CHECK(termination == ASP_TERMINATION_CONVERGED && iterations == 0 && evaluations == 1 &&
             error <= tolerance && second_fraction == first_fraction))
    fprintf(stderr,
            "  %s (variable %s, interaction %d, control %d): termination %d, %lld iterations, "
            "%lld evaluations, error %g, contact fraction %g then %g\n",
            c->algorithm, c->variable != NULL ? c->variable : "default", (int)c->interaction,
            c->control, termination, (long long)iterations, (long long)evaluations, error,
            first_fraction, second_fraction);

  asp_solver_destroy(solver);
  asp_system_destroy(system);
}

int main(void) {
  asp_grid *grid = NULL;
  double rms_height = 0.0, rms_slope = 0.0, rms_curvature = 0.0, top = -HUGE_VAL,
         bottom = HUGE_VAL;
  int i;

  CHECK_OK(asp_grid_create_2d(nx, ny, 1.0, 1.0, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / nx, ASP_RMS_SLOPE, 0.1, 5,
                                      heights, n));
  CHECK_OK(asp_topography_statistics(grid, heights, n, &rms_height, &rms_slope, &rms_curvature));
  for (i = 0; i < n; ++i) {
    if (heights[i] > top) top = heights[i];
    if (heights[i] < bottom) bottom = heights[i];
  }
  {
    /* Some contact, from a pixel to a few percent: a mean pressure of 0.005 E*, a
     * penetration of a tenth of the height range, a mean gap of a third of it. */
    const double delta = 0.1 * (top - bottom), pressure = 0.005, gap = (top - bottom) / 3.0;
    const struct warm_case cases[] = {
        {"pk", NULL, hard_wall, ASP_CONTROL_MEAN_PRESSURE, pressure},
        {"pk", NULL, hard_wall, ASP_CONTROL_PENETRATION, delta},
        {"bugnicourt", "pressure", hard_wall, ASP_CONTROL_MEAN_PRESSURE, pressure},
        {"bugnicourt", "pressure", hard_wall, ASP_CONTROL_PENETRATION, delta},
        {"bugnicourt", "gap", hard_wall, ASP_CONTROL_PENETRATION, delta},
        {"bugnicourt", "gap", hard_wall, ASP_CONTROL_MEAN_GAP, gap},
        {"bugnicourt", "gap", adhesive, ASP_CONTROL_PENETRATION, delta},
        {"lbfgsb", "pressure", hard_wall, ASP_CONTROL_PENETRATION, delta},
        {"lbfgsb", "gap", hard_wall, ASP_CONTROL_PENETRATION, delta},
        {"lbfgs_fourier", NULL, soft_wall, ASP_CONTROL_PENETRATION, delta},
    };
    size_t k;
    for (k = 0; k < sizeof cases / sizeof cases[0]; ++k) check_warm_solve(grid, &cases[k]);
  }
  asp_grid_destroy(grid);
  return check_summary("warm_solves");
}
