/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Constant families (asperity.h, "Constants"): FFT planning 1xx, normalisations 2xx, scalar
 * results 3xx, fields 4xx, controls 5xx, history columns 6xx, termination reasons 7xx,
 * detrending modes 8xx, solver report keys 9xx, status codes 0..99. Every constant lies in its
 * family's range and no two are equal; every call that takes a constant of one family refuses
 * the constants of every other family, and values of no family, with
 * ASP_ERR_INVALID_ARGUMENT and a message naming the argument and both families, and changes
 * nothing. */
#include <limits.h>
#include <stdint.h>

#include "check.h"

enum {
  PLANNING,
  NORMALISATION,
  SCALAR,
  FIELD,
  CONTROL,
  COLUMN,
  TERMINATION,
  DETREND,
  REPORT,
  FAMILIES
};

/* How a message names each family: the family's own word, as the header's list has it. */
static const char *const family_word[FAMILIES] = {
    "planning",       "normalisation", "scalar",     "field",     "control",
    "history column", "termination",   "detrending", "report key"};

typedef struct {
  int value;
  const char *name;
  int family;
} Constant;

#define C(name, family) {name, #name, family}
static const Constant constants[] = {
    C(ASP_FFT_ESTIMATE, PLANNING),
    C(ASP_FFT_MEASURE, PLANNING),
    C(ASP_FFT_PATIENT, PLANNING),
    C(ASP_RMS_HEIGHT, NORMALISATION),
    C(ASP_RMS_SLOPE, NORMALISATION),
    C(ASP_CONTACT_FRACTION, SCALAR),
    C(ASP_MEAN_PRESSURE, SCALAR),
    C(ASP_MEAN_GAP, SCALAR),
    C(ASP_ELASTIC_ENERGY, SCALAR),
    C(ASP_PENETRATION, SCALAR),
    C(ASP_TOTAL_FORCE, SCALAR),
    C(ASP_K0, SCALAR),
    C(ASP_REFERENCE_PRESSURE, SCALAR),
    C(ASP_MEAN_MODE_ENERGY, SCALAR),
    C(ASP_ATTRACTIVE_FRACTION, SCALAR),
    C(ASP_REPULSIVE_FORCE, SCALAR),
    C(ASP_ATTRACTIVE_FORCE, SCALAR),
    C(ASP_INTERACTION_ENERGY, SCALAR),
    C(ASP_WORK_OF_ADHESION, SCALAR),
    C(ASP_ADHESION_RANGE, SCALAR),
    C(ASP_COMPRESSIVE_FRACTION, SCALAR),
    C(ASP_FIELD_PRESSURE, FIELD),
    C(ASP_FIELD_GAP, FIELD),
    C(ASP_FIELD_DISPLACEMENT, FIELD),
    C(ASP_FIELD_TOPOGRAPHY, FIELD),
    C(ASP_FIELD_CONTACT, FIELD),
    C(ASP_CONTROL_MEAN_PRESSURE, CONTROL),
    C(ASP_CONTROL_PENETRATION, CONTROL),
    C(ASP_CONTROL_MEAN_GAP, CONTROL),
    C(ASP_HISTORY_ITERATION, COLUMN),
    C(ASP_HISTORY_EVALUATIONS, COLUMN),
    C(ASP_HISTORY_TRANSFORMS, COLUMN),
    C(ASP_HISTORY_SECONDS, COLUMN),
    C(ASP_HISTORY_ERROR, COLUMN),
    C(ASP_HISTORY_OBJECTIVE, COLUMN),
    C(ASP_HISTORY_CONTACT_FRACTION, COLUMN),
    C(ASP_TERMINATION_CONVERGED, TERMINATION),
    C(ASP_TERMINATION_ITERATION_LIMIT, TERMINATION),
    C(ASP_TERMINATION_CANCELLED, TERMINATION),
    C(ASP_TERMINATION_STALLED, TERMINATION),
    C(ASP_TERMINATION_BREAKDOWN, TERMINATION),
    C(ASP_TERMINATION_SEPARATED, TERMINATION),
    C(ASP_DETREND_MEAN, DETREND),
    C(ASP_DETREND_PLANE, DETREND),
    C(ASP_DETREND_CURVATURE, DETREND),
    C(ASP_REPORT_TERMINATION, REPORT),
    C(ASP_REPORT_CONVERGED, REPORT),
    C(ASP_REPORT_ITERATIONS, REPORT),
    C(ASP_REPORT_EVALUATIONS, REPORT),
    C(ASP_REPORT_TRANSFORMS, REPORT),
    C(ASP_REPORT_FINAL_ERROR, REPORT),
    C(ASP_REPORT_ELAPSED_SECONDS, REPORT),
    C(ASP_REPORT_HISTORY_LENGTH, REPORT),
};
#undef C
#define N_CONSTANTS ((int)(sizeof constants / sizeof constants[0]))

