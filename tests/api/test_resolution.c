/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asp_system_check_resolution through the public header: the cohesive zone of each
 * interaction against the pixel, computed here from its formula (for the soft wall with two
 * ranges from the potential itself, by bisection for its well and its inflection), on
 * resolved and unresolved scenes, 1D and 2D, square and oblong pixels, periodic and free; the
 * threshold of one pixel; what it says of the plain hard wall, of a soft wall without
 * attraction and of a user's potential (without calling it); outputs that stay finite for
 * parameters whose zone is beyond the doubles; and bad arguments. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"

#define QUARTER_PI 0.78539816339744830962

/* The ratio and the round-off it carries: the library forms the zone from logarithms of the
 * parameters (each exact to an ulp) and one exponential, whose relative error is about the
 * size of the logarithm (tens) times the double's epsilon; 1e-12 leaves a margin of ten. */
#define RATIO_TOLERANCE 1e-12

static char sentence[1024];

/* The ratio, the flag and the sentence of a system (each call checked). */
static double ratio_of(const asp_system *system, int *resolved) {
  double ratio = -1.0;
  int64_t length = -1;
  *resolved = -1;
  CHECK_OK(asp_system_check_resolution(system, &ratio, resolved, sentence,
                                       (int64_t)sizeof sentence, &length));
  CHECK(isfinite(ratio) && ratio >= 0.0);
  CHECK(*resolved == 0 || *resolved == 1);
  CHECK(length == (int64_t)strlen(sentence) && length > 0);
  return ratio;
}

static int starts_with(const char *text, const char *start) {
  return strncmp(text, start, strlen(start)) == 0;
}

