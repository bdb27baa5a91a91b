/* SPDX-License-Identifier: GPL-2.0-or-later */
/* lbfgsb through the C API: its options ("memory", "variable") with their defaults, ranges
 * and refusals; the controls it refuses on each variable, with messages naming them; and a
 * solve with a small memory on either variable that converges with the pressure >= 0. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "check.h"

enum { nx = 32, ny = 24, n = nx * ny };

int main(void) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  static double h[n], p[n];
  double memory = 0, penetration = 0;
  char text[64];
  const char *variables[2] = {"pressure", "gap"};
  int v;

  CHECK_OK(asp_grid_create_2d(nx, ny, 1.0, 1.0 * ny / nx, &grid));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 1.0, 0.25, 4.0 / nx, ASP_RMS_SLOPE, 0.1, 5,
                                      h, n));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, h, n));
  CHECK_OK(asp_solver_create("lbfgsb", &solver));

  /* Defaults: 5 pairs, on the pressure. */
  CHECK_OK(asp_solver_get_option(solver, "memory", &memory));
  CHECK(memory == 5);
  CHECK_OK(asp_solver_get_option_string(solver, "variable", text, sizeof text, NULL));
  CHECK(strcmp(text, "pressure") == 0);

  /* The memory is a whole number in [1, 100]; a refusal names the option and the range,
   * and leaves the value as it was. */
  CHECK_ERROR(asp_solver_set_option(solver, "memory", 0), ASP_ERR_INVALID_ARGUMENT,
              "'memory'");
  CHECK_MESSAGE_HAS("[1, 100]");
  CHECK_ERROR(asp_solver_set_option(solver, "memory", 101), ASP_ERR_INVALID_ARGUMENT,
              "'memory'");
  CHECK_ERROR(asp_solver_set_option(solver, "memory", 2.5), ASP_ERR_INVALID_ARGUMENT,
              "whole number");
  CHECK_ERROR(asp_solver_set_option(solver, "memory", NAN), ASP_ERR_INVALID_ARGUMENT,
              "'memory'");
  CHECK_ERROR(asp_solver_set_option_string(solver, "memory", "5"), ASP_ERR_INVALID_ARGUMENT,
              "takes a number");
  CHECK_ERROR(asp_solver_set_option_string(solver, "variable", "displacement"),
              ASP_ERR_INVALID_ARGUMENT, "pressure, gap");
  CHECK_OK(asp_solver_get_option(solver, "memory", &memory));
  CHECK(memory == 5);
  CHECK_OK(asp_solver_set_option(solver, "memory", 3));
  CHECK_OK(asp_solver_get_option(solver, "memory", &memory));
  CHECK(memory == 3);
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-10));

  /* A penetration that gives partial contact: that of pk's solution at a light load. */
  {
    asp_solver *pk = NULL;
    CHECK_OK(asp_solver_create("pk", &pk));
    CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
    CHECK_OK(asp_system_get(system, ASP_PENETRATION, &penetration));
    asp_solver_destroy(pk);
  }

  for (v = 0; v < 2; ++v) {
    int converged = 0, i;
    double smallest = 1.0;
    CHECK_OK(asp_solver_set_option_string(solver, "variable", variables[v]));
    /* L-BFGS-B keeps bounds, not a mean: mean-gap control is refused on either variable,
     * and mean-pressure control on the pressure, naming the control and the variable, before
     * anything changes (on the gap the load is a work term, no constraint). */
    if (v == 0) {
      CHECK_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
                  ASP_ERR_UNSUPPORTED, "mean_pressure");
      CHECK_MESSAGE_HAS("variable = pressure");
    } else {
      CHECK_OK(asp_solver_supports(solver, system, ASP_CONTROL_MEAN_PRESSURE));
    }
    CHECK_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_GAP, 0.01),
                ASP_ERR_UNSUPPORTED, "mean_gap");
    CHECK_MESSAGE_HAS(v == 0 ? "variable = pressure" : "variable = gap");
    CHECK_MESSAGE_HAS(v == 0 ? "it offers: penetration" : "it offers: penetration, mean_pressure");

    CHECK_OK(asp_system_reset(system));
    CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, penetration));
    CHECK_OK(asp_solver_converged(solver, &converged));
    CHECK(converged == 1);
    CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n));
    for (i = 0; i < n; ++i) smallest = fmin(smallest, p[i]);
    CHECK(smallest >= 0.0);
  }

  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  return check_summary("api.lbfgsb");
}
