/* SPDX-License-Identifier: GPL-2.0-or-later */
/* The contact through the public header: the contact map ASP_FIELD_CONTACT (1.0 in contact,
 * 0.0 elsewhere), whose mean is ASP_CONTACT_FRACTION, and ASP_COMPRESSIVE_FRACTION (the
 * pixels in contact with p > 0). With the hard wall the map is where the gap is 0, exactly:
 * an adhesive sphere solved on the gap, a rough surface by "pk" cut at its iteration limit
 * (whose gap is >= 0 everywhere). For a soft wall it is where phi'(g) < 0 (off contact the
 * pressure can be an attraction of rounding size, whose sign decides nothing: the command's
 * test, tests/cli/check_contact.sh, shows one). The new constants belong to their families. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define N 64

static double mean_of(const double *v, int64_t n) {
  double sum = 0.0;
  int64_t i;
  for (i = 0; i < n; ++i) sum += v[i];
  return sum / (double)n;
}

/* The map against the gap (hard wall): 1.0 exactly where g == 0, 0.0 elsewhere, and no
 * g < 0; the keys against the map and the pressure. */
static void check_hard_wall_map(asp_system *system, const char *what) {
  double *gap = malloc(N * N * sizeof(double));
  double *pressure = malloc(N * N * sizeof(double));
  double *map = malloc(N * N * sizeof(double));
  double fraction = -1.0, compressive = -1.0, compressive_count = 0.0;
  int i, agree = 1, feasible = 1;
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_GAP, gap, N * N));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, N * N));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_CONTACT, map, N * N));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &fraction));
  CHECK_OK(asp_system_get(system, ASP_COMPRESSIVE_FRACTION, &compressive));
  for (i = 0; i < N * N; ++i) {
    agree &= map[i] == (gap[i] == 0.0 ? 1.0 : 0.0);
    feasible &= gap[i] >= 0.0;
    compressive_count += map[i] == 1.0 && pressure[i] > 0.0 ? 1.0 : 0.0;
  }
  if (!CHECK(agree)) fprintf(stderr, "  %s: the map is not where the gap is 0\n", what);
  if (!CHECK(feasible)) fprintf(stderr, "  %s: a gap below 0\n", what);
  CHECK(fraction > 0.0 && fraction < 1.0);
  CHECK(mean_of(map, N * N) == fraction);
  CHECK(compressive == compressive_count / (N * N));
  free(gap);
  free(pressure);
  free(map);
}

int main(void) {
  const double box = 1.0, radius = 1.0, modulus = 1.0, work = 1e-4, range = 2e-3;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  double *heights = malloc(N * N * sizeof(double));
  double *map = malloc(N * N * sizeof(double));
  double *pressure = malloc(N * N * sizeof(double));
  double fraction = -1.0, compressive = -1.0, contact = -1.0, attractive = -1.0;
  double positive = 0.0;
  int i, converged = 0;

  /* ---- the constants' families ---- */
  CHECK_OK(asp_grid_create_2d(N, N, box, box, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_topography_paraboloid(grid, radius, heights, N * N));
  CHECK_OK(asp_system_create(grid, modulus, &system));
  CHECK_OK(asp_system_set_topography(system, heights, N * N));
  CHECK_ERROR(asp_system_get_field(system, ASP_COMPRESSIVE_FRACTION, map, N * N),
              ASP_ERR_INVALID_ARGUMENT, "ASP_COMPRESSIVE_FRACTION");
  CHECK_ERROR(asp_system_get(system, ASP_FIELD_CONTACT, &fraction), ASP_ERR_INVALID_ARGUMENT,
              "ASP_FIELD_CONTACT");

  /* ---- an adhesive sphere on the gap: contact is the JKR area, its edge under tension ---- */
  CHECK_OK(asp_system_set_adhesion(system, work, range));
  CHECK_OK(asp_solver_create("bugnicourt", &solver));
  CHECK_OK(asp_solver_set_option_string(solver, "variable", "gap"));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-8));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 1e-3));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged);
  check_hard_wall_map(system, "adhesive sphere");
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &contact));
  CHECK_OK(asp_system_get(system, ASP_COMPRESSIVE_FRACTION, &compressive));
  CHECK_OK(asp_system_get(system, ASP_ATTRACTIVE_FRACTION, &attractive));
  /* The tensile ring on the wall: contact pixels without compressive pressure. */
  CHECK(compressive < contact);
  CHECK(attractive > contact - compressive);
  asp_solver_destroy(solver);
  solver = NULL;

  /* ---- "pk" cut at 3 iterations on a rough surface: still no gap below 0 ---- */
  CHECK_OK(asp_topography_self_affine(grid, 0.8, box, box / 4, 4.0 * box / N, ASP_RMS_SLOPE,
                                      0.1, 9, heights, N * N));
  CHECK_OK(asp_system_set_topography(system, heights, N * N));
  CHECK_OK(asp_system_set_hard_wall(system));
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-12));
  CHECK_OK(asp_solver_set_max_iterations(solver, 3));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(!converged);
  check_hard_wall_map(system, "pk at its iteration limit");
  asp_solver_destroy(solver);
  solver = NULL;

  /* ---- a soft wall: contact where phi'(g) < 0, the map's mean the key ---- */
  CHECK_OK(asp_system_set_soft_wall(system, 1e-4, 1e-3, 1e-4, 1e-3));
  CHECK_OK(asp_solver_create("lbfgs", &solver));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-8));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged);
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_CONTACT, map, N * N));
  CHECK_OK(asp_system_get_field(system, ASP_FIELD_PRESSURE, pressure, N * N));
  CHECK_OK(asp_system_get(system, ASP_CONTACT_FRACTION, &fraction));
  CHECK_OK(asp_system_get(system, ASP_COMPRESSIVE_FRACTION, &compressive));
  for (i = 0; i < N * N; ++i) {
    CHECK(map[i] == 0.0 || map[i] == 1.0);
    positive += pressure[i] > 0.0 ? 1.0 : 0.0;
  }
  CHECK(mean_of(map, N * N) == fraction);
  CHECK(fraction > 0.0 && fraction < 0.5);
  CHECK(compressive <= fraction);
  fprintf(stderr, "soft wall: contact %.4f, compressive %.4f, p > 0 on %.4f of the pixels\n",
          fraction, compressive, positive / (N * N));

  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  free(heights);
  free(map);
  free(pressure);
  return check_summary("test_contact");
}
