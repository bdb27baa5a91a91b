/* SPDX-License-Identifier: GPL-2.0-or-later */
/* What asperity.h promises about watching a solve: the history (off by default, one row per
 * iteration from iteration 0 when on, a new one per solve), the progress callback (once per
 * iteration, with the history's iteration and error; non-zero cancels cleanly, leaving a
 * valid, consistent state from which the next solve continues), the termination reasons, and
 * the refusal of bad history arguments.
 *
 * "Consistent" is checked against the header's definitions, independently of the library: the
 * gap the pressure makes is recomputed by a plain DFT (g_p = K^-1 p - h + max h - delta with
 * K~(q) = E*|q|/2 and K~(0) = ASP_K0); the gap stored is its projection onto the wall (0 where
 * p > 0, max(g_p, 0) elsewhere: asp_system_get_field), and the error is computed from g_p (the
 * largest gap violation, |g_p| where p > 0 and max(-g_p, 0) where p = 0, times the pixel
 * stiffness mean_q K~(q), divided by ASP_REFERENCE_PRESSURE).
 *
 * ASP_TERMINATION_BREAKDOWN is not tested: no input the public interface accepts is known to
 * make "pk" produce a non-finite value (the library refuses such scenes before the solve), so
 * it cannot be provoked honestly from here. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

static const double pi = 3.14159265358979323846;

/* A scene: a grid, its heights and a system on it. */
typedef struct {
  asp_grid *grid;
  asp_system *system;
  int64_t nx, ny, n;
  double lx, ly, modulus;
  double *heights;
} Scene;

static int make_rough_scene(Scene *s, int dimension, int64_t nx, double lx, double modulus,
                            int64_t seed) {
  int ok;
  s->nx = nx;
  s->ny = dimension == 2 ? nx : 1;
  s->n = s->nx * s->ny;
  s->lx = lx;
  s->ly = dimension == 2 ? lx : 1.0;
  s->modulus = modulus;
  s->grid = NULL;
  s->system = NULL;
  s->heights = malloc((size_t)s->n * sizeof(double));
  ok = s->heights != NULL;
  ok = ok && (dimension == 2 ? asp_grid_create_2d(nx, nx, lx, lx, &s->grid)
                             : asp_grid_create_1d(nx, lx, &s->grid)) == ASP_OK;
  ok = ok && asp_topography_self_affine(s->grid, 0.8, lx, lx / 2, 4.0 * lx / (double)nx,
                                        ASP_RMS_SLOPE, 0.1, seed, s->heights, s->n) == ASP_OK;
  ok = ok && asp_system_create(s->grid, modulus, &s->system) == ASP_OK;
  ok = ok && asp_system_set_topography(s->system, s->heights, s->n) == ASP_OK;
  if (!ok) fprintf(stderr, "cannot make a scene: %s\n", asp_last_error_message());
  return ok;
}

static double get_scalar(const Scene *s, int key) {
  double value = NAN;
  asp_system_get(s->system, key, &value);
  return value;
}

static void free_scene(Scene *s) {
  asp_system_destroy(s->system);
  asp_grid_destroy(s->grid);
  free(s->heights);
}

/* Frequency of index k on an axis of n points, folded to |k| <= n/2. */
static double folded(int64_t k, int64_t n) { return (double)(2 * k <= n ? k : n - k); }

/* K~(q) of mode (kx, ky), or k0 for q = 0. */
static double stiffness(const Scene *s, int64_t kx, int64_t ky, double k0) {
  const double qx = 2.0 * pi * folded(kx, s->nx) / s->lx;
  const double qy = 2.0 * pi * folded(ky, s->ny) / s->ly;
  if (kx == 0 && ky == 0) return k0;
  return 0.5 * s->modulus * sqrt(qx * qx + qy * qy);
}

