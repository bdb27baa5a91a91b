#!/usr/bin/env bash
# Checks the asperity command from the outside, as a user runs it:
#   - every bad argument exits with status 2 before any work, with a message on standard error
#     that names the argument and says what is wrong, and prints nothing on standard output;
#   - --help documents the exit statuses; --version, --list-algorithms and --describe;
#   - small solves: a converged one exits 0, one cut short exits 1, and the report says how the
#     solve ended and never shows inf or nan;
#   - --history writes a CSV file: a header with every column, then rows of numbers;
#   - the progress line appears only when standard error is a terminal;
#   - Ctrl-C cancels the solve cleanly (exit 1, reported as cancelled).
# Grids are small (64 x 64 unless a case needs more) so that the whole check takes seconds.
# Usage: check_command.sh PATH_TO_ASPERITY WORK_DIRECTORY
set -u
cli=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
out=$work/stdout err=$work/stderr

passed=0 failed=0 skipped=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
pass() { passed=$((passed + 1)); }
skip() { echo "skipped: $*"; skipped=$((skipped + 1)); }
show() { local a s=asperity; for a in "$@"; do s+=" $(printf '%q' "$a")"; done; echo "$s"; }

# run ARGS...: runs the command; standard output and error go to files, the status to $rc.
run() { "$cli" "$@" > "$out" 2> "$err" < /dev/null; rc=$?; }

# bad ARGUMENT PROBLEM ARGS...: the command run with ARGS exits 2 and says on standard error
# ARGUMENT (literally) and PROBLEM (an extended regular expression), with nothing on stdout.
bad() {
  local argument=$1 problem=$2
  shift 2
  run "$@"
  local what
  what=$(show "$@")
  if [ "$rc" -ne 2 ]; then
    fail "$what: exit status $rc, expected 2; stderr: $(cat "$err")"
  elif ! grep -qF -- "$argument" "$err"; then
    fail "$what: the message does not name '$argument': $(cat "$err")"
  elif ! grep -qE -- "$problem" "$err"; then
    fail "$what: the message does not say '$problem': $(cat "$err")"
  elif [ -s "$out" ]; then
    fail "$what: printed on standard output: $(cat "$out")"
  else
    pass
  fi
}

# expect WHAT CONDITION...: records a check whose condition is a command.
expect() {
  local what=$1
  shift
  if "$@"; then pass; else fail "$what"; fi
}

has() { grep -qE -- "$1" "$2"; }
lacks() { ! grep -qE -- "$1" "$2"; }

# ---- bad arguments: exit 2, the argument and its problem named --------------------------------
# --size below 33 used to fail inside the library with a message about cutoffs.
bad --size "too small: at least 33" --size 16
bad --size "too small: at least 33" --size 32
bad --size "too small" --size -64
# An empty value used to read as 0.
bad --size "empty" --size ''
bad --size "not a whole number" --size 12abc
bad --size "not a whole number" --size 64.0
bad --size "not a whole number" --size ' 64'
# 1518500250^2 * 8 bytes wraps a 64-bit size.
bad --size "too large" --size 1518500250
bad --size "too large" --size 9223372036854775807
bad --size "out of range" --size 99999999999999999999
# A seed beyond 64 bits used to become INT64_MAX silently.
bad --seed "out of range" --seed 99999999999999999999
bad --seed "out of range" --seed -99999999999999999999
bad --seed "not a whole number" --seed 1e3
# Options, positional arguments and flags used to be answered with "needs a value".
bad -x "unknown option" -x
bad --frobnicate "unknown option" --frobnicate
bad --frobnicate "unknown option" --frobnicate=3
bad foo "unexpected argument" foo
bad scene.txt "unexpected argument" --size 64 scene.txt
bad --size "needs a value" --size
bad --size "needs a value" --size --seed 3
bad --version "takes no value" --version=1
# A mean pressure of 1e308 used to print inf and -nan and exit 0.
bad --mean-pressure "out of range" --mean-pressure 1e308
bad --mean-pressure "out of range" --mean-pressure 1.5
bad --mean-pressure "out of range" --mean-pressure -0.001
bad --mean-pressure "too large for a double" --mean-pressure 1e400
bad --mean-pressure "not a finite number" --mean-pressure nan
bad --mean-pressure "not a finite number" --mean-pressure inf
bad --mean-pressure "empty" --mean-pressure ''
bad --penetration "out of range" --penetration 1.5
bad --penetration "out of range" --penetration -0.001
bad --penetration "not a finite number" --penetration nan
bad --mean-pressure "cannot be combined with --penetration" --penetration 0.004 --mean-pressure 0.01
bad --penetration "cannot be combined with --mean-pressure" --mean-pressure 0.01 --penetration 0.004
bad --tolerance "not a number" --tolerance abc
bad --tolerance "tolerance" --tolerance 0
bad --algorithm "unknown algorithm" --algorithm no-such-solver
bad --algorithm "unknown algorithm" --algorithm no-such-solver --describe
bad --algorithm "empty" --algorithm ''
bad --option "expected NAME=VALUE" --option tolerance
bad --option "NAME is empty" --option =3
bad --option "no option 'no_such_option'" --option no_such_option=1
bad --option "not a finite number" --option tolerance=inf
bad --option "max_iterations" --option max_iterations=0
bad --option "tolerance" --option tolerance=fast
bad --history "empty" --history ''
bad --history "cannot open for writing" --size 64 --history "$work/no/such/directory/h.csv"

