/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Soft potentials through the public header (asp_system_set_soft_wall,
 * asp_system_set_lennard_jones, asp_system_set_hard_wall, asp_system_set_potential): NULL
 * handles and callbacks, bad values refused by name with the handle still usable; the
 * interaction energy of each against a sum of phi over the gap field; a C callback that fails
 * (non-zero return, NaN) reported as ASP_ERR_CALLBACK; the constrained solvers "pk",
 * "bugnicourt" and "lbfgsb" refusing soft walls with a message naming the solver and the
 * interaction; a user's potential with the hard wall solved by "lbfgsb" on the gap, the
 * exponential adhesion as a callback giving the built-in adhesion's solution; and the hard
 * wall back, under which "pk" solves as before. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define N 32

/* The soft wall of asp_system_set_soft_wall, by thesis eqs. 12-13, for gaps above its
 * continuation thresholds (the scene's gaps are all >= 0). */
typedef struct {
  double gamma_r, rho_r, gamma_a, rho_a;
  int status;       /* returned */
  int64_t nan_at;   /* where phi is made NaN (< 0: nowhere) */
  int calls;
} soft_wall_data;

static double soft_wall_phi(const soft_wall_data *w, double g) {
  return w->gamma_r * exp(-2.0 * g / w->rho_r) - w->gamma_a * exp(-g / w->rho_a);
}

static int soft_wall_callback(int64_t n, const double *gap, double *phi, double *dphi,
                              double *d2phi, void *user_data) {
  soft_wall_data *w = (soft_wall_data *)user_data;
  int64_t i;
  ++w->calls;
  for (i = 0; i < n; ++i) {
    const double r = w->gamma_r * exp(-2.0 * gap[i] / w->rho_r);
    const double a = w->gamma_a * exp(-gap[i] / w->rho_a);
    phi[i] = r - a;
    dphi[i] = -2.0 * r / w->rho_r + a / w->rho_a;
    if (d2phi != NULL) d2phi[i] = 4.0 * r / (w->rho_r * w->rho_r) - a / (w->rho_a * w->rho_a);
  }
  if (w->nan_at >= 0 && w->nan_at < n) phi[w->nan_at] = NAN;
  return w->status;
}

/* The exponential adhesion of asp_system_set_adhesion, phi = -w exp(-g/rho) on g >= 0, as a
 * user's potential for the hard wall. */
typedef struct {
  double work, range;
} adhesion_data;

static int adhesion_callback(int64_t n, const double *gap, double *phi, double *dphi,
                             double *d2phi, void *user_data) {
  const adhesion_data *a = (const adhesion_data *)user_data;
  int64_t i;
  for (i = 0; i < n; ++i) {
    phi[i] = -a->work * exp(-gap[i] / a->range);
    dphi[i] = -phi[i] / a->range;
    if (d2phi != NULL) d2phi[i] = phi[i] / (a->range * a->range);
  }
  return 0;
}

/* The Lennard-Jones 9-3 wall, continued below z0/2 by its Taylor expansion there:
 * phi = 244 w, phi' = -4536 w/z0, phi'' = 91584 w/z0^2. */
static double lennard_jones_phi(double w, double z0, double g) {
  const double s = g - 0.5 * z0;
  double u3;
  if (s < 0.0) return w * (244.0 + s / z0 * (-4536.0 + 0.5 * s / z0 * 91584.0));
  u3 = pow(z0 / g, 3.0);
  return 0.5 * w * (u3 * u3 * u3 - 3.0 * u3);
}