/* out = K^-1 p by a plain 2D DFT (separable, O(n (nx + ny))), with the q = 0 mode p^/k0. */
static void compliance_times(const Scene *s, const double *p, double k0, double *out) {
  const int64_t nx = s->nx, ny = s->ny, n = s->n;
  double *re = calloc((size_t)n, sizeof(double)), *im = calloc((size_t)n, sizeof(double));
  double *tre = calloc((size_t)n, sizeof(double)), *tim = calloc((size_t)n, sizeof(double));
  int64_t i, j, k;
  /* Forward along x, then along y: P(kx, ky) = sum p(i, j) e^{-2 pi i (kx i/nx + ky j/ny)}. */
  for (j = 0; j < ny; ++j)
    for (k = 0; k < nx; ++k)
      for (i = 0; i < nx; ++i) {
        const double a = -2.0 * pi * (double)((k * i) % nx) / (double)nx;
        tre[k + nx * j] += p[i + nx * j] * cos(a);
        tim[k + nx * j] += p[i + nx * j] * sin(a);
      }
  for (k = 0; k < ny; ++k)
    for (i = 0; i < nx; ++i)
      for (j = 0; j < ny; ++j) {
        const double a = -2.0 * pi * (double)((k * j) % ny) / (double)ny;
        re[i + nx * k] += tre[i + nx * j] * cos(a) - tim[i + nx * j] * sin(a);
        im[i + nx * k] += tre[i + nx * j] * sin(a) + tim[i + nx * j] * cos(a);
      }
  for (j = 0; j < ny; ++j)
    for (i = 0; i < nx; ++i) {
      const double c = 1.0 / (stiffness(s, i, j, k0) * (double)n);
      re[i + nx * j] *= c;
      im[i + nx * j] *= c;
    }
  /* Backward: along y, then along x, keeping the real part. */
  memset(tre, 0, (size_t)n * sizeof(double));
  memset(tim, 0, (size_t)n * sizeof(double));
  for (j = 0; j < ny; ++j)
    for (i = 0; i < nx; ++i)
      for (k = 0; k < ny; ++k) {
        const double a = 2.0 * pi * (double)((k * j) % ny) / (double)ny;
        tre[i + nx * j] += re[i + nx * k] * cos(a) - im[i + nx * k] * sin(a);
        tim[i + nx * j] += re[i + nx * k] * sin(a) + im[i + nx * k] * cos(a);
      }
  for (j = 0; j < ny; ++j)
    for (i = 0; i < nx; ++i) {
      double sum = 0.0;
      for (k = 0; k < nx; ++k) {
        const double a = 2.0 * pi * (double)((k * i) % nx) / (double)nx;
        sum += tre[k + nx * j] * cos(a) - tim[k + nx * j] * sin(a);
      }
      out[i + nx * j] = sum;
    }
  free(re);
  free(im);
  free(tre);
  free(tim);
}

/* The state left in the system is finite and consistent (see the top of the file), it
 * satisfies the control, and its error is the one the solver reported. */
