/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Solver options through the C API, as asperity.h documents them for "pk": the common options
 * "tolerance" (real > 0, default 1e-8), "max_iterations" (integer >= 1, default 10000) and
 * "stall_window" (integer >= 0, default 1000), set and read by name; unknown names, values out
 * of range, non-whole integers, NaN and the wrong (string/number) form are refused with
 * ASP_ERR_INVALID_ARGUMENT naming the option and listing the valid names or the range; the
 * shorthands asp_solver_set_tolerance and asp_solver_set_max_iterations are the named options;
 * a refusal changes nothing and the solver stays usable. Also the text-buffer rules of
 * asp_algorithms, asp_solver_describe and asp_solver_get_option_string. */
#include <stdint.h>
#include <stdlib.h>

#include "check.h"

#define NX 32
#define N (NX * NX)

/* What the three options should hold, kept up to date as the test changes them. */
typedef struct {
  double tolerance, max_iterations, stall_window;
} Expected;

static asp_grid *grid = NULL;
static asp_system *scene = NULL;

/* A rough 32 x 32 scene at about 10 % contact. */
static int make_scene(void) {
  static double h[N];
  if (asp_grid_create_2d(NX, NX, 1.0, 1.0, &grid) != ASP_OK) return 0;
  if (asp_topography_self_affine(grid, 0.8, 1.0, 0.5, 4.0 / NX, ASP_RMS_SLOPE, 0.1, 3, h, N) !=
      ASP_OK)
    return 0;
  if (asp_system_create(grid, 1.0, &scene) != ASP_OK) return 0;
  return asp_system_set_topography(scene, h, N) == ASP_OK;
}

/* The options still hold what was set, and the solver still solves, honouring them: the
 * error meets the tolerance when it converged, and no more than max_iterations ran. */
static void check_unchanged_and_usable(asp_solver *solver, const Expected *e, int line) {
  double value = -1.0, error = -1.0;
  int64_t iterations = -1;
  int converged = -1, ok = 1;
  ok &= asp_solver_get_option(solver, "tolerance", &value) == ASP_OK && value == e->tolerance;
  ok &= asp_solver_get_option(solver, "max_iterations", &value) == ASP_OK &&
        value == e->max_iterations;
  ok &= asp_solver_get_option(solver, "stall_window", &value) == ASP_OK &&
        value == e->stall_window;
  ok &= asp_system_reset(scene) == ASP_OK;
  ok &= asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005) == ASP_OK;
  ok &= asp_solver_converged(solver, &converged) == ASP_OK;
  ok &= asp_solver_iterations(solver, &iterations) == ASP_OK &&
        (double)iterations <= e->max_iterations;
  ok &= asp_solver_final_error(solver, &error) == ASP_OK && isfinite(error);
  ok &= !converged || error <= e->tolerance;
  if (!ok) fprintf(stderr, "(options or solve after the refusal checked at line %d)\n", line);
  check_record(ok, __FILE__, line, "options unchanged and solver usable after a refusal");
}
#define CHECK_UNCHANGED_AND_USABLE(solver, e) check_unchanged_and_usable((solver), (e), __LINE__)

/* The message (of the last CHECK_ERROR) lists every option of "pk". */
static void check_lists_options(void) {
  CHECK_MESSAGE_HAS("tolerance");
  CHECK_MESSAGE_HAS("max_iterations");
  CHECK_MESSAGE_HAS("stall_window");
}

static void test_defaults(void) {
  asp_solver *solver = NULL;
  double value = 0.0;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == 1e-8);
  CHECK_OK(asp_solver_get_option(solver, "max_iterations", &value));
  CHECK(value == 10000.0);
  CHECK_OK(asp_solver_get_option(solver, "stall_window", &value));
  CHECK(value == 1000.0);
  asp_solver_destroy(solver);
}

