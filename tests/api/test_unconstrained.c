/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The unconstrained solvers of soft potentials through the public header: each of "lbfgs",
 * "lbfgs_fourier", "gfmd", "fire" and "fire_mass_weighted" solves a soft wall on a small rough
 * scene, under penetration and under mean-pressure control, to the same state; a C callback
 * that computes the same soft wall gives the same state as the built-in one; a callback that
 * fails in the middle of a solve (non-zero return, NaN) ends it with ASP_ERR_CALLBACK, leaves
 * the state the solve started from and the handles usable; the Lennard-Jones wall solves. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "check.h"

enum { nx = 32, ny = 32, n = nx * ny };

static const char *const solvers[] = {"lbfgs", "lbfgs_fourier", "gfmd", "fire",
                                      "fire_mass_weighted"};

/* The soft wall gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a), evaluated by the user (the
 * scene's gaps stay far above its continuation thresholds); fails on its call `fail_at`
 * (0: never) by returning 7, or by writing NaN if `with_nan`. */
typedef struct {
  double gamma_r, rho_r, gamma_a, rho_a;
  int calls, fail_at, with_nan;
} wall_data;

static int wall_callback(int64_t count, const double *gap, double *phi, double *dphi,
                         double *d2phi, void *user_data) {
  wall_data *w = (wall_data *)user_data;
  int64_t i;
  ++w->calls;
  for (i = 0; i < count; ++i) {
    const double r = w->gamma_r * exp(-2.0 * gap[i] / w->rho_r);
    const double a = w->gamma_a * exp(-gap[i] / w->rho_a);
    phi[i] = r - a;
    dphi[i] = -2.0 * r / w->rho_r + a / w->rho_a;
    if (d2phi != NULL) d2phi[i] = 4.0 * r / (w->rho_r * w->rho_r) - a / (w->rho_a * w->rho_a);
  }
  if (w->calls == w->fail_at) {
    if (!w->with_nan) return 7;
    dphi[count / 2] = NAN;
  }
  return 0;
}

static double largest_difference(const double *a, const double *b, double *scale) {
  double d = 0, s = 0;
  int64_t i;
  for (i = 0; i < n; ++i) {
    d = fmax(d, fabs(a[i] - b[i]));
    s = fmax(s, fabs(b[i]));
  }
  *scale = s;
  return d;
}

/* Solves from the reset state; the gap and pressure fields into g and p. */
static void solve(const char *name, asp_system *system, int control, double value, double *p,
                  double *g) {
  asp_solver *solver = NULL;
  int converged = 0;
  CHECK_OK(asp_solver_create(name, &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-10));
  CHECK_OK(asp_solver_set_max_iterations(solver, 200000));
  CHECK_OK(asp_system_reset(system));
  CHECK_OK(asp_solver_solve(solver, system, control, value));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, g, n));
  asp_solver_destroy(solver);
}

/* The same state: both solved to an error of 1e-10 of the scene's pressure scale, so 1e-7 of
 * the peak values leaves room for the conditioning of the soft wall. */
static void check_same_state(const double *p, const double *g, const double *p0,
                             const double *g0) {
  double p_scale = 0, g_scale = 0;
  const double dp = largest_difference(p, p0, &p_scale);
  const double dg = largest_difference(g, g0, &g_scale);
  CHECK(dp <= 1e-7 * p_scale);
  CHECK(dg <= 1e-7 * g_scale);
}

int main(void) {
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double *h = malloc(n * sizeof *h), *p0 = malloc(n * sizeof *p0), *g0 = malloc(n * sizeof *g0),
         *p = malloc(n * sizeof *p), *g = malloc(n * sizeof *g),
         *start = malloc(n * sizeof *start);
  wall_data wall = {0.05, 0.3, 0.01, 0.3, 0, 0, 0};
  int control, status;
  size_t k;
  double contact = 0, energy = 0;

  CHECK(h && p0 && g0 && p && g && start);
  /* Pixels of unit size; a self-affine surface of rms slope 0.1; a soft wall of range 0.3
   * pixels whose well lies at 0.3 ln 10 = 0.69. */
  CHECK_OK(asp_grid_create_2d(nx, ny, 32.0, 32.0, &grid));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, 32.0, 16.0, 2.0, ASP_RMS_SLOPE, 0.1, 5, h, n));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, h, n));
  CHECK_OK(asp_system_set_soft_wall(system, wall.gamma_r, wall.rho_r, wall.gamma_a, wall.rho_a));

  for (control = ASP_CONTROL_MEAN_PRESSURE; control <= ASP_CONTROL_PENETRATION; ++control) {
    /* The crest 0.45 from the wall, inside its repulsion; or a mean pressure of 3e-4. */
    const double value = control == ASP_CONTROL_PENETRATION ? -0.45 : 3e-4;
    solve("lbfgs_fourier", system, control, value, p0, g0);
    CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &contact));
    CHECK(contact > 0.0 && contact < 0.5);
    for (k = 0; k < sizeof solvers / sizeof *solvers; ++k) {
      solve(solvers[k], system, control, value, p, g);
      check_same_state(p, g, p0, g0);
    }
    /* The same soft wall from a C callback: the same state. */
    CHECK_OK(asp_system_set_potential(system, wall_callback, &wall, 0));
    solve("lbfgs_fourier", system, control, value, p, g);
    check_same_state(p, g, p0, g0);
    CHECK(wall.calls > 0);
    CHECK_OK(asp_system_set_soft_wall(system, wall.gamma_r, wall.rho_r, wall.gamma_a,
                                      wall.rho_a));
  }

  /* A callback that fails on its fifth call, by its status or with NaN: ASP_ERR_CALLBACK, and
   * the state the solve started from (the callback's converged penetration solve) is kept. */
  CHECK_OK(asp_system_set_potential(system, wall_callback, &wall, 0));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, start, n));
  CHECK_OK(asp_solver_create("lbfgs", &solver));
  for (status = 0; status < 2; ++status) {
    wall.calls = 0;
    wall.fail_at = 5;
    wall.with_nan = status;
    CHECK_ERROR(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, -0.4),
                ASP_ERR_CALLBACK, status ? "nan" : "7");
    CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, g, n));
    CHECK(memcmp(g, start, n * sizeof *g) == 0);
  }
  /* The handles are usable: the next solve, with a callback that does not fail, works. */
  wall.fail_at = 0;
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, -0.45));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, g, n));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, p, n));
  check_same_state(p, g, p0, g0);
  asp_solver_destroy(solver);

  /* The Lennard-Jones wall (w = 0.01, z0 = 0.5): two solvers agree, and the interaction
   * energy is negative (attraction dominates away from the few contacts). */
  CHECK_OK(asp_system_set_lennard_jones(system, 0.01, 0.5));
  solve("lbfgs_fourier", system, ASP_CONTROL_PENETRATION, -0.6, p0, g0);
  solve("lbfgs", system, ASP_CONTROL_PENETRATION, -0.6, p, g);
  check_same_state(p, g, p0, g0);
  CHECK_OK(asp_system_get(system, ASP_INTERACTION_ENERGY, &energy));
  CHECK(energy < 0.0);

  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(h);
  free(p0);
  free(g0);
  free(p);
  free(g);
  free(start);
  return check_summary("api.unconstrained");
}