static void check_consistent_state(const Scene *s, const asp_solver *solver, int control,
                                   double value, int line) {
  const int64_t n = s->n;
  double *p = malloc((size_t)n * sizeof(double)), *g = malloc((size_t)n * sizeof(double));
  double *u = malloc((size_t)n * sizeof(double)), *h = malloc((size_t)n * sizeof(double));
  double *kp = malloc((size_t)n * sizeof(double));
  double k0 = 0, reference = 0, delta = 0, mean_p = 0, mean_g = 0, force = 0, fraction = 0;
  double reported = -1, top, bottom, sum_p = 0, sum_g = 0, in_contact = 0, worst = 0, scale = 0;
  double violation = 0, k_pixel = 0;
  int64_t i, j;
  int ok = 1, finite = 1, non_negative = 1;

  ok &= asp_system_get_field(s->system, ASP_FIELD_PRESSURE, p, n) == ASP_OK;
  ok &= asp_system_get_field(s->system, ASP_FIELD_GAP, g, n) == ASP_OK;
  ok &= asp_system_get_field(s->system, ASP_FIELD_DISPLACEMENT, u, n) == ASP_OK;
  ok &= asp_system_get_field(s->system, ASP_FIELD_TOPOGRAPHY, h, n) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_K0, &k0) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_REFERENCE_PRESSURE, &reference) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_PENETRATION, &delta) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_MEAN_PRESSURE, &mean_p) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_MEAN_GAP, &mean_g) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_TOTAL_FORCE, &force) == ASP_OK;
  ok &= asp_system_get(s->system, ASP_CONTACT_FRACTION, &fraction) == ASP_OK;
  ok &= asp_solver_final_error(solver, &reported) == ASP_OK;
  check_record(ok, __FILE__, line, "the state and the report can be read");

  top = bottom = h[0];
  for (i = 0; i < n; ++i) {
    finite &= isfinite(p[i]) && isfinite(g[i]) && isfinite(u[i]);
    non_negative &= p[i] >= 0.0;
    sum_p += p[i];
    sum_g += g[i];
    in_contact += g[i] == 0.0 ? 1.0 : 0.0;
    if (h[i] > top) top = h[i];
    if (h[i] < bottom) bottom = h[i];
  }
  check_record(finite, __FILE__, line, "every field value is finite");
  check_record(non_negative, __FILE__, line, "no tensile pressure against a non-adhesive wall");
  check_near(force, mean_p * s->lx * s->ly, 1e-12 * fabs(force), __FILE__, line,
             "total force = mean pressure * lx * ly");
  check_near(mean_p, sum_p / (double)n, 1e-12 * fabs(mean_p), __FILE__, line,
             "ASP_MEAN_PRESSURE is the mean of the pressure field");
  check_near(mean_g, sum_g / (double)n, 1e-12 * (fabs(mean_g) + top - bottom), __FILE__, line,
             "ASP_MEAN_GAP is the mean of the gap field");
  check_near(fraction, in_contact / (double)n, 1e-15, __FILE__, line,
             "ASP_CONTACT_FRACTION is the fraction of pixels with g = 0");
  if (control == ASP_CONTROL_MEAN_PRESSURE)
    check_near(mean_p, value, 1e-12 * value, __FILE__, line, "the mean pressure is the target");
  else
    check_near(delta, value, 1e-12 * fabs(value), __FILE__, line,
               "the penetration is the target");

  /* The gap is the projection of the one the pressure produces (kp becomes that, g_p). */
  compliance_times(s, p, k0, kp);
  for (i = 0; i < n; ++i) {
    double projected;
    kp[i] += -h[i] + top - delta;
    projected = p[i] > 0.0 || kp[i] < 0.0 ? 0.0 : kp[i];
    if (fabs(projected - g[i]) > worst) worst = fabs(projected - g[i]);
    if (fabs(kp[i]) > scale) scale = fabs(kp[i]);
    if (p[i] > 0.0 && g[i] != 0.0) worst = HUGE_VAL;
  }
  check_near(worst, 0.0, 1e-11 * scale, __FILE__, line,
             "g is 0 where p > 0, and max(K^-1 p - h + max h - delta, 0) elsewhere");

  /* The reported error is the error of the solver's iterate, as the header defines it. */
  for (j = 0; j < s->ny; ++j)
    for (i = 0; i < s->nx; ++i) k_pixel += stiffness(s, i, j, k0) / (double)n;
  for (i = 0; i < n; ++i) {
    const double v = p[i] > 0.0 ? fabs(kp[i]) : (kp[i] < 0.0 ? -kp[i] : 0.0);
    if (v > violation) violation = v;
  }
  /* g_p is the test's own DFT, not the solver's gap: its rounding, at most the 1e-11 * scale
   * allowed above, is added to the 1e-9 of the error that the solver's own sums leave. */
  check_near(violation * k_pixel / reference, reported,
             1e-9 * reported + 1e-11 * scale * k_pixel / reference, __FILE__, line,
             "the final error is the largest gap violation * k_pixel / p_ref of g_p");

  free(p);
  free(g);
  free(u);
  free(h);
  free(kp);
}
#define CHECK_CONSISTENT_STATE(scene, solver, control, value) \
  check_consistent_state((scene), (solver), (control), (value), __LINE__)

/* ---- the history --------------------------------------------------------------------------- */

#define COLUMNS 7
static const int columns[COLUMNS] = {
    ASP_HISTORY_ITERATION, ASP_HISTORY_EVALUATIONS, ASP_HISTORY_TRANSFORMS,
    ASP_HISTORY_SECONDS,   ASP_HISTORY_ERROR,       ASP_HISTORY_OBJECTIVE,
    ASP_HISTORY_CONTACT_FRACTION};

