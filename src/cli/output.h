/* What the asperity command prints: the report of a solve, the live progress line and the
 * history file. */
#ifndef ASPERITY_CLI_OUTPUT_H
#define ASPERITY_CLI_OUTPUT_H

#include <signal.h>
#include <stdint.h>
#include <stdio.h>

#include "asperity/asperity.h"

/* The report of one solve of the built-in scene. */
struct cli_report {
  const char *algorithm;
  int64_t size;
  int64_t seed;
  int termination; /* ASP_TERMINATION_* */
  int64_t iterations;
  double seconds;
  double error;
  double tolerance;
  double contact_fraction;
  double mean_pressure;
  double penetration;
};

/* Fills the report's results from the solver and the system after a solve (the caller sets
 * algorithm, size and seed). Returns ASP_OK or the status of the call that failed. */
int cli_report_read(const asp_solver *solver, const asp_system *system, struct cli_report *r);

/* Prints the report to out. Returns 0, or CLI_EXIT_FAILURE after a message on err if a
 * number is not finite (the library promises finite results; a report never shows inf or
 * nan). */
int cli_report_print(const struct cli_report *r, FILE *out, FILE *err);

/* "converged", "iteration limit", ... for an ASP_TERMINATION_* reason. */
const char *cli_termination_name(int reason);

/* The progress callback's state. The line is drawn only when stderr is a terminal; the
 * callback also cancels the solve once *interrupted is set (by Ctrl-C). */
struct cli_progress {
  FILE *stream;
  int draw;                            /* stream is a terminal */
  volatile sig_atomic_t *interrupted;  /* may be NULL */
  double last_drawn;                   /* seconds of the last line drawn, < 0 before any */
  int width;                           /* characters of the line on screen */
};

/* Sets up *p for stream, drawing only if stream is a terminal. */
void cli_progress_init(struct cli_progress *p, FILE *stream, volatile sig_atomic_t *interrupted);

/* An asp_progress_fn; user_data is a struct cli_progress. */
int cli_progress_update(int64_t iteration, double seconds, double error, void *user_data);

/* Erases the line, if one was drawn, so that what follows starts on a clean line. */
void cli_progress_clear(struct cli_progress *p);

/* Writes the solver's history as CSV to file: a header with every column's name, then one
 * row per iteration. Returns 0 and sets *rows, or after a message on err (naming path)
 * CLI_EXIT_FAILURE when the library fails, a value is not finite or the write fails. Does not
 * close the file. */
int cli_history_write(const asp_solver *solver, FILE *file, const char *path, FILE *err,
                      int64_t *rows);

#endif