static void test_set_and_get(void) {
  asp_solver *solver = NULL, *other = NULL;
  double value = 0.0;
  Expected e = {1e-8, 10000.0, 1000.0};
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_create("pk", &other));

  CHECK_OK(asp_solver_set_option(solver, "tolerance", 2.5e-7));
  CHECK(strcmp(asp_last_error_message(), "") == 0);
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == 2.5e-7);
  e.tolerance = 2.5e-7;
  CHECK_OK(asp_solver_set_option(solver, "max_iterations", 77.0));
  CHECK_OK(asp_solver_get_option(solver, "max_iterations", &value));
  CHECK(value == 77.0);
  e.max_iterations = 77.0;
  CHECK_OK(asp_solver_set_option(solver, "stall_window", 12.0));
  CHECK_OK(asp_solver_get_option(solver, "stall_window", &value));
  CHECK(value == 12.0);
  e.stall_window = 12.0;

  /* The ends of the documented ranges are accepted: any tolerance > 0, max_iterations 1,
   * stall_window 0 ("never"), and large whole counts. */
  CHECK_OK(asp_solver_set_option(solver, "tolerance", 1e-300));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == 1e-300);
  CHECK_OK(asp_solver_set_option(solver, "tolerance", 1e3));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == 1e3);
  CHECK_OK(asp_solver_set_option(solver, "max_iterations", 1.0));
  CHECK_OK(asp_solver_get_option(solver, "max_iterations", &value));
  CHECK(value == 1.0);
  CHECK_OK(asp_solver_set_option(solver, "max_iterations", 1e15));
  CHECK_OK(asp_solver_get_option(solver, "max_iterations", &value));
  CHECK(value == 1e15);
  CHECK_OK(asp_solver_set_option(solver, "stall_window", 0.0));
  CHECK_OK(asp_solver_get_option(solver, "stall_window", &value));
  CHECK(value == 0.0);
  CHECK_OK(asp_solver_set_option(solver, "stall_window", 1e15));
  CHECK_OK(asp_solver_get_option(solver, "stall_window", &value));
  CHECK(value == 1e15);

  /* Options belong to their solver, and persist over solves. */
  CHECK_OK(asp_solver_set_option(solver, "tolerance", e.tolerance));
  CHECK_OK(asp_solver_set_option(solver, "max_iterations", e.max_iterations));
  CHECK_OK(asp_solver_set_option(solver, "stall_window", e.stall_window));
  CHECK_OK(asp_solver_get_option(other, "tolerance", &value));
  CHECK(value == 1e-8);
  CHECK_OK(asp_solver_get_option(other, "max_iterations", &value));
  CHECK(value == 10000.0);
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_UNCHANGED_AND_USABLE(solver, &e);

  asp_solver_destroy(other);
  asp_solver_destroy(solver);
}

static void test_unknown_names(void) {
  asp_solver *solver = NULL;
  char text[64];
  double value = 42.0;
  Expected e = {1e-8, 10000.0, 1000.0};
  CHECK_OK(asp_solver_create("pk", &solver));

  CHECK_ERROR(asp_solver_set_option(solver, "tolerence", 1e-6), ASP_ERR_INVALID_ARGUMENT,
              "'tolerence'");
  check_lists_options();
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_get_option(solver, "memory", &value), ASP_ERR_INVALID_ARGUMENT,
              "'memory'");
  check_lists_options();
  CHECK(value == 42.0);
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_option_string(solver, "variable", "gap"), ASP_ERR_INVALID_ARGUMENT,
              "'variable'");
  check_lists_options();
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_get_option_string(solver, "variable", text, sizeof text, NULL),
              ASP_ERR_INVALID_ARGUMENT, "'variable'");
  check_lists_options();
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  /* Names are exact: no case folding, no surrounding blanks, not empty. */
  CHECK_ERROR(asp_solver_set_option(solver, "Tolerance", 1e-6), ASP_ERR_INVALID_ARGUMENT,
              "'Tolerance'");
  check_lists_options();
  CHECK_ERROR(asp_solver_set_option(solver, "tolerance ", 1e-6), ASP_ERR_INVALID_ARGUMENT,
              "'tolerance '");
  CHECK_ERROR(asp_solver_set_option(solver, "", 1e-6), ASP_ERR_INVALID_ARGUMENT, "''");
  check_lists_options();
  CHECK_UNCHANGED_AND_USABLE(solver, &e);

  /* NULL pointers are named. */
  CHECK_ERROR(asp_solver_set_option(solver, NULL, 1e-6), ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_get_option(solver, NULL, &value), ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_get_option(solver, "tolerance", NULL), ASP_ERR_NULL_POINTER, "'value'");
  CHECK_ERROR(asp_solver_set_option_string(solver, NULL, "x"), ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_set_option_string(solver, "tolerance", NULL), ASP_ERR_NULL_POINTER,
              "'value'");
  CHECK_ERROR(asp_solver_get_option_string(solver, NULL, text, sizeof text, NULL),
              ASP_ERR_NULL_POINTER, "'name'");
  CHECK_ERROR(asp_solver_set_option(NULL, "tolerance", 1e-6), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_get_option(NULL, "tolerance", &value), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_option_string(NULL, "tolerance", "x"), ASP_ERR_NULL_POINTER,
              "'solver'");
  CHECK_ERROR(asp_solver_get_option_string(NULL, "tolerance", text, sizeof text, NULL),
              ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  asp_solver_destroy(solver);
}