/* A history: the length and each column, indexed like `columns`. */
typedef struct {
  int64_t length;
  double *column[COLUMNS];
} History;

static int read_history(const asp_solver *solver, History *history) {
  int c, ok = 1;
  history->length = -1;
  for (c = 0; c < COLUMNS; ++c) history->column[c] = NULL;
  if (asp_solver_history_length(solver, &history->length) != ASP_OK) return 0;
  for (c = 0; c < COLUMNS; ++c) {
    history->column[c] = malloc((size_t)(history->length + 1) * sizeof(double));
    ok &= history->column[c] != NULL &&
          asp_solver_get_history(solver, columns[c], history->column[c], history->length) ==
              ASP_OK;
  }
  return ok;
}

static void free_history(History *history) {
  int c;
  for (c = 0; c < COLUMNS; ++c) free(history->column[c]);
}

/* Everything the header says about the rows of a history of the solver's last solve. */
static void check_history(const asp_solver *solver, const History *h, int line) {
  const double *iteration = h->column[0], *evaluations = h->column[1];
  const double *transforms = h->column[2], *seconds = h->column[3], *error = h->column[4];
  const double *objective = h->column[5], *fraction = h->column[6];
  int64_t i, iterations = -1, evaluation_count = -1, transform_count = -1;
  double tolerance = 0, final_error = -1, elapsed = -1;
  int reason = 0, ok = 1;
  ok &= asp_solver_iterations(solver, &iterations) == ASP_OK;
  ok &= asp_solver_final_error(solver, &final_error) == ASP_OK;
  ok &= asp_solver_evaluations(solver, &evaluation_count) == ASP_OK;
  ok &= asp_solver_transforms(solver, &transform_count) == ASP_OK;
  ok &= asp_solver_termination(solver, &reason) == ASP_OK;
  ok &= asp_solver_elapsed_seconds(solver, &elapsed) == ASP_OK;
  ok &= asp_solver_get_option(solver, "tolerance", &tolerance) == ASP_OK;
  check_record(ok, __FILE__, line, "the report can be read");
  if (!check_record(h->length == iterations + 1, __FILE__, line,
                    "one row per iteration, from iteration 0"))
    return;

  for (i = 0; i < h->length; ++i) {
    int row = 1;
    row &= iteration[i] == (double)i;
    row &= evaluations[i] >= 0 && transforms[i] >= 0 && seconds[i] >= 0;
    row &= isfinite(error[i]) && error[i] >= 0 && isfinite(objective[i]);
    row &= fraction[i] >= 0.0 && fraction[i] <= 1.0;
    row &= evaluations[i] == floor(evaluations[i]) && transforms[i] == floor(transforms[i]);
    if (i > 0) {
      row &= iteration[i] > iteration[i - 1];
      row &= evaluations[i] >= evaluations[i - 1] && transforms[i] >= transforms[i - 1];
      row &= seconds[i] >= seconds[i - 1];
    }
    /* The solve stops when the error falls to the tolerance: no earlier row has. */
    if (i + 1 < h->length) row &= !(error[i] <= tolerance);
    if (!row) {
      fprintf(stderr, "  row %lld: %g %g %g %g %g %g %g\n", (long long)i, iteration[i],
              evaluations[i], transforms[i], seconds[i], error[i], objective[i], fraction[i]);
      check_record(0, __FILE__, line, "history row as documented");
      return;
    }
  }
  check_record(1, __FILE__, line, "history rows as documented");
  check_record(evaluations[h->length - 1] > 0 && transforms[h->length - 1] > 0, __FILE__, line,
               "evaluations and transforms are counted");
  check_record(evaluations[h->length - 1] == (double)evaluation_count &&
                   transforms[h->length - 1] == (double)transform_count,
               __FILE__, line, "the report's work counters are the last row's");
  check_record(error[h->length - 1] == final_error, __FILE__, line,
               "the last row's error is the final error");
  check_record(seconds[h->length - 1] <= elapsed, __FILE__, line,
               "the history's seconds are within the solve's elapsed seconds");
  if (reason == ASP_TERMINATION_CONVERGED)
    check_record(error[h->length - 1] <= tolerance, __FILE__, line,
                 "converged: the last error meets the tolerance");
  else
    check_record(error[h->length - 1] > tolerance, __FILE__, line,
                 "not converged: the last error does not meet the tolerance");
}
#define CHECK_HISTORY(solver, h) check_history((solver), (h), __LINE__)

