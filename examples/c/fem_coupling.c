/* SPDX-License-Identifier: GPL-2.0-or-later */
/* A rough adhesive contact in series with an elastic spring, as a finite-element code couples
 * it: a spring of stiffness k (force per length) pulled at its far end to the displacement D
 * presses the rough surface onto the half-space with the penetration delta, and equilibrium is
 *   R(delta) = k (D - delta) - F(delta) = 0,   F = A pbar, the contact force.
 * Each load step solves it by Newton's method on delta, with the consistent tangent
 *   dR/d(delta) = -k - A d(pbar)/d(delta)
 * from asp_solver_normal_stiffness, each contact solve warm-started from the last. The
 * residual of every Newton step is printed: it falls quadratically. One step is done again
 * with a finite-difference tangent (two more solves per Newton step) to compare.
 * Exits non-zero if a solve does not converge or Newton needs more than 6 steps
 * (it takes 3).
 * Build against an installed asperity with
 *   cc -std=c99 fem_coupling.c $(pkg-config --cflags --libs asperity) -lm -o fem_coupling */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <asperity/asperity.h>

#define MAX_NEWTON 6

/* Prints the failure and returns non-zero when a call did not succeed. */
static int failed(int status, const char *call) {
  if (status == ASP_OK) return 0;
  fprintf(stderr, "%s: %s: %s\n", call, asp_status_string(status), asp_last_error_message());
  return 1;
}

/* The contact force F at delta (a warm-started solve) and, if tangent is not NULL, the
 * tangent A d(pbar)/d(delta). Returns non-zero on a failure or a solve that did not converge. */
static int contact(asp_solver *solver, asp_system *system, double area, double delta,
                   double *force, double *tangent) {
  double pbar = 0.0, stiffness = 0.0;
  int converged = 0;
  if (failed(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, delta), "asp_solver_solve"))
    return 1;
  asp_solver_converged(solver, &converged);
  if (!converged) {
    fprintf(stderr, "the contact solve at delta = %g did not converge\n", delta);
    return 1;
  }
  asp_system_get(system, ASP_MEAN_PRESSURE, &pbar);
  *force = area * pbar;
  if (tangent != NULL) {
    if (failed(asp_solver_normal_stiffness(solver, system, &stiffness),
               "asp_solver_normal_stiffness"))
      return 1;
    *tangent = area * stiffness;
  }
  return 0;
}

/* Newton's method on delta for the spring pulled to D, from *delta; finite_difference: the
 * tangent from central differences of two more solves at delta +- h instead. Prints the
 * residual of each step and returns the steps taken, or -1 on a failure or no convergence.
 * *solves counts the contact solves. */
static int newton(asp_solver *solver, asp_system *system, double area, double spring, double d,
                  double tolerance, int finite_difference, double h, double *delta,
                  int *solves) {
  int step;
  for (step = 0; step <= MAX_NEWTON; ++step) {
    double force = 0.0, tangent = 0.0, residual = 0.0;
    if (finite_difference) {
      double up = 0.0, down = 0.0;
      if (contact(solver, system, area, *delta + h, &up, NULL) ||
          contact(solver, system, area, *delta - h, &down, NULL))
        return -1;
      tangent = (up - down) / (2 * h);
      *solves += 2;
    }
    if (contact(solver, system, area, *delta, &force, finite_difference ? NULL : &tangent))
      return -1;
    *solves += 1;
    residual = spring * (d - *delta) - force;
    printf("    Newton step %d: delta %.12f  residual %.3e\n", step, *delta, residual);
    if (fabs(residual) <= tolerance) return step;
    *delta -= residual / (-spring - tangent);
  }
  fprintf(stderr, "Newton did not converge in %d steps\n", MAX_NEWTON);
  return -1;
}

int main(void) {
  const int64_t n = 64;          /* pixels per side */
  const double length = 1.0;     /* box side */
  const double modulus = 1.0;    /* contact modulus E* */
  const double work = 1e-5;      /* work of adhesion w */
  const double range = 2e-3;     /* its range rho */
  const double spring = 0.05;    /* k, force per length: of the order of the contact's */
  const double area = length * length;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double *heights = NULL;
  double top = -HUGE_VAL, bottom = HUGE_VAL, delta = 0.0, d = 0.0, tolerance = 0.0;
  double saved = 0.0;
  int64_t i = 0;
  int step = 0, steps = 0, solves = 0, status = 1;

  if (failed(asp_grid_create_2d(n, n, length, length, &grid), "asp_grid_create_2d")) goto done;
  heights = malloc((size_t)(n * n) * sizeof *heights);
  if (heights == NULL) goto done;
  if (failed(asp_topography_self_affine(grid, 0.8, length, length / 4, 4 * length / n,
                                        ASP_RMS_SLOPE, 0.1, 42, heights, n * n),
             "asp_topography_self_affine"))
    goto done;
  for (i = 0; i < n * n; ++i) {
    top = heights[i] > top ? heights[i] : top;
    bottom = heights[i] < bottom ? heights[i] : bottom;
  }
  if (failed(asp_system_create(grid, modulus, &system), "asp_system_create") ||
      failed(asp_system_set_topography(system, heights, n * n), "asp_system_set_topography") ||
      failed(asp_system_set_adhesion(system, work, range), "asp_system_set_adhesion") ||
      failed(asp_solver_create("bugnicourt", &solver), "asp_solver_create") ||
      failed(asp_solver_set_option_string(solver, "variable", "gap"), "variable = gap") ||
      failed(asp_solver_set_tolerance(solver, 1e-12), "asp_solver_set_tolerance"))
    goto done;

  /* The residual is met to 1e-9 of the largest spring force, far below what a finite-element
   * code needs and well above the contact solves' own error. */
  tolerance = 1e-9 * spring * (top - bottom);
  printf("spring k = %g in series with a rough adhesive contact (%lldx%lld, w = %g, rho = %g)\n",
         spring, (long long)n, (long long)n, work, range);
  for (step = 1; step <= 5; ++step) {
    d = 0.15 * step * (top - bottom);
    printf("load step %d: D = %.6f\n", step, d);
    /* Each step starts from the last one's delta; the first from D, as if the contact were
     * rigid (at delta = 0 only the top pixel touches, and adhesion makes F fall with delta
     * there: a poor place to start Newton). */
    if (step == 1) delta = d;
    saved = delta;
    steps = newton(solver, system, area, spring, d, tolerance, 0, 0.0, &delta, &solves);
    if (steps < 0) goto done;
    printf("  consistent tangent: %d Newton steps, %d contact solves\n", steps, solves);
    if (step == 3) {
      /* The same step with a finite-difference tangent, from the same start: h small enough
       * that the contact set rarely changes within it, large enough for the solves' error. */
      const double converged_delta = delta;
      int fd_solves = 0;
      delta = saved;
      printf("  the same with a finite-difference tangent (h = 1e-6 of the height range):\n");
      steps = newton(solver, system, area, spring, d, tolerance, 1, 1e-6 * (top - bottom), &delta,
                     &fd_solves);
      if (steps < 0) goto done;
      printf("  finite-difference tangent: %d Newton steps, %d contact solves\n", steps,
             fd_solves);
      if (fabs(delta - converged_delta) > 1e-8 * (top - bottom)) {
        fprintf(stderr, "the two tangents found different equilibria\n");
        goto done;
      }
    }
    solves = 0;
  }
  status = 0;

done:
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  free(heights);
  asp_grid_destroy(grid);
  return status;
}