# ---- information ---------------------------------------------------------------------------
run --help
expect "--help exits 0" [ "$rc" -eq 0 ]
expect "--help documents exit statuses 0 to 3" \
  bash -c 'grep -q "Exit status" "$1" && grep -qE "^  0 " "$1" && grep -qE "^  1 " "$1" &&
           grep -qE "^  2 " "$1" && grep -qE "^  3 " "$1"' _ "$out"
expect "--help names every option" bash -c '
  for o in --size --seed --mean-pressure --penetration --algorithm --tolerance --option --history \
           --version --list-algorithms --describe; do
    grep -q -- "$o" "$1" || exit 1
  done' _ "$out"
run -h
expect "-h prints the help" has "^usage: asperity" "$out"

run --version
expect "--version exits 0" [ "$rc" -eq 0 ]
expect "--version prints the version" has "^asperity [0-9]+\.[0-9]+\.[0-9]+" "$out"
expect "--version prints one line" [ "$(wc -l < "$out")" -eq 1 ]

run --list-algorithms
expect "--list-algorithms exits 0" [ "$rc" -eq 0 ]
expect "--list-algorithms lists pk" has "^pk$" "$out"

run --describe
expect "--describe exits 0" [ "$rc" -eq 0 ]
expect "--describe describes pk" has "^pk: " "$out"
expect "--describe lists the options" has "tolerance" "$out"
run --describe --algorithm pk
expect "--describe --algorithm pk exits 0" [ "$rc" -eq 0 ]

# ---- solves --------------------------------------------------------------------------------
run --size 64
expect "a 64 x 64 solve exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the report says it converged" has "^termination +converged" "$out"
expect "the report gives the contact fraction" has "^contact fraction +0\.[0-9]+" "$out"
expect "the report shows no inf or nan" lacks "inf|nan" "$out"
# stderr is a file here: no progress line, nothing at all.
expect "no progress line when stderr is not a terminal" [ ! -s "$err" ]

run --size=64 --seed=-7 --mean-pressure=0.01 --tolerance=1e-6 --option stall_window=50
expect "the --name=value form works (exit $rc, stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the report names the seed" has "seed -7" "$out"

# Solvers that offer no load control (lbfgsb; bugnicourt on the gap) solve the scene under
# penetration control; under load control they are refused, naming the control.
run --size 64 --algorithm lbfgsb --penetration 0.004
expect "lbfgsb under --penetration exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the report gives the penetration asked for" has "^penetration +0\.004$" "$out"
run --size 64 --algorithm bugnicourt --option variable=gap --penetration 0.004
expect "bugnicourt on the gap under --penetration exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
bad --algorithm "does not offer mean_pressure control" --size 64 --algorithm lbfgsb

run --size 64 --option max_iterations=3
expect "a solve cut short by the iteration limit exits 1" [ "$rc" -eq 1 ]
expect "the report says the iteration limit ended it" has "^termination +iteration limit" "$out"
expect "a solve cut short shows no inf or nan" lacks "inf|nan" "$out"

# ---- history -------------------------------------------------------------------------------
csv=$work/history.csv
run --size 64 --history "$csv"
expect "a solve with --history exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "--history writes the file" [ -s "$csv" ]
header=iteration,evaluations,transforms,seconds,error,objective,contact_fraction
expect "the history has the header line" [ "$(head -n 1 "$csv")" = "$header" ]
expect "the history has at least one row" [ "$(wc -l < "$csv")" -ge 2 ]
expect "every history row has 7 numeric columns" awk -F, '
  NR > 1 {
    if (NF != 7) exit 1
    for (i = 1; i <= NF; ++i)
      if ($i !~ /^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/) exit 1
    rows++
  }
  END { exit rows > 0 ? 0 : 1 }' "$csv"
expect "the history starts at iteration 0" [ "$(sed -n 2p "$csv" | cut -d, -f1)" = 0 ]
expect "the report says where the history went" has "^history .*history\.csv" "$out"

# A write that fails after the solve is a failure of the system: exit 3. A file-size limit of 0
# makes every write to a file fail (EFBIG, with SIGXFSZ ignored); the report goes through a pipe,
# which the limit does not cover.
full=$work/limited.csv
( trap '' XFSZ && ulimit -f 0 && exec "$cli" --size 64 --history "$full" 2>&1 < /dev/null ) |
  cat > "$out"
rc=${PIPESTATUS[0]}
expect "a history that cannot be written exits 3 (got $rc)" [ "$rc" -eq 3 ]
expect "a history that cannot be written is named in the message" \
  has "--history '.*limited\.csv': writing failed" "$out"

# ---- terminal and interruption ---------------------------------------------------------------
# script(1) from util-linux runs the command on a pseudo-terminal.
if script -qefc true /dev/null > /dev/null 2>&1; then
  script -qefc "$(printf '%q' "$cli") --size 64" /dev/null > "$out" 2>&1 < /dev/null
  expect "a progress line is drawn on a terminal" has $'\riteration 0 +error ' "$out"
  expect "the progress line is erased before the report" has $'\r *\rasperity ' "$out"
else
  skip "no script(1) to run the command on a terminal"
fi

# An endless solve (tolerance out of reach, no stall detection), interrupted after 0.3 s.
if command -v timeout > /dev/null; then
  timeout --preserve-status -s INT 0.3 "$cli" --size 64 --tolerance 1e-300 \
    --option stall_window=0 --option max_iterations=1e15 > "$out" 2> "$err" < /dev/null
  rc=$?
  expect "Ctrl-C ends the solve with exit 1 (got $rc)" [ "$rc" -eq 1 ]
  expect "Ctrl-C is reported as cancelled" has "^termination +cancelled" "$out"
else
  skip "no timeout(1) to interrupt the command"
fi

echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