static void test_history_off_by_default(Scene *s) {
  asp_solver *solver = NULL;
  int64_t length = -1;
  int status;
  CHECK_OK(asp_solver_create("pk", &solver));
  /* Before any solve there is no history: refused as a report before any solve, or empty. */
  status = asp_solver_history_length(solver, &length);
  CHECK(status == ASP_ERR_INVALID_STATE || (status == ASP_OK && length == 0));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK(length == 0);
  asp_solver_destroy(solver);
}

static void test_history_rows(Scene *s) {
  asp_solver *solver = NULL;
  History h;
  int64_t length = -1, iterations = -1;
  int reason = 0, converged = 0;
  double fraction = -1, objective_first, objective_last, energy;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK(read_history(solver, &h));
  CHECK(h.length > 2);
  CHECK_HISTORY(solver, &h);
  if (h.length > 2) {
    /* The last row describes the state left in the system. */
    CHECK_OK(asp_system_get(s->system, ASP_CONTACT_FRACTION, &fraction));
    CHECK_NEAR(h.column[6][h.length - 1], fraction, 0.5 / (double)s->n);
    /* The objective is minimised: it ends lower than it starts, at the value asp_solver_describe
     * and docs/algorithms.md give for "pk": minus the elastic energy, q = 0 term included. */
    objective_first = h.column[5][0];
    objective_last = h.column[5][h.length - 1];
    CHECK(objective_last < objective_first);
    energy = get_scalar(s, ASP_ELASTIC_ENERGY) + get_scalar(s, ASP_MEAN_MODE_ENERGY);
    CHECK_NEAR(objective_last, -energy, 1e-6 * energy);
  }
  CHECK_CONSISTENT_STATE(s, solver, ASP_CONTROL_MEAN_PRESSURE, 0.005);
  free_history(&h);

  /* Each solve starts a new history: a warm start at another load. */
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.008));
  CHECK(read_history(solver, &h));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(h.length == iterations + 1);
  CHECK_HISTORY(solver, &h);
  free_history(&h);
  /* Penetration control records the same way. */
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_PENETRATION, 0.01));
  CHECK(read_history(solver, &h));
  CHECK_HISTORY(solver, &h);
  free_history(&h);

  /* Off again: the next solve records nothing. */
  CHECK_OK(asp_solver_set_history(solver, 0));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK(length == 0);
  /* Any non-zero value turns it on. */
  CHECK_OK(asp_solver_set_history(solver, -3));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(length == iterations + 1 && length > 1);
  asp_solver_destroy(solver);
}

static void test_history_arguments(Scene *s) {
  asp_solver *solver = NULL;
  double values[512];
  int64_t length = 0;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK(length > 1 && length < 512);
  if (!(length > 1 && length < 512)) length = 2;

  CHECK_ERROR(asp_solver_get_history(solver, 0, values, length), ASP_ERR_INVALID_ARGUMENT,
              "'column'");
  CHECK_ERROR(asp_solver_get_history(solver, 600, values, length), ASP_ERR_INVALID_ARGUMENT,
              "'column'");
  CHECK_ERROR(asp_solver_get_history(solver, 608, values, length), ASP_ERR_INVALID_ARGUMENT,
              "'column'");
  CHECK_ERROR(asp_solver_get_history(solver, -1, values, length), ASP_ERR_INVALID_ARGUMENT,
              "'column'");
  CHECK_ERROR(asp_solver_get_history(solver, ASP_HISTORY_ERROR, values, length - 1),
              ASP_ERR_SIZE_MISMATCH, "'values'");
  CHECK_ERROR(asp_solver_get_history(solver, ASP_HISTORY_ERROR, values, length + 1),
              ASP_ERR_SIZE_MISMATCH, "'values'");
  CHECK_ERROR(asp_solver_get_history(solver, ASP_HISTORY_ERROR, values, -1),
              ASP_ERR_SIZE_MISMATCH, "'values'");
  CHECK_ERROR(asp_solver_get_history(solver, ASP_HISTORY_ERROR, values, 0),
              ASP_ERR_SIZE_MISMATCH, "'values'");
  CHECK_ERROR(asp_solver_get_history(solver, ASP_HISTORY_ERROR, NULL, length),
              ASP_ERR_NULL_POINTER, "'values'");
  CHECK_ERROR(asp_solver_get_history(NULL, ASP_HISTORY_ERROR, values, length),
              ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_history_length(solver, NULL), ASP_ERR_NULL_POINTER, "'length'");
  CHECK_ERROR(asp_solver_history_length(NULL, &length), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_history(NULL, 1), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_progress(NULL, NULL, NULL), ASP_ERR_NULL_POINTER, "'solver'");
  /* The refusals left the history as it was. */
  CHECK_OK(asp_solver_history_length(solver, &length));
  CHECK(length > 1);
  CHECK_OK(asp_solver_get_history(solver, ASP_HISTORY_ITERATION, values, length));
  CHECK(values[0] == 0.0 && values[length - 1] == (double)(length - 1));
  asp_solver_destroy(solver);
}

