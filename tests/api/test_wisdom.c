/* SPDX-License-Identifier: GPL-2.0-or-later */
/* FFTW wisdom and planning (asperity.h, asp_fft_export_wisdom, asp_fft_import_wisdom,
 * asp_grid_set_fft_planning): wisdom learnt by ASP_FFT_MEASURE planning is saved to a file and
 * loaded into another process, where it adds to what that process knows; a file that cannot
 * be written or read is refused with ASP_ERR_IO naming the path, and nothing else changes.
 *
 * The header documents file paths only (no buffer form), so the text-buffer conventions of the
 * library are tested with its text calls in api.solver_options.
 *
 * Another process is this program run again with "--child": it imports a file (or not) and
 * exports what it then knows. Files are written in the current directory. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define NX 48
#define NY 40
#define N (NX * NY)

static const char *const saved = "api_wisdom_saved.txt";
static const char *const child_saved = "api_wisdom_child.txt";
static const char *const child_plain = "api_wisdom_child_plain.txt";
static const char *const garbage = "api_wisdom_garbage.txt";
static const char *const empty = "api_wisdom_empty.txt";
static const char *const truncated = "api_wisdom_truncated.txt";

/* A whole file as a NUL-terminated string (NULL if it cannot be read). */
static char *read_file(const char *path, long *size) {
  FILE *f = fopen(path, "rb");
  char *text;
  long n;
  if (f == NULL) return NULL;
  if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
    fclose(f);
    return NULL;
  }
  text = malloc((size_t)n + 1);
  if (text != NULL && fread(text, 1, (size_t)n, f) != (size_t)n) {
    free(text);
    text = NULL;
  }
  if (text != NULL) text[n] = '\0';
  fclose(f);
  if (size != NULL) *size = n;
  return text;
}

static int write_file(const char *path, const char *text, size_t n) {
  FILE *f = fopen(path, "wb");
  int ok;
  if (f == NULL) return 0;
  ok = fwrite(text, 1, n, f) == n;
  return fclose(f) == 0 && ok;
}

/* A solve on a NX x NY grid with the given planning: makes the grid's FFT plans. */
static int solve_on_new_grid(int planning) {
  static double h[N];
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  int converged = 0;
  int ok = asp_grid_create_2d(NX, NY, 1.0, 1.0, &grid) == ASP_OK &&
           asp_grid_set_fft_planning(grid, planning) == ASP_OK &&
           asp_topography_sinusoid(grid, 0.01, 1, 1, h, N) == ASP_OK &&
           asp_system_create(grid, 1.0, &system) == ASP_OK &&
           asp_system_set_topography(system, h, N) == ASP_OK &&
           asp_solver_create("pk", &solver) == ASP_OK &&
           asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01) == ASP_OK &&
           asp_solver_converged(solver, &converged) == ASP_OK && converged == 1;
  if (!ok) fprintf(stderr, "solve failed: %s\n", asp_last_error_message());
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
  return ok;
}

/* The other process: argv = program --child [import-path] export-path. */
static int child(int argc, char **argv) {
  if (argc == 4 && asp_fft_import_wisdom(argv[2]) != ASP_OK) return 2;
  if (asp_fft_export_wisdom(argv[argc - 1]) != ASP_OK) return 3;
  return 0;
}

/* `text` has a line equal to the n characters at `line`. */
static int has_line(const char *text, const char *line, size_t n) {
  const char *at = text;
  for (;;) {
    const char *end = strchr(at, '\n');
    const size_t m = end != NULL ? (size_t)(end - at) : strlen(at);
    if (m == n && strncmp(at, line, n) == 0) return 1;
    if (end == NULL) return 0;
    at = end + 1;
  }
}

/* Every line of `part` is a line of `whole`. */
static int lines_contained(const char *part, const char *whole) {
  const char *line = part;
  for (;;) {
    const char *end = strchr(line, '\n');
    const size_t n = end != NULL ? (size_t)(end - line) : strlen(line);
    if (n > 0 && !has_line(whole, line, n)) return 0;
    if (end == NULL) return 1;
    line = end + 1;
  }
}

static void test_planning(void) {
  asp_grid *grid = NULL;
  static double h[N];
  asp_system *system = NULL;
  asp_solver *solver = NULL;
  CHECK_OK(asp_grid_create_2d(NX, NY, 1.0, 1.0, &grid));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
  CHECK_OK(asp_grid_set_fft_planning(grid, ASP_FFT_MEASURE));
  CHECK_OK(asp_topography_sinusoid(grid, 0.01, 1, 1, h, N));
  CHECK_OK(asp_system_create(grid, 1.0, &system));
  CHECK_OK(asp_system_set_topography(system, h, N));
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01));
  /* Once plans exist, the planning can no longer change. */
  CHECK_ERROR(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE), ASP_ERR_INVALID_STATE, NULL);
  CHECK_ERROR(asp_grid_set_fft_planning(grid, 7), ASP_ERR_INVALID_ARGUMENT, "'planning'");
  CHECK_OK(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.02));
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  asp_grid_destroy(grid);
}

