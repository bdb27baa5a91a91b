/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asp_solver_normal_stiffness through the public header: NULL arguments refused by name; a
 * state that is not the converged result of the solver's last solve (no solve, a solve that
 * did not converge, another system, a system changed since by any of its setters, a refused
 * solve) refused with
 * ASP_ERR_INVALID_STATE and the report left as it was; the stiffness of a rough hard-wall
 * contact and of a user's potential against central differences of solves at delta +- h;
 * and a failing potential callback reported as ASP_ERR_CALLBACK. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define N 32

/* A repulsive exponential, phi = gamma exp(-g/rho), given as a user's potential. */
typedef struct {
  double gamma, rho;
  int fail;  /* non-zero: return an error */
} exponential;

static int exponential_potential(int64_t n, const double *gap, double *phi, double *dphi,
                                 double *d2phi, void *user_data) {
  const exponential *e = (const exponential *)user_data;
  int64_t i;
  if (e->fail) return 1;
  for (i = 0; i < n; ++i) {
    const double v = e->gamma * exp(-gap[i] / e->rho);
    phi[i] = v;
    dphi[i] = -v / e->rho;
    if (d2phi != NULL) d2phi[i] = v / (e->rho * e->rho);
  }
  return 0;
}

/* Mean pressure after a converged solve at delta. */
static double solved_mean_pressure(asp_solver *solver, asp_system *system, double delta) {
  double p = 0.0;
  int converged = 0;
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, delta));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &p));
  return p;
}