/* ---- the progress callback ----------------------------------------------------------------- */

#define MAX_CALLS 4096
typedef struct {
  int64_t calls;
  int64_t iteration[MAX_CALLS];
  double seconds[MAX_CALLS];
  double error[MAX_CALLS];
  int64_t cancel_at;         /* return non-zero at this iteration (-1: never) */
  int cancel_when_converged; /* return non-zero once the error meets this tolerance */
  double tolerance;
  int wrong_user_data;
} Calls;

static int record_call(int64_t iteration, double seconds, double error, void *user_data) {
  Calls *c = (Calls *)user_data;
  if (c->calls < MAX_CALLS) {
    c->iteration[c->calls] = iteration;
    c->seconds[c->calls] = seconds;
    c->error[c->calls] = error;
  }
  ++c->calls;
  if (c->cancel_when_converged && error <= c->tolerance) return 1;
  return iteration == c->cancel_at ? 7 : 0;
}

static void reset_calls(Calls *c) {
  c->calls = 0;
  c->cancel_at = -1;
  c->cancel_when_converged = 0;
  c->tolerance = 0;
}

static void test_progress(Scene *s) {
  static Calls calls;
  asp_solver *solver = NULL;
  History h;
  int64_t i, iterations = -1;
  int same = 1;
  CHECK_OK(asp_solver_create("pk", &solver));
  reset_calls(&calls);
  CHECK_OK(asp_solver_set_progress(solver, record_call, &calls));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(read_history(solver, &h));
  /* Once per iteration, iteration 0 included, with the history's iteration and error. */
  CHECK(calls.calls == iterations + 1);
  CHECK(calls.calls == h.length);
  for (i = 0; i < calls.calls && i < h.length && i < MAX_CALLS; ++i) {
    same &= calls.iteration[i] == i && (double)calls.iteration[i] == h.column[0][i];
    same &= calls.error[i] == h.column[4][i];
    same &= calls.seconds[i] >= 0.0 && (i == 0 || calls.seconds[i] >= calls.seconds[i - 1]);
  }
  CHECK(same);
  free_history(&h);

  /* Without the history, the callback still comes once per iteration. */
  reset_calls(&calls);
  CHECK_OK(asp_solver_set_history(solver, 0));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_PENETRATION, 0.01));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(calls.calls == iterations + 1);
  CHECK(calls.calls > 0 && calls.iteration[0] == 0);

  /* NULL removes it. */
  reset_calls(&calls);
  CHECK_OK(asp_solver_set_progress(solver, NULL, &calls));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK(calls.calls == 0);
  asp_solver_destroy(solver);
}

/* user_data is passed through untouched, per solver. */
static int check_user_data(int64_t iteration, double seconds, double error, void *user_data) {
  Calls *c = (Calls *)user_data;
  (void)iteration;
  (void)seconds;
  (void)error;
  if (c->cancel_at != 12345) c->wrong_user_data = 1;
  ++c->calls;
  return 0;
}

