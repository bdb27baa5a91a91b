/* The report, the progress line and the history file of the asperity command. */
#define _POSIX_C_SOURCE 200809L /* isatty, fileno */

#include "output.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _WIN32
#include <io.h>
#define isatty _isatty
#define fileno _fileno
#else
#include <unistd.h>
#endif

#include "options.h"

/* ---- report ---------------------------------------------------------------------------------- */

const char *cli_termination_name(int reason) {
  switch (reason) {
    case ASP_TERMINATION_CONVERGED: return "converged";
    case ASP_TERMINATION_ITERATION_LIMIT: return "iteration limit";
    case ASP_TERMINATION_CANCELLED: return "cancelled";
    case ASP_TERMINATION_STALLED: return "stalled";
    case ASP_TERMINATION_BREAKDOWN: return "breakdown";
    default: return "unknown";
  }
}

int cli_report_read(const asp_solver *solver, const asp_system *system, struct cli_report *r) {
  int status = asp_solver_termination(solver, &r->termination);
  if (status == ASP_OK) status = asp_solver_iterations(solver, &r->iterations);
  if (status == ASP_OK) status = asp_solver_elapsed_seconds(solver, &r->seconds);
  if (status == ASP_OK) status = asp_solver_final_error(solver, &r->error);
  if (status == ASP_OK) status = asp_solver_get_option(solver, "tolerance", &r->tolerance);
  if (status == ASP_OK) status = asp_system_get(system, ASP_CONTACT_FRACTION, &r->contact_fraction);
  if (status == ASP_OK) status = asp_system_get(system, ASP_MEAN_PRESSURE, &r->mean_pressure);
  if (status == ASP_OK) status = asp_system_get(system, ASP_PENETRATION, &r->penetration);
  return status;
}

int cli_report_print(const struct cli_report *r, FILE *out, FILE *err) {
  const struct {
    const char *name;
    double value;
  } numbers[] = {{"time", r->seconds},
                 {"error", r->error},
                 {"tolerance", r->tolerance},
                 {"contact fraction", r->contact_fraction},
                 {"mean pressure", r->mean_pressure},
                 {"penetration", r->penetration}};
  size_t k;
  for (k = 0; k < sizeof numbers / sizeof numbers[0]; ++k)
    if (!isfinite(numbers[k].value)) {
      fprintf(err,
              "asperity: the library returned a %s that is not finite, after a solve that "
              "ended as '%s'; this is a bug in asperity, please report it\n",
              numbers[k].name, cli_termination_name(r->termination));
      return CLI_EXIT_FAILURE;
    }

  fprintf(out, "asperity %s: %s on a %lld x %lld self-affine surface (seed %lld)\n",
          asp_version_string(), r->algorithm, (long long)r->size, (long long)r->size,
          (long long)r->seed);
  fprintf(out, "termination       %s after %lld iterations (%.3f s)\n",
          cli_termination_name(r->termination), (long long)r->iterations, r->seconds);
  fprintf(out, "error             %.3e (tolerance %.3g)\n", r->error, r->tolerance);
  fprintf(out, "contact fraction  %.6f\n", r->contact_fraction);
  fprintf(out, "mean pressure     %.6g\n", r->mean_pressure);
  fprintf(out, "penetration       %.6g\n", r->penetration);
  return 0;
}

/* ---- progress line --------------------------------------------------------------------------- */

/* Redraw at most this often: a solve makes thousands of iterations a second on small grids. */
#define CLI_PROGRESS_INTERVAL 0.1

void cli_progress_init(struct cli_progress *p, FILE *stream, volatile sig_atomic_t *interrupted) {
  p->stream = stream;
  p->draw = isatty(fileno(stream));
  p->interrupted = interrupted;
  p->last_drawn = -1.0;
  p->width = 0;
}