static const int statuses[] = {ASP_OK,
                               ASP_ERR_NULL_POINTER,
                               ASP_ERR_INVALID_ARGUMENT,
                               ASP_ERR_SIZE_MISMATCH,
                               ASP_ERR_OUT_OF_MEMORY,
                               ASP_ERR_UNSUPPORTED,
                               ASP_ERR_INVALID_STATE,
                               ASP_ERR_FFT,
                               ASP_ERR_CALLBACK,
                               ASP_ERR_INTERNAL,
                               ASP_ERR_IO};

/* Values that belong to no family, inside and outside the families' ranges. */
static const int strays[] = {INT_MIN, -701, -1, 0, 1, 2, 99, 100, 104, 199, 200,
                             203, 300, 317, 399, 400, 406, 500, 504, 600, 608,
                             700, 707, 800, 804, 900, 909, 1000, INT_MAX};
#define N_STRAYS ((int)(sizeof strays / sizeof strays[0]))

#define NX 8
#define N (NX * NX)

static asp_grid *grid = NULL;
static asp_system *scene = NULL;
static asp_solver *solver = NULL;
static double heights[N];

/* The calls that take a constant, each with `value` in the place of its constant; the
 * argument's name as the header spells it; the family it expects. */
typedef struct {
  const char *call;
  const char *argument;
  int family;
} Taker;

static const Taker takers[] = {
    {"asp_grid_set_fft_planning", "'planning'", PLANNING},
    {"asp_topography_self_affine", "'normalise'", NORMALISATION},
    {"asp_system_get", "'key'", SCALAR},
    {"asp_system_get_field", "'field'", FIELD},
    {"asp_solver_solve", "'control'", CONTROL},
    {"asp_solver_get_history", "'column'", COLUMN},
    {"asp_topography_detrend", "'mode'", DETREND},
    {"asp_solver_get", "'key'", REPORT},
};
#define N_TAKERS ((int)(sizeof takers / sizeof takers[0]))

static int call_with(int taker, int value, asp_grid *fresh_grid) {
  static double out[N];
  double scalar = 0.0;
  switch (taker) {
    case 0: return asp_grid_set_fft_planning(fresh_grid, value);
    case 1:
      return asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 0.25, value, 1.0, 1, out, N);
    case 2: return asp_system_get(scene, value, &scalar);
    case 3: return asp_system_get_field(scene, value, out, N);
    case 4: return asp_solver_solve(solver, scene, value, 0.01);
    case 6: {
      int i;
      for (i = 0; i < N; ++i) out[i] = heights[i];
      return asp_topography_detrend(grid, value, out, N);
    }
    case 7:
      /* A solve first, so that only the key can be wrong. */
      asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.01);
      return asp_solver_get(solver, value, &scalar);
    default: {
      /* A solve with a history first, so that only the column can be wrong. */
      int64_t length = 0;
      asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.01);
      asp_solver_history_length(solver, &length);
      return asp_solver_get_history(solver, value, out, length);
    }
  }
}

