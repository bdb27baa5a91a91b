/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Which solver is fastest on my scene? An adhesive rough surface against a soft wall, solved
 * by every unconstrained solver with its history recorded, and for each the time and the
 * iterations it took to bring the error (the largest force-balance residual over the
 * reference pressure) below 1e-4 and 1e-8.
 * Build against an installed asperity with
 *   cc -std=c99 soft_wall_solvers.c $(pkg-config --cflags --libs asperity) -o soft_wall_solvers */
#include <stdio.h>
#include <stdlib.h>

#include <asperity/asperity.h>

/* Prints the failure and returns non-zero when a call did not succeed. */
static int failed(int status, const char *call) {
  if (status == ASP_OK) return 0;
  fprintf(stderr, "%s: %s: %s\n", call, asp_status_string(status), asp_last_error_message());
  return 1;
}

/* The first row of the history whose error is at most `target`, or -1. */
static int64_t first_below(const double *errors, int64_t rows, double target) {
  int64_t k;
  for (k = 0; k < rows; ++k)
    if (errors[k] <= target) return k;
  return -1;
}

static void print_reached(const double *errors, const double *seconds, int64_t rows,
                          double target) {
  const int64_t k = first_below(errors, rows, target);
  if (k < 0)
    printf("  %20s", "-");
  else
    printf("  %7lld it %8.4f s", (long long)k, seconds[k]);
}

int main(void) {
  const char *const solvers[] = {"lbfgs_fourier", "lbfgs", "fire_mass_weighted", "fire",
                                 "gfmd"};
  const int64_t n = 128;      /* pixels per side, each of unit length */
  const double rms_slope = 0.1;
  /* The soft wall gamma_r exp(-2g/rho) - gamma_a exp(-g/rho): its well, at
   * rho ln(2 gamma_r/gamma_a) = 0.69, is 2e-3 deep (the work of adhesion). */
  const double gamma_r = 0.05, gamma_a = 0.02, rho = 0.3;
  const double mean_pressure = 3e-4;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  double *heights = NULL, *errors = NULL, *seconds = NULL;
  int status = 1, reference_converged = 0;
  size_t k;

  if (failed(asp_grid_create_2d(n, n, (double)n, (double)n, &grid), "asp_grid_create_2d"))
    goto done;
  heights = malloc((size_t)(n * n) * sizeof *heights);
  if (heights == NULL) goto done;
  if (failed(asp_topography_self_affine(grid, 0.8, (double)n, n / 2.0, 2.0, ASP_RMS_SLOPE,
                                        rms_slope, 5, heights, n * n),
             "asp_topography_self_affine"))
    goto done;
  /* The statistics transform the heights: the grid's FFT plans, made on first use (with
   * FFTW_MEASURE), are made here rather than inside the first solver's timed solve. */
  {
    double rms_height = 0.0, slope = 0.0, curvature = 0.0;
    if (failed(asp_topography_statistics(grid, heights, n * n, &rms_height, &slope, &curvature),
               "asp_topography_statistics"))
      goto done;
    printf("%lld x %lld pixels, rms height %.3f, rms slope %.3f; mean pressure %g\n",
           (long long)n, (long long)n, rms_height, slope, mean_pressure);
  }
  if (failed(asp_system_create(grid, 1.0, &system), "asp_system_create")) goto done;
  if (failed(asp_system_set_topography(system, heights, n * n), "asp_system_set_topography"))
    goto done;
  if (failed(asp_system_set_soft_wall(system, gamma_r, rho, gamma_a, rho),
             "asp_system_set_soft_wall"))
    goto done;

  printf("%-20s %8s %10s %6s %22s %22s\n", "solver", "contact", "end", "evals", "error 1e-4",
         "error 1e-8");
  for (k = 0; k < sizeof solvers / sizeof *solvers; ++k) {
    asp_solver *solver = NULL;
    int64_t rows = 0, evaluations = 0;
    int reason = 0, converged = 0;
    double contact = 0.0;
    if (failed(asp_solver_create(solvers[k], &solver), "asp_solver_create")) goto done;
    asp_solver_set_tolerance(solver, 1e-8);
    asp_solver_set_history(solver, 1);
    asp_system_reset(system); /* every solver from the same cold start */
    if (failed(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure),
               "asp_solver_solve")) {
      asp_solver_destroy(solver);
      goto done;
    }
    asp_solver_termination(solver, &reason);
    asp_solver_converged(solver, &converged);
    asp_solver_evaluations(solver, &evaluations);
    asp_system_get(system, ASP_CONTACT_FRACTION, &contact);
    asp_solver_history_length(solver, &rows);
    errors = realloc(errors, (size_t)rows * sizeof *errors);
    seconds = realloc(seconds, (size_t)rows * sizeof *seconds);
    if (rows > 0 && (errors == NULL || seconds == NULL)) {
      asp_solver_destroy(solver);
      goto done;
    }
    asp_solver_get_history(solver, ASP_HISTORY_ERROR, errors, rows);
    asp_solver_get_history(solver, ASP_HISTORY_SECONDS, seconds, rows);
    printf("%-20s %8.4f %10s %6lld", solvers[k], contact, converged ? "converged" : "stopped",
           (long long)evaluations);
    print_reached(errors, seconds, rows, 1e-4);
    print_reached(errors, seconds, rows, 1e-8);
    printf("\n");
    if (k == 0) reference_converged = converged;
    asp_solver_destroy(solver);
  }
  status = reference_converged ? 0 : 1;

done:
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(heights);
  free(errors);
  free(seconds);
  return status;
}