/* One refused numeric value: the status, the option's name and `range` (the documented
 * bound, as the message should state it) in the message, nothing changed. */
static void check_refused_value(asp_solver *solver, const char *name, double value,
                                const char *range, const Expected *e, int line) {
  char quoted[64];
  sprintf(quoted, "'%s'", name);
  if (!check_error(asp_solver_set_option(solver, name, value), ASP_ERR_INVALID_ARGUMENT, quoted,
                   __FILE__, line, "asp_solver_set_option refuses the value"))
    fprintf(stderr, "  (option %s, value %g)\n", name, value);
  if (range != NULL && strstr(check_message, range) == NULL) {
    fprintf(stderr, "%s:%d: message '%s' does not state the range '%s'\n", __FILE__, line,
            check_message, range);
    check_record(0, __FILE__, line, "the message states the range");
  } else {
    check_record(1, __FILE__, line, "the message states the range");
  }
  check_unchanged_and_usable(solver, e, line);
}
#define CHECK_REFUSED_VALUE(solver, name, value, range, e) \
  check_refused_value((solver), (name), (value), (range), (e), __LINE__)

static void test_out_of_range(void) {
  asp_solver *solver = NULL;
  Expected e = {1e-6, 500.0, 40.0};
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_option(solver, "tolerance", e.tolerance));
  CHECK_OK(asp_solver_set_option(solver, "max_iterations", e.max_iterations));
  CHECK_OK(asp_solver_set_option(solver, "stall_window", e.stall_window));

  /* Each message states the bound of the documented range: tolerance > 0 (an open bound at
   * 0), max_iterations from 1, stall_window from 0. */
  CHECK_REFUSED_VALUE(solver, "tolerance", 0.0, "(0,", &e);
  CHECK_REFUSED_VALUE(solver, "tolerance", -1e-6, "(0,", &e);
  CHECK_REFUSED_VALUE(solver, "tolerance", -0.0, "(0,", &e);
  CHECK_REFUSED_VALUE(solver, "max_iterations", 0.0, "[1,", &e);
  CHECK_REFUSED_VALUE(solver, "max_iterations", -3.0, "[1,", &e);
  CHECK_REFUSED_VALUE(solver, "stall_window", -1.0, "[0,", &e);
  /* Integer options take whole numbers. */
  CHECK_REFUSED_VALUE(solver, "max_iterations", 2.5, "[1,", &e);
  CHECK_REFUSED_VALUE(solver, "stall_window", 0.5, "[0,", &e);
  CHECK_REFUSED_VALUE(solver, "max_iterations", 1e-300, "[1,", &e);
  /* Not numbers at all. */
  CHECK_REFUSED_VALUE(solver, "tolerance", NAN, NULL, &e);
  CHECK_REFUSED_VALUE(solver, "max_iterations", NAN, NULL, &e);
  CHECK_REFUSED_VALUE(solver, "stall_window", NAN, NULL, &e);
  CHECK_REFUSED_VALUE(solver, "tolerance", -INFINITY, NULL, &e);
  CHECK_REFUSED_VALUE(solver, "max_iterations", -INFINITY, NULL, &e);
  CHECK_REFUSED_VALUE(solver, "stall_window", -INFINITY, NULL, &e);

  /* The other form: the options of "pk" are numbers, so their string setter refuses them,
   * naming the option; the value is not parsed. */
  CHECK_ERROR(asp_solver_set_option_string(solver, "tolerance", "1e-3"),
              ASP_ERR_INVALID_ARGUMENT, "'tolerance'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_option_string(solver, "max_iterations", "3"),
              ASP_ERR_INVALID_ARGUMENT, "'max_iterations'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_option_string(solver, "stall_window", "0"),
              ASP_ERR_INVALID_ARGUMENT, "'stall_window'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  asp_solver_destroy(solver);
}