static void test_ranges_and_distinct(void) {
  int i, j, distinct = 1, in_range = 1;
  for (i = 0; i < N_CONSTANTS; ++i) {
    const int lowest = 100 * (constants[i].family + 1);
    if (constants[i].value < lowest || constants[i].value > lowest + 99) {
      fprintf(stderr, "  %s = %d is outside its family's range %d..%d\n", constants[i].name,
              constants[i].value, lowest, lowest + 99);
      in_range = 0;
    }
    for (j = 0; j < i; ++j)
      if (constants[i].value == constants[j].value) {
        fprintf(stderr, "  %s and %s are both %d\n", constants[i].name, constants[j].name,
                constants[i].value);
        distinct = 0;
      }
    for (j = 0; j < (int)(sizeof statuses / sizeof statuses[0]); ++j)
      if (constants[i].value == statuses[j]) distinct = 0;
  }
  CHECK(in_range);
  CHECK(distinct);
  for (j = 0; j < (int)(sizeof statuses / sizeof statuses[0]); ++j)
    CHECK(statuses[j] == j && statuses[j] >= 0 && statuses[j] <= 99);
}

/* Every call refuses every constant of another family and every stray value. */
static void test_refusals(void) {
  int t, i;
  for (t = 0; t < N_TAKERS; ++t) {
    int refused = 0, wrong = 0;
    /* The planning can only be set before plans exist: a fresh grid for each try, so that a
     * refusal for the wrong reason (plans already made) cannot pass for the right one. */
    for (i = 0; i < N_CONSTANTS + N_STRAYS; ++i) {
      const int is_constant = i < N_CONSTANTS;
      const int value = is_constant ? constants[i].value : strays[i - N_CONSTANTS];
      asp_grid *fresh = NULL;
      int status, ok;
      if (is_constant && constants[i].family == takers[t].family) continue;
      if (asp_grid_create_2d(NX, NX, 1.0, 1.0, &fresh) != ASP_OK) return;
      status = call_with(t, value, fresh);
      check_save_message();
      ok = status == ASP_ERR_INVALID_ARGUMENT && strstr(check_message, takers[t].call) != NULL &&
           strstr(check_message, takers[t].argument) != NULL &&
           strstr(check_message, family_word[takers[t].family]) != NULL;
      if (is_constant)
        ok = ok && strstr(check_message, constants[i].name) != NULL &&
             strstr(check_message, family_word[constants[i].family]) != NULL;
      if (ok) {
        ++refused;
      } else {
        ++wrong;
        fprintf(stderr, "  %s with %s (%d): status %d, message '%s'\n", takers[t].call,
                is_constant ? constants[i].name : "a stray value", value, status,
                check_message);
      }
      asp_grid_destroy(fresh);
    }
    printf("%s: %d refusals as documented\n", takers[t].call, refused);
    if (!CHECK(wrong == 0))
      fprintf(stderr, "  %s refused %d values not as documented (see above)\n", takers[t].call,
              wrong);
  }
}

/* Every call accepts the constants of its own family. */
static void test_own_family_accepted(void) {
  int t, i;
  for (t = 0; t < N_TAKERS; ++t)
    for (i = 0; i < N_CONSTANTS; ++i) {
      asp_grid *fresh = NULL;
      int status;
      if (constants[i].family != takers[t].family) continue;
      /* "pk" does not offer mean-gap control: refused as unsupported, not as a misfit. */
      if (constants[i].value == ASP_CONTROL_MEAN_GAP) {
        CHECK_ERROR(call_with(t, constants[i].value, NULL), ASP_ERR_UNSUPPORTED, "mean_gap");
        continue;
      }
      if (asp_grid_create_2d(NX, NX, 1.0, 1.0, &fresh) != ASP_OK) return;
      status = call_with(t, constants[i].value, fresh);
      if (!CHECK(status == ASP_OK))
        fprintf(stderr, "  %s refused its own %s: %s\n", takers[t].call, constants[i].name,
                asp_last_error_message());
      asp_grid_destroy(fresh);
    }
  /* Termination reasons are only ever given out, from their own family. */
  {
    int reason = 0;
    CHECK_OK(asp_solver_termination(solver, &reason));
    CHECK(reason >= 701 && reason <= 705);
  }
}