static void test_round_trip(const char *program) {
  char command[4096];
  char *ours, *theirs, *plain;
  long size = 0;
  /* MEASURE planning of a shape new to this process leaves wisdom to save. */
  CHECK(solve_on_new_grid(ASP_FFT_MEASURE));
  remove(saved);
  CHECK_OK(asp_fft_export_wisdom(saved));
  CHECK(strcmp(asp_last_error_message(), "") == 0);
  ours = read_file(saved, &size);
  CHECK(ours != NULL && size > 0);
  CHECK_OK(asp_fft_import_wisdom(saved));
  CHECK_OK(asp_fft_import_wisdom(saved)); /* importing again only adds what is known */

  /* Another process: what it knows after importing includes all of this file, which it did
   * not know without importing. */
  sprintf(command, "\"%s\" --child %s %s", program, saved, child_saved);
  CHECK(strlen(program) < 3000 && system(command) == 0);
  sprintf(command, "\"%s\" --child %s", program, child_plain);
  CHECK(system(command) == 0);
  theirs = read_file(child_saved, NULL);
  plain = read_file(child_plain, NULL);
  CHECK(theirs != NULL && plain != NULL);
  if (ours != NULL && theirs != NULL && plain != NULL) {
    CHECK(lines_contained(ours, theirs));
    CHECK(!lines_contained(ours, plain));
  }
  free(ours);
  free(theirs);
  free(plain);
  /* Wisdom this process already has does not stop it from planning: solves still work. */
  CHECK(solve_on_new_grid(ASP_FFT_MEASURE));
  CHECK(solve_on_new_grid(ASP_FFT_ESTIMATE));
}

static void test_refusals(void) {
  static const char junk[] = "this is not FFTW wisdom\n(fftw-3.3 nonsense ((( \n";
  char *good;
  long size = 0;
  /* Files that cannot be written. */
  CHECK_ERROR(asp_fft_export_wisdom("api-no-such-directory/sub/wisdom.txt"), ASP_ERR_IO,
              "api-no-such-directory/sub/wisdom.txt");
  CHECK_ERROR(asp_fft_export_wisdom("."), ASP_ERR_IO, "'.'");
  CHECK_ERROR(asp_fft_export_wisdom(""), ASP_ERR_IO, "''");
  /* Files that cannot be read, or read as wisdom. */
  CHECK_ERROR(asp_fft_import_wisdom("api-no-such-file.txt"), ASP_ERR_IO, "api-no-such-file.txt");
  CHECK_ERROR(asp_fft_import_wisdom("."), ASP_ERR_IO, "'.'");
  CHECK_ERROR(asp_fft_import_wisdom(""), ASP_ERR_IO, "''");
  CHECK(write_file(garbage, junk, sizeof junk - 1));
  CHECK_ERROR(asp_fft_import_wisdom(garbage), ASP_ERR_IO, garbage);
  CHECK(write_file(empty, "", 0));
  CHECK_ERROR(asp_fft_import_wisdom(empty), ASP_ERR_IO, empty);
  good = read_file(saved, &size);
  CHECK(good != NULL && size > 8);
  if (good != NULL && size > 8) {
    CHECK(write_file(truncated, good, (size_t)size / 2));
    CHECK_ERROR(asp_fft_import_wisdom(truncated), ASP_ERR_IO, truncated);
  }
  free(good);
  /* NULL is named. */
  CHECK_ERROR(asp_fft_export_wisdom(NULL), ASP_ERR_NULL_POINTER, "'path'");
  CHECK_ERROR(asp_fft_import_wisdom(NULL), ASP_ERR_NULL_POINTER, "'path'");

  /* After all that, wisdom still loads and saves, and solves still work. */
  CHECK_OK(asp_fft_import_wisdom(saved));
  CHECK_OK(asp_fft_export_wisdom(saved));
  CHECK(solve_on_new_grid(ASP_FFT_MEASURE));
}

int main(int argc, char **argv) {
  if (argc >= 3 && strcmp(argv[1], "--child") == 0) return child(argc, argv);
  test_planning();
  test_round_trip(argv[0]);
  test_refusals();
  remove(saved);
  remove(child_saved);
  remove(child_plain);
  remove(garbage);
  remove(empty);
  remove(truncated);
  return check_summary("api.wisdom");
}
