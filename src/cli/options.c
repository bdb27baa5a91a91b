/* Reading and checking the asperity command's arguments. Nothing here calls the library: an
 * argument is refused here when its text or its value is wrong for the built-in scene, and the
 * library judges solver options and algorithm names when main applies them. */
#include "options.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void cli_usage(FILE *out) {
  fprintf(out,
          "usage: asperity [OPTION]...\n"
          "\n"
          "Solves the built-in scene, which needs no input files: a periodic self-affine surface\n"
          "(Hurst exponent 0.8, rms slope 0.1, roll-off at a quarter of the box, short cutoff at\n"
          "8 pixels) pressed on an elastic half-space (E* = 1, box 1 x 1) at a mean pressure or a\n"
          "penetration, and prints how the solve ended and the contact's main results.\n"
          "\n"
          "Scene and solve:\n"
          "  --size N             grid of N x N pixels, N >= %d (default 512)\n"
          "  --seed S             seed of the random surface, a 64-bit integer (default 1)\n"
          "  --mean-pressure P    mean pressure in units of E*, 0 <= P <= %g (default 0.002)\n"
          "  --penetration D      solve under penetration control instead, D in units of the\n"
          "                       box, 0 <= D <= %g (for solvers that offer no load control,\n"
          "                       such as lbfgsb); not together with --mean-pressure\n"
          "  --algorithm NAME     solver (default pk; see --list-algorithms)\n"
          "  --tolerance T        stopping tolerance on the error, the same as\n"
          "                       --option tolerance=T (default 1e-8)\n"
          "  --option NAME=VALUE  sets a solver option (see --describe); repeatable, applied in\n"
          "                       order. A VALUE that reads as a number sets a numeric option,\n"
          "                       any other a text option\n"
          "  --history FILE       writes the solve's history to FILE as CSV: a header line, then\n"
          "                       one row per iteration (iteration, evaluations, transforms,\n"
          "                       seconds, error, objective, contact_fraction)\n"
          "\n"
          "Information (prints, then exits without solving):\n"
          "  --version            the library's version\n"
          "  --list-algorithms    the algorithms of this build, one per line\n"
          "  --describe           what the chosen algorithm does and its options\n"
          "  -h, --help           this text\n"
          "\n"
          "An option's value follows it as the next argument or after '=' (--size=256).\n"
          "When standard error is a terminal, a progress line (iteration, error, seconds)\n"
          "is shown there during the solve. Ctrl-C stops the solve at the next iteration and\n"
          "reports it as cancelled; a second Ctrl-C quits at once.\n"
          "\n"
          "Exit status:\n"
          "  0  the solve converged (or an information option ran)\n"
          "  1  the solve ended without converging: iteration limit, stalled, cancelled or\n"
          "     breakdown (the report says which, and shows the state the solve left)\n"
          "  2  a bad argument, refused before any work: unknown or malformed option, value out\n"
          "     of range, unknown algorithm or solver option, history file that cannot be\n"
          "     opened for writing\n"
          "  3  the library or the system failed: out of memory, FFT planning, a scene the\n"
          "     library cannot represent, writing the history file\n",
          CLI_MIN_SIZE, CLI_MAX_MEAN_PRESSURE, CLI_MAX_PENETRATION);
}

/* Every refusal is one line naming the argument (and its value, when it has one), then a hint. */
static int refuse(FILE *err, const char *argument, const char *value, const char *problem) {
  if (value != NULL)
    fprintf(err, "asperity: %s '%s': %s\n", argument, value, problem);
  else
    fprintf(err, "asperity: %s: %s\n", argument, problem);
  fprintf(err, "Run 'asperity --help' for the options.\n");
  return CLI_EXIT_USAGE;
}

/* strtoll and strtod skip leading white space and accept a sign; a value must be the number
 * and nothing else, so white space anywhere is refused. */
static int starts_with_space(const char *text) {
  return text[0] != '\0' && isspace((unsigned char)text[0]);
}

