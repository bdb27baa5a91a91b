/* The asperity command's arguments: what they may be, how they are read and checked. */
#ifndef ASPERITY_CLI_OPTIONS_H
#define ASPERITY_CLI_OPTIONS_H

#include <stdint.h>
#include <stdio.h>

/* Exit statuses of the command, documented in its --help. */
#define CLI_EXIT_CONVERGED 0     /* the solve converged (or an informational option ran) */
#define CLI_EXIT_NOT_CONVERGED 1 /* the solve ended without converging */
#define CLI_EXIT_USAGE 2         /* a bad argument; nothing was computed */
#define CLI_EXIT_FAILURE 3       /* the library or the system failed */

/* The built-in scene's fixed parameters (the --help text states them too). */
#define CLI_BOX_LENGTH 1.0
#define CLI_CONTACT_MODULUS 1.0
#define CLI_HURST 0.8
#define CLI_RMS_SLOPE 0.1
#define CLI_ROLLOFF_PER_BOX 4     /* roll-off wavelength: a quarter of the box */
#define CLI_SHORT_CUTOFF_PIXELS 8 /* short cutoff wavelength, in pixels */
/* The smallest grid whose short cutoff lies below its roll-off: 8/n < 1/4. */
#define CLI_MIN_SIZE (CLI_SHORT_CUTOFF_PIXELS * CLI_ROLLOFF_PER_BOX + 1)
/* The largest mean pressure, in units of E*: the built-in surface is in full contact well
 * below it, and strains of order one are outside linear elasticity. */
#define CLI_MAX_MEAN_PRESSURE 1.0
/* The largest penetration, in units of the box length: far beyond full contact of the
 * built-in surface, whose heights span about a hundredth of the box. */
#define CLI_MAX_PENETRATION 1.0

/* One solver option, from --option NAME=VALUE or --tolerance T, applied in command-line order. */
struct cli_setting {
  const char *argument; /* the command-line option it came from: --option or --tolerance */
  const char *shown;    /* its value as written (NAME=VALUE for --option), for messages */
  char *name;           /* owned */
  const char *text;     /* VALUE as written */
  int is_number;        /* the whole text reads as a finite number */
  double number;
};

struct cli_options {
  int64_t size;
  int64_t seed;
  double mean_pressure;
  int mean_pressure_given;
  double penetration; /* used when penetration_control is set */
  int penetration_control;
  const char *algorithm;
  const char *history_path; /* NULL: no history */
  struct cli_setting *settings;
  int n_settings;
  /* Informational requests: each prints and the command exits without solving. */
  int help;
  int version;
  int list_algorithms;
  int describe;
};

/* Reads argv into *options (defaults for what is not given). On a bad argument, writes a
 * message to err naming the argument and the problem and returns CLI_EXIT_USAGE (or
 * CLI_EXIT_FAILURE if memory runs out); otherwise returns 0. Call cli_options_free afterwards
 * in every case. */
int cli_parse(int argc, char **argv, struct cli_options *options, FILE *err);
void cli_options_free(struct cli_options *options);

void cli_usage(FILE *out);

#endif
