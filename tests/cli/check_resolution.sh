#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# The command's warning for a scene whose grid does not resolve its interaction
# (asp_system_check_resolution): a "warning" line among the scene's lines, before any solve,
# in run --check, run, compare and sweep, for an adhesive hard wall whose cohesive zone
# (pi/4) E* rho^2/w is 0.05 pixels of a 64 x 64 grid; none for the same scene with a zone of
# 5 pixels, nor for the built-in scene (3.2 pixels). Also the soft wall and the Lennard-Jones
# wall, unresolved, in run --check. Solves are cut to a few iterations: only what is printed
# before them is checked.
# Usage: check_resolution.sh PATH_TO_ASPERITY SOURCE_DIRECTORY WORK_DIRECTORY
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
run() { "$cli" "$@" > "$out" 2> "$err" < /dev/null; rc=$?; }

# The small rough contact (64 x 64 pixels on a box of 1 um, E* = 1) with the adhesive hard
# wall of range rho and work w, solved by bugnicourt on the gap under penetration control
# (the value is given apart: a sweep replaces it), cut to 20 iterations.
adhesive() {
  local w=$1 rho=$2
  echo "$small" --set interaction.type=adhesive_hard_wall \
    --set interaction.work_of_adhesion="$w" --set interaction.range="$rho" \
    --set control.quantity=penetration \
    --algorithm bugnicourt --option variable=gap --set solver.max_iterations=20 --no-plots
}
at="--set control.value=0.002"
# 1e-3 is 0.064 pixels: the cohesive zone (pi/4) 1e-6/1e-3 = 7.9e-4 um, 0.0503 pixels.
unresolved=$(adhesive 1e-3 1e-3)
# 1e-2 is 0.64 pixels: the zone (pi/4) 1e-4/1e-3 = 0.079 um, 5.03 pixels.
resolved=$(adhesive 1e-3 1e-2)

# warned WHAT: stdout has the warning, with the zone in pixels, before LINE (a regular
# expression: the first line that comes after the scene).
warned() {
  local what=$1 pixels=$2 before=$3
  local at_warning at_before
  at_warning=$(grep -n -m 1 "^warning  *not resolved: the cohesive zone" "$out" | cut -d: -f1)
  at_before=$(grep -n -m 1 -E "$before" "$out" | cut -d: -f1)
  if [ -z "$at_warning" ]; then
    fail "$what: no warning; stdout: $(cat "$out"); stderr: $(cat "$err")"
  elif ! grep -q "^warning .* $pixels pixels .*lattice trapping" "$out"; then
    fail "$what: the warning does not give $pixels pixels and lattice trapping: $(grep '^warning' "$out")"
  elif [ -z "$at_before" ] || [ "$at_warning" -ge "$at_before" ]; then
    fail "$what: the warning does not come before /$before/: $(cat "$out")"
  else
    pass
  fi
}
not_warned() {
  local what=$1 expected_line=$2
  if grep -q "^warning" "$out"; then
    fail "$what: a warning: $(grep '^warning' "$out")"
  elif ! grep -qE "$expected_line" "$out"; then
    fail "$what: no /$expected_line/ (did it run? exit $rc; stderr: $(cat "$err"))"
  else
    pass
  fi
}

# shellcheck disable=SC2086 # the scene's arguments are words without blanks
{
  # ---- run --check ----
  run run $unresolved $at --check
  [ "$rc" -eq 0 ] && pass || fail "run --check of an unresolved scene exits $rc, expected 0"
  warned "run --check, unresolved" 0.0503 "^solver .* serves the scene"
  run run $resolved $at --check
  not_warned "run --check, resolved" "^solver .* serves the scene"
  run run --check
  not_warned "run --check of the built-in scene (3.2 pixels)" "^solver .* serves the scene"

  # ---- run ----
  run run $unresolved $at --output run-unresolved
  warned "run, unresolved" 0.0503 "^(control|termination) "
  run run $resolved $at --output run-resolved
  not_warned "run, resolved" "^termination "

  # ---- compare ----
  run compare $unresolved $at --solvers bugnicourt --repeats 1 --output compare-unresolved
  warned "compare, unresolved" 0.0503 "^(control|bugnicourt:gap) "
  run compare $resolved $at --solvers bugnicourt --repeats 1 --output compare-resolved
  not_warned "compare, resolved" "^bugnicourt:gap "

  # ---- sweep ----
  run sweep $unresolved --quantity penetration --from 0 --to 0.002 --steps 1 --no-unload \
    --output sweep-unresolved
  warned "sweep, unresolved" 0.0503 "^(sweep|step) "
  run sweep $resolved --quantity penetration --from 0 --to 0.002 --steps 1 --no-unload \
    --output sweep-resolved
  not_warned "sweep, resolved" "^ +1 loading"

  # ---- the soft walls: the built-in scene's wall on pixels 8 times larger (its zone of
  # 6.3e-3 um is 0.402 of a pixel of 1/64 um), and a Lennard-Jones wall of w = 1e-3 and
  # z0 = 1e-3 um (zone 0.366 z0^2/w = 3.66e-4 um, 0.0234 pixels) ----
  run run "$small" --set interaction.type=soft_wall --set interaction.gamma_r=3.2e-4 \
    --set interaction.gamma_a=8e-5 --set interaction.range=1e-4 --algorithm lbfgs_fourier --check
  warned "run --check, soft wall" 0.402 "^solver .* serves the scene"
  run run "$small" --set interaction.type=lennard_jones --set interaction.work_of_adhesion=1e-3 \
    --set interaction.equilibrium_distance=1e-3 --algorithm lbfgs_fourier --check
  warned "run --check, Lennard-Jones wall" 0.0234 "^solver .* serves the scene"
  # The plain hard wall of the small scene: nothing to resolve.
  run run "$small" --check
  not_warned "run --check, plain hard wall" "^solver .* serves the scene"
}

echo "check_resolution: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