static int read_int64(FILE *err, const char *argument, const char *text, int64_t *out) {
  char *end = NULL;
  long long value;
  if (text[0] == '\0') return refuse(err, argument, text, "empty, expected a whole number");
  errno = 0;
  value = strtoll(text, &end, 10);
  if (starts_with_space(text) || end == text || *end != '\0')
    return refuse(err, argument, text, "not a whole number");
#if LLONG_MAX > INT64_MAX
  if (value < INT64_MIN || value > INT64_MAX) errno = ERANGE;
#endif
  if (errno == ERANGE)
    return refuse(err, argument, text,
                  "out of range: a 64-bit integer lies between -9223372036854775808 and "
                  "9223372036854775807");
  *out = (int64_t)value;
  return 0;
}

/* A finite double from text; messages show the argument and `shown` (the text as the user
 * wrote it). Returns 0 if read, the refusal status if not, or -1 without a message when
 * `quiet_if_not_number` is set and the text is not a number at all. */
static int read_double(FILE *err, const char *argument, const char *shown, const char *text,
                       double *out, int quiet_if_not_number) {
  char *end = NULL;
  double value;
  if (text[0] == '\0') {
    if (quiet_if_not_number) return -1;
    return refuse(err, argument, shown, "empty, expected a number");
  }
  errno = 0;
  value = strtod(text, &end);
  if (starts_with_space(text) || end == text || *end != '\0') {
    if (quiet_if_not_number) return -1;
    return refuse(err, argument, shown, "not a number");
  }
  if (errno == ERANGE)
    return refuse(err, argument, shown,
                  value > 1.0 || value < -1.0 ? "out of range: too large for a double"
                                              : "out of range: too small for a normal double");
  if (!isfinite(value)) return refuse(err, argument, shown, "not a finite number");
  *out = value;
  return 0;
}

static int check_size(FILE *err, const char *argument, const char *text, int64_t n) {
  /* The command holds the n x n heights in one array: n*n*sizeof(double) bytes must be
   * addressable and n*n must be an int64_t pixel count. */
  const uint64_t bytes_limit = (uint64_t)(SIZE_MAX / sizeof(double));
  const uint64_t limit = bytes_limit < (uint64_t)INT64_MAX ? bytes_limit : (uint64_t)INT64_MAX;
  char problem[160];
  if (n < CLI_MIN_SIZE) {
    snprintf(problem, sizeof problem,
             "too small: at least %d, so that the surface's short cutoff (%d pixels) lies "
             "below its roll-off (a quarter of the box)",
             CLI_MIN_SIZE, CLI_SHORT_CUTOFF_PIXELS);
    return refuse(err, argument, text, problem);
  }
  if ((uint64_t)n > limit / (uint64_t)n)
    return refuse(err, argument, text,
                  "too large: the heights of an N x N grid would need more memory than this "
                  "machine can address");
  return 0;
}

static int check_mean_pressure(FILE *err, const char *argument, const char *text, double p) {
  char problem[160];
  if (p < 0.0 || p > CLI_MAX_MEAN_PRESSURE) {
    snprintf(problem, sizeof problem,
             "out of range: the mean pressure must lie between 0 and %g (in units of E*)",
             CLI_MAX_MEAN_PRESSURE);
    return refuse(err, argument, text, problem);
  }
  return 0;
}

static int check_penetration(FILE *err, const char *argument, const char *text, double d) {
  char problem[160];
  if (d < 0.0 || d > CLI_MAX_PENETRATION) {
    snprintf(problem, sizeof problem,
             "out of range: the penetration must lie between 0 and %g (in units of the box)",
             CLI_MAX_PENETRATION);
    return refuse(err, argument, text, problem);
  }
  return 0;
}

static char *copy_text(const char *text, size_t length) {
  char *copy = malloc(length + 1);
  if (copy != NULL) {
    memcpy(copy, text, length);
    copy[length] = '\0';
  }
  return copy;
}

