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
# The jump test of a load-controlled sweep: the sphere's sweep stays on one JKR branch and
# reports no jump; a wavy surface (scenes/wavy_snap_in.toml) snaps into full contact between
# two loading steps, and the note and the sweep.csv row marked `jump` must be that step and no
# other; under penetration control, where the load jumps instead, nothing is reported.
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
  # One JKR branch from the first load to the pull-off: no step jumped.
  expect "$algorithm: the sphere's sweep reports no jump ($(grep '^note:' "$algorithm.out"))" \
    [ "$(grep -c '^note: the contact jumped' "$algorithm.out"),$(awk -F, 'NR > 1 && $14 != ""' "$csv" | wc -l)" = "0,0" ]
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

# A sweep of a single load still searches the pull-off: its one loading step is the stable
# state the search starts from.
sed 's/^sweep = .*/sweep = { values = [0.004] }/' "$scene" > one_value.toml
"$cli" sweep one_value.toml --planning estimate --no-plots --output one_value \
  > one_value.out 2> one_value.err < /dev/null
rc=$?
expect "a one-load sweep exits 0 (stderr: $(cat one_value.err))" [ "$rc" -eq 0 ]
read -r stable separating <<< "$(pull_off_of one_value.out)"
expect "a one-load sweep finds the pull-off ($(grep '^pull-off' one_value.out))" \
  within "${stable:-0}" -9.892e-3 -7.419e-3

# A wavy surface under increasing load: partial contact up to a load where its branch ends,
# then full contact. The step that jumped is the loading step with the largest move in
# penetration, the first in full contact; its note gives the two steps' figures as sweep.csv
# has them. Unloading keeps full contact until the surfaces separate: one jump in all.
wavy=$source/tests/cli/scenes/wavy_snap_in.toml
for algorithm in bugnicourt lbfgsb; do
  out=wavy-$algorithm
  "$cli" sweep "$wavy" --algorithm "$algorithm" --planning estimate --no-plots \
    --output "$out" > "$out.out" 2> "$out.err" < /dev/null
  rc=$?
  expect "$algorithm: the wavy sweep exits 0 (stderr: $(cat "$out.err"))" [ "$rc" -eq 0 ]
  csv=$out/sweep.csv
  # The loading step whose penetration moved most from the step before.
  biggest=$(awk -F, 'NR > 2 && $2 == "loading" && $5 - d > most { most = $5 - d; k = $1 }
                     NR > 1 { d = $5 } END { print k }' "$csv")
  yes_rows=$(awk -F, 'NR > 1 && $14 == "yes" { printf "%s%s", sep, $1; sep = " " }' "$csv")
  expect "$algorithm: one row marked jump (${yes_rows:-none}), the largest move in penetration (${biggest:-none})" \
    [ "${yes_rows:-none}" = "${biggest:-missing}" ]
  expect "$algorithm: the jump is into full contact from partial contact" \
    awk -F, -v k="${biggest:-0}" '$1 == k - 1 { before = $7 } $1 == k { after = $7 }
                                  END { exit !(before > 0.3 && before < 0.9 && after == 1) }' "$csv"
  expect "$algorithm: the only other column value is empty" \
    [ "$(awk -F, 'NR > 1 && $14 != "" && $14 != "yes"' "$csv" | wc -l)" -eq 0 ]
  # The note, after the step's line, with that step's and the one before's figures.
  expected=$(awk -F, -v k="${biggest:-0}" '$1 == k - 1 { d1 = $5; p1 = $4; k1 = $13 }
      $1 == k { printf "note: the contact jumped to another stable branch between steps %d and %d (penetration %.6g -> %.6g at mean pressure %.6g -> %.6g; secant %.6g, tangents %.6g, %.6g)\n",
                k - 1, k, d1, $5, p1, $4, ($4 - p1) / ($5 - d1), k1, $13 }' "$csv")
  expect "$algorithm: one note, after step ${biggest:-?}'s line ($(grep '^note:' "$out.out"))" \
    [ "$(grep -c '^note: the contact jumped' "$out.out")" -eq 1 ]
  expect "$algorithm: the note says what sweep.csv has ($expected)" \
    [ "$(grep -A1 "^ *${biggest:-x} loading " "$out.out" | sed -n 2p)" = "$expected" ]
done

# Under penetration control the same snap-in shows as a drop of the load at one penetration,
# and the steps are not compared: across the snap-in from 0.0095 to 0.0105 both states are
# stable with tangents 0.64 and pi, and the secant is negative.
"$cli" sweep "$wavy" --quantity penetration --from 0.0045 --to 0.0105 --steps 6 --no-unload \
  --planning estimate --no-plots --output wavy-penetration > wavy-penetration.out \
  2> wavy-penetration.err < /dev/null
rc=$?
expect "the wavy sweep by penetration exits 0 (stderr: $(cat wavy-penetration.err))" [ "$rc" -eq 0 ]
csv=wavy-penetration/sweep.csv
expect "by penetration the load drops at the snap-in (its last step)" \
  awk -F, 'NR > 1 { if (p != "" && $4 < p) drops++; p = $4 } END { exit !(drops == 1 && $7 == 1) }' "$csv"
expect "by penetration no jump is reported" \
  [ "$(grep -c '^note: the contact jumped' wavy-penetration.out),$(awk -F, 'NR > 1 && $14 != ""' "$csv" | wc -l)" = "0,0" ]

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
