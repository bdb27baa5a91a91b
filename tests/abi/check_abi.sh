#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The ABI guard: the built library against the committed baseline abi/libasperity.abi.
# Functions added to the C API pass; anything removed or changed (a function, a parameter's
# or return type, the soname) fails, with libabigail's report and how to change the ABI on
# purpose. With --notices-removal, checks instead that a baseline with a function the library
# lacks is refused (that the guard can fail).
#
#   check_abi.sh SOURCE_DIR BUILD_DIR LIBRARY [--notices-removal WORK_DIR]
set -uo pipefail
source=$1 build=$2 library=$3
baseline=$source/abi/libasperity.abi
compare() {
  abidiff --exported-interfaces-only --no-added-syms \
    --headers-dir2 "$source/include" --headers-dir2 "$build/include" "$1" "$library"
}

if [ "${4:-}" = --notices-removal ]; then
  work=$5
  mkdir -p "$work"
  # The baseline with asp_abi_version renamed: the library lacks that function.
  sed "s/'asp_abi_version'/'asp_abi_version_removed'/g" "$baseline" > "$work/removed.abi"
  compare "$work/removed.abi" > "$work/report.txt"
  status=$?
  if [ $((status & 8)) -eq 0 ]; then
    echo "FAIL: a removed function was not reported as incompatible (abidiff status $status)"
    cat "$work/report.txt"
    exit 1
  fi
  grep -q asp_abi_version_removed "$work/report.txt" || { echo "FAIL: report"; exit 1; }
  # The baseline with asp_grid_create_2d's lx of nx's type (int64_t): a changed parameter.
  python3 - "$baseline" "$work/changed.abi" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
start = text.index("<function-decl name='asp_grid_create_2d'")
end = text.index("</function-decl>", start)
decl = text[start:end]
types = dict((n, t) for t, n in re.findall(r"parameter type-id='([^']+)' name='(\w+)'", decl))
decl = decl.replace("type-id='%s' name='lx'" % types["lx"], "type-id='%s' name='lx'" % types["nx"])
open(sys.argv[2], "w").write(text[:start] + decl + text[end:])
PY
  compare "$work/changed.abi" > "$work/changed.txt"
  status=$?
  if [ "$status" -eq 0 ] || ! grep -q asp_grid_create_2d "$work/changed.txt"; then
    echo "FAIL: a changed parameter type was not reported (abidiff status $status)"
    exit 1
  fi
  echo "the guard notices a removed function and a changed parameter"
  exit 0
fi

compare "$baseline"
status=$?
if [ "$status" -ne 0 ]; then
  echo
  echo "The C interface changed incompatibly against abi/libasperity.abi (abidiff status $status)."
  echo "If that is meant: bump ASPERITY_ABI_VERSION in CMakeLists.txt, rebuild, run"
  echo "tools/update-abi-baseline.sh BUILD_DIR and commit the new baseline (docs/abi.md)."
  exit 1
fi
echo "the ABI matches the baseline (additions allowed)"
