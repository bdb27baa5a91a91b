/* The asperity command: solves a built-in rough-contact scene and prints the results.
 * It uses only the public C interface, like any other program that links the library.
 *
 * The flow: read the arguments (options.c); answer an informational request; make the solver
 * and apply its options, so that a bad algorithm or option is refused before any work; build
 * the scene; solve; report (output.c). Exit statuses are those of options.h. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asperity/asperity.h"
#include "options.h"
#include "output.h"

/* Ctrl-C during a solve cancels it through the progress callback; a second one quits. */
static volatile sig_atomic_t interrupted = 0;

static void on_interrupt(int signal_number) {
  interrupted = 1;
  signal(signal_number, SIG_DFL);
}

/* A library call failed for a reason other than a bad argument. */
static int failed(int status, const char *what) {
  fprintf(stderr, "asperity: %s failed: %s (%s)\n", what, asp_status_string(status),
          asp_last_error_message());
  return CLI_EXIT_FAILURE;
}

/* The library refused what an argument asked for: a bad argument when it calls the request
 * invalid or unsupported, a failure otherwise (out of memory, ...). */
static int refused(int status, const char *argument, const char *value) {
  if (status != ASP_ERR_INVALID_ARGUMENT && status != ASP_ERR_UNSUPPORTED)
    return failed(status, argument);
  fprintf(stderr, "asperity: %s '%s': %s\n", argument, value, asp_last_error_message());
  fprintf(stderr, "Run 'asperity --help' for the options.\n");
  return CLI_EXIT_USAGE;
}

/* Prints the text of asp_algorithms (solver NULL) or of asp_solver_describe. */
static int print_library_text(const asp_solver *solver, FILE *out) {
  const char *what = solver != NULL ? "describing the algorithm" : "listing the algorithms";
  int64_t length = 0;
  char *text;
  int status = solver != NULL ? asp_solver_describe(solver, NULL, 0, &length)
                              : asp_algorithms(NULL, 0, &length);
  if (status != ASP_OK) return failed(status, what);
  if (length < 0 || (uint64_t)length >= SIZE_MAX || (text = malloc((size_t)length + 1)) == NULL) {
    fprintf(stderr, "asperity: %s: out of memory\n", what);
    return CLI_EXIT_FAILURE;
  }
  status = solver != NULL ? asp_solver_describe(solver, text, length + 1, NULL)
                          : asp_algorithms(text, length + 1, NULL);
  if (status == ASP_OK) fputs(text, out);
  free(text);
  return status == ASP_OK ? 0 : failed(status, what);
}

/* --tolerance, --option and --history, in command-line order. */
static int configure(asp_solver *solver, const struct cli_options *o) {
  int k, status;
  for (k = 0; k < o->n_settings; ++k) {
    const struct cli_setting *s = &o->settings[k];
    status = s->is_number ? asp_solver_set_option(solver, s->name, s->number)
                          : asp_solver_set_option_string(solver, s->name, s->text);
    if (status != ASP_OK) return refused(status, s->argument, s->shown);
  }
  if (o->history_path != NULL && (status = asp_solver_set_history(solver, 1)) != ASP_OK)
    return failed(status, "turning the history on");
  return 0;
}

