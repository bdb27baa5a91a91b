#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Fuzzes every driver of a build configured with ASPERITY_FUZZ for a bounded time, each on a
# copy of its seed corpus (corpus/<driver>/, which stays as committed), and fails on the first
# finding: a crash or a broken contract (the drivers trap), an error of the sanitizers, a leak,
# an input that runs longer than 10 s (-timeout) or needs more than 2 GB (-rss_limit_mb).
#
#   tests/fuzz/run_fuzzers.sh BUILD_DIR SECONDS_PER_DRIVER
#
# The reproducer of a finding is left in BUILD_DIR/fuzz-findings/, named by libFuzzer
# (crash-..., leak-..., timeout-..., oom-...); `BUILD_DIR/tests/fuzz/fuzz_DRIVER FILE` runs it
# again. New inputs found on the way are left in BUILD_DIR/fuzz-corpus/<driver>/.
set -uo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 BUILD_DIR SECONDS_PER_DRIVER" >&2
  exit 2
fi
build=$(cd "$1" && pwd) || exit 2
seconds=$2
here=$(cd "$(dirname "$0")" && pwd)
findings=$build/fuzz-findings
mkdir -p "$findings"

status=0
for seeds in "$here"/corpus/*/; do
  driver=$(basename "$seeds")
  program=$build/tests/fuzz/fuzz_$driver
  if [ ! -x "$program" ]; then
    echo "run_fuzzers.sh: $program is not built (configure with -DASPERITY_FUZZ=ON)" >&2
    status=1
    continue
  fi
  corpus=$build/fuzz-corpus/$driver
  rm -rf "$corpus" && mkdir -p "$corpus" && cp "$seeds"* "$corpus"/
  dictionary=()
  [ -f "$here/$driver.dict" ] && dictionary=(-dict="$here/$driver.dict")
  echo "== fuzz_$driver for $seconds s"
  # One thread per solve: the grids of the C API driver are far below the size at which the
  # library uses more, and a fuzzer's executions should not compete for the cores.
  if OMP_NUM_THREADS=1 "$program" "$corpus" "${dictionary[@]}" -max_total_time="$seconds" \
       -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$findings/$driver-" \
       -print_final_stats=1 > "$build/fuzz-$driver.log" 2>&1; then
    grep -E "^stat::(number_of_executed_units|peak_rss_mb)|^#[0-9]+.*DONE" \
      "$build/fuzz-$driver.log" | tr '\n' ' '
    echo
  else
    echo "run_fuzzers.sh: fuzz_$driver found a problem (reproducer in $findings):" >&2
    tail -n 60 "$build/fuzz-$driver.log" >&2
    status=1
  fi
done
exit $status
