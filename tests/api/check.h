/* SPDX-License-Identifier: GPL-2.0-or-later */
/* Checks for the C API tests: each CHECK prints file:line, the failing expression and the
 * library's last error message, and counts the failure; check_summary() prints the counts and
 * gives the program's exit status (non-zero if any check failed).
 *
 * Error checks read asp_last_error_message() right after the call, before any other asperity
 * call can replace it. */
#ifndef ASPERITY_TESTS_API_CHECK_H
#define ASPERITY_TESTS_API_CHECK_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "asperity/asperity.h"

static int check_passed = 0;
static int check_failed = 0;

/* The message of the last call, copied so that later calls cannot change it. */
static char check_message[2048];

static inline void check_save_message(void) {
  const char *m = asp_last_error_message();
  strncpy(check_message, m != NULL ? m : "(NULL)", sizeof check_message - 1);
  check_message[sizeof check_message - 1] = '\0';
}

static inline int check_record(int ok, const char *file, int line, const char *expression) {
  if (ok) {
    ++check_passed;
  } else {
    ++check_failed;
    fprintf(stderr, "%s:%d: check failed: %s\n", file, line, expression);
  }
  return ok;
}

/* A condition. */
#define CHECK(condition) check_record((condition) ? 1 : 0, __FILE__, __LINE__, #condition)

/* A call that must succeed; on failure prints its status and message. */
static inline int check_ok(int status, const char *file, int line, const char *call) {
  check_save_message();
  if (status != ASP_OK)
    fprintf(stderr, "%s:%d: status %d (%s), message '%s'\n", file, line, status,
            asp_status_string(status), check_message);
  return check_record(status == ASP_OK, file, line, call);
}
#define CHECK_OK(call) check_ok((call), __FILE__, __LINE__, #call " == ASP_OK")

/* A call that must fail with `expected` and a message containing `text` (NULL: any message
 * that is not empty). The message stays in check_message for further checks. */
static inline int check_error(int status, int expected, const char *text, const char *file,
                              int line, const char *call) {
  int ok;
  check_save_message();
  ok = status == expected && check_message[0] != '\0' &&
       (text == NULL || strstr(check_message, text) != NULL);
  if (!ok)
    fprintf(stderr, "%s:%d: status %d (want %d), message '%s' (want %s%s%s)\n", file, line,
            status, expected, check_message, text != NULL ? "it to contain '" : "any message",
            text != NULL ? text : "", text != NULL ? "'" : "");
  return check_record(ok, file, line, call);
}
#define CHECK_ERROR(call, expected, text) \
  check_error((call), (expected), (text), __FILE__, __LINE__, #call)

/* The message saved by the last CHECK_OK or CHECK_ERROR contains `text`. */
static inline int check_message_has(const char *text, const char *file, int line) {
  const int ok = strstr(check_message, text) != NULL;
  if (!ok) fprintf(stderr, "%s:%d: message '%s' lacks '%s'\n", file, line, check_message, text);
  return check_record(ok, file, line, "the message names what it should");
}
#define CHECK_MESSAGE_HAS(text) check_message_has((text), __FILE__, __LINE__)

/* |a - b| <= tolerance, both finite. */
static inline int check_near(double a, double b, double tolerance, const char *file, int line,
                             const char *expression) {
  const int ok = isfinite(a) && isfinite(b) && fabs(a - b) <= tolerance;
  if (!ok)
    fprintf(stderr, "%s:%d: %.17g and %.17g differ by %.3g > %.3g\n", file, line, a, b,
            fabs(a - b), tolerance);
  return check_record(ok, file, line, expression);
}
#define CHECK_NEAR(a, b, tolerance) \
  check_near((a), (b), (tolerance), __FILE__, __LINE__, #a " ~ " #b " within " #tolerance)

/* Prints the counts; returns the exit status of the program. */
static inline int check_summary(const char *program) {
  printf("%s: %d checks passed, %d failed\n", program, check_passed, check_failed);
  return check_failed == 0 ? 0 : 1;
}

#endif /* ASPERITY_TESTS_API_CHECK_H */