static void test_user_data(Scene *s) {
  static Calls a, b;
  asp_solver *first = NULL, *second = NULL;
  reset_calls(&a);
  reset_calls(&b);
  a.cancel_at = b.cancel_at = 12345;
  a.wrong_user_data = b.wrong_user_data = 0;
  CHECK_OK(asp_solver_create("pk", &first));
  CHECK_OK(asp_solver_create("pk", &second));
  CHECK_OK(asp_solver_set_progress(first, check_user_data, &a));
  CHECK_OK(asp_solver_set_progress(second, check_user_data, &b));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(first, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK(a.calls > 0 && b.calls == 0 && !a.wrong_user_data);
  CHECK_OK(asp_solver_solve(second, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.004));
  CHECK(b.calls > 0 && !b.wrong_user_data);
  asp_solver_destroy(first);
  asp_solver_destroy(second);
}

/* ---- termination reasons ------------------------------------------------------------------- */

static void test_cancelled(Scene *s, int control, double value) {
  static Calls calls;
  asp_solver *solver = NULL;
  History h;
  int reason = 0, converged = -1;
  int64_t iterations = -1;
  double error = -1, cold_error = -1;
  printf("cancel, control %d\n", control);
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  reset_calls(&calls);
  calls.cancel_at = 5;
  CHECK_OK(asp_solver_set_progress(solver, record_call, &calls));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, control, value));
  CHECK(strcmp(asp_last_error_message(), "") == 0);
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CANCELLED);
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 0);
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(iterations == 5);
  CHECK(calls.calls == 6);
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK(calls.calls == 6 && error == calls.error[5]);
  CHECK(read_history(solver, &h));
  CHECK(h.length == 6);
  CHECK_HISTORY(solver, &h);
  free_history(&h);
  CHECK_CONSISTENT_STATE(s, solver, control, value);

  /* The next solve starts from that state: its iteration 0 is the cancelled iterate, with the
   * same error, and it converges. */
  CHECK_OK(asp_solver_set_progress(solver, NULL, NULL));
  CHECK_OK(asp_solver_solve(solver, s->system, control, value));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);
  CHECK(read_history(solver, &h));
  CHECK(h.length > 1);
  if (h.length > 1) CHECK_NEAR(h.column[4][0], error, 1e-9 * error);
  free_history(&h);
  CHECK_CONSISTENT_STATE(s, solver, control, value);
  /* A cold start begins elsewhere. */
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, control, value));
  CHECK(read_history(solver, &h));
  if (h.length > 1) cold_error = h.column[4][0];
  CHECK(fabs(cold_error - error) > 1e-6 * error);
  free_history(&h);

  /* Cancelled at the starting point: iteration 0, the starting state. */
  reset_calls(&calls);
  calls.cancel_at = 0;
  CHECK_OK(asp_solver_set_progress(solver, record_call, &calls));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, control, value));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CANCELLED);
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(iterations == 0 && calls.calls == 1);
  CHECK_CONSISTENT_STATE(s, solver, control, value);
  asp_solver_destroy(solver);
}

/* The header: a callback that asks to stop at the iteration whose error met the tolerance
 * gets ASP_TERMINATION_CONVERGED: a converged state is reported as converged. */
static void test_cancelled_at_convergence(Scene *s) {
  static Calls calls;
  asp_solver *solver = NULL;
  int reason = 0, converged = -1;
  double error = -1;
  CHECK_OK(asp_solver_create("pk", &solver));
  reset_calls(&calls);
  calls.cancel_when_converged = 1;
  calls.tolerance = 1e-8;
  CHECK_OK(asp_solver_set_progress(solver, record_call, &calls));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK(error <= 1e-8);
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);
  /* "converged" follows the reason. */
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == (reason == ASP_TERMINATION_CONVERGED));
  asp_solver_destroy(solver);
}

static void test_converged(Scene *s, int control, double value) {
  asp_solver *solver = NULL;
  int reason = 0, converged = -1;
  double error = -1, seconds = -1;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-10));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, control, value));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_CONVERGED);
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK(error <= 1e-10);
  CHECK_OK(asp_solver_elapsed_seconds(solver, &seconds));
  CHECK(isfinite(seconds) && seconds >= 0.0);
  CHECK_CONSISTENT_STATE(s, solver, control, value);
  asp_solver_destroy(solver);
}