/* Reading a number option through the string getter is not documented either way; it must
 * not succeed with something other than the number. */
static void test_number_read_as_text(void) {
  asp_solver *solver = NULL;
  char text[64];
  int64_t length = -1;
  int status;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_option(solver, "max_iterations", 321.0));
  status = asp_solver_get_option_string(solver, "max_iterations", text, sizeof text, &length);
  check_save_message();
  if (status == ASP_OK) {
    CHECK(strtod(text, NULL) == 321.0);
    CHECK(length == (int64_t)strlen(text));
  } else {
    CHECK(status == ASP_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("'max_iterations'");
  }
  asp_solver_destroy(solver);
}

static void test_shorthands(void) {
  asp_solver *solver = NULL, *named = NULL;
  double value = 0.0;
  int64_t by_shorthand = -1, by_name = -2;
  int reason_shorthand = 0, reason_name = 0;
  Expected e = {1e-8, 10000.0, 1000.0};
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_create("pk", &named));

  CHECK_OK(asp_solver_set_tolerance(solver, 3e-5));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == 3e-5);
  e.tolerance = 3e-5;
  CHECK_OK(asp_solver_set_max_iterations(solver, 250));
  CHECK_OK(asp_solver_get_option(solver, "max_iterations", &value));
  CHECK(value == 250.0);
  e.max_iterations = 250.0;
  /* And the named option is what the shorthand changes, in both directions. */
  CHECK_OK(asp_solver_set_option(solver, "tolerance", 4e-6));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == 4e-6);
  CHECK_OK(asp_solver_set_tolerance(solver, e.tolerance));
  CHECK_OK(asp_solver_get_option(solver, "tolerance", &value));
  CHECK(value == e.tolerance);

  /* The shorthands refuse what the named options refuse, and name the option. */
  CHECK_ERROR(asp_solver_set_tolerance(solver, 0.0), ASP_ERR_INVALID_ARGUMENT, "'tolerance'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_tolerance(solver, -2.0), ASP_ERR_INVALID_ARGUMENT, "'tolerance'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_tolerance(solver, NAN), ASP_ERR_INVALID_ARGUMENT, "'tolerance'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_max_iterations(solver, 0), ASP_ERR_INVALID_ARGUMENT,
              "'max_iterations'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_max_iterations(solver, -7), ASP_ERR_INVALID_ARGUMENT,
              "'max_iterations'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_max_iterations(solver, INT64_MIN), ASP_ERR_INVALID_ARGUMENT,
              "'max_iterations'");
  CHECK_UNCHANGED_AND_USABLE(solver, &e);
  CHECK_ERROR(asp_solver_set_tolerance(NULL, 1e-6), ASP_ERR_NULL_POINTER, "'solver'");
  CHECK_ERROR(asp_solver_set_max_iterations(NULL, 5), ASP_ERR_NULL_POINTER, "'solver'");

  /* The documented range of max_iterations is "integer >= 1", and the shorthand takes an
   * int64_t: its largest value is such an integer. */
  CHECK_OK(asp_solver_set_max_iterations(solver, INT64_MAX));
  CHECK_OK(asp_solver_set_max_iterations(solver, 250));

  /* Same effect on a solve: three iterations set either way stop both solves alike. */
  CHECK_OK(asp_solver_set_max_iterations(solver, 3));
  CHECK_OK(asp_solver_set_tolerance(solver, 1e-12));
  CHECK_OK(asp_solver_set_option(named, "max_iterations", 3.0));
  CHECK_OK(asp_solver_set_option(named, "tolerance", 1e-12));
  CHECK_OK(asp_system_reset(scene));
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_iterations(solver, &by_shorthand));
  CHECK_OK(asp_solver_termination(solver, &reason_shorthand));
  CHECK_OK(asp_system_reset(scene));
  CHECK_OK(asp_solver_solve(named, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_iterations(named, &by_name));
  CHECK_OK(asp_solver_termination(named, &reason_name));
  CHECK(by_shorthand == 3 && by_name == 3);
  CHECK(reason_shorthand == ASP_TERMINATION_ITERATION_LIMIT);
  CHECK(reason_name == ASP_TERMINATION_ITERATION_LIMIT);

  asp_solver_destroy(named);
  asp_solver_destroy(solver);
}

