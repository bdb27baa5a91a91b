/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Mean-pressure control with adhesion through the public header: "bugnicourt" and "lbfgsb"
 * on the gap serve it on the free substrate; a tensile load on an adhesive sphere gives the
 * state that penetration control gives at the penetration it reports; a load beyond the
 * pull-off force ends as ASP_TERMINATION_SEPARATED, not converged, with a finite state out of
 * contact; a user's potential is refused under load control, before anything changes. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define N 48

static int pull(int64_t n, const double *gap, double *phi, double *dphi, double *d2phi,
                void *user_data) {
  int64_t i;
  (void)user_data;
  for (i = 0; i < n; ++i) {
    phi[i] = -1e-4 * exp(-gap[i] / 1e-3);
    dphi[i] = -phi[i] / 1e-3;
    if (d2phi != NULL) d2phi[i] = phi[i] / 1e-6;
  }
  return 0;
}

/* An adhesive paraboloid (E* = R = 1, w = 2e-4, Tabor parameter 3) on a free box of N
 * pixels, its JKR pull-off radius 14 pixels, brought into contact under penetration control. */
static asp_system *sphere(asp_grid *grid, const double *heights, asp_solver *solver) {
  asp_system *system = NULL;
  const double work = 2e-4, range = cbrt(work * work) / 3.0;
  CHECK_OK(asp_system_create_free(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, heights, N * N));
  CHECK_OK(asp_system_set_adhesion(system, work, range));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.002));
  return system;
}

int main(void) {
  const double pi = 3.14159265358979323846, work = 2e-4;
  const double box = N * cbrt(9 * pi * work / 8) / 14.0, area = box * box;
  const double unit = pi * work / area; /* mean pressure of the force pi w R */
  const char *names[2] = {"bugnicourt", "lbfgsb"};
  asp_grid *grid = NULL;
  double *heights = malloc(N * N * sizeof(double));
  double *a = malloc(N * N * sizeof(double));
  double *b = malloc(N * N * sizeof(double));
  int s, i;

  CHECK_OK(asp_grid_create_2d(N, N, box, box, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_paraboloid(grid, 1.0, heights, N * N));

  for (s = 0; s < 2; ++s) {
    asp_solver *solver = NULL;
    asp_system *by_load = NULL, *by_penetration = NULL;
    double penetration = 0.0, value = 0.0, largest = 0.0, difference = 0.0;
    int reason = 0, converged = 1;
    CHECK_OK(asp_solver_create(names[s], &solver));
    CHECK_OK(asp_solver_set_option_string(solver, "variable", "gap"));
    CHECK_OK(asp_solver_set_tolerance(solver, 1e-9));
    by_load = sphere(grid, heights, solver);
    by_penetration = sphere(grid, heights, solver);
    CHECK_OK(asp_solver_supports(solver, by_load, ASP_CONTROL_MEAN_PRESSURE));

    /* A tensile load within the pull-off force (JKR's -1.5 pi w R): a stable state, the one
     * penetration control gives at its penetration (to what the tolerance 1e-9 leaves:
     * measured 1e-8 of the largest pressure). */
    CHECK_OK(asp_solver_solve(solver, by_load, ASP_CONTROL_MEAN_PRESSURE, -unit));
    CHECK_OK(asp_solver_converged(solver, &converged));
    CHECK(converged == 1);
    CHECK_OK(asp_system_get(by_load, ASP_MEAN_PRESSURE, &value));
    CHECK(fabs(value + unit) <= 1e-6 * unit);
    CHECK_OK(asp_system_get(by_load, ASP_PENETRATION, &penetration));
    CHECK_OK(asp_solver_solve(solver, by_penetration, ASP_CONTROL_PENETRATION, penetration));
    CHECK_OK(asp_system_get(by_penetration, ASP_MEAN_PRESSURE, &value));
    CHECK(fabs(value + unit) <= 1e-6 * unit);
    CHECK_OK(asp_system_get_field(by_load, ASP_FIELD_PRESSURE, a, N * N));
    CHECK_OK(asp_system_get_field(by_penetration, ASP_FIELD_PRESSURE, b, N * N));
    for (i = 0; i < N * N; ++i) {
      largest = fmax(largest, fabs(a[i]));
      difference = fmax(difference, fabs(a[i] - b[i]));
    }
    CHECK(difference <= 1e-6 * largest);

    /* Twice JKR's pull-off force: no stable state; the surfaces separate. */
    CHECK_OK(asp_solver_solve(solver, by_load, ASP_CONTROL_MEAN_PRESSURE, -3.0 * unit));
    CHECK_OK(asp_solver_termination(solver, &reason));
    CHECK(reason == ASP_TERMINATION_SEPARATED);
    CHECK_OK(asp_solver_converged(solver, &converged));
    CHECK(converged == 0);
    CHECK_OK(asp_system_get(by_load, ASP_CONTACT_FRACTION, &value));
    CHECK(value == 0.0);
    CHECK_OK(asp_system_get(by_load, ASP_PENETRATION, &value));
    CHECK(isfinite(value));
    CHECK_OK(asp_system_get_field(by_load, ASP_FIELD_GAP, a, N * N));
    for (i = 0; i < N * N; ++i) CHECK(isfinite(a[i]) && a[i] >= 0.0);

    /* A user's potential with the hard wall: lbfgsb takes it under penetration control, not
     * under load control (the separation could not be told); refused before anything
     * changes. */
    if (s == 1) {
      CHECK_OK(asp_system_set_potential(by_penetration, pull, NULL, 1));
      CHECK_OK(asp_solver_supports(solver, by_penetration, ASP_CONTROL_PENETRATION));
      CHECK_ERROR(asp_solver_supports(solver, by_penetration, ASP_CONTROL_MEAN_PRESSURE),
                  ASP_ERR_UNSUPPORTED, "mean_pressure");
      CHECK_MESSAGE_HAS("user potential with hard wall");
      CHECK_ERROR(asp_solver_solve(solver, by_penetration, ASP_CONTROL_MEAN_PRESSURE, -unit),
                  ASP_ERR_UNSUPPORTED, "mean_pressure");
      CHECK_OK(asp_system_get_field(by_penetration, ASP_FIELD_PRESSURE, a, N * N));
      for (i = 0; i < N * N && a[i] == b[i]; ++i) {
      }
      CHECK(i == N * N);
    }
    asp_system_destroy(by_load);
    asp_system_destroy(by_penetration);
    asp_solver_destroy(solver);
  }
  asp_grid_destroy(grid);
  free(heights);
  free(a);
  free(b);
  return check_summary("api.load_control");
}