/* The exponential soft wall of thesis eqs. 12-13 and its first two derivatives. */
typedef struct {
  double gamma_r, rho_r, gamma_a, rho_a;
} soft_wall;
static double soft_phi(const soft_wall *w, double g) {
  return w->gamma_r * exp(-2.0 * g / w->rho_r) - w->gamma_a * exp(-g / w->rho_a);
}
static double soft_dphi(const soft_wall *w, double g) {
  return -2.0 * w->gamma_r / w->rho_r * exp(-2.0 * g / w->rho_r) +
         w->gamma_a / w->rho_a * exp(-g / w->rho_a);
}
static double soft_d2phi(const soft_wall *w, double g) {
  return 4.0 * w->gamma_r / (w->rho_r * w->rho_r) * exp(-2.0 * g / w->rho_r) -
         w->gamma_a / (w->rho_a * w->rho_a) * exp(-g / w->rho_a);
}
/* The root of f on [lo, hi], f(lo) < 0 < f(hi), to the last bit. */
static double bisect(double (*f)(const soft_wall *, double), const soft_wall *w, double lo,
                     double hi) {
  int k;
  for (k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (f(w, mid) < 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}
static double minus_d2phi(const soft_wall *w, double g) { return -soft_d2phi(w, g); }

/* A user's potential that counts its calls: the check must not call it. */
static int calls = 0;
static int counting_potential(int64_t n, const double *gap, double *phi, double *dphi,
                              double *d2phi, void *user_data) {
  int64_t i;
  (void)user_data;
  ++calls;
  for (i = 0; i < n; ++i) {
    phi[i] = -exp(-gap[i]);
    dphi[i] = exp(-gap[i]);
    if (d2phi != NULL) d2phi[i] = -exp(-gap[i]);
  }
  return 0;
}

int main(void) {
  asp_grid *square = NULL, *oblong = NULL, *line = NULL, *tiny = NULL, *wide = NULL;
  asp_system *system = NULL, *free_system = NULL, *on_oblong = NULL, *on_line = NULL;
  asp_system *extreme = NULL;
  const double dx = 1.0 / 64; /* the square grid's pixel */
  double ratio, expected, w, rho;
  int resolved;
  int64_t length;
  char small[8];

  CHECK_OK(asp_grid_create_2d(64, 64, 1.0, 1.0, &square));
  CHECK_OK(asp_grid_set_fft_planning(square, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_system_create(square, 1.0, &system));

  /* ---- the plain hard wall: nothing to resolve ---- */
  ratio = ratio_of(system, &resolved);
  CHECK(ratio == 0.0 && resolved == 1);
  CHECK(starts_with(sentence, "resolved: ") && strstr(sentence, "hard wall") != NULL);
  CHECK(strstr(sentence, "nothing") != NULL);

  /* ---- exponential adhesion: (pi/4) E* rho^2/w against dx ---- */
  rho = 0.01;
  w = 1e-3; /* 5.03 pixels */
  CHECK_OK(asp_system_set_adhesion(system, w, rho));
  expected = QUARTER_PI * 1.0 * rho * rho / w / dx;
  ratio = ratio_of(system, &resolved);
  CHECK_NEAR(ratio, expected, RATIO_TOLERANCE * expected);
  CHECK(resolved == 1);
  CHECK(starts_with(sentence, "resolved: ") && strstr(sentence, "5.03 pixels") != NULL);
  CHECK(strstr(sentence, "(pi/4) E* rho^2/w") != NULL);

  w = 0.1; /* 0.0503 pixels: a range of 0.64 pixels under strong adhesion */
  CHECK_OK(asp_system_set_adhesion(system, w, rho));
  expected = QUARTER_PI * rho * rho / w / dx;
  ratio = ratio_of(system, &resolved);
  CHECK_NEAR(ratio, expected, RATIO_TOLERANCE * expected);
  CHECK(resolved == 0);
  CHECK(starts_with(sentence, "not resolved: ") && strstr(sentence, "0.0503 pixels") != NULL);
  CHECK(strstr(sentence, "lattice trapping") != NULL);
  CHECK(strstr(sentence, "finer grid") != NULL);

  /* The threshold is one pixel: 1 % above resolves, 1 % below does not. */
  CHECK_OK(asp_system_set_adhesion(system, QUARTER_PI * rho * rho / (dx * 1.01), rho));
  ratio = ratio_of(system, &resolved);
  CHECK_NEAR(ratio, 1.01, RATIO_TOLERANCE);
  CHECK(resolved == 1);
  CHECK_OK(asp_system_set_adhesion(system, QUARTER_PI * rho * rho / (dx * 0.99), rho));
  ratio = ratio_of(system, &resolved);
  CHECK_NEAR(ratio, 0.99, RATIO_TOLERANCE);
  CHECK(resolved == 0);

  /* The contact modulus enters linearly; the free substrate counts the same pixel. */
  CHECK_OK(asp_system_create_free(square, 4.0, &free_system));
  CHECK_OK(asp_system_set_adhesion(free_system, 0.1, rho));
  expected = QUARTER_PI * 4.0 * rho * rho / 0.1 / dx;
  CHECK_NEAR(ratio_of(free_system, &resolved), expected, RATIO_TOLERANCE * expected);
  CHECK(resolved == 0);

  /* Oblong pixels: the smaller side counts (ly/ny = 1/128 < lx/nx = 1/64). */
  CHECK_OK(asp_grid_create_2d(64, 32, 1.0, 0.25, &oblong));
  CHECK_OK(asp_system_create(oblong, 1.0, &on_oblong));
  CHECK_OK(asp_system_set_adhesion(on_oblong, 1e-3, rho));
  expected = QUARTER_PI * rho * rho / 1e-3 / (0.25 / 32);
  CHECK_NEAR(ratio_of(on_oblong, &resolved), expected, RATIO_TOLERANCE * expected);
  /* 1D: lx/nx (the grid's ly of 1 plays no part). */
  CHECK_OK(asp_grid_create_1d(100, 2.0, &line));
  CHECK_OK(asp_system_create(line, 1.0, &on_line));
  CHECK_OK(asp_system_set_adhesion(on_line, 1e-3, rho));
  expected = QUARTER_PI * rho * rho / 1e-3 / 0.02;
  CHECK_NEAR(ratio_of(on_line, &resolved), expected, RATIO_TOLERANCE * expected);
  CHECK(resolved == 1);

  /* Work 0 is the plain hard wall again. */
  CHECK_OK(asp_system_set_adhesion(system, 0.0, rho));
  CHECK(ratio_of(system, &resolved) == 0.0 && resolved == 1);

  /* ---- the soft wall with one range: w = gamma_a^2/(4 gamma_r), s = gamma_a^2/(8 gamma_r
   * rho), l = 4 pi E* gamma_r rho^2/gamma_a^2. The built-in scene's wall (3.2 pixels of its
   * 512^2 grid on a box of 1) on the same pixel, then with a range 5 times shorter. ---- */
  {
    const double gamma_r = 3.2e-4, gamma_a = 8e-5, pixel = 1.0 / 512;
    asp_grid *scene_pixels = NULL;
    asp_system *soft = NULL;
    CHECK_OK(asp_grid_create_2d(64, 64, 64 * pixel, 64 * pixel, &scene_pixels));
    CHECK_OK(asp_system_create(scene_pixels, 1.0, &soft));
    rho = 1e-4;
    CHECK_OK(asp_system_set_soft_wall(soft, gamma_r, rho, gamma_a, rho));
    expected = 16.0 * QUARTER_PI * gamma_r * rho * rho / (gamma_a * gamma_a) / pixel;
    ratio = ratio_of(soft, &resolved);
    CHECK_NEAR(ratio, expected, RATIO_TOLERANCE * expected);
    CHECK(resolved == 1 && ratio > 3.0);
    CHECK(strstr(sentence, "soft wall") != NULL && strstr(sentence, "5e-06") != NULL);
    rho = 2e-5;
    CHECK_OK(asp_system_set_soft_wall(soft, gamma_r, rho, gamma_a, rho));
    expected = 16.0 * QUARTER_PI * gamma_r * rho * rho / (gamma_a * gamma_a) / pixel;
    ratio = ratio_of(soft, &resolved);
    CHECK_NEAR(ratio, expected, RATIO_TOLERANCE * expected);
    CHECK(resolved == 0 && starts_with(sentence, "not resolved: "));
    /* Without attraction: convex, nothing to resolve. */
    CHECK_OK(asp_system_set_soft_wall(soft, gamma_r, rho, 0.0, rho));
    CHECK(ratio_of(soft, &resolved) == 0.0 && resolved == 1);
    CHECK(strstr(sentence, "no attraction") != NULL);
    /* An attraction that fades no slower than the repulsion (rho_a <= rho_r/2) makes no
     * well at a positive gap. */
    CHECK_OK(asp_system_set_soft_wall(soft, 1.0, 1e-3, 1e-3, 4e-4));
    CHECK(ratio_of(soft, &resolved) == 0.0 && resolved == 1);
    CHECK(strstr(sentence, "no adhesive well") != NULL);
    asp_system_destroy(soft);
    asp_grid_destroy(scene_pixels);
  }

  /* ---- the soft wall with two ranges: its well and its largest tensile stress found here
   * on the potential itself, by bisection (to the last bit; both are stationary values, so
   * the ratio is exact to round-off) ---- */
  {
    const soft_wall wall = {1e-3, 0.02, 2e-4, 0.03};
    const double modulus = 1e-3;
    asp_system *soft = NULL;
    double well, inflection, depth, stress;
    CHECK_OK(asp_system_create(square, modulus, &soft));
    CHECK_OK(asp_system_set_soft_wall(soft, wall.gamma_r, wall.rho_r, wall.gamma_a, wall.rho_a));
    /* phi' rises through 0 at the well, phi'' falls through 0 at the inflection */
    well = bisect(soft_dphi, &wall, -0.1, 1.0);
    inflection = bisect(minus_d2phi, &wall, -0.1, 1.0);
    CHECK(well > 0.0 && inflection > well);
    depth = -soft_phi(&wall, well);
    stress = soft_dphi(&wall, inflection);
    expected = QUARTER_PI * modulus * depth / (stress * stress) / dx;
    ratio = ratio_of(soft, &resolved);
    CHECK_NEAR(ratio, expected, 1e-10 * expected);
    CHECK(resolved == 1);
    asp_system_destroy(soft);
  }

  /* ---- the Lennard-Jones wall: s = (27/10)(2/5)^(2/3) w/z0 ---- */
  {
    const double z0 = 0.01, stress_per_w = 2.7 * pow(0.4, 2.0 / 3.0) / z0;
    w = 1e-3;
    CHECK_OK(asp_system_set_lennard_jones(system, w, z0));
    expected = QUARTER_PI * w / (stress_per_w * w * stress_per_w * w) / dx;
    ratio = ratio_of(system, &resolved);
    CHECK_NEAR(ratio, expected, RATIO_TOLERANCE * expected);
    CHECK(resolved == 1 && strstr(sentence, "Lennard-Jones") != NULL);
    w = 1e-2;
    CHECK_OK(asp_system_set_lennard_jones(system, w, z0));
    expected = QUARTER_PI * w / (stress_per_w * w * stress_per_w * w) / dx;
    ratio = ratio_of(system, &resolved);
    CHECK_NEAR(ratio, expected, RATIO_TOLERANCE * expected);
    CHECK(resolved == 0 && starts_with(sentence, "not resolved: "));
  }

  /* ---- a user's potential, with and without the hard wall: no known length, said so; the
   * callback is not called ---- */
  CHECK_OK(asp_system_set_potential(system, counting_potential, NULL, 0));
  CHECK(ratio_of(system, &resolved) == 0.0 && resolved == 0);
  CHECK(starts_with(sentence, "unknown: ") && strstr(sentence, "cannot tell") != NULL);
  CHECK_OK(asp_system_set_potential(system, counting_potential, NULL, 1));
  CHECK(ratio_of(system, &resolved) == 0.0 && resolved == 0);
  CHECK(starts_with(sentence, "unknown: "));
  CHECK(calls == 0);

  /* ---- every output finite: a zone beyond the largest double is given as it, one below
   * the smallest normal double as that ---- */
  CHECK_OK(asp_grid_create_2d(64, 64, 64e-10, 64e-10, &tiny));
  CHECK_OK(asp_system_create(tiny, 1e20, &extreme));
  CHECK_OK(asp_system_set_adhesion(extreme, 1e-300, 1e-10)); /* l = 7.9e299, dx = 1e-10 */
  ratio = ratio_of(extreme, &resolved);
  CHECK(ratio == DBL_MAX && resolved == 1);
  asp_system_destroy(extreme);
  CHECK_OK(asp_grid_create_2d(64, 64, 64.0, 64.0, &wide));
  CHECK_OK(asp_system_create(wide, 1e-10, &extreme));
  CHECK_OK(asp_system_set_adhesion(extreme, 1e300, 1e-5)); /* l = 7.9e-321, dx = 1 */
  ratio = ratio_of(extreme, &resolved);
  CHECK(ratio == DBL_MIN && resolved == 0);

  /* ---- bad arguments ---- */
  CHECK_OK(asp_system_set_adhesion(system, 0.1, 0.01));
  CHECK_ERROR(asp_system_check_resolution(NULL, &ratio, &resolved, sentence,
                                          (int64_t)sizeof sentence, &length),
              ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_check_resolution(system, &ratio, &resolved, NULL, 16, &length),
              ASP_ERR_NULL_POINTER, "'buffer'");
  CHECK_ERROR(asp_system_check_resolution(system, &ratio, &resolved, sentence, -1, &length),
              ASP_ERR_INVALID_ARGUMENT, "'size'");
  /* A buffer too small: the text cut and terminated, its whole length, and the figures. */
  ratio = -1.0;
  resolved = -1;
  length = -1;
  CHECK_ERROR(asp_system_check_resolution(system, &ratio, &resolved, small,
                                          (int64_t)sizeof small, &length),
              ASP_ERR_SIZE_MISMATCH, "'size'");
  CHECK(small[sizeof small - 1] == '\0' && strlen(small) == sizeof small - 1);
  CHECK(strncmp(small, "not resolved", sizeof small - 1) == 0);
  CHECK(length > (int64_t)sizeof small);
  CHECK(resolved == 0 && ratio > 0.0 && ratio < 1.0);
  /* Size 0: the length alone, or, without a length pointer, a refusal. */
  CHECK_OK(asp_system_check_resolution(system, NULL, NULL, NULL, 0, &length));
  CHECK(length > 0);
  CHECK_ERROR(asp_system_check_resolution(system, NULL, NULL, NULL, 0, NULL),
              ASP_ERR_SIZE_MISMATCH, "'size'");
  /* Every output pointer but the buffer may be NULL. */
  CHECK_OK(asp_system_check_resolution(system, NULL, NULL, sentence, (int64_t)sizeof sentence,
                                       NULL));
  CHECK((int64_t)strlen(sentence) == length);

  asp_system_destroy(extreme);
  asp_system_destroy(on_line);
  asp_system_destroy(on_oblong);
  asp_system_destroy(free_system);
  asp_system_destroy(system);
  asp_grid_destroy(wide);
  asp_grid_destroy(tiny);
  asp_grid_destroy(line);
  asp_grid_destroy(oblong);
  asp_grid_destroy(square);
  return check_summary("resolution");
}