/* A refused constant changes nothing: the state, the grid's planning, the report. */
static void test_refusal_changes_nothing(void) {
  static double before[N], after[N];
  asp_grid *fresh = NULL;
  int64_t iterations = -1, again = -2;
  int i, same = 1;
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.01));
  CHECK_OK(asp_solver_iterations(solver, &iterations));
  CHECK_OK(asp_system_get_field(scene, ASP_FIELD_PRESSURE, before, N));
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_CONTACT_FRACTION, 0.02),
              ASP_ERR_INVALID_ARGUMENT, "'control'");
  CHECK_ERROR(asp_solver_solve(solver, scene, ASP_FIELD_PRESSURE, 0.02),
              ASP_ERR_INVALID_ARGUMENT, "'control'");
  CHECK_ERROR(asp_system_get_field(scene, ASP_CONTROL_PENETRATION, after, N),
              ASP_ERR_INVALID_ARGUMENT, "'field'");
  CHECK_OK(asp_system_get_field(scene, ASP_FIELD_PRESSURE, after, N));
  for (i = 0; i < N; ++i) same &= before[i] == after[i];
  CHECK(same);

  /* A planning refused on a fresh grid leaves it fresh: a right one is still accepted. */
  CHECK_OK(asp_grid_create_2d(NX, NX, 1.0, 1.0, &fresh));
  CHECK_ERROR(asp_grid_set_fft_planning(fresh, ASP_RMS_HEIGHT), ASP_ERR_INVALID_ARGUMENT,
              "'planning'");
  CHECK_ERROR(asp_grid_set_fft_planning(fresh, ASP_TERMINATION_CONVERGED),
              ASP_ERR_INVALID_ARGUMENT, "'planning'");
  CHECK_OK(asp_grid_set_fft_planning(fresh, ASP_FFT_ESTIMATE));
  asp_grid_destroy(fresh);

  /* A history column given a termination reason: refused, the history still there. */
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.01));
  CHECK_OK(asp_solver_iterations(solver, &again));
  {
    int64_t length = 0;
    CHECK_OK(asp_solver_history_length(solver, &length));
    CHECK_ERROR(asp_solver_get_history(solver, ASP_TERMINATION_CONVERGED, after, length),
                ASP_ERR_INVALID_ARGUMENT, "'column'");
    CHECK_MESSAGE_HAS("ASP_TERMINATION_CONVERGED");
    CHECK_OK(asp_solver_get_history(solver, ASP_HISTORY_ITERATION, after, length));
  }
  /* The documented examples. */
  {
    double value = 0;
    CHECK_ERROR(asp_system_get(scene, ASP_FIELD_GAP, &value), ASP_ERR_INVALID_ARGUMENT, "'key'");
    CHECK_MESSAGE_HAS("ASP_FIELD_GAP");
    CHECK_ERROR(asp_system_get(scene, ASP_HISTORY_ERROR, &value), ASP_ERR_INVALID_ARGUMENT,
                "'key'");
    CHECK_MESSAGE_HAS("ASP_HISTORY_ERROR");
  }
}

int main(void) {
  if (asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid) != ASP_OK ||
      asp_topography_sinusoid(grid, 0.01, 1, 1, heights, N) != ASP_OK ||
      asp_system_create(grid, 1.0, &scene) != ASP_OK ||
      asp_system_set_topography(scene, heights, N) != ASP_OK ||
      asp_solver_create("pk", &solver) != ASP_OK || asp_solver_set_history(solver, 1) != ASP_OK ||
      asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.01) != ASP_OK) {
    fprintf(stderr, "cannot set up: %s\n", asp_last_error_message());
    return 1;
  }
  test_ranges_and_distinct();
  test_refusals();
  test_own_family_accepted();
  test_refusal_changes_nothing();
  asp_solver_destroy(solver);
  asp_system_destroy(scene);
  asp_grid_destroy(grid);
  return check_summary("api.constant_families");
}