/* The options act on the solve: a looser tolerance stops earlier, at an error that meets it. */
static void test_options_act(void) {
  asp_solver *solver = NULL;
  double error = 0.0;
  int64_t loose = 0, tight = 0;
  int converged = 0;
  CHECK_OK(asp_solver_create("pk", &solver));
  CHECK_OK(asp_solver_set_option(solver, "tolerance", 1e-3));
  CHECK_OK(asp_system_reset(scene));
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK(error <= 1e-3);
  CHECK_OK(asp_solver_iterations(solver, &loose));
  CHECK_OK(asp_solver_set_option(solver, "tolerance", 1e-11));
  CHECK_OK(asp_system_reset(scene));
  CHECK_OK(asp_solver_solve(solver, scene, ASP_CONTROL_MEAN_PRESSURE, 0.005));
  CHECK_OK(asp_solver_converged(solver, &converged));
  CHECK(converged == 1);
  CHECK_OK(asp_solver_final_error(solver, &error));
  CHECK(error <= 1e-11);
  CHECK_OK(asp_solver_iterations(solver, &tight));
  CHECK(loose < tight);
  asp_solver_destroy(solver);
}

/* The text-buffer rules of asperity.h (asp_algorithms): *length gets the whole length without
 * the NUL; size 0 with a NULL buffer asks for the length; a buffer too small gets the text cut
 * to size - 1 characters and ASP_ERR_SIZE_MISMATCH; nothing is written beyond size. */
typedef int (*TextCall)(const asp_solver *solver, char *buffer, int64_t size, int64_t *length);

static int algorithms_text(const asp_solver *solver, char *buffer, int64_t size,
                           int64_t *length) {
  (void)solver;
  return asp_algorithms(buffer, size, length);
}

static void check_text_rules(TextCall call, const asp_solver *solver, const char *name) {
  char full[8192], cut[8192];
  int64_t length = -1, again = -1, i;
  printf("text rules of %s\n", name);
  CHECK_OK(call(solver, NULL, 0, &length));
  CHECK(length > 0 && length < (int64_t)sizeof full);
  if (!(length > 0 && length < (int64_t)sizeof full)) return;

  memset(full, 'X', sizeof full);
  CHECK_OK(call(solver, full, length + 1, &again));
  CHECK(again == length);
  CHECK((int64_t)strlen(full) == length);
  CHECK(full[length + 1] == 'X');
  CHECK_OK(call(solver, full, (int64_t)sizeof full, NULL));
  CHECK((int64_t)strlen(full) == length);

  /* One byte short: the text without its last character, and SIZE_MISMATCH. */
  memset(cut, 'X', sizeof cut);
  again = -1;
  CHECK_ERROR(call(solver, cut, length, &again), ASP_ERR_SIZE_MISMATCH, "'size'");
  CHECK(again == length);
  CHECK((int64_t)strlen(cut) == length - 1);
  CHECK(strncmp(cut, full, (size_t)(length - 1)) == 0);
  CHECK(cut[length] == 'X');
  /* One byte: only the NUL. */
  memset(cut, 'X', sizeof cut);
  CHECK_ERROR(call(solver, cut, 1, &again), ASP_ERR_SIZE_MISMATCH, "'size'");
  CHECK(cut[0] == '\0' && cut[1] == 'X');
  CHECK(again == length);
  /* Too small without a length pointer is still refused. */
  memset(cut, 'X', sizeof cut);
  CHECK_ERROR(call(solver, cut, length, NULL), ASP_ERR_SIZE_MISMATCH, "'size'");
  CHECK((int64_t)strlen(cut) == length - 1 && cut[length] == 'X');
  /* A negative size and a missing buffer are named. */
  CHECK_ERROR(call(solver, cut, -1, &again), ASP_ERR_INVALID_ARGUMENT, "'size'");
  CHECK_ERROR(call(solver, NULL, 16, &again), ASP_ERR_NULL_POINTER, "'buffer'");
  for (i = 0; i < length; ++i)
    if (full[i] == '\0') break;
  CHECK(i == length);
}