int main(void) {
  const double box = 1.0, radius = 1.0, modulus = 1.0, penetration = 2e-3;
  const double pixel_area = box * box / (N * N);
  /* A soft wall whose range is a few times the pixel's compliance length. */
  soft_wall_data wall = {1e-4, 2e-3, 5e-5, 2e-3, 0, -1, 0};
  const double w = 1e-4, z0 = 2e-3;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *pk = NULL, *dual = NULL, *primal = NULL, *lbfgsb = NULL;
  double *heights = malloc(N * N * sizeof(double));
  double *gap = malloc(N * N * sizeof(double));
  double value = 0.0, energy = 0.0, sum = 0.0, hard_wall_pressure = 0.0;
  int converged = 0, i = 0;

  CHECK_OK(asp_grid_create_2d(N, N, box, box, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_paraboloid(grid, radius, heights, N * N));
  CHECK_OK(asp_system_create(grid, modulus, &system));
  CHECK_OK(asp_system_set_topography(system, heights, N * N));
  CHECK_OK(asp_solver_create("pk", &pk));
  CHECK_OK(asp_solver_set_tolerance(pk, 1e-10));
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration));
  CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &hard_wall_pressure));
  CHECK(hard_wall_pressure > 0.0);

  /* ---- NULL handles and callbacks ---- */
  CHECK_ERROR(asp_system_set_soft_wall(NULL, 1.0, 1.0, 0.5, 1.0), ASP_ERR_NULL_POINTER,
              "'system'");
  CHECK_ERROR(asp_system_set_lennard_jones(NULL, w, z0), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_hard_wall(NULL), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_potential(NULL, soft_wall_callback, &wall, 0),
              ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_potential(system, NULL, &wall, 0), ASP_ERR_NULL_POINTER, "'fn'");
  CHECK_MESSAGE_HAS("asp_system_set_potential");
  CHECK_ERROR(asp_system_set_potential(system, NULL, NULL, 1), ASP_ERR_NULL_POINTER, "'fn'");

  /* ---- bad values, each named ---- */
  CHECK_ERROR(asp_system_set_soft_wall(system, 0.0, 1.0, 0.5, 1.0), ASP_ERR_INVALID_ARGUMENT,
              "'gamma_r'");
  CHECK_ERROR(asp_system_set_soft_wall(system, NAN, 1.0, 0.5, 1.0), ASP_ERR_INVALID_ARGUMENT,
              "'gamma_r'");
  CHECK_ERROR(asp_system_set_soft_wall(system, 1.0, -1.0, 0.5, 1.0), ASP_ERR_INVALID_ARGUMENT,
              "'rho_r'");
  CHECK_ERROR(asp_system_set_soft_wall(system, 1.0, INFINITY, 0.5, 1.0),
              ASP_ERR_INVALID_ARGUMENT, "'rho_r'");
  CHECK_ERROR(asp_system_set_soft_wall(system, 1.0, 1.0, -0.5, 1.0), ASP_ERR_INVALID_ARGUMENT,
              "'gamma_a'");
  CHECK_ERROR(asp_system_set_soft_wall(system, 1.0, 1.0, 0.5, 0.0), ASP_ERR_INVALID_ARGUMENT,
              "'rho_a'");
  /* The attraction outgrows the repulsion inside the wall: no lower bound. */
  CHECK_ERROR(asp_system_set_soft_wall(system, 1.0, 2.0, 5.0, 1.0), ASP_ERR_INVALID_ARGUMENT,
              "lower bound");
  CHECK_MESSAGE_HAS("'gamma_r'");
  CHECK_MESSAGE_HAS("'rho_a'");
  CHECK_ERROR(asp_system_set_lennard_jones(system, 0.0, z0), ASP_ERR_INVALID_ARGUMENT,
              "'work_of_adhesion'");
  CHECK_ERROR(asp_system_set_lennard_jones(system, -w, z0), ASP_ERR_INVALID_ARGUMENT,
              "'work_of_adhesion'");
  CHECK_ERROR(asp_system_set_lennard_jones(system, w, 0.0), ASP_ERR_INVALID_ARGUMENT,
              "'equilibrium_distance'");
  CHECK_ERROR(asp_system_set_lennard_jones(system, w, NAN), ASP_ERR_INVALID_ARGUMENT,
              "'equilibrium_distance'");
  /* Its curvature 91584 w/z0^2 at the continuation threshold overflows. */
  CHECK_ERROR(asp_system_set_lennard_jones(system, 1e300, 1e-10), ASP_ERR_INVALID_ARGUMENT,
              "continuation threshold");

  /* ---- the handle is usable and still the hard wall: pk solves as before ---- */
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration));
  CHECK_OK(asp_solver_converged(pk, &converged));
  CHECK(converged == 1);

  /* ---- the soft wall: its energy is a sum phi(g); no adhesion keys ---- */
  CHECK_OK(asp_system_set_soft_wall(system, wall.gamma_r, wall.rho_r, wall.gamma_a, wall.rho_a));
  CHECK_OK(asp_system_get(system, ASP_WORK_OF_ADHESION, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_system_get(system, ASP_ADHESION_RANGE, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, gap, N * N));
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &energy));
  sum = 0.0;
  for (i = 0; i < N * N; ++i) sum += soft_wall_phi(&wall, gap[i]);
  /* The same sum of the same terms, up to the rounding of each (1e-13 of the largest). */
  CHECK_NEAR(energy, pixel_area * sum, 1e-13 * pixel_area * N * N * wall.gamma_r);

  /* ---- the constrained solvers refuse it, naming themselves and the interaction ---- */
  CHECK_ERROR(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "does not handle a soft wall");
  CHECK_MESSAGE_HAS("'pk'");
  CHECK_MESSAGE_HAS("it handles: non-adhesive hard wall");
  CHECK_OK(asp_solver_create("bugnicourt", &dual));
  CHECK_ERROR(asp_solver_solve(dual, system, ASP_CONTROL_MEAN_PRESSURE, 1e-3),
              ASP_ERR_UNSUPPORTED, "does not handle a soft wall");
  CHECK_MESSAGE_HAS("'bugnicourt'");
  CHECK_OK(asp_solver_create("bugnicourt", &primal));
  CHECK_OK(asp_solver_set_option_string(primal, "variable", "gap"));
  CHECK_ERROR(asp_solver_solve(primal, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "does not handle a soft wall");
  CHECK_MESSAGE_HAS("adhesive hard wall");
  CHECK_OK(asp_solver_create("lbfgsb", &lbfgsb));
  CHECK_ERROR(asp_solver_solve(lbfgsb, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "does not handle a soft wall");
  CHECK_MESSAGE_HAS("'lbfgsb'");
  /* A refused solve leaves no report. */
  CHECK_ERROR(asp_solver_converged(pk, &converged), ASP_ERR_INVALID_STATE, NULL);

  /* ---- the Lennard-Jones wall ---- */
  CHECK_OK(asp_system_set_lennard_jones(system, w, z0));
  CHECK_OK(asp_system_get(system, ASP_WORK_OF_ADHESION, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &energy));
  sum = 0.0;
  for (i = 0; i < N * N; ++i) sum += lennard_jones_phi(w, z0, gap[i]);
  /* The contact's pixels (gap 0) sit in the continuation, at phi(0) = (244 + 2268 + 11448) w,
   * the largest term; each is rounded to a few ulp. */
  CHECK_NEAR(energy, pixel_area * sum, 1e-13 * pixel_area * N * N * 13960.0 * w);
  CHECK_ERROR(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "does not handle a Lennard-Jones wall");
  CHECK_ERROR(asp_solver_solve(lbfgsb, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "Lennard-Jones");

  /* ---- a C callback: the soft wall again, then failing ---- */
  CHECK_OK(asp_system_set_potential(system, soft_wall_callback, &wall, 0));
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &value));
  CHECK(wall.calls == 1); /* once for all pixels */
  CHECK_OK(asp_system_set_soft_wall(system, wall.gamma_r, wall.rho_r, wall.gamma_a, wall.rho_a));
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &energy));
  CHECK_NEAR(value, energy, 1e-13 * pixel_area * N * N * wall.gamma_r);
  CHECK_OK(asp_system_set_potential(system, soft_wall_callback, &wall, 0));
  wall.status = 5;
  CHECK_ERROR(asp_system_get(system, ASP_INTERACTION_ENERGY, &value), ASP_ERR_CALLBACK,
              "returned 5");
  wall.status = 0;
  wall.nan_at = 17;
  CHECK_ERROR(asp_system_get(system, ASP_INTERACTION_ENERGY, &value), ASP_ERR_CALLBACK,
              "index 17");
  CHECK_MESSAGE_HAS("phi = nan");
  wall.nan_at = -1;
  CHECK_ERROR(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "does not handle a user potential");
  CHECK_OK(asp_system_set_potential(system, soft_wall_callback, &wall, 1));
  CHECK_ERROR(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration),
              ASP_ERR_UNSUPPORTED, "user potential with hard wall");

  /* ---- a user's potential with the hard wall: lbfgsb on the gap solves it, and the
   * exponential adhesion as a callback gives the built-in adhesion's solution ---- */
  {
    adhesion_data adhesion = {2e-5, 4e-3};
    double callback_pressure = 0.0, builtin_pressure = 0.0, callback_gap = 0.0,
           builtin_gap = 0.0;
    CHECK_OK(asp_solver_set_option_string(lbfgsb, "variable", "gap"));
    CHECK_OK(asp_solver_set_tolerance(lbfgsb, 1e-10));
    CHECK_OK(asp_system_set_potential(system, adhesion_callback, &adhesion, 1));
    CHECK_OK(asp_system_reset(system));
    CHECK_OK(asp_solver_solve(lbfgsb, system, ASP_CONTROL_PENETRATION, penetration));
    CHECK_OK(asp_solver_converged(lbfgsb, &converged));
    CHECK(converged == 1);
    CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &callback_pressure));
    CHECK_OK(asp_system_get(system, ASP_MEAN_GAP, &callback_gap));
    CHECK_OK(asp_system_set_adhesion(system, adhesion.work, adhesion.range));
    CHECK_OK(asp_system_reset(system));
    CHECK_OK(asp_solver_solve(lbfgsb, system, ASP_CONTROL_PENETRATION, penetration));
    CHECK_OK(asp_solver_converged(lbfgsb, &converged));
    CHECK(converged == 1);
    CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &builtin_pressure));
    CHECK_OK(asp_system_get(system, ASP_MEAN_GAP, &builtin_gap));
    /* Adhesion pulls: the load at this penetration is below the plain hard wall's. */
    CHECK(builtin_pressure < hard_wall_pressure);
    /* Both solved to 1e-10 of the reference pressure. */
    CHECK_NEAR(callback_pressure, builtin_pressure, 1e-7 * fabs(builtin_pressure));
    CHECK_NEAR(callback_gap, builtin_gap, 1e-7 * fabs(builtin_gap));
    /* bugnicourt on the gap does not take a user's potential. */
    CHECK_OK(asp_system_set_potential(system, adhesion_callback, &adhesion, 1));
    CHECK_ERROR(asp_solver_solve(primal, system, ASP_CONTROL_PENETRATION, penetration),
                ASP_ERR_UNSUPPORTED, "user potential with hard wall");
  }

  /* ---- the hard wall back: pk solves again, to the load it found before ---- */
  CHECK_OK(asp_system_set_hard_wall(system));
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration));
  CHECK_OK(asp_solver_converged(pk, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get(system, ASP_MEAN_PRESSURE, &value));
  /* Both solves met the tolerance 1e-10 of the reference pressure: the loads agree far
   * better than 1e-6 of themselves. */
  CHECK_NEAR(value, hard_wall_pressure, 1e-6 * hard_wall_pressure);
  /* set_adhesion with work 0 is the same hard wall, also from a soft wall. */
  CHECK_OK(asp_system_set_lennard_jones(system, w, z0));
  CHECK_OK(asp_system_set_adhesion(system, 0.0, 1.0));
  CHECK_OK(asp_solver_solve(pk, system, ASP_CONTROL_PENETRATION, penetration));

  asp_solver_destroy(pk);
  asp_solver_destroy(dual);
  asp_solver_destroy(primal);
  asp_solver_destroy(lbfgsb);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(heights);
  free(gap);
  return check_summary("api.potentials");
}