/* A solver option: from --option NAME=VALUE (shown is the whole NAME=VALUE, and VALUE may be
 * a number or text) or from --tolerance VALUE (a number). */
static int add_setting(FILE *err, struct cli_options *o, const char *argument, const char *shown,
                       const char *name, size_t name_length, const char *value, int number_only) {
  struct cli_setting *s = &o->settings[o->n_settings];
  int status = read_double(err, argument, shown, value, &s->number, !number_only);
  if (status > 0) return status;
  s->argument = argument;
  s->shown = shown;
  s->text = value;
  s->is_number = status == 0;
  s->name = copy_text(name, name_length);
  if (s->name == NULL) {
    fprintf(err, "asperity: out of memory\n");
    return CLI_EXIT_FAILURE;
  }
  ++o->n_settings;
  return 0;
}

/* The options, in the order of --help. */
enum cli_key {
  KEY_SIZE, KEY_SEED, KEY_MEAN_PRESSURE, KEY_PENETRATION, KEY_ALGORITHM, KEY_TOLERANCE, KEY_OPTION, KEY_HISTORY,
  KEY_VERSION, KEY_LIST_ALGORITHMS, KEY_DESCRIBE, KEY_HELP
};
static const struct {
  const char *name;
  enum cli_key key;
  int takes_value;
} known_options[] = {{"--size", KEY_SIZE, 1},
                     {"--seed", KEY_SEED, 1},
                     {"--mean-pressure", KEY_MEAN_PRESSURE, 1},
                     {"--penetration", KEY_PENETRATION, 1},
                     {"--algorithm", KEY_ALGORITHM, 1},
                     {"--tolerance", KEY_TOLERANCE, 1},
                     {"--option", KEY_OPTION, 1},
                     {"--history", KEY_HISTORY, 1},
                     {"--version", KEY_VERSION, 0},
                     {"--list-algorithms", KEY_LIST_ALGORITHMS, 0},
                     {"--describe", KEY_DESCRIBE, 0},
                     {"--help", KEY_HELP, 0},
                     {"-h", KEY_HELP, 0}};
#define CLI_KNOWN_OPTIONS (sizeof known_options / sizeof known_options[0])

/* The option's index in known_options, or -1. name_length counts the characters of arg before
 * an '=' (the whole of arg without one). */
static int find_option(const char *arg, size_t name_length) {
  size_t k;
  for (k = 0; k < CLI_KNOWN_OPTIONS; ++k)
    if (strlen(known_options[k].name) == name_length &&
        strncmp(known_options[k].name, arg, name_length) == 0)
      return (int)k;
  return -1;
}

/* Sets what the option with a value asks for, or refuses the value. */
static int take_value(FILE *err, struct cli_options *o, enum cli_key key, const char *name,
                      const char *value) {
  int status = 0;
  switch (key) {
    case KEY_SIZE: {
      int64_t n = 0;
      status = read_int64(err, name, value, &n);
      if (status == 0) status = check_size(err, name, value, n);
      if (status == 0) o->size = n;
      break;
    }
    case KEY_SEED: status = read_int64(err, name, value, &o->seed); break;
    case KEY_MEAN_PRESSURE: {
      double p = 0.0;
      status = read_double(err, name, value, value, &p, 0);
      if (status == 0) status = check_mean_pressure(err, name, value, p);
      if (status == 0) o->mean_pressure = p;
      if (status == 0 && o->penetration_control)
        return refuse(err, name, value, "cannot be combined with --penetration");
      o->mean_pressure_given = 1;
      break;
    }
    case KEY_PENETRATION: {
      double d = 0.0;
      status = read_double(err, name, value, value, &d, 0);
      if (status == 0) status = check_penetration(err, name, value, d);
      if (status == 0 && o->mean_pressure_given)
        return refuse(err, name, value, "cannot be combined with --mean-pressure");
      if (status == 0) {
        o->penetration = d;
        o->penetration_control = 1;
      }
      break;
    }
    case KEY_ALGORITHM:
      if (value[0] == '\0') return refuse(err, name, value, "empty, expected a name");
      o->algorithm = value;
      break;
    case KEY_TOLERANCE:
      status = add_setting(err, o, name, value, "tolerance", strlen("tolerance"), value, 1);
      break;
    case KEY_OPTION: {
      const char *separator = strchr(value, '=');
      if (separator == NULL) return refuse(err, name, value, "expected NAME=VALUE");
      if (separator == value) return refuse(err, name, value, "the NAME is empty");
      status = add_setting(err, o, name, value, value, (size_t)(separator - value),
                           separator + 1, 0);
      break;
    }
    case KEY_HISTORY:
      if (value[0] == '\0') return refuse(err, name, value, "empty, expected a file name");
      o->history_path = value;
      break;
    default: break; /* options without a value do not come here */
  }
  return status;
}