/* Builds the scene, solves it and reports. */
static int solve(asp_solver *solver, const struct cli_options *o) {
  const int64_t n = o->size;
  const int64_t n_pixels = n * n; /* cli_parse made sure that n*n doubles are addressable */
  const double length = CLI_BOX_LENGTH;
  asp_grid *grid = NULL;
  asp_system *system = NULL;
  double *heights = NULL;
  FILE *history = NULL;
  struct cli_progress progress;
  struct cli_report report;
  void (*previous_handler)(int) = SIG_ERR;
  int status = CLI_EXIT_FAILURE, asp_status;

  /* Open the history file first: a path that cannot be written is a bad argument, found
   * before the work rather than after it. */
  if (o->history_path != NULL && (history = fopen(o->history_path, "w")) == NULL) {
    fprintf(stderr, "asperity: --history '%s': cannot open for writing: %s\n", o->history_path,
            strerror(errno));
    return CLI_EXIT_USAGE;
  }

  /* From here on Ctrl-C is kept for the solve, unless the command was started ignoring it. */
  previous_handler = signal(SIGINT, on_interrupt);
  if (previous_handler == SIG_IGN) signal(SIGINT, SIG_IGN);

  if ((asp_status = asp_grid_create_2d(n, n, length, length, &grid)) != ASP_OK) {
    status = failed(asp_status, "creating the grid");
    goto done;
  }
  if ((heights = malloc((size_t)n_pixels * sizeof *heights)) == NULL) {
    fprintf(stderr, "asperity: out of memory: the heights of a %lld x %lld grid need %.0f MB\n",
            (long long)n, (long long)n, (double)n_pixels * sizeof *heights / 1e6);
    goto done;
  }
  if ((asp_status = asp_topography_self_affine(
           grid, CLI_HURST, length, length / CLI_ROLLOFF_PER_BOX,
           CLI_SHORT_CUTOFF_PIXELS * length / (double)n, ASP_RMS_SLOPE, CLI_RMS_SLOPE, o->seed,
           heights, n_pixels)) != ASP_OK) {
    status = failed(asp_status, "making the surface");
    goto done;
  }
  if ((asp_status = asp_system_create(grid, CLI_CONTACT_MODULUS, &system)) != ASP_OK) {
    status = failed(asp_status, "creating the system");
    goto done;
  }
  if ((asp_status = asp_system_set_topography(system, heights, n_pixels)) != ASP_OK) {
    status = failed(asp_status, "setting the surface");
    goto done;
  }

  cli_progress_init(&progress, stderr, &interrupted);
  if ((asp_status = asp_solver_set_progress(solver, cli_progress_update, &progress)) != ASP_OK) {
    status = failed(asp_status, "setting the progress callback");
    goto done;
  }
  asp_status = o->penetration_control
                   ? asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, o->penetration)
                   : asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, o->mean_pressure);
  cli_progress_clear(&progress);
  if (asp_status == ASP_ERR_UNSUPPORTED) { /* the algorithm cannot serve this scene */
    status = refused(asp_status, "--algorithm", o->algorithm);
    goto done;
  }
  if (asp_status != ASP_OK) {
    status = failed(asp_status, "solving");
    goto done;
  }

  report.algorithm = o->algorithm;
  report.size = n;
  report.seed = o->seed;
  if ((asp_status = cli_report_read(solver, system, &report)) != ASP_OK) {
    status = failed(asp_status, "reading the results");
    goto done;
  }
  if ((status = cli_report_print(&report, stdout, stderr)) != 0) goto done;

  if (history != NULL) {
    int64_t rows = 0;
    if ((status = cli_history_write(solver, history, o->history_path, stderr, &rows)) != 0)
      goto done;
    errno = 0;
    if (fclose(history) != 0) {
      history = NULL;
      fprintf(stderr, "asperity: --history '%s': writing failed: %s\n", o->history_path,
              errno != 0 ? strerror(errno) : "write error");
      status = CLI_EXIT_FAILURE;
      goto done;
    }
    history = NULL;
    printf("history           %lld rows in %s\n", (long long)rows, o->history_path);
  }
  status = report.termination == ASP_TERMINATION_CONVERGED ? CLI_EXIT_CONVERGED
                                                            : CLI_EXIT_NOT_CONVERGED;

done:
  /* The file is left as it is (empty when the solve did not run): it may not even be a regular
   * file of ours to remove. */
  if (history != NULL) fclose(history);
  if (previous_handler != SIG_ERR) signal(SIGINT, previous_handler);
  asp_solver_set_progress(solver, NULL, NULL);
  asp_system_destroy(system);
  free(heights);
  asp_grid_destroy(grid);
  return status;
}

static int run(const struct cli_options *o) {
  asp_solver *solver = NULL;
  int status;

  if (o->help) {
    cli_usage(stdout);
    return CLI_EXIT_CONVERGED;
  }
  if (o->version) printf("asperity %s\n", asp_version_string());
  if (o->list_algorithms && (status = print_library_text(NULL, stdout)) != 0) return status;
  if ((o->version || o->list_algorithms) && !o->describe) return CLI_EXIT_CONVERGED;

  if ((status = asp_solver_create(o->algorithm, &solver)) != ASP_OK)
    return refused(status, "--algorithm", o->algorithm);
  if (o->describe)
    status = print_library_text(solver, stdout);
  else if ((status = configure(solver, o)) == 0)
    status = solve(solver, o);
  asp_solver_destroy(solver);
  return status;
}

int main(int argc, char **argv) {
  struct cli_options options;
  int status = cli_parse(argc, argv, &options, stderr);
  if (status == 0) status = run(&options);
  cli_options_free(&options);
  return status;
}
