/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The elastic layer on a rigid base through the public header (asp_system_create_layer):
 * its own K~(0) = M/t (read, not set), one wavevector pressed into full contact on a 1D
 * grid against p~ = K~(q) u~ with the layer's closed form, the energies it reports, the
 * solvers that take it, and the arguments it refuses, each named. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

enum { n = 64 };

static double get(const asp_system *system, int key) {
  double value = NAN;
  if (asp_system_get(system, key, &value) != ASP_OK)
    fprintf(stderr, "asp_system_get(%d): %s\n", key, asp_last_error_message());
  return value;
}

/* The layer's K~(q) from its closed form (Carbone & Mangialardi 2008), direct: the scene
 * below has qt near 1, where neither cosh overflows nor the denominator cancels. */
static double layer_stiffness(double e_star, double nu, double t, double q) {
  const double s = q * t, kappa = 3.0 - 4.0 * nu;
  return 0.5 * e_star * q * (kappa * cosh(2 * s) + 2 * s * s + 0.5 * (1 + kappa * kappa)) /
         (kappa * sinh(2 * s) - 2 * s);
}

int main(void) {
  const double pi = 3.14159265358979323846;
  const double e_star = 2.0, nu = 0.25, t = 0.15, l = 1.0, h0 = 1e-3;
  const double m = e_star * (1 - nu * nu) * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double k0 = m / t, q = 2 * pi / l, kq = layer_stiffness(e_star, nu, t, q);
  asp_grid *grid = NULL;
  asp_system *layer = NULL, *refused = NULL;
  asp_solver *solver = NULL;
  double h[n], p[n], worst = 0.0, delta, pbar;
  const char *algorithms[] = {"pk", "bugnicourt", "lbfgsb"};
  int64_t i;
  size_t k;

  CHECK_OK(asp_grid_create_1d(n, l, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_system_create_layer(grid, e_star, nu, t, &layer));

  /* ---- K~(0) is the layer's own, M/t, to rounding; setting it is refused ---- */
  CHECK_NEAR(get(layer, ASP_K0), k0, 1e-14 * k0);
  CHECK_ERROR(asp_system_set_k0(layer, 1.0), ASP_ERR_UNSUPPORTED, "periodic elastic layer");
  CHECK_NEAR(get(layer, ASP_K0), k0, 1e-14 * k0);

  /* ---- one wavevector in full contact: u = h - h0 + delta, so
   * p = K~(0)(delta - h0) + K~(q) h0 cos(qx), exactly per mode; solved to 1e-12 of the
   * reference pressure, checked to 1e-9 of the mean pressure ---- */
  for (i = 0; i < n; ++i) h[i] = h0 * cos(q * l * (double)i / n);
  CHECK_OK(asp_system_set_topography(layer, h, n));
  delta = h0 + 2.0 * kq * h0 / k0; /* twice what full contact needs */
  pbar = k0 * (delta - h0);
  for (k = 0; k < sizeof algorithms / sizeof algorithms[0]; ++k) {
    CHECK_OK(asp_solver_create(algorithms[k], &solver));
    CHECK_OK(asp_solver_set_tolerance(solver, 1e-12));
    CHECK_OK(asp_solver_supports(solver, layer, ASP_CONTROL_PENETRATION));
    CHECK_OK(asp_system_reset(layer));
    CHECK_OK(asp_solver_solve(solver, layer, ASP_CONTROL_PENETRATION, delta));
    CHECK_OK(asp_system_get_field(layer, ASP_FIELD_PRESSURE, p, n));
    worst = 0.0;
    for (i = 0; i < n; ++i) worst = fmax(worst, fabs(p[i] - (pbar + kq * h[i])));
    if (!CHECK(worst < 1e-9 * pbar)) fprintf(stderr, "%s: off by %g\n", algorithms[k], worst);
    CHECK(get(layer, ASP_CONTACT_FRACTION) == 1.0);
    asp_solver_destroy(solver);
    solver = NULL;
  }

  /* ---- energies: ELASTIC is the q != 0 part, (l/2) K~(q) (h0/2)^2 2 = l K~ h0^2/4 per
   * unit length; MEAN_MODE the layer's uniform compression l pbar^2/(2 M/t) ---- */
  CHECK_NEAR(get(layer, ASP_ELASTIC_ENERGY), l * kq * h0 * h0 / 4, 1e-8 * l * kq * h0 * h0);
  CHECK_NEAR(get(layer, ASP_MEAN_MODE_ENERGY), l * pbar * pbar / (2 * k0),
             1e-8 * l * pbar * pbar / k0);

  /* ---- refusals, each naming its argument; nothing is made ---- */
  CHECK_ERROR(asp_system_create_layer(NULL, e_star, nu, t, &refused), ASP_ERR_NULL_POINTER,
              "'grid'");
  CHECK(refused == NULL);
  CHECK_ERROR(asp_system_create_layer(grid, e_star, nu, t, NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_system_create_layer(grid, e_star, 0.5, t, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'poisson_ratio'");
  CHECK_MESSAGE_HAS("infinite");
  CHECK(refused == NULL);
  CHECK_ERROR(asp_system_create_layer(grid, e_star, -0.2, t, &refused),
              ASP_ERR_INVALID_ARGUMENT, "'poisson_ratio'");
  CHECK_ERROR(asp_system_create_layer(grid, e_star, nu, 0.0, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'thickness'");
  CHECK_ERROR(asp_system_create_layer(grid, e_star, nu, NAN, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'thickness'");
  CHECK_ERROR(asp_system_create_layer(grid, -1.0, nu, t, &refused), ASP_ERR_INVALID_ARGUMENT,
              "'contact_modulus'");
  CHECK(refused == NULL);

  asp_system_destroy(layer);
  asp_grid_destroy(grid);
  return check_summary("test_layer");
}