int main(void) {
  const double box = 1.0, modulus = 1.0;
  asp_grid *grid = NULL;
  asp_system *system = NULL, *other = NULL;
  asp_solver *pk = NULL, *lbfgs = NULL;
  double *heights = malloc(N * N * sizeof(double));
  double k = 0.0, again = 0.0, range = 0.0, delta = 0.0, h = 0.0, up = 0.0, down = 0.0;
  double error = 0.0, error_after = 0.0;
  double top = -HUGE_VAL, bottom = HUGE_VAL;
  int converged = 0, i = 0;
  exponential wall = {0.0, 0.0, 0};

  CHECK_OK(asp_grid_create_2d(N, N, box, box, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, box, 0.25 * box, 4.0 * box / N,
                                      ASP_RMS_SLOPE, 0.1, 3, heights, N * N));
  CHECK_OK(asp_system_create(grid, modulus, &system));
  CHECK_OK(asp_system_set_topography(system, heights, N * N));
  CHECK_OK(asp_system_create(grid, modulus, &other));
  CHECK_OK(asp_system_set_topography(other, heights, N * N));
  for (i = 0; i < N * N; ++i) {
    top = heights[i] > top ? heights[i] : top;
    bottom = heights[i] < bottom ? heights[i] : bottom;
  }
  range = top - bottom;
  CHECK_OK(asp_solver_create("pk", &pk));
  CHECK_OK(asp_solver_set_tolerance(pk, 1e-13));

  /* ---- NULL arguments, each named ---- */
  CHECK_ERROR(asp_solver_normal_stiffness(NULL, system, &k), ASP_ERR_NULL_POINTER, "solver");
  CHECK_ERROR(asp_solver_normal_stiffness(pk, NULL, &k), ASP_ERR_NULL_POINTER, "system");
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, NULL), ASP_ERR_NULL_POINTER, "stiffness");

  /* ---- no solve yet ---- */
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &k), ASP_ERR_INVALID_STATE, "no solve");

  /* ---- a solve that did not converge ---- */
  delta = 0.3 * range;
  CHECK_OK(asp_solver_set_max_iterations(pk, 1));
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, delta));
  CHECK_OK(asp_solver_converged(pk, &converged));
  CHECK(converged == 0);
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &k), ASP_ERR_INVALID_STATE,
              "did not converge");
  CHECK_OK(asp_solver_set_max_iterations(pk, 100000));

  /* ---- against central differences: the contact set is held for h = 1e-7 delta, where the
   * solves' error (1e-13 of the reference pressure) makes 1e-6 of the difference at most ---- */
  k = 0.0;
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_solver_final_error(pk, &error));
  CHECK_OK(asp_solver_normal_stiffness(pk, system, &k));
  CHECK(k > 0.0);
  /* Asking again gives the same, and leaves the report as it was. */
  CHECK_OK(asp_solver_normal_stiffness(pk, system, &again));
  CHECK(again == k);
  CHECK_OK(asp_solver_final_error(pk, &error_after));
  CHECK(error_after == error);

  /* ---- another system, or this one changed since the solve ---- */
  CHECK_ERROR(asp_solver_normal_stiffness(pk, other, &again), ASP_ERR_INVALID_STATE,
              "not the state the solver's last solve left");
  CHECK_OK(asp_system_set_k0(system, 2.0));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_system_set_reference_pressure(system, 0.5));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  CHECK_OK(asp_system_set_reference_pressure(system, 0.0));
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_system_reset(system));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  /* Every other change: the topography (even the same heights), the interaction (even the
   * same one again). */
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_system_set_topography(system, heights, N * N));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_system_set_hard_wall(system));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_system_set_adhesion(system, 0.0, 1.0));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_system_set_soft_wall(system, 1e-3, 1e-3, 0.0, 1e-3));
  CHECK_OK(asp_system_set_hard_wall(system));
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE,
              "changed since");
  /* A solve that was refused leaves no solve to take the stiffness of. */
  solved_mean_pressure(pk, system, delta);
  CHECK_ERROR(asp_solver_solve(pk, system, ASP_CONTROL_MEAN_GAP, 0.1), ASP_ERR_UNSUPPORTED, NULL);
  CHECK_ERROR(asp_solver_normal_stiffness(pk, system, &again), ASP_ERR_INVALID_STATE, "no solve");

  /* The central difference, each solve warm-started from the last. */
  solved_mean_pressure(pk, system, delta);
  CHECK_OK(asp_solver_normal_stiffness(pk, system, &k));
  h = 1e-7 * delta;
  up = solved_mean_pressure(pk, system, delta + h);
  down = solved_mean_pressure(pk, system, delta - h);
  printf("hard wall: stiffness %.10g, central difference %.10g\n", k, (up - down) / (2 * h));
  CHECK(fabs(k - (up - down) / (2 * h)) <= 1e-5 * k);

  /* ---- a user's potential without the wall, solved by "lbfgs": phi'' from the callback ---- */
  wall.rho = 0.02 * range;
  wall.gamma = 1e-3 * wall.rho;
  CHECK_OK(asp_system_set_potential(system, exponential_potential, &wall, 0));
  CHECK_OK(asp_solver_create("lbfgs", &lbfgs));
  CHECK_OK(asp_solver_set_tolerance(lbfgs, 1e-12));
  CHECK_OK(asp_solver_set_max_iterations(lbfgs, 100000));
  solved_mean_pressure(lbfgs, system, delta);
  CHECK_OK(asp_solver_normal_stiffness(lbfgs, system, &k));
  /* The callback failing now fails the stiffness, and nothing else changes. */
  wall.fail = 1;
  CHECK_ERROR(asp_solver_normal_stiffness(lbfgs, system, &again), ASP_ERR_CALLBACK, NULL);
  wall.fail = 0;
  CHECK_OK(asp_solver_normal_stiffness(lbfgs, system, &again));
  CHECK(again == k);
  /* The pressure is smooth in delta: the truncation error (h^2/6) p''' is of order (h/rho)^2
   * of the stiffness, 1e-10 at h = 1e-5 rho. */
  h = 1e-5 * wall.rho;
  up = solved_mean_pressure(lbfgs, system, delta + h);
  down = solved_mean_pressure(lbfgs, system, delta - h);
  printf("user potential: stiffness %.10g, central difference %.10g\n", k,
         (up - down) / (2 * h));
  CHECK(fabs(k - (up - down) / (2 * h)) <= 1e-5 * k);

  asp_solver_destroy(lbfgs);
  asp_solver_destroy(pk);
  asp_system_destroy(other);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(heights);
  return check_summary("api.normal_stiffness");
}