static int describe_text(const asp_solver *solver, char *buffer, int64_t size, int64_t *length) {
  return asp_solver_describe(solver, buffer, size, length);
}

static void test_texts(void) {
  asp_solver *solver = NULL;
  char text[8192];
  int64_t length = 0;
  const char *options;
  char *line;
  int listed = 0;
  CHECK_OK(asp_solver_create("pk", &solver));
  check_text_rules(algorithms_text, NULL, "asp_algorithms");
  check_text_rules(describe_text, solver, "asp_solver_describe");

  /* asp_algorithms: one name per line, "pk" among them. */
  CHECK_OK(asp_algorithms(text, sizeof text, &length));
  CHECK(strncmp(text, "pk\n", 3) == 0 || strstr(text, "\npk\n") != NULL);
  CHECK(length > 0 && text[length - 1] == '\n');

  /* asp_solver_describe names what "pk" serves (both controls, the periodic substrate, the
   * hard wall) and lists each option with its type, default and range; every option it lists
   * can be read by name. */
  CHECK_OK(asp_solver_describe(solver, text, sizeof text, &length));
  CHECK(strstr(text, "pk") != NULL);
  CHECK(strstr(text, "mean_pressure") != NULL || strstr(text, "mean pressure") != NULL);
  CHECK(strstr(text, "penetration") != NULL);
  CHECK(strstr(text, "periodic") != NULL);
  CHECK(strstr(text, "hard wall") != NULL);
  CHECK(strstr(text, "real") != NULL && strstr(text, "integer") != NULL);
  CHECK(strstr(text, "tolerance") != NULL);
  CHECK(strstr(text, "max_iterations") != NULL);
  CHECK(strstr(text, "stall_window") != NULL);
  CHECK(strstr(text, "1e-08") != NULL);
  CHECK(strstr(text, "10000") != NULL);
  options = strstr(text, "options:");
  CHECK(options != NULL);
  for (line = options != NULL ? strchr(options, '\n') : NULL; line != NULL && line[1] == ' ';
       line = strchr(line + 1, '\n')) {
    char name[64];
    double value;
    char small[256];
    if (sscanf(line + 1, " %63[A-Za-z0-9_]", name) != 1) continue;
    ++listed;
    if (asp_solver_get_option(solver, name, &value) != ASP_OK) {
      /* A string option: readable with the string getter. */
      int64_t n = -1;
      if (!CHECK(asp_solver_get_option_string(solver, name, small, sizeof small, &n) == ASP_OK))
        fprintf(stderr, "  option '%s' listed by asp_solver_describe cannot be read\n", name);
    }
  }
  CHECK(listed >= 3);
  CHECK_ERROR(asp_solver_describe(NULL, text, sizeof text, &length), ASP_ERR_NULL_POINTER,
              "'solver'");
  asp_solver_destroy(solver);
}

int main(void) {
  if (!make_scene()) {
    fprintf(stderr, "cannot make the scene: %s\n", asp_last_error_message());
    return 1;
  }
  test_defaults();
  test_set_and_get();
  test_unknown_names();
  test_out_of_range();
  test_number_read_as_text();
  test_shorthands();
  test_options_act();
  test_texts();
  asp_system_destroy(scene);
  asp_grid_destroy(grid);
  return check_summary("api.solver_options");
}
