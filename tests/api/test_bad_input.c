/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Bad input across the whole C API, one function after another: every required handle or
 * pointer passed as NULL (ASP_ERR_NULL_POINTER naming it), every floating-point argument
 * given NaN and infinities (ASP_ERR_INVALID_ARGUMENT naming it), every array given a count
 * one off (ASP_ERR_SIZE_MISMATCH naming it), constants of the wrong family, and callbacks
 * that call back into the library with the handles being solved (ASP_ERR_INVALID_STATE, the
 * call refused and the solve unharmed), and asp_solver_supports agreeing with what a solve
 * does for every algorithm, control, substrate and interaction. After each refusal on a system, its topography,
 * pressure, gap and scalars are unchanged to the bit, and the handles work: the contract of
 * the header's "Errors" section. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#define NX 32
#define NY 24
#define N (NX * NY)

static asp_grid *grid;
static asp_system *sys;
static asp_solver *solver;
static double heights[N], field[N], spare[N + 1];

/* ---- the system's state, to check that a refused call left it alone -------------------- */

typedef struct {
  double topography[N], pressure[N], gap[N], scalars[4];
} Snapshot;

static void take(Snapshot *s) {
  const int keys[4] = {ASP_MEAN_PRESSURE, ASP_MEAN_GAP, ASP_PENETRATION, ASP_CONTACT_FRACTION};
  int k;
  CHECK_OK(asp_system_get_field(sys, ASP_FIELD_TOPOGRAPHY, s->topography, N));
  CHECK_OK(asp_system_get_field(sys, ASP_FIELD_PRESSURE, s->pressure, N));
  CHECK_OK(asp_system_get_field(sys, ASP_FIELD_GAP, s->gap, N));
  for (k = 0; k < 4; ++k) CHECK_OK(asp_system_get(sys, keys[k], &s->scalars[k]));
}

static Snapshot before, after;

/* A refused call: its status, its message naming `name`, and the system as it was. */
#define REFUSED(call, status, name)                                      \
  do {                                                                   \
    take(&before);                                                       \
    CHECK_ERROR(call, status, name);                                     \
    take(&after);                                                        \
    CHECK(memcmp(&before, &after, sizeof before) == 0);                  \
  } while (0)

/* ---- NULL handles and pointers --------------------------------------------------------- */

