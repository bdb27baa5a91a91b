#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Checks `asperity sweep --quantity mean_pressure` on an adhesive sphere (scenes/
# adhesive_sphere.toml: 40 x 40 pixels, a second or two): loading by load, unloading back and
# on into tension until a load separates the surfaces (termination "separated"), the bracket
# halved four times (phase "pull-off"), and the pull-off force reported as the most tensile
# load with a stable state. The force pi w R is a mean pressure of 4.946e-3 on that box: the
# pull-off must lie between JKR's -1.5 and DMT's -2 pi w R (at Tabor 2, Maugis-Dugdale's is
# about -1.55), and "bugnicourt" and "lbfgsb" must find the same bracket. A sweep by load
# without adhesion searches no pull-off.
# Usage: check_adhesive_sweep.sh PATH_TO_ASPERITY SOURCE_DIRECTORY WORK_DIRECTORY
set -u
cli=$1 source=$2 work=$3
scene=$source/tests/cli/scenes/adhesive_sphere.toml
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
export XDG_CACHE_HOME=$work/cache
passed=0 failed=0
expect() {
  local what=$1
  shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL: $what"; failed=$((failed + 1)); fi
}

# The pull-off line's two mean pressures: the most tensile stable load, the separating one.
pull_off_of() { sed -n 's/^pull-off .*(mean pressure \([^)]*\)).* (mean pressure \([^)]*\)).*/\1 \2/p' "$1"; }
within() { awk -v v="$1" -v lo="$2" -v hi="$3" 'BEGIN { exit !(v >= lo && v <= hi) }'; }
rows() { awk -F, -v phase="$2" -v end="$3" '$2 == phase && $12 == end' "$1" | wc -l; }

for algorithm in bugnicourt lbfgsb; do
  "$cli" sweep "$scene" --algorithm "$algorithm" --planning estimate --no-plots \
    --output "$algorithm" > "$algorithm.out" 2> "$algorithm.err" < /dev/null
  rc=$?
  expect "$algorithm: the sweep exits 0 (stderr: $(cat "$algorithm.err"))" [ "$rc" -eq 0 ]
  csv=$algorithm/sweep.csv
  expect "$algorithm: 3 loading steps, all converged" [ "$(rows "$csv" loading converged)" -eq 3 ]
  expect "$algorithm: the unloading ends with one separated step" \
    [ "$(rows "$csv" unloading separated)" -eq 1 ]
  expect "$algorithm: the unloading goes into tension" \
    [ "$(awk -F, '$2 == "unloading" && $12 == "converged" && $3 < 0' "$csv" | wc -l)" -ge 1 ]
  expect "$algorithm: four pull-off trials, each converged or separated" \
    [ "$(awk -F, '$2 == "pull-off" && ($12 == "converged" || $12 == "separated")' "$csv" | wc -l)" -eq 4 ]
  expect "$algorithm: no separated state keeps contact" \
    [ "$(awk -F, '$12 == "separated" && $7 != 0' "$csv" | wc -l)" -eq 0 ]
  read -r stable separating <<< "$(pull_off_of "$algorithm.out")"
  expect "$algorithm: a pull-off line ($(grep '^pull-off' "$algorithm.out"))" [ -n "${separating:-}" ]
  # The bracket: a sixteenth of the unloading step of 0.002 (1.25e-4), the stable end above.
  expect "$algorithm: the bracket is 1.25e-4 wide" \
    within "$(awk -v a="${stable:-0}" -v b="${separating:-0}" 'BEGIN { print a - b }')" 1.24e-4 1.26e-4
  expect "$algorithm: the pull-off ($stable) lies between -1.5 and -2 pi w R" \
    within "${stable:-0}" -9.892e-3 -7.419e-3
  echo "$algorithm: pull-off between ${separating:-?} and ${stable:-?}"
  eval "bracket_$algorithm='${stable:-} ${separating:-}'"
done
expect "bugnicourt and lbfgsb find the same bracket" [ "$bracket_bugnicourt" = "$bracket_lbfgsb" ]

# Without adhesion: a sweep by load, no pull-off search.
"$cli" sweep "$source/tests/cli/scenes/small.toml" --quantity mean_pressure --from 0.005 \
  --to 0.01 --steps 1 --algorithm lbfgsb --option variable=gap --planning estimate --no-plots \
  --output plain > plain.out 2> plain.err < /dev/null
rc=$?
expect "a plain sweep by load on the gap exits 0 (stderr: $(cat plain.err))" [ "$rc" -eq 0 ]
expect "a plain sweep has 3 steps and no pull-off" \
  [ "$(wc -l < plain/sweep.csv),$(grep -c '^pull-off' plain.out)" = "4,0" ]

echo "check_adhesive_sweep: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
