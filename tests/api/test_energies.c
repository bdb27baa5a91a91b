/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Elastic energies (asperity.h, ASP_ELASTIC_ENERGY, ASP_MEAN_MODE_ENERGY, asp_system_set_k0):
 *   ASP_ELASTIC_ENERGY   = (A/2) sum over q != 0 of K~(q)|u^_q|^2, K~(q) = E*|q|/2, u^ = DFT(u)/N;
 *                          it does not depend on K~(0);
 *   ASP_MEAN_MODE_ENERGY = A pbar^2/(2 K~(0));
 *   ELASTIC + MEAN_MODE  = (a/2) sum p u;
 *   K~(0) defaults to the mean of K~ at the lowest wavevector along x and y (E* pi/lx in 1D)
 *   and, under mean-pressure control, changes the penetration but not the pressure.
 * Checked on sinusoids with closed forms (full contact: one Fourier mode, so the energy is
 * exact; Westergaard's partial contact: the energy of his pressure profile), on a rough 2D
 * surface on a non-square box against a plain DFT of the displacement, under both controls. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

static const double pi = 3.14159265358979323846;

typedef struct {
  asp_grid *grid;
  asp_system *system;
  asp_solver *solver;
  int64_t nx, ny, n;
  double lx, ly, modulus;
  double *h, *p, *u;
} Scene;

static int make_scene(Scene *s, int dimension, int64_t nx, int64_t ny, double lx, double ly,
                      double modulus) {
  int ok;
  s->nx = nx;
  s->ny = dimension == 2 ? ny : 1;
  s->n = s->nx * s->ny;
  s->lx = lx;
  s->ly = dimension == 2 ? ly : 1.0;
  s->modulus = modulus;
  s->grid = NULL;
  s->system = NULL;
  s->solver = NULL;
  s->h = calloc((size_t)s->n, sizeof(double));
  s->p = calloc((size_t)s->n, sizeof(double));
  s->u = calloc((size_t)s->n, sizeof(double));
  ok = s->h != NULL && s->p != NULL && s->u != NULL;
  ok = ok && (dimension == 2 ? asp_grid_create_2d(nx, ny, lx, ly, &s->grid)
                             : asp_grid_create_1d(nx, lx, &s->grid)) == ASP_OK;
  ok = ok && asp_system_create(s->grid, modulus, &s->system) == ASP_OK;
  ok = ok && asp_solver_create("pk", &s->solver) == ASP_OK;
  ok = ok && asp_solver_set_tolerance(s->solver, 1e-12) == ASP_OK;
  if (!ok) fprintf(stderr, "cannot make a scene: %s\n", asp_last_error_message());
  return ok;
}

static void free_scene(Scene *s) {
  asp_solver_destroy(s->solver);
  asp_system_destroy(s->system);
  asp_grid_destroy(s->grid);
  free(s->h);
  free(s->p);
  free(s->u);
}

static double area(const Scene *s) { return s->lx * s->ly; }

static double get(const Scene *s, int key) {
  double value = NAN;
  if (asp_system_get(s->system, key, &value) != ASP_OK)
    fprintf(stderr, "asp_system_get(%d): %s\n", key, asp_last_error_message());
  return value;
}

static int solve(Scene *s, int control, double value) {
  int converged = 0;
  if (asp_solver_solve(s->solver, s->system, control, value) != ASP_OK ||
      asp_solver_converged(s->solver, &converged) != ASP_OK) {
    fprintf(stderr, "solve: %s\n", asp_last_error_message());
    return 0;
  }
  return converged;
}

/* (A/2) sum over q != 0 of (E*|q|/2) |u^_q|^2 with u^ = DFT(u)/N: a plain separable 2D DFT. */
static double energy_of(const Scene *s, const double *u) {
  const int64_t nx = s->nx, ny = s->ny, n = s->n;
  double *re = calloc((size_t)n, sizeof(double)), *im = calloc((size_t)n, sizeof(double));
  double sum = 0.0;
  int64_t i, j, k, l;
  for (j = 0; j < ny; ++j)
    for (k = 0; k < nx; ++k)
      for (i = 0; i < nx; ++i) {
        const double a = -2.0 * pi * (double)((k * i) % nx) / (double)nx;
        re[k + nx * j] += u[i + nx * j] * cos(a);
        im[k + nx * j] += u[i + nx * j] * sin(a);
      }
  for (k = 0; k < nx; ++k)
    for (l = 0; l < ny; ++l) {
      double r = 0.0, m = 0.0, qx, qy;
      if (k == 0 && l == 0) continue;
      for (j = 0; j < ny; ++j) {
        const double a = -2.0 * pi * (double)((l * j) % ny) / (double)ny;
        r += re[k + nx * j] * cos(a) - im[k + nx * j] * sin(a);
        m += re[k + nx * j] * sin(a) + im[k + nx * j] * cos(a);
      }
      qx = 2.0 * pi * (double)(2 * k <= nx ? k : nx - k) / s->lx;
      qy = 2.0 * pi * (double)(2 * l <= ny ? l : ny - l) / s->ly;
      sum += 0.5 * s->modulus * sqrt(qx * qx + qy * qy) * (r * r + m * m) / ((double)n * n);
    }
  free(re);
  free(im);
  return 0.5 * area(s) * sum;
}

/* The energies of the system's state agree with the definitions. */
static void check_energies(Scene *s, int line) {
  const double elastic = get(s, ASP_ELASTIC_ENERGY), mean_mode = get(s, ASP_MEAN_MODE_ENERGY);
  const double k0 = get(s, ASP_K0), mean = get(s, ASP_MEAN_PRESSURE);
  double pu = 0.0;
  int64_t i;
  asp_system_get_field(s->system, ASP_FIELD_PRESSURE, s->p, s->n);
  asp_system_get_field(s->system, ASP_FIELD_DISPLACEMENT, s->u, s->n);
  for (i = 0; i < s->n; ++i) pu += s->p[i] * s->u[i];
  pu *= 0.5 * area(s) / (double)s->n;
  check_near(elastic, energy_of(s, s->u), 1e-10 * elastic, __FILE__, line,
             "ASP_ELASTIC_ENERGY = (A/2) sum_{q != 0} K~(q)|u^_q|^2");
  check_near(mean_mode, area(s) * mean * mean / (2.0 * k0), 1e-14 * mean_mode, __FILE__, line,
             "ASP_MEAN_MODE_ENERGY = A pbar^2/(2 K~(0))");
  check_near(elastic + mean_mode, pu, 1e-11 * pu, __FILE__, line,
             "ELASTIC + MEAN_MODE = (a/2) sum p u");
}
#define CHECK_ENERGIES(s) check_energies((s), __LINE__)

/* Default K~(0): E* pi/lx in 1D, E* (2 pi/lx + 2 pi/ly)/4 in 2D. */
static void test_default_k0(void) {
  Scene line, box;
  if (!make_scene(&line, 1, 16, 1, 2.5, 1.0, 3.0)) return;
  CHECK_NEAR(get(&line, ASP_K0), 3.0 * pi / 2.5, 1e-15 * 3.0 * pi / 2.5);
  free_scene(&line);
  if (!make_scene(&box, 2, 16, 8, 2.0, 0.5, 3.0)) return;
  CHECK_NEAR(get(&box, ASP_K0), 0.5 * 3.0 * (2.0 * pi / 2.0 + 2.0 * pi / 0.5) / 2.0,
             1e-15 * 3.0 * pi * 2.5);
  free_scene(&box);
}

/* A sinusoid in full contact is one Fourier mode: u - mean u = h (the gap is 0), so
 *   ASP_ELASTIC_ENERGY = (lx/2) 2 (E* q1/2)(h0/2)^2 = pi E* h0^2/4 (per unit length, q1 = 2 pi/lx),
 * whatever K~(0); the penetration is max h + pbar/K~(0). */
static void test_full_contact(void) {
  const double h0 = 0.02, modulus = 3.0, lx = 2.0;
  const double p_star = pi * modulus * h0 / lx, mean = 2.0 * p_star;
  const double exact = pi * modulus * h0 * h0 / 4.0;
  double k0;
  Scene s;
  if (!make_scene(&s, 1, 64, 1, lx, 1.0, modulus)) return;
  CHECK_OK(asp_topography_sinusoid(s.grid, h0, 1, 0, s.h, s.n));
  CHECK_OK(asp_system_set_topography(s.system, s.h, s.n));
  CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
  CHECK(get(&s, ASP_CONTACT_FRACTION) == 1.0);
  k0 = get(&s, ASP_K0);
  CHECK_NEAR(get(&s, ASP_ELASTIC_ENERGY), exact, 1e-12 * exact);
  CHECK_NEAR(get(&s, ASP_MEAN_MODE_ENERGY), lx * mean * mean / (2.0 * k0), 1e-14 * mean * mean);
  CHECK_NEAR(get(&s, ASP_PENETRATION), h0 + mean / k0, 1e-12 * (h0 + mean / k0));
  CHECK_ENERGIES(&s);

  /* Four times stiffer mean mode: same elastic energy, a quarter of the mean-mode energy. */
  CHECK_OK(asp_system_set_k0(s.system, 4.0 * k0));
  CHECK_OK(asp_system_reset(s.system));
  CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
  CHECK(get(&s, ASP_K0) == 4.0 * k0);
  CHECK_NEAR(get(&s, ASP_ELASTIC_ENERGY), exact, 1e-12 * exact);
  CHECK_NEAR(get(&s, ASP_MEAN_MODE_ENERGY), lx * mean * mean / (8.0 * k0), 1e-14 * mean * mean);
  CHECK_NEAR(get(&s, ASP_PENETRATION), h0 + mean / (4.0 * k0), 1e-12 * h0);
  CHECK_ENERGIES(&s);

  /* Under penetration control K~(0) sets the mean pressure, pbar = K~(0)(delta - h0), and the
   * deformation, hence the elastic energy, stays that of full contact. */
  CHECK_OK(asp_system_reset(s.system));
  CHECK(solve(&s, ASP_CONTROL_PENETRATION, 3.0 * h0));
  CHECK_NEAR(get(&s, ASP_MEAN_PRESSURE), 4.0 * k0 * 2.0 * h0, 1e-12 * k0 * h0);
  CHECK_NEAR(get(&s, ASP_ELASTIC_ENERGY), exact, 1e-12 * exact);
  CHECK_ENERGIES(&s);
  free_scene(&s);
}

/* Westergaard's partial contact of h = h0 cos(2 pi x/l) at pbar = p* sin^2(psi), p* = pi E* h0/l,
 * psi = pi a/l: p(x) = (2 pbar/sin^2 psi) cos(pi x/l) sqrt(sin^2 psi - sin^2(pi x/l)) for
 * |x| < a. With sin(pi x/l) = sin psi sin t, p dx = (2 pbar l/pi) cos^2 t dt, so its Fourier
 * coefficients are smooth integrals over t in [0, pi/2] (the midpoint rule converges fast), and
 *   E_el = (l/2) sum_{k != 0} |p^_k|^2/K~(q_k) = (l/2) sum_{k >= 1} 2 p^_k^2/(E* pi k/l).
 * The sum is cut at k = 400: p^_k ~ k^(-3/2), so the tail is below 1e-8 of the total. */
static double westergaard_energy(double modulus, double h0, double l, double mean) {
  enum { nodes = 4096, modes = 400 };
  static double x[nodes], weight[nodes];
  const double s = sqrt(mean / (pi * modulus * h0 / l)), dt = 0.5 * pi / nodes;
  double energy = 0.0;
  int k, m;
  for (m = 0; m < nodes; ++m) {
    const double t = (m + 0.5) * dt;
    x[m] = (l / pi) * asin(s * sin(t));
    weight[m] = cos(t) * cos(t) * dt;
  }
  for (k = 1; k <= modes; ++k) {
    const double q = 2.0 * pi * k / l;
    double integral = 0.0, coefficient;
    for (m = 0; m < nodes; ++m) integral += weight[m] * cos(q * x[m]);
    coefficient = (4.0 * mean / pi) * integral; /* p^_k = (2/l) int_0^a p cos(q x) dx */
    energy += 2.0 * coefficient * coefficient / (0.5 * modulus * q);
  }
  return 0.5 * l * energy;
}

/* The elastic energy of Westergaard's solution, to within the discretisation error, at two
 * resolutions (the contact edge is resolved to a pixel; measured relative errors 3e-4 at 128
 * pixels, 4e-5 at 256, 2e-5 at 512, 1.2e-6 at 2048, falling faster than the pixel size, so the
 * bounds are 1e-3 at 256, 1e-4 at 2048 and a fall by at least 8 between them); and it does not
 * move when K~(0) does. */
static double westergaard_error(int64_t n, double bound) {
  const double h0 = 0.01, modulus = 2.0, l = 1.0;
  const double p_star = pi * modulus * h0 / l, mean = 0.25 * p_star;
  const double exact = westergaard_energy(modulus, h0, l, mean);
  double elastic, k0, error = HUGE_VAL, factor;
  const double factors[3] = {4.0, 0.25, 1e3};
  int f;
  Scene s;
  if (!make_scene(&s, 1, n, 1, l, 1.0, modulus)) return error;
  CHECK_OK(asp_topography_sinusoid(s.grid, h0, 1, 0, s.h, s.n));
  CHECK_OK(asp_system_set_topography(s.system, s.h, s.n));
  CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
  elastic = get(&s, ASP_ELASTIC_ENERGY);
  error = fabs(elastic - exact) / exact;
  printf("Westergaard at %lld pixels: elastic energy %.10g, closed form %.10g, relative error "
         "%.2g\n",
         (long long)n, elastic, exact, error);
  CHECK(error <= bound);
  CHECK_ENERGIES(&s);
  k0 = get(&s, ASP_K0);
  for (f = 0; f < 3; ++f) {
    factor = factors[f];
    CHECK_OK(asp_system_set_k0(s.system, factor * k0));
    CHECK_OK(asp_system_reset(s.system));
    CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
    CHECK_NEAR(get(&s, ASP_ELASTIC_ENERGY), elastic, 1e-9 * elastic);
    CHECK_NEAR(get(&s, ASP_MEAN_MODE_ENERGY), l * mean * mean / (2.0 * factor * k0),
               1e-14 * l * mean * mean / (factor * k0));
    CHECK_ENERGIES(&s);
  }
  free_scene(&s);
  return error;
}

static void test_westergaard(void) {
  const double coarse = westergaard_error(256, 1e-3);
  const double fine = westergaard_error(2048, 1e-4);
  CHECK(fine < coarse / 8.0);
}

/* A rough surface on a non-square 2D box: the definitions hold under both controls; under
 * mean-pressure control the elastic energy and the pressure do not depend on K~(0), the
 * penetration moves by pbar (1/K~(0)' - 1/K~(0)). */
static void test_rough_surface(void) {
  const double mean = 0.004;
  double elastic, k0, delta, mean_mode, pressure_before[512];
  int64_t i;
  int same = 1;
  Scene s;
  if (!make_scene(&s, 2, 32, 16, 2.0, 1.0, 1.5)) return;
  CHECK_OK(asp_topography_self_affine(s.grid, 0.8, 1.0, 0.5, 0.125, ASP_RMS_SLOPE, 0.1, 5, s.h,
                                      s.n));
  CHECK_OK(asp_system_set_topography(s.system, s.h, s.n));
  CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
  CHECK(get(&s, ASP_CONTACT_FRACTION) > 0.02 && get(&s, ASP_CONTACT_FRACTION) < 0.5);
  CHECK_ENERGIES(&s);
  elastic = get(&s, ASP_ELASTIC_ENERGY);
  mean_mode = get(&s, ASP_MEAN_MODE_ENERGY);
  k0 = get(&s, ASP_K0);
  delta = get(&s, ASP_PENETRATION);
  CHECK(elastic > 0.0 && mean_mode > 0.0);
  memcpy(pressure_before, s.p, (size_t)s.n * sizeof(double));

  CHECK_OK(asp_system_set_k0(s.system, 10.0 * k0));
  CHECK_OK(asp_system_reset(s.system));
  CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
  CHECK_ENERGIES(&s);
  CHECK_NEAR(get(&s, ASP_ELASTIC_ENERGY), elastic, 1e-9 * elastic);
  CHECK_NEAR(get(&s, ASP_MEAN_MODE_ENERGY), mean_mode / 10.0, 1e-13 * mean_mode);
  CHECK_NEAR(get(&s, ASP_PENETRATION), delta + mean * (1.0 / (10.0 * k0) - 1.0 / k0),
             1e-9 * delta);
  for (i = 0; i < s.n; ++i) same &= fabs(s.p[i] - pressure_before[i]) <= 1e-9 * mean * 100.0;
  CHECK(same);

  /* Penetration control: K~(0) now decides the mean pressure, and with it the deformation;
   * the definitions still hold. */
  CHECK_OK(asp_system_reset(s.system));
  CHECK(solve(&s, ASP_CONTROL_PENETRATION, delta));
  /* A stiffer mean mode takes less of delta: more is left to press the asperities. */
  CHECK(get(&s, ASP_MEAN_PRESSURE) > mean);
  CHECK_ENERGIES(&s);
  CHECK_OK(asp_system_set_k0(s.system, k0));
  CHECK_OK(asp_system_reset(s.system));
  CHECK(solve(&s, ASP_CONTROL_PENETRATION, delta));
  CHECK_NEAR(get(&s, ASP_MEAN_PRESSURE), mean, 1e-9 * mean);
  CHECK_NEAR(get(&s, ASP_ELASTIC_ENERGY), elastic, 1e-8 * elastic);
  CHECK_ENERGIES(&s);
  free_scene(&s);
}

/* Right after asp_system_set_k0, before any solve: ASP_ELASTIC_ENERGY has not changed,
 * ASP_MEAN_MODE_ENERGY is A pbar^2/(2 K~(0)) with the new K~(0), and the numbers of the state
 * still satisfy the documented relations (ELASTIC + MEAN_MODE = (a/2) sum p u; the mean
 * displacement is pbar/K~(0) with the K~(0) in use). */
static void test_right_after_set_k0(void) {
  const double h0 = 0.01, modulus = 2.0, mean = 0.25 * pi * modulus * h0;
  double elastic, k0, mean_u = 0.0;
  int64_t i;
  Scene s;
  if (!make_scene(&s, 1, 256, 1, 1.0, 1.0, modulus)) return;
  CHECK_OK(asp_topography_sinusoid(s.grid, h0, 1, 0, s.h, s.n));
  CHECK_OK(asp_system_set_topography(s.system, s.h, s.n));
  CHECK(solve(&s, ASP_CONTROL_MEAN_PRESSURE, mean));
  elastic = get(&s, ASP_ELASTIC_ENERGY);
  k0 = get(&s, ASP_K0);
  CHECK_OK(asp_system_set_k0(s.system, 4.0 * k0));
  CHECK(get(&s, ASP_K0) == 4.0 * k0);
  CHECK(get(&s, ASP_ELASTIC_ENERGY) == elastic);
  CHECK_NEAR(get(&s, ASP_MEAN_MODE_ENERGY), mean * mean / (8.0 * k0), 1e-14 * mean * mean / k0);
  CHECK_OK(asp_system_get_field(s.system, ASP_FIELD_DISPLACEMENT, s.u, s.n));
  for (i = 0; i < s.n; ++i) mean_u += s.u[i] / (double)s.n;
  CHECK_NEAR(mean_u, mean / (4.0 * k0), 1e-12 * mean / k0);
  CHECK_ENERGIES(&s);
  free_scene(&s);
}

/* The undeformed state (zero pressure, after asp_system_set_topography) has u = 0: both
 * energies are 0, in any units the library accepts. */
static void test_undeformed(void) {
  const double units[3][2] = {{1.0, 0.01}, {1e-100, 1e50}, {1e50, 1e150}};
  int k;
  for (k = 0; k < 3; ++k) {
    const double modulus = units[k][0], h0 = units[k][1];
    double elastic = NAN, mean_mode = NAN;
    int64_t i;
    Scene s;
    if (!make_scene(&s, 1, 64, 1, 1.0, 1.0, modulus)) return;
    CHECK_OK(asp_topography_sinusoid(s.grid, h0, 1, 0, s.h, s.n));
    for (i = 0; i < s.n; ++i) s.h[i] += 0.1 * h0 * cos(2.0 * pi * 5.0 * (double)i / 64.0 + 0.3);
    if (asp_system_set_topography(s.system, s.h, s.n) == ASP_OK) {
      printf("undeformed state, E* %g, heights %g\n", modulus, h0);
      CHECK_OK(asp_system_get(s.system, ASP_MEAN_MODE_ENERGY, &mean_mode));
      CHECK(mean_mode == 0.0);
      /* Rounding of the stored gap may leave |u| ~ 1e-16 h: energy ~ 1e-32 E* h^2 l. */
      if (CHECK_OK(asp_system_get(s.system, ASP_ELASTIC_ENERGY, &elastic)))
        CHECK(fabs(elastic) <= 1e-24 * modulus * h0 * h0);
    }
    free_scene(&s);
  }
}

int main(void) {
  test_default_k0();
  test_full_contact();
  test_westergaard();
  test_rough_surface();
  test_right_after_set_k0();
  test_undeformed();
  return check_summary("api.energies");
}
