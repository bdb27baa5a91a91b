#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The command says "contact" the way the library does, in every output:
#   - the built-in scene (an adhesive soft wall, on 128^2 pixels here): the mean of contact.npy
#     is the contact fraction the report prints and summary.csv gives (to the last digit), and
#     the last row of history.csv gives the same; summary.csv gives the compressive fraction,
#     no larger. (The map used to be the sign of the pressure, which off contact is of
#     rounding size, ±2e-13 here, with a sign that changes with the FFT plan: 0.63 of the
#     pixels in one run, 0.07 = the contact in another.)
#   - an adhesive hard wall solved on the gap and cut short at its iteration limit (exit 1):
#     the report says what the state is, no gap below 0 in gap.npy, and contact.npy, the
#     summary and the last history row agree.
# Usage: check_contact.sh PATH_TO_ASPERITY SOURCE_DIRECTORY WORK_DIRECTORY
set -u
cli=$1 source=$2 work=$3
small=$source/tests/cli/scenes/small.toml
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
export XDG_CACHE_HOME=$work/cache
out=$work/stdout err=$work/stderr

passed=0 failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
pass() { passed=$((passed + 1)); }
expect() {
  local what=$1
  shift
  if "$@"; then pass; else fail "$what"; fi
}
run() { "$cli" "$@" > "$out" 2> "$err" < /dev/null; rc=$?; }

# npy_values FILE: the doubles of a little-endian .npy file (format 1.0 or 2.0), one a line.
npy_values() {
  local file=$1 major header_length
  major=$(od -A n -t u1 -j 6 -N 1 "$file" | tr -d ' ')
  if [ "$major" = 1 ]; then
    header_length=$(( $(od -A n -t u2 -j 8 -N 2 --endian=little "$file" | tr -d ' ') + 10 ))
  else
    header_length=$(( $(od -A n -t u4 -j 8 -N 4 --endian=little "$file" | tr -d ' ') + 12 ))
  fi
  od -A n -v -t f8 -j "$header_length" --endian=little "$file" | tr -s ' ' '\n' | sed '/^$/d'
}
# The mean of a contact map, as the library computes the fraction (a count over the pixels),
# to 17 digits; and its values other than 0 and 1, if any.
map_mean() { npy_values "$1" | awk '{ s += $1; n++ } END { printf "%.17g\n", s / n }'; }
not_binary() { npy_values "$1" | awk '$1 != 0 && $1 != 1' | head -n 1; }
# summary.csv's value of a quantity; history.csv's last value of a column.
summary_value() { awk -F, -v q="$2" '$1 == q { print $2 }' "$1/summary.csv"; }
last_history() {
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
                        { v = $c } END { print v }' "$1/history.csv"
}
# Two numbers equal as doubles (the CSV writes 17 significant digits).
same() { awk -v a="$1" -v b="$2" 'BEGIN { exit (a + 0 == b + 0 && a != "") ? 0 : 1 }'; }

# ---- the built-in scene: an adhesive soft wall ----
run run --set grid.nx=128 --set grid.ny=128 --set topography.short_cutoff=0.0625 \
  --set output.fields='["contact"]' --output builtin
if [ "$rc" -ne 0 ]; then
  fail "the built-in scene at 128^2 did not converge (exit $rc): $(cat "$err")"
else
  pass
  mean=$(map_mean builtin/contact.npy)
  printed=$(awk '/^contact fraction/ { print $3 }' "$out")
  summary=$(summary_value builtin contact_fraction)
  compressive=$(summary_value builtin compressive_fraction)
  expect "contact.npy holds only 0 and 1" [ -z "$(not_binary builtin/contact.npy)" ]
  expect "the mean of contact.npy ($mean) is the printed contact fraction ($printed)" \
    [ "$(printf '%.6f' "$mean")" = "$printed" ]
  expect "the mean of contact.npy ($mean) is summary.csv's contact_fraction ($summary)" \
    same "$mean" "$summary"
  expect "history.csv's last contact_fraction is summary.csv's ($summary)" \
    same "$(last_history builtin contact_fraction)" "$summary"
  expect "summary.csv gives a compressive_fraction ($compressive) <= contact_fraction" \
    awk -v c="$compressive" -v f="$summary" 'BEGIN { exit (c != "" && c + 0 <= f + 0) ? 0 : 1 }'
fi

# ---- an adhesive hard wall on the gap, cut short ----
run run "$small" --set interaction.type='"adhesive_hard_wall"' \
  --set interaction.work_of_adhesion=1e-4 --set interaction.range=2e-3 \
  --set solver.algorithm='"bugnicourt"' --option variable='"gap"' \
  --set control.quantity='"penetration"' --set control.value=0.0 \
  --set solver.max_iterations=4 --set solver.tolerance=1e-12 \
  --set output.fields='["contact", "gap"]' --output cut
if [ "$rc" -ne 1 ]; then
  fail "the adhesive solve cut at 4 iterations exits $rc, expected 1: $(cat "$err")"
else
  pass
  mean=$(map_mean cut/contact.npy)
  summary=$(summary_value cut contact_fraction)
  expect "the report says the state is the last iterate, projected onto g >= 0" \
    grep -q "last iterate.*g >= 0" "$out"
  expect "no gap below 0 in gap.npy" \
    [ -z "$(npy_values cut/gap.npy | awk '$1 < 0' | head -n 1)" ]
  expect "the mean of contact.npy ($mean) is summary.csv's contact_fraction ($summary)" \
    same "$mean" "$summary"
  expect "history.csv's last contact_fraction is summary.csv's ($summary)" \
    same "$(last_history cut contact_fraction)" "$summary"
  mismatch=$(paste <(npy_values cut/gap.npy) <(npy_values cut/contact.npy) |
    awk '($1 == 0) != ($2 == 1)' | head -n 1)
  expect "contact.npy is 1 exactly where gap.npy is 0 (gap, map: $mismatch)" [ -z "$mismatch" ]
fi

echo "check_contact: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