int cli_progress_update(int64_t iteration, double seconds, double error, void *user_data) {
  struct cli_progress *p = (struct cli_progress *)user_data;
  if (p->draw && (p->last_drawn < 0.0 || seconds - p->last_drawn >= CLI_PROGRESS_INTERVAL)) {
    char line[96];
    int width;
    if (isfinite(error))
      width = snprintf(line, sizeof line, "iteration %lld  error %.3e  %.1f s",
                       (long long)iteration, error, seconds);
    else
      width = snprintf(line, sizeof line, "iteration %lld  error not finite  %.1f s",
                       (long long)iteration, seconds);
    if (width < 0) width = 0;
    if (width >= (int)sizeof line) width = (int)sizeof line - 1;
    /* Spaces cover what is left of a longer previous line. */
    fprintf(p->stream, "\r%s%*s", line, p->width > width ? p->width - width : 0, "");
    fflush(p->stream);
    if (width > p->width) p->width = width;
    p->last_drawn = seconds;
  }
  return p->interrupted != NULL && *p->interrupted ? 1 : 0;
}

void cli_progress_clear(struct cli_progress *p) {
  if (p->draw && p->width > 0) {
    fprintf(p->stream, "\r%*s\r", p->width, "");
    fflush(p->stream);
  }
  p->width = 0;
}

/* ---- history file ---------------------------------------------------------------------------- */

static const struct {
  int column;
  const char *name;
} history_columns[] = {{ASP_HISTORY_ITERATION, "iteration"},
                       {ASP_HISTORY_EVALUATIONS, "evaluations"},
                       {ASP_HISTORY_TRANSFORMS, "transforms"},
                       {ASP_HISTORY_SECONDS, "seconds"},
                       {ASP_HISTORY_ERROR, "error"},
                       {ASP_HISTORY_OBJECTIVE, "objective"},
                       {ASP_HISTORY_CONTACT_FRACTION, "contact_fraction"}};
#define CLI_HISTORY_COLUMNS (sizeof history_columns / sizeof history_columns[0])

static int library_failure(FILE *err, const char *path, int status) {
  fprintf(err, "asperity: --history '%s': reading the history failed: %s (%s)\n", path,
          asp_status_string(status), asp_last_error_message());
  return CLI_EXIT_FAILURE;
}

int cli_history_write(const asp_solver *solver, FILE *file, const char *path, FILE *err,
                      int64_t *rows) {
  const size_t columns = CLI_HISTORY_COLUMNS;
  double *values = NULL;
  int64_t n = 0, i;
  size_t c;
  int status = asp_solver_history_length(solver, &n);
  if (status != ASP_OK) return library_failure(err, path, status);

  if (n > 0) {
    if ((uint64_t)n > SIZE_MAX / columns / sizeof *values ||
        (values = malloc(columns * (size_t)n * sizeof *values)) == NULL) {
      fprintf(err, "asperity: --history '%s': out of memory for %lld rows\n", path,
              (long long)n);
      return CLI_EXIT_FAILURE;
    }
    for (c = 0; c < columns; ++c) {
      status = asp_solver_get_history(solver, history_columns[c].column, values + c * (size_t)n,
                                      n);
      if (status != ASP_OK) {
        free(values);
        return library_failure(err, path, status);
      }
    }
    for (c = 0; c < columns * (size_t)n; ++c)
      if (!isfinite(values[c])) {
        fprintf(err,
                "asperity: --history '%s': the library's history holds a %s that is not "
                "finite (row %lld); this is a bug in asperity, please report it\n",
                path, history_columns[c / (size_t)n].name, (long long)(c % (size_t)n));
        free(values);
        return CLI_EXIT_FAILURE;
      }
  }

  for (c = 0; c < columns; ++c) fprintf(file, "%s%s", c ? "," : "", history_columns[c].name);
  fputc('\n', file);
  for (i = 0; i < n; ++i) {
    for (c = 0; c < columns; ++c)
      fprintf(file, "%s%.17g", c ? "," : "", values[c * (size_t)n + (size_t)i]);
    fputc('\n', file);
  }
  free(values);
  errno = 0;
  if (fflush(file) != 0 || ferror(file)) {
    fprintf(err, "asperity: --history '%s': writing failed: %s\n", path,
            errno != 0 ? strerror(errno) : "write error");
    return CLI_EXIT_FAILURE;
  }
  *rows = n;
  return 0;
}