int cli_parse(int argc, char **argv, struct cli_options *o, FILE *err) {
  int i, only_positional = 0;
  o->size = 512;
  o->seed = 1;
  o->mean_pressure = 0.002;
  o->mean_pressure_given = 0;
  o->penetration = 0.0;
  o->penetration_control = 0;
  o->algorithm = "pk";
  o->history_path = NULL;
  o->n_settings = 0;
  o->help = o->version = o->list_algorithms = o->describe = 0;
  /* At most one setting per argument. */
  o->settings = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *o->settings);
  if (o->settings == NULL) {
    fprintf(err, "asperity: out of memory\n");
    return CLI_EXIT_FAILURE;
  }

  for (i = 1; i < argc; ++i) {
    const char *arg = argv[i];
    const char *equals = strchr(arg, '=');
    const size_t name_length = equals != NULL ? (size_t)(equals - arg) : strlen(arg);
    const char *value = equals != NULL ? equals + 1 : NULL;
    const char *name;
    int k, status;

    if (only_positional || arg[0] != '-' || arg[1] == '\0')
      return refuse(err, arg, NULL,
                    "unexpected argument: the command reads no files and takes only options "
                    "(its scene is built in)");
    if (strcmp(arg, "--") == 0) { /* the end of the options */
      only_positional = 1;
      continue;
    }
    k = find_option(arg, name_length);
    if (k < 0) {
      /* Name the option without its value: "--frobnicate" for "--frobnicate=3". */
      fprintf(err, "asperity: %.*s: unknown option\n", (int)name_length, arg);
      fprintf(err, "Run 'asperity --help' for the options.\n");
      return CLI_EXIT_USAGE;
    }
    name = known_options[k].name;

    if (!known_options[k].takes_value) {
      if (value != NULL) return refuse(err, name, NULL, "takes no value");
      switch (known_options[k].key) {
        case KEY_VERSION: o->version = 1; break;
        case KEY_LIST_ALGORITHMS: o->list_algorithms = 1; break;
        case KEY_DESCRIBE: o->describe = 1; break;
        default: o->help = 1; break;
      }
      continue;
    }

    /* The value follows '=' or is the next argument, which must not be an option (so that
     * "--size --seed 3" says that --size lacks its value); negative numbers are values. */
    if (value == NULL) {
      if (i + 1 >= argc) return refuse(err, name, NULL, "needs a value");
      if (strncmp(argv[i + 1], "--", 2) == 0 && argv[i + 1][2] != '\0') {
        char problem[96];
        snprintf(problem, sizeof problem, "needs a value (got the option '%.60s')",
                 argv[i + 1]);
        return refuse(err, name, NULL, problem);
      }
      value = argv[++i];
    }
    if ((status = take_value(err, o, known_options[k].key, name, value)) != 0) return status;
  }
  return 0;
}

void cli_options_free(struct cli_options *o) {
  int k;
  if (o->settings == NULL) return;
  for (k = 0; k < o->n_settings; ++k) free(o->settings[k].name);
  free(o->settings);
  o->settings = NULL;
  o->n_settings = 0;
}