static void test_iteration_limit(Scene *s, int control, double value) {
  asp_solver *solver = NULL;
  History h;
  int reason = 0, converged = -1;
  int64_t iterations = -1;
  double error = -1;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_solver_set_max_iterations(solver, 1));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, control, value));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_ITERATION_LIMIT);
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 0);
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(iterations == 1);
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK(isfinite(error) && error > 1e-8);
  CHECK(read_history(solver, &h));
  CHECK(h.length == 2);
  CHECK_HISTORY(solver, &h);
  free_history(&h);
  CHECK_CONSISTENT_STATE(s, solver, control, value);
  asp_solver_destroy(solver);
}

/* Stalled, honestly: a tolerance below what rounding lets the error reach (about 1e-14 here),
 * so the error levels off; with a stall window of 20 the solve stops as stalled once the
 * smallest error has not fallen by 1 % within 20 iterations. With the window 0 (never) or the
 * default 1000, the same solve runs into the iteration limit instead. */
static void test_stalled(Scene *s) {
  asp_solver *solver = NULL;
  History h;
  int reason = 0, converged = -1;
  int64_t iterations = -1, i;
  const int64_t window = 20;
  double before = HUGE_VAL, within = HUGE_VAL;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-30));
  CHECK_OK(asp_solver_set_option(solver, "stall_window", (double)window));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_STALLED);
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 0);
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(iterations >= window && iterations < 10000);
  CHECK(read_history(solver, &h));
  CHECK_HISTORY(solver, &h);
  if (h.length == iterations + 1 && iterations >= window) {
    /* No 1 % progress of the smallest error within the last `window` iterations. */
    for (i = 0; i <= iterations - window; ++i)
      if (h.column[4][i] < before) before = h.column[4][i];
    for (i = iterations - window + 1; i <= iterations; ++i)
      if (h.column[4][i] < within) within = h.column[4][i];
    CHECK(within >= 0.99 * before);
    /* ... and it had converged as far as rounding allows. */
    CHECK(before < 1e-12);
  }
  free_history(&h);
  CHECK_CONSISTENT_STATE(s, solver, ASP_CONTROL_MEAN_PRESSURE, 0.005);

  CHECK_OK(asp_solver_set_max_iterations(solver, 150));
  CHECK_OK(asp_solver_set_option(solver, "stall_window", 0.0));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_ITERATION_LIMIT);
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK(iterations == 150);
  CHECK_OK(asp_solver_set_option(solver, "stall_window", 1000.0));
  CHECK_OK(asp_system_reset(s->system));
  CHECK_OK(asp_solver_solve(solver, s->system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_termination(solver, &reason));
  CHECK(reason == ASP_TERMINATION_ITERATION_LIMIT);
  asp_solver_destroy(solver);
}

int main(void) {
  Scene line, surface;
  if (!make_rough_scene(&line, 1, 128, 3.0, 2.0, 11)) return 1;
  if (!make_rough_scene(&surface, 2, 32, 1.0, 1.0, 7)) return 1;

  test_history_off_by_default(&surface);
  test_history_rows(&surface);
  test_history_arguments(&surface);
  test_progress(&surface);
  test_user_data(&surface);

  test_converged(&line, ASP_CONTROL_MEAN_PRESSURE, 0.01);
  test_converged(&surface, ASP_CONTROL_PENETRATION, 0.01);
  test_iteration_limit(&line, ASP_CONTROL_MEAN_PRESSURE, 0.01);
  test_iteration_limit(&surface, ASP_CONTROL_PENETRATION, 0.01);
  test_cancelled(&line, ASP_CONTROL_MEAN_PRESSURE, 0.01);
  test_cancelled(&line, ASP_CONTROL_PENETRATION, 0.02);
  test_cancelled(&surface, ASP_CONTROL_MEAN_PRESSURE, 0.005);
  test_cancelled_at_convergence(&surface);
  test_stalled(&surface);

  free_scene(&line);
  free_scene(&surface);
  return check_summary("api.solver_monitor");
}
