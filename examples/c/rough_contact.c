/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Presses a self-affine rough surface onto an elastic half-space and prints the contact.
 * Build against an installed asperity with
 *   cc -std=c99 rough_contact.c $(pkg-config --cflags --libs asperity) -o rough_contact */
#include <stdio.h>
#include <stdlib.h>

#include <asperity/asperity.h>

/* Prints the failure and returns non-zero when a call did not succeed. */
static int failed(int status, const char *call) {
  if (status == ASP_OK) return 0;
  fprintf(stderr, "%s: %s: %s\n", call, asp_status_string(status), asp_last_error_message());
  return 1;
}

int main(void) {
  const int64_t n = 128;          /* pixels per side */
  const double length = 1.0;      /* box side */
  const double modulus = 1.0;     /* contact modulus E* */
  const double rms_slope = 0.1;
  const double mean_pressure = 0.002;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double *heights = NULL;
  double fraction = 0.0, penetration = 0.0, error = 0.0, iterations = 0.0, converged = 0.0;
  int status = 1;

  if (failed(asp_grid_create_2d(n, n, length, length, &grid), "asp_grid_create_2d")) goto done;
  heights = malloc((size_t)(n * n) * sizeof *heights);
  if (heights == NULL) goto done;
  /* Hurst 0.8, no roughness longer than the box, roll-off at a quarter of it, short cutoff at
   * 4 pixels, rms slope 0.1, seed 42. */
  if (failed(asp_topography_self_affine(grid, 0.8, length, length / 4, 4 * length / n,
                                        ASP_RMS_SLOPE, rms_slope, 42, heights, n * n),
             "asp_topography_self_affine"))
    goto done;
  if (failed(asp_system_create(grid, modulus, &system), "asp_system_create")) goto done;
  if (failed(asp_system_set_topography(system, heights, n * n), "asp_system_set_topography"))
    goto done;
  if (failed(asp_solver_create("pk", &solver), "asp_solver_create")) goto done;
  if (failed(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, mean_pressure),
             "asp_solver_solve"))
    goto done;

  asp_system_get(system, ASP_CONTACT_FRACTION, &fraction);
  asp_system_get(system, ASP_PENETRATION, &penetration);
  asp_solver_get(solver, ASP_REPORT_ITERATIONS, &iterations); /* counts: exact doubles */
  asp_solver_get(solver, ASP_REPORT_FINAL_ERROR, &error);
  asp_solver_get(solver, ASP_REPORT_CONVERGED, &converged);
  printf("asperity %s\n", asp_version_string());
  printf("contact fraction %.5f at mean pressure %g (kappa = %.3f)\n", fraction, mean_pressure,
         fraction * modulus * rms_slope / mean_pressure);
  printf("penetration %.6g, %.0f iterations, error %.2e, %s\n", penetration, iterations, error,
         converged != 0.0 ? "converged" : "not converged");
  status = converged != 0.0 ? 0 : 1;

done:
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  free(heights);
  asp_grid_destroy(grid);
  return status;
}