static void null_pointers(void) {
  asp_grid *g = NULL;
  asp_system *s = NULL;
  asp_solver *v = NULL;
  int i = 0;
  int64_t a = 0, b = 0, c = 0;
  double x = 0.0, y = 0.0;
  char text[256];

  /* The history of main()'s solve, before a refused solve below leaves the solver without a
   * report (documented). */
  CHECK_OK(asp_solver_history_length(solver, &a));
  CHECK(a > 0);
  CHECK_ERROR(asp_solver_get_history(NULL, ASP_HISTORY_ERROR, field, a), ASP_ERR_NULL_POINTER,
              "'solver'");
  CHECK_ERROR(asp_solver_get_history(solver, ASP_HISTORY_ERROR, NULL, a), ASP_ERR_NULL_POINTER,
              "'values'");

  CHECK_ERROR(asp_grid_create_1d(NX, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_grid_create_2d(NX, NY, 1.0, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_grid_get_shape(NULL, &i, &a, &b, &c), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_grid_get_box(NULL, &x, &y), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_grid_set_fft_planning(NULL, ASP_FFT_ESTIMATE), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_grid_set_threads(NULL, 1), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_grid_get_threads(NULL, &i), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_grid_get_threads(grid, NULL), ASP_ERR_NULL_POINTER, "'threads'");
  CHECK_ERROR(asp_grid_get_slab(NULL, &a, &b, &c), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_fft_export_wisdom(NULL), ASP_ERR_NULL_POINTER, "'path'");
  CHECK_ERROR(asp_fft_import_wisdom(NULL), ASP_ERR_NULL_POINTER, "'path'");

  CHECK_ERROR(asp_topography_flat(NULL, field, N), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_topography_flat(grid, NULL, N), ASP_ERR_NULL_POINTER, "'heights'");
  CHECK_ERROR(asp_topography_sphere(NULL, 10.0, field, N), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_topography_sphere(grid, 10.0, NULL, N), ASP_ERR_NULL_POINTER, "'heights'");
  CHECK_ERROR(asp_topography_paraboloid(NULL, 10.0, field, N), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_topography_paraboloid(grid, 10.0, NULL, N), ASP_ERR_NULL_POINTER,
              "'heights'");
  CHECK_ERROR(asp_topography_sinusoid(NULL, 1.0, 1, 1, field, N), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_topography_sinusoid(grid, 1.0, 1, 1, NULL, N), ASP_ERR_NULL_POINTER,
              "'heights'");
  CHECK_ERROR(asp_topography_double_sinewave(NULL, 1.0, 0.1, 4, field, N), ASP_ERR_NULL_POINTER,
              "'grid'");
  CHECK_ERROR(asp_topography_double_sinewave(grid, 1.0, 0.1, 4, NULL, N), ASP_ERR_NULL_POINTER,
              "'heights'");
  CHECK_ERROR(asp_topography_self_affine(NULL, 0.8, 32.0, 8.0, 2.0, ASP_RMS_SLOPE, 0.1, 1, field,
                                         N),
              ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_topography_self_affine(grid, 0.8, 32.0, 8.0, 2.0, ASP_RMS_SLOPE, 0.1, 1, NULL,
                                         N),
              ASP_ERR_NULL_POINTER, "'heights'");
  CHECK_ERROR(asp_topography_statistics(NULL, heights, N, &x, NULL, NULL), ASP_ERR_NULL_POINTER,
              "'grid'");
  CHECK_ERROR(asp_topography_statistics(grid, NULL, N, &x, NULL, NULL), ASP_ERR_NULL_POINTER,
              "'heights'");
  CHECK_ERROR(asp_topography_detrend(NULL, ASP_DETREND_PLANE, field, N), ASP_ERR_NULL_POINTER,
              "'grid'");
  CHECK_ERROR(asp_topography_detrend(grid, ASP_DETREND_PLANE, NULL, N), ASP_ERR_NULL_POINTER,
              "'heights'");
  CHECK_ERROR(asp_topography_power_spectrum(NULL, heights, N, 8, field, spare),
              ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_topography_power_spectrum(grid, NULL, N, 8, field, spare),
              ASP_ERR_NULL_POINTER, "'heights'");
  CHECK_ERROR(asp_topography_power_spectrum(grid, heights, N, 8, NULL, spare),
              ASP_ERR_NULL_POINTER, "'q'");
  CHECK_ERROR(asp_topography_power_spectrum(grid, heights, N, 8, field, NULL),
              ASP_ERR_NULL_POINTER, "'c'");

  CHECK_ERROR(asp_system_create(NULL, 1.0, &s), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK(s == NULL);
  CHECK_ERROR(asp_system_create(grid, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_system_create_free(NULL, 1.0, &s), ASP_ERR_NULL_POINTER, "'grid'");
  CHECK_ERROR(asp_system_create_free(grid, 1.0, NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_system_set_topography(NULL, heights, N), ASP_ERR_NULL_POINTER, "'system'");
  REFUSED(asp_system_set_topography(sys, NULL, N), ASP_ERR_NULL_POINTER, "'heights'");
  CHECK_ERROR(asp_system_set_k0(NULL, 1.0), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_adhesion(NULL, 0.01, 0.1), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_soft_wall(NULL, 0.1, 0.1, 0.01, 0.1), ASP_ERR_NULL_POINTER,
              "'system'");
  CHECK_ERROR(asp_system_set_lennard_jones(NULL, 0.01, 0.1), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_hard_wall(NULL), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_set_potential(NULL, NULL, NULL, 0), ASP_ERR_NULL_POINTER, "'system'");
  REFUSED(asp_system_set_potential(sys, NULL, NULL, 0), ASP_ERR_NULL_POINTER, "'fn'");
  CHECK_ERROR(asp_system_set_reference_pressure(NULL, 1.0), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_reset(NULL), ASP_ERR_NULL_POINTER, "'system'");
  CHECK_ERROR(asp_system_get(NULL, ASP_MEAN_PRESSURE, &x), ASP_ERR_NULL_POINTER, "'system'");
  REFUSED(asp_system_get(sys, ASP_MEAN_PRESSURE, NULL), ASP_ERR_NULL_POINTER, "'value'");
  CHECK_ERROR(asp_system_get_field(NULL, ASP_FIELD_GAP, field, N), ASP_ERR_NULL_POINTER,
              "'system'");
  REFUSED(asp_system_get_field(sys, ASP_FIELD_GAP, NULL, N), ASP_ERR_NULL_POINTER, "'values'");

  CHECK_ERROR(asp_solver_create(NULL, &v), ASP_ERR_NULL_POINTER, "'algorithm'");
  CHECK(v == NULL);
  CHECK_ERROR(asp_solver_create("pk", NULL), ASP_ERR_NULL_POINTER, "'out'");
  CHECK_ERROR(asp_solver_describe(NULL, text, sizeof text, &a), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_option(NULL, "tolerance", 1e-6), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_option(solver, NULL, 1e-6), ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_set_option_string(NULL, "variable", "gap"), ASP_ERR_NULL_POINTER,
              "'solver'");
  CHECK_ERROR(asp_solver_set_option_string(solver, NULL, "gap"), ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_set_option_string(solver, "variable", NULL), ASP_ERR_NULL_POINTER,
              "'value'");
  CHECK_ERROR(asp_solver_get_option(NULL, "tolerance", &x), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_get_option(solver, NULL, &x), ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_get_option(solver, "tolerance", NULL), ASP_ERR_NULL_POINTER, "'value'");
  CHECK_ERROR(asp_solver_get_option_string(NULL, "variable", text, sizeof text, &a),
              ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_get_option_string(solver, NULL, text, sizeof text, &a),
              ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_set_tolerance(NULL, 1e-6), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_max_iterations(NULL, 10), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_progress(NULL, NULL, NULL), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_history(NULL, 1), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_solve(NULL, sys, ASP_CONTROL_MEAN_PRESSURE, 0.01), ASP_ERR_NULL_POINTER,
              "'solver'");
  REFUSED(asp_solver_solve(solver, NULL, ASP_CONTROL_MEAN_PRESSURE, 0.01), ASP_ERR_NULL_POINTER,
          "'system'");
  CHECK_ERROR(asp_solver_supports(NULL, sys, ASP_CONTROL_MEAN_PRESSURE), ASP_ERR_NULL_POINTER,
              "'solver'");
  CHECK_ERROR(asp_solver_supports(solver, NULL, ASP_CONTROL_MEAN_PRESSURE), ASP_ERR_NULL_POINTER,
              "'system'");
  CHECK_ERROR(asp_solver_termination(NULL, &i), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_termination(solver, NULL), ASP_ERR_NULL_POINTER, "'reason'");
  CHECK_ERROR(asp_solver_iterations(NULL, &a), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_iterations(solver, NULL), ASP_ERR_NULL_POINTER, "'iterations'");
  CHECK_ERROR(asp_solver_evaluations(NULL, &a), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_evaluations(solver, NULL), ASP_ERR_NULL_POINTER, "'evaluations'");
  CHECK_ERROR(asp_solver_transforms(NULL, &a), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_transforms(solver, NULL), ASP_ERR_NULL_POINTER, "'transforms'");
  CHECK_ERROR(asp_solver_final_error(NULL, &x), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_final_error(solver, NULL), ASP_ERR_NULL_POINTER, "'error'");
  CHECK_ERROR(asp_solver_converged(NULL, &i), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_converged(solver, NULL), ASP_ERR_NULL_POINTER, "'converged'");
  CHECK_ERROR(asp_solver_elapsed_seconds(NULL, &x), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_elapsed_seconds(solver, NULL), ASP_ERR_NULL_POINTER, "'seconds'");
  CHECK_ERROR(asp_solver_history_length(NULL, &a), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_history_length(solver, NULL), ASP_ERR_NULL_POINTER, "'length'");
  (void)g;
  /* Destroying NULL is a no-op. */
  asp_grid_destroy(NULL);
  asp_system_destroy(NULL);
  asp_solver_destroy(NULL);
}

/* ---- NaN and infinities in every floating-point argument ------------------------------- */

static void non_finite_numbers(void) {
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  asp_grid *g = NULL;
  asp_system *s = NULL;
  int k;
  for (k = 0; k < 3; ++k) {
    const double v = bad[k];
    CHECK_ERROR(asp_grid_create_1d(NX, v, &g), ASP_ERR_INVALID_ARGUMENT, "'lx'");
    CHECK(g == NULL);
    CHECK_ERROR(asp_grid_create_2d(NX, NY, v, 1.0, &g), ASP_ERR_INVALID_ARGUMENT, "'lx'");
    CHECK_ERROR(asp_grid_create_2d(NX, NY, 1.0, v, &g), ASP_ERR_INVALID_ARGUMENT, "'ly'");
    CHECK_ERROR(asp_topography_sphere(grid, v, field, N), ASP_ERR_INVALID_ARGUMENT, "'radius'");
    CHECK_ERROR(asp_topography_paraboloid(grid, v, field, N), ASP_ERR_INVALID_ARGUMENT,
                "'radius'");
    CHECK_ERROR(asp_topography_sinusoid(grid, v, 1, 1, field, N), ASP_ERR_INVALID_ARGUMENT,
                "'amplitude'");
    CHECK_ERROR(asp_topography_double_sinewave(grid, v, 0.1, 4, field, N),
                ASP_ERR_INVALID_ARGUMENT, "'amplitude'");
    CHECK_ERROR(asp_topography_double_sinewave(grid, 1.0, v, 4, field, N),
                ASP_ERR_INVALID_ARGUMENT, "'ripple_amplitude'");
    CHECK_ERROR(asp_topography_self_affine(grid, v, 32.0, 8.0, 2.0, ASP_RMS_SLOPE, 0.1, 1, field,
                                           N),
                ASP_ERR_INVALID_ARGUMENT, "'hurst'");
    CHECK_ERROR(asp_topography_self_affine(grid, 0.8, v, 8.0, 2.0, ASP_RMS_SLOPE, 0.1, 1, field,
                                           N),
                ASP_ERR_INVALID_ARGUMENT, "'long_cutoff'");
    CHECK_ERROR(asp_topography_self_affine(grid, 0.8, 32.0, v, 2.0, ASP_RMS_SLOPE, 0.1, 1, field,
                                           N),
                ASP_ERR_INVALID_ARGUMENT, "'rolloff'");
    CHECK_ERROR(asp_topography_self_affine(grid, 0.8, 32.0, 8.0, v, ASP_RMS_SLOPE, 0.1, 1, field,
                                           N),
                ASP_ERR_INVALID_ARGUMENT, "'short_cutoff'");
    CHECK_ERROR(asp_topography_self_affine(grid, 0.8, 32.0, 8.0, 2.0, ASP_RMS_SLOPE, v, 1, field,
                                           N),
                ASP_ERR_INVALID_ARGUMENT, "'target'");
    CHECK_ERROR(asp_system_create(grid, v, &s), ASP_ERR_INVALID_ARGUMENT, "'contact_modulus'");
    CHECK(s == NULL);
    CHECK_ERROR(asp_system_create_free(grid, v, &s), ASP_ERR_INVALID_ARGUMENT,
                "'contact_modulus'");
    REFUSED(asp_system_set_k0(sys, v), ASP_ERR_INVALID_ARGUMENT, "'k0'");
    REFUSED(asp_system_set_adhesion(sys, v, 0.1), ASP_ERR_INVALID_ARGUMENT, "'work_of_adhesion'");
    REFUSED(asp_system_set_adhesion(sys, 0.01, v), ASP_ERR_INVALID_ARGUMENT, "'range'");
    REFUSED(asp_system_set_soft_wall(sys, v, 0.1, 0.01, 0.1), ASP_ERR_INVALID_ARGUMENT,
            "'gamma_r'");
    REFUSED(asp_system_set_soft_wall(sys, 0.1, v, 0.01, 0.1), ASP_ERR_INVALID_ARGUMENT, "'rho_r'");
    REFUSED(asp_system_set_soft_wall(sys, 0.1, 0.1, v, 0.1), ASP_ERR_INVALID_ARGUMENT,
            "'gamma_a'");
    REFUSED(asp_system_set_soft_wall(sys, 0.1, 0.1, 0.01, v), ASP_ERR_INVALID_ARGUMENT, "'rho_a'");
    REFUSED(asp_system_set_lennard_jones(sys, v, 0.1), ASP_ERR_INVALID_ARGUMENT,
            "'work_of_adhesion'");
    REFUSED(asp_system_set_lennard_jones(sys, 0.01, v), ASP_ERR_INVALID_ARGUMENT,
            "'equilibrium_distance'");
    REFUSED(asp_system_set_reference_pressure(sys, v), ASP_ERR_INVALID_ARGUMENT,
            "'reference_pressure'");
    CHECK_ERROR(asp_solver_set_option(solver, "tolerance", v), ASP_ERR_INVALID_ARGUMENT,
                "tolerance");
    CHECK_ERROR(asp_solver_set_tolerance(solver, v), ASP_ERR_INVALID_ARGUMENT, "tolerance");
    REFUSED(asp_solver_solve(solver, sys, ASP_CONTROL_MEAN_PRESSURE, v), ASP_ERR_INVALID_ARGUMENT,
            "'value'");
    REFUSED(asp_solver_solve(solver, sys, ASP_CONTROL_PENETRATION, v), ASP_ERR_INVALID_ARGUMENT,
            "'value'");
  }
  /* NaN and infinities inside arrays. */
  memcpy(field, heights, sizeof heights);
  for (k = 0; k < 3; ++k) {
    field[N / 3] = bad[k];
    REFUSED(asp_system_set_topography(sys, field, N), ASP_ERR_INVALID_ARGUMENT, "'heights'");
    CHECK_ERROR(asp_topography_statistics(grid, field, N, &spare[0], NULL, NULL),
                ASP_ERR_INVALID_ARGUMENT, "'heights'");
    CHECK_ERROR(asp_topography_detrend(grid, ASP_DETREND_PLANE, field, N),
                ASP_ERR_INVALID_ARGUMENT, "'heights'");
    CHECK_ERROR(asp_topography_power_spectrum(grid, field, N, 8, spare, spare),
                ASP_ERR_INVALID_ARGUMENT, "'heights'");
  }
}

/* ---- counts that do not match ---------------------------------------------------------- */

static void wrong_counts(void) {
  const int64_t off[2] = {N - 1, N + 1};
  double out = 0.0;
  int k;
  for (k = 0; k < 2; ++k) {
    const int64_t n = off[k];
    CHECK_ERROR(asp_topography_flat(grid, spare, n), ASP_ERR_SIZE_MISMATCH, "'heights'");
    CHECK_ERROR(asp_topography_sphere(grid, 10.0, spare, n), ASP_ERR_SIZE_MISMATCH, "'heights'");
    CHECK_ERROR(asp_topography_paraboloid(grid, 10.0, spare, n), ASP_ERR_SIZE_MISMATCH,
                "'heights'");
    CHECK_ERROR(asp_topography_sinusoid(grid, 1.0, 1, 1, spare, n), ASP_ERR_SIZE_MISMATCH,
                "'heights'");
    CHECK_ERROR(asp_topography_double_sinewave(grid, 1.0, 0.1, 4, spare, n),
                ASP_ERR_SIZE_MISMATCH, "'heights'");
    CHECK_ERROR(asp_topography_self_affine(grid, 0.8, 32.0, 8.0, 2.0, ASP_RMS_SLOPE, 0.1, 1, spare,
                                           n),
                ASP_ERR_SIZE_MISMATCH, "'heights'");
    CHECK_ERROR(asp_topography_statistics(grid, spare, n, &out, NULL, NULL),
                ASP_ERR_SIZE_MISMATCH, "'heights'");
    CHECK_ERROR(asp_topography_detrend(grid, ASP_DETREND_PLANE, spare, n), ASP_ERR_SIZE_MISMATCH,
                "'heights'");
    CHECK_ERROR(asp_topography_power_spectrum(grid, spare, n, 8, field, field),
                ASP_ERR_SIZE_MISMATCH, "'heights'");
    REFUSED(asp_system_set_topography(sys, spare, n), ASP_ERR_SIZE_MISMATCH, "'heights'");
    REFUSED(asp_system_get_field(sys, ASP_FIELD_PRESSURE, spare, n), ASP_ERR_SIZE_MISMATCH,
            "'values'");
  }
  /* Negative counts. */
  CHECK_ERROR(asp_topography_flat(grid, spare, -1), ASP_ERR_SIZE_MISMATCH, "'heights'");
  REFUSED(asp_system_set_topography(sys, spare, -N), ASP_ERR_SIZE_MISMATCH, "'heights'");
}

/* ---- sizes, moduli and constants out of their domains ---------------------------------- */

static void out_of_domain(void) {
  asp_grid *g = NULL;
  asp_system *s = NULL;
  asp_solver *unknown = NULL;
  CHECK_ERROR(asp_grid_create_1d(0, 1.0, &g), ASP_ERR_INVALID_ARGUMENT, "'nx'");
  CHECK_ERROR(asp_grid_create_1d(-4, 1.0, &g), ASP_ERR_INVALID_ARGUMENT, "'nx'");
  CHECK_ERROR(asp_grid_create_2d(NX, 0, 1.0, 1.0, &g), ASP_ERR_INVALID_ARGUMENT, "'ny'");
  CHECK_ERROR(asp_grid_create_2d(NX, NY, -1.0, 1.0, &g), ASP_ERR_INVALID_ARGUMENT, "'lx'");
  CHECK_ERROR(asp_grid_create_2d(NX, NY, 1.0, 0.0, &g), ASP_ERR_INVALID_ARGUMENT, "'ly'");
  CHECK(g == NULL);
  CHECK_ERROR(asp_grid_set_threads(grid, 0), ASP_ERR_INVALID_ARGUMENT, "'threads'");
  CHECK_ERROR(asp_system_create(grid, 0.0, &s), ASP_ERR_INVALID_ARGUMENT, "'contact_modulus'");
  CHECK_ERROR(asp_system_create(grid, -1.0, &s), ASP_ERR_INVALID_ARGUMENT, "'contact_modulus'");
  CHECK(s == NULL);
  REFUSED(asp_system_set_k0(sys, -1.0), ASP_ERR_INVALID_ARGUMENT, "'k0'");
  REFUSED(asp_system_set_adhesion(sys, -0.01, 0.1), ASP_ERR_INVALID_ARGUMENT,
          "'work_of_adhesion'");
  REFUSED(asp_system_set_adhesion(sys, 0.01, 0.0), ASP_ERR_INVALID_ARGUMENT, "'range'");
  REFUSED(asp_system_set_lennard_jones(sys, 0.01, -0.1), ASP_ERR_INVALID_ARGUMENT,
          "'equilibrium_distance'");
  CHECK_ERROR(asp_solver_set_tolerance(solver, -1e-6), ASP_ERR_INVALID_ARGUMENT, "tolerance");
  CHECK_ERROR(asp_solver_set_max_iterations(solver, 0), ASP_ERR_INVALID_ARGUMENT,
              "max_iterations");
  CHECK_ERROR(asp_solver_set_option(solver, "no_such_option", 1.0), ASP_ERR_INVALID_ARGUMENT,
              "no_such_option");
  CHECK_ERROR(asp_solver_create("no_such_solver", &unknown), ASP_ERR_UNSUPPORTED,
              "no_such_solver");
  CHECK(unknown == NULL);
  /* Constants of another family, each refused naming the argument. */
  REFUSED(asp_system_get(sys, ASP_FIELD_GAP, &spare[0]), ASP_ERR_INVALID_ARGUMENT, "'key'");
  REFUSED(asp_system_get_field(sys, ASP_MEAN_PRESSURE, field, N), ASP_ERR_INVALID_ARGUMENT,
          "'field'");
  REFUSED(asp_solver_solve(solver, sys, ASP_CONTACT_FRACTION, 0.01), ASP_ERR_INVALID_ARGUMENT,
          "'control'");
  CHECK_ERROR(asp_grid_set_fft_planning(grid, ASP_RMS_SLOPE), ASP_ERR_INVALID_ARGUMENT,
              "'planning'");
  CHECK_ERROR(asp_topography_detrend(grid, ASP_FIELD_GAP, field, N), ASP_ERR_INVALID_ARGUMENT,
              "'mode'");
  CHECK_ERROR(asp_topography_self_affine(grid, 0.8, 32.0, 8.0, 2.0, ASP_FIELD_GAP, 0.1, 1, field,
                                         N),
              ASP_ERR_INVALID_ARGUMENT, "'normalise'");
  /* A solver that does not serve the scene: pk with a soft wall. */
  CHECK_OK(asp_system_set_soft_wall(sys, 0.1, 0.5, 0.01, 0.5));
  REFUSED(asp_solver_solve(solver, sys, ASP_CONTROL_MEAN_PRESSURE, 0.01), ASP_ERR_UNSUPPORTED,
          "pk");
  CHECK_OK(asp_system_set_hard_wall(sys));
}

/* ---- callbacks that call back into the library ----------------------------------------- */

typedef struct {
  int calls, refused_get, refused_solve, refused_set, other_grid_ok, progress_refused;
  asp_grid *other;
} Reentry;

static int reentering_potential(int64_t n, const double *gap, double *phi, double *dphi,
                                double *d2phi, void *user_data) {
  /* A soft exponential repulsion, and on the first calls attempts to use the system and
   * solver being solved, which must be refused, and another grid, which must work. */
  Reentry *r = (Reentry *)user_data;
  int64_t i;
  for (i = 0; i < n; ++i) {
    const double e = exp(-gap[i] / 0.5);
    phi[i] = 0.1 * e;
    dphi[i] = -0.2 * e;
    if (d2phi != NULL) d2phi[i] = 0.4 * e;
  }
  if (r->calls++ < 3) {
    double v = 0.0;
    int dimension = 0;
    if (asp_system_get(sys, ASP_MEAN_PRESSURE, &v) == ASP_ERR_INVALID_STATE &&
        strstr(asp_last_error_message(), "'system'") != NULL)
      ++r->refused_get;
    if (asp_solver_solve(solver, sys, ASP_CONTROL_PENETRATION, 0.1) == ASP_ERR_INVALID_STATE)
      ++r->refused_solve;
    if (asp_system_set_topography(sys, heights, N) == ASP_ERR_INVALID_STATE) ++r->refused_set;
    asp_system_destroy(sys); /* refused: the solve goes on with it */
    asp_solver_destroy(solver);
    if (asp_grid_get_shape(r->other, &dimension, NULL, NULL, NULL) == ASP_OK && dimension == 1)
      ++r->other_grid_ok;
  }
  return 0;
}

static int reentering_progress(int64_t iteration, double seconds, double error, void *user_data) {
  Reentry *r = (Reentry *)user_data;
  (void)seconds;
  (void)error;
  if (iteration == 1 && asp_solver_set_tolerance(solver, 1e-3) == ASP_ERR_INVALID_STATE &&
      strstr(asp_last_error_message(), "'solver'") != NULL)
    ++r->progress_refused;
  return 0;
}

static void callbacks_reentering(void) {
  Reentry r;
  int converged = 0;
  double tolerance = 0.0;
  asp_solver *lbfgs = NULL;
  memset(&r, 0, sizeof r);
  CHECK_OK(asp_grid_create_1d(16, 1.0, &r.other));
  CHECK_OK(asp_solver_create("lbfgs", &lbfgs));
  /* The callbacks find the handles being solved in these globals. */
  asp_solver_destroy(solver);
  solver = lbfgs;
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-8));
  CHECK_OK(asp_solver_set_progress(solver, reentering_progress, &r));
  CHECK_OK(asp_system_set_potential(sys, reentering_potential, &r, 0));
  CHECK_OK(asp_solver_solve(solver, sys, ASP_CONTROL_PENETRATION, 0.1));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK(r.calls >= 3);
  CHECK(r.refused_get == 3 && r.refused_solve == 3 && r.refused_set == 3);
  CHECK(r.other_grid_ok == 3);
  CHECK(r.progress_refused == 1);
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &tolerance));
  CHECK(tolerance == 1e-8);
  /* After the solve the handles are the caller's again. */
  CHECK_OK(asp_system_get(sys, ASP_MEAN_PRESSURE, &tolerance));
  CHECK_OK(asp_solver_set_progress(solver, NULL, NULL));
  CHECK_OK(asp_system_set_hard_wall(sys));
  asp_grid_destroy(r.other);
}

/* ---- asp_solver_supports says what asp_solver_solve then does --------------------------- */

static void supports_agrees_with_solve(void) {
  static const char *const algorithms[][2] = {
      {"pk", NULL},           {"bugnicourt", "pressure"}, {"bugnicourt", "gap"},
      {"lbfgsb", "pressure"}, {"lbfgsb", "gap"},          {"lbfgs", NULL},
      {"lbfgs_fourier", NULL}, {"gfmd", NULL},            {"fire", NULL},
      {"fire_mass_weighted", NULL}};
  const int controls[3] = {ASP_CONTROL_MEAN_PRESSURE, ASP_CONTROL_PENETRATION,
                           ASP_CONTROL_MEAN_GAP};
  const double values[3] = {0.001, 0.05, 0.05};
  asp_grid *small = NULL;
  double h[16 * 16];
  int substrate, interaction, a, k;
  CHECK_OK(asp_grid_create_2d(16, 16, 16.0, 16.0, &small));
  CHECK_OK(asp_topography_sphere(small, 40.0, h, 16 * 16));
  for (substrate = 0; substrate < 2; ++substrate)
    for (interaction = 0; interaction < 3; ++interaction) {
      asp_system *s = NULL;
      CHECK_OK(substrate == 0 ? asp_system_create(small, 1.0, &s)
                              : asp_system_create_free(small, 1.0, &s));
      CHECK_OK(asp_system_set_topography(s, h, 16 * 16));
      if (interaction == 1) CHECK_OK(asp_system_set_adhesion(s, 0.001, 0.5));
      if (interaction == 2) CHECK_OK(asp_system_set_soft_wall(s, 0.01, 0.5, 0.001, 0.5));
      for (a = 0; a < (int)(sizeof algorithms / sizeof algorithms[0]); ++a)
        for (k = 0; k < 3; ++k) {
          asp_solver *v = NULL;
          int supported, solved;
          CHECK_OK(asp_solver_create(algorithms[a][0], &v));
          if (algorithms[a][1] != NULL)
            CHECK_OK(asp_solver_set_option_string(v, "variable", algorithms[a][1]));
          CHECK_OK(asp_solver_set_max_iterations(v, 3));
          supported = asp_solver_supports(v, s, controls[k]);
          solved = asp_solver_solve(v, s, controls[k], values[k]);
          if (!CHECK(supported == ASP_OK ? solved == ASP_OK : solved == supported))
            fprintf(stderr, "  %s/%s, %s substrate, interaction %d, control %d: supports %d, "
                            "solve %d (%s)\n",
                    algorithms[a][0], algorithms[a][1] ? algorithms[a][1] : "-",
                    substrate == 0 ? "periodic" : "free", interaction, controls[k], supported,
                    solved, asp_last_error_message());
          asp_solver_destroy(v);
        }
      asp_system_destroy(s);
    }
  asp_grid_destroy(small);
}

int main(void) {
  CHECK_OK(asp_grid_create_2d(NX, NY, (double)NX, (double)NY, &grid));
  CHECK_OK(asp_topography_self_affine(grid, 0.8, (double)NX, 8.0, 2.0, ASP_RMS_SLOPE, 0.1, 5,
                                      heights, N));
  CHECK_OK(asp_system_create(grid, 1.0, &sys));
  CHECK_OK(asp_system_set_topography(sys, heights, N));
  CHECK_OK(asp_solver_create("pk", &solver));
  /* A solved state, so that "unchanged" is about a state worth keeping, and its history. */
  CHECK_OK(asp_solver_set_history(solver, 1));
  CHECK_OK(asp_solver_solve(solver, sys, ASP_CONTROL_MEAN_PRESSURE, 0.01));

  null_pointers();
  non_finite_numbers();
  wrong_counts();
  out_of_domain();
  callbacks_reentering();
  supports_agrees_with_solve();

  asp_solver_destroy(solver);
  asp_system_destroy(sys);
  asp_grid_destroy(grid);
  return check_summary("api.bad_input");
}
