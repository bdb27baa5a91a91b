/* The asperity command: solves a built-in rough-contact scene and prints the results.
 * It uses only the public C interface, like any other program that links the library. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"

struct scene {
  int64_t n;           /* pixels per side */
  double length;       /* box side */
  double modulus;      /* E* */
  double hurst;
  double rms_slope;
  double mean_pressure;
  double tolerance;
  int64_t seed;
};

static void usage(FILE *out) {
  fprintf(out,
          "usage: asperity [--size N] [--seed S] [--mean-pressure P] [--tolerance T]\n"
          "\n"
          "Solves the built-in scene: a periodic self-affine surface (Hurst 0.8, rms slope 0.1,\n"
          "roll-off at a quarter of the box, short cutoff at 8 pixels) pressed on an elastic\n"
          "half-space (E* = 1, box 1 x 1) at mean pressure 0.002 with the Polonsky-Keer solver.\n"
          "  --size N           grid of N x N pixels (default 512)\n"
          "  --seed S           seed of the random surface (default 1)\n"
          "  --mean-pressure P  mean pressure, in units of E* (default 0.002)\n"
          "  --tolerance T      stopping tolerance on the error (default 1e-8)\n");
}

static int check(int status, const char *what) {
  if (status != ASP_OK)
    fprintf(stderr, "asperity: %s failed: %s (%s)\n", what, asp_status_string(status),
            asp_last_error_message());
  return status;
}

static int parse(int argc, char **argv, struct scene *s) {
  int i;
  for (i = 1; i < argc; ++i) {
    const char *key = argv[i];
    char *end = NULL;
    if (strcmp(key, "--help") == 0 || strcmp(key, "-h") == 0) {
      usage(stdout);
      exit(0);
    }
    if (i + 1 >= argc) {
      fprintf(stderr, "asperity: option %s needs a value\n", key);
      return 1;
    }
    ++i;
    if (strcmp(key, "--size") == 0) {
      s->n = strtoll(argv[i], &end, 10);
    } else if (strcmp(key, "--seed") == 0) {
      s->seed = strtoll(argv[i], &end, 10);
    } else if (strcmp(key, "--mean-pressure") == 0) {
      s->mean_pressure = strtod(argv[i], &end);
    } else if (strcmp(key, "--tolerance") == 0) {
      s->tolerance = strtod(argv[i], &end);
    } else {
      fprintf(stderr, "asperity: unknown option %s\n", key);
      usage(stderr);
      return 1;
    }
    if (end == NULL || *end != '\0') {
      fprintf(stderr, "asperity: option %s: cannot read '%s'\n", key, argv[i]);
      return 1;
    }
  }
  return 0;
}

int main(int argc, char **argv) {
  struct scene s = {512, 1.0, 1.0, 0.8, 0.1, 0.002, 1e-8, 1};
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double *heights = NULL;
  double fraction = 0, pressure = 0, penetration = 0, error = 0, seconds = 0;
  int64_t n_pixels = 0, iterations = 0;
  int converged = 0, status = 1;

  if (parse(argc, argv, &s) != 0) return 2;

  if (check(asp_grid_create_2d(s.n, s.n, s.length, s.length, &grid), "creating the grid"))
    goto done;
  asp_grid_get_shape(grid, NULL, NULL, NULL, &n_pixels);
  heights = malloc((size_t)n_pixels * sizeof *heights);
  if (heights == NULL) {
    fprintf(stderr, "asperity: out of memory\n");
    goto done;
  }
  if (check(asp_topography_self_affine(grid, s.hurst, s.length, s.length / 4,
                                       8 * s.length / (double)s.n, ASP_RMS_SLOPE, s.rms_slope,
                                       s.seed, heights, n_pixels),
            "making the surface"))
    goto done;
  if (check(asp_system_create(grid, s.modulus, &system), "creating the system")) goto done;
  if (check(asp_system_set_topography(system, heights, n_pixels), "setting the surface"))
    goto done;
  if (check(asp_solver_create("pk", &solver), "creating the solver")) goto done;
  if (check(asp_solver_set_tolerance(solver, s.tolerance), "setting the tolerance")) goto done;
  if (check(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, s.mean_pressure),
            "solving"))
    goto done;

  asp_system_get(system, ASP_CONTACT_FRACTION, &fraction);
  asp_system_get(system, ASP_MEAN_PRESSURE, &pressure);
  asp_system_get(system, ASP_PENETRATION, &penetration);
  asp_solver_iterations(solver, &iterations);
  asp_solver_final_error(solver, &error);
  asp_solver_converged(solver, &converged);
  asp_solver_elapsed_seconds(solver, &seconds);

  printf("asperity %s: Polonsky-Keer on a %lld x %lld self-affine surface (seed %lld)\n",
         asp_version_string(), (long long)s.n, (long long)s.n, (long long)s.seed);
  printf("contact fraction  %.6f\n", fraction);
  printf("mean pressure     %.6g\n", pressure);
  printf("penetration       %.6g\n", penetration);
  printf("iterations        %lld\n", (long long)iterations);
  printf("error             %.3e (tolerance %.1e, %s)\n", error, s.tolerance,
         converged ? "converged" : "NOT converged");
  printf("time              %.3f s\n", seconds);
  status = converged ? 0 : 3;

done:
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  free(heights);
  asp_grid_destroy(grid);
  return status;
}
