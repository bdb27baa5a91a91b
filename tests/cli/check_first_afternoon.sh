#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Checks what a new user meets in a first afternoon with the asperity command:
#   - compare on an adhesive scene compares every variant that serves it (bugnicourt:gap,
#     lbfgsb:gap), named so in the table, the CSV files and the pictures;
#   - unknown keys and options: every accepted key listed, a "did you mean" for a misspelt
#     key, option or algorithm, a misspelt required key reported as the unknown key it is,
#     and a solver that cannot serve the scene refused for that (naming those that can),
#     not for an option meant for another solver;
#   - a measured surface on the periodic substrate gets a note;
#   - info says what fits the command line (--missing), and heights without a unit are not
#     called pixels;
#   - the pictures: the gnuplot scripts the command writes, kept by a program of our own
#     named by ASPERITY_GNUPLOT (which then runs the real gnuplot when there is one, so that
#     the scripts are also checked to draw): powers of ten drawn as powers, viridis maps, a
#     diverging map centred on zero for an adhesive pressure, the pressure's unit, the error
#     explained and the tolerance drawn, the scene's file name (not its path) in titles.
# Usage: check_first_afternoon.sh PATH_TO_ASPERITY SOURCE_DIRECTORY WORK_DIRECTORY
set -u
cli=$1 source=$2 work=$3
scenes=$source/tests/cli/scenes data=$source/tests/io/data
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
export XDG_CACHE_HOME=$work/cache
out=$work/stdout err=$work/stderr
small=$scenes/small.toml

passed=0 failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
pass() { passed=$((passed + 1)); }
run() { "$cli" "$@" > "$out" 2> "$err" < /dev/null; rc=$?; }
expect() {
  local what=$1
  shift
  if "$@"; then pass; else fail "$what"; fi
}
has() { grep -qE -- "$1" "$2"; }
has_text() { grep -qF -- "$1" "$2"; }
lacks() { ! grep -qE -- "$1" "$2"; }

# bad WHAT... ARGS: exit status 2, and standard error holds each fixed text before "--".
bad() {
  local texts=()
  while [ "$1" != "--" ]; do texts+=("$1"); shift; done
  shift
  run "$@"
  if [ "$rc" -ne 2 ]; then
    fail "asperity $*: exit status $rc, expected 2; stderr: $(cat "$err")"
    return
  fi
  local t
  for t in "${texts[@]}"; do
    if ! grep -qF -- "$t" "$err"; then
      fail "asperity $*: the message lacks '$t': $(cat "$err")"
      return
    fi
  done
  pass
}

# The pictures' scripts: ASPERITY_GNUPLOT names this program, which keeps a copy of each
# script under the name of the picture it draws, then draws it with the real gnuplot, or
# without one writes a PNG signature where the script says.
scripts=$work/scripts
mkdir -p "$scripts"
real_gnuplot=$(command -v gnuplot || true)
cat > keep-gnuplot <<EOF
#!/bin/sh
output=\$(sed -n "s/^set output '\\(.*\\)'\$/\\1/p" "\$1")
name=\$(basename "\$output" | sed 's/^\\.//; s/\\.png\\..*\$/.png/')
cp "\$1" "$scripts/\$(basename "\$(dirname "\$output")")-\$name.gp"
if [ -n "$real_gnuplot" ]; then exec "$real_gnuplot" "\$1"; fi
printf '\\211PNG\\r\\n\\032\\n' > "\$output"
EOF
chmod +x keep-gnuplot
export ASPERITY_GNUPLOT=$work/keep-gnuplot
script_of() { echo "$scripts/$1-$2.gp"; }  # script_of DIRECTORY PICTURE

# An adhesive sphere under penetration control: bugnicourt and lbfgsb serve it on the gap.
cat > adhesive.toml <<'S'
[grid]
nx = 32

[substrate]
contact_modulus = 1.0

[topography]
type = "sphere"
radius = 2.0

[interaction]
type = "adhesive_hard_wall"
work_of_adhesion = 1e-4
range = 0.01

[control]
quantity = "penetration"
value = 0.002

[solver]
algorithm = "bugnicourt"
options = { variable = "gap" }
S

# ---- 1. compare: every variant that serves the scene ------------------------------------------
run compare "$work/adhesive.toml" --repeats 1 --output compare-adhesive
expect "compare on the adhesive scene converges (exit $rc; stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
for variant in bugnicourt:gap lbfgsb:gap; do
  expect "compare's table has a row of $variant" has "^$variant +converged" "$out"
  expect "compare_summary.csv has a row of $variant" \
    has "^$variant," compare-adhesive/compare_summary.csv
  expect "compare.csv has rows of $variant" has "^$variant," compare-adhesive/compare.csv
  expect "the error plot names $variant" \
    has "title '$variant' noenhanced" "$(script_of compare-adhesive error_vs_time.png)"
done
expect "lbfgsb on the pressure is skipped, by name" \
  has "^skipped +lbfgsb:pressure: .*adhesive hard wall" "$out"
expect "no picture failed to draw: $(cat "$err")" lacks "gnuplot failed" "$err"
# A name alone is each of its variants that serves the scene; a variant named must serve it.
run compare adhesive.toml --solvers lbfgsb --repeats 1 --output compare-lbfgsb
expect "--solvers lbfgsb compares lbfgsb:gap (exit $rc; $(cat "$err"))" has "^lbfgsb:gap +converged" "$out"
bad "lbfgsb:pressure" "does not handle an adhesive hard wall" -- \
  compare adhesive.toml --solvers lbfgsb:pressure --output refused
# A hard-wall scene: bugnicourt on the pressure serves its mean-pressure control.
run compare "$small" --solvers bugnicourt,pk --repeats 1 --output compare-small
expect "compare names bugnicourt:pressure on a hard wall (stderr: $(cat "$err"))" \
  has "^bugnicourt:pressure +converged" "$out"
expect "... and pk by its name alone" has "^pk +converged" "$out"
# The scene's algorithm may name its variable the same way.
run run adhesive.toml --set solver.algorithm=lbfgsb:gap --set solver.options='{}' \
  --output run-lbfgsb-gap
expect "solver.algorithm = lbfgsb:gap runs lbfgsb on the gap (exit $rc; $(cat "$err"))" \
  [ "$rc" -eq 0 ]

# ---- 2. unknown keys and options --------------------------------------------------------------
bad "solver.maxiter: unknown key; did you mean max_iterations?" "stall_window" "tolerance" -- \
  run "$small" --set solver.maxiter=3
sed 's/^work_of_adhesion/work_adhesion/' adhesive.toml > misspelt.toml
bad "misspelt.toml:13:" "interaction.work_adhesion: unknown key; did you mean work_of_adhesion?" \
  "range" -- run misspelt.toml
sed 's/^\[topography\]/[topograhy]/' adhesive.toml > misspelt_table.toml
bad "misspelt_table.toml:7:1: topograhy: unknown key; did you mean topography?" -- \
  run misspelt_table.toml
bad "solver.options.maxiter" "has no option 'maxiter'; did you mean max_iterations?" -- \
  run "$small" --option maxiter=3
bad "--tolerence" "unknown option; did you mean --tolerance?" -- run "$small" --tolerence 1e-8
bad "--repeat" "did you mean --repeats?" -- compare "$small" --repeat 2
bad "--mising" "did you mean --missing?" -- info "$data/savetxt_nan.txt" --mising interpolate
bad "lbfgs_fouirer" "did you mean lbfgs_fourier?" -- run "$small" --algorithm lbfgs_fouirer
bad "--algorithm pk" "solver 'pk' does not handle an adhesive hard wall" \
  "the solvers that serve this scene: bugnicourt:gap, lbfgsb:gap" -- \
  run adhesive.toml --algorithm pk
expect "... not an option 'variable' meant for bugnicourt" lacks "variable" "$err"
bad "--algorithm lbfgsb" "with variable = pressure does not handle an adhesive hard wall" \
  "lbfgsb:gap" -- run adhesive.toml --algorithm lbfgsb --set solver.options='{}' --check

# ---- 3. a measured surface on the periodic substrate ------------------------------------------
cat > measured.toml <<S
[topography]
type = "file"
path = "$data/c_order.npy"
pixel_size = 0.1

[substrate]
type = "periodic"
contact_modulus = 1.0

[control]
quantity = "mean_pressure"
value = 0.001
S
run run measured.toml --check
expect "a measured surface on the periodic substrate gets a note (exit $rc; $(cat "$err"))" \
  has "^note +a measured surface on the periodic substrate.*free" "$out"
sed '/^type = "periodic"/d' measured.toml > measured_free.toml
run run measured_free.toml --check
expect "... and none on the free one" lacks "periodic substrate" "$out"

# ---- 4. info: the command line's words, and heights without a unit -----------------------------
bad "--missing interpolate" -- info "$data/savetxt_nan.txt"
expect "info names its option, not the scene's key" lacks "topography.missing" "$err"
bad 'topography.missing = "interpolate"' -- run measured.toml \
  --set topography.path="$data/savetxt_nan.txt" --check
run info "$data/c_order.npy" --output info-c
expect "info on a file without units runs (exit $rc)" [ "$rc" -eq 0 ]
expect "heights without a unit are not in pixels" lacks "^(heights|rms height).*pixels" "$out"
expect "... they are said to have no unit" has "^heights .*no unit" "$out"
expect "lengths without a size are in pixels" has "^pixel size +1 x 1 pixels" "$out"

# ---- 6. the pictures --------------------------------------------------------------------------
spectrum=$(script_of info-c power_spectrum.png)
expect "info's power spectrum was drawn (stderr: $(cat "$err"))" [ -s "$spectrum" ]
expect "the terminal draws enhanced text, so that 10^{-1} is a power" \
  has "^set terminal pngcairo .* enhanced" "$spectrum"
expect "... and the ticks are powers of ten" has "^set format x '10\^\{%L\}'" "$spectrum"
expect "... while the texts are drawn as they are" has "^set xlabel .* noenhanced" "$spectrum"

run run adhesive.toml --set output.fields='["pressure", "gap"]' --output run-adhesive
expect "the adhesive run converges (exit $rc; $(cat "$err"))" [ "$rc" -eq 0 ]
pressure=$(script_of run-adhesive pressure.png) gap=$(script_of run-adhesive gap.png)
expect "the adhesive pressure (both signs) is drawn with white at zero" \
  has "^set palette defined \(-.* '#2166ac', .* 0 '#f7f7f7', .* '#b2182b'\)" "$pressure"
expect "... from its lowest to its highest value" has "^set cbrange \[-" "$pressure"
expect "the gap map is viridis" has "^set palette defined \(0 '#440154'.*1 '#fde725'\)" "$gap"
expect "... not the rainbow" lacks "rgb 33,13,10" "$gap"
expect "pressure without a unit is in the units of E*" \
  has "^set cblabel 'pressure \(in the units of E\*\)'" "$pressure"
expect "the report says 'in the units of E*'" has "^mean pressure .*\(in the units of E\*\)" "$out"
convergence=$(script_of run-adhesive convergence.png)
expect "the convergence plot says what the error is" \
  has "^set ylabel 'error \(largest force-balance residual over the free set / reference pressure\)'" \
  "$convergence"
expect "... and draws the tolerance" has "^plot .*, 1e-08 with lines .*title 'tolerance 1e-08'" \
  "$convergence"
expect "no picture failed to draw: $(cat "$err")" lacks "gnuplot failed" "$err"

run run "$small" --set substrate.pressure_unit=MPa --set output.fields='["pressure"]' \
  --output run-mpa
expect "a hard-wall pressure (one sign) is viridis" \
  has "^set palette defined \(0 '#440154'" "$(script_of run-mpa pressure.png)"
expect "a scene's pressure unit labels the map" \
  has "^set cblabel 'pressure \[MPa\]'" "$(script_of run-mpa pressure.png)"
expect "... and the report" has "^mean pressure .*\(MPa\)$" "$out"
expect "... and the control" has "^control .*\(MPa\)$" "$out"
expect "... and the summary" has "^mean_pressure,.*,MPa$" run-mpa/summary.csv
bad "substrate.pressure_unit" "is empty" -- run "$small" --set substrate.pressure_unit='""'

run sweep "$small" --set substrate.pressure_unit=MPa --quantity penetration --from 0 \
  --to 0.002 --steps 1 --no-unload --output sweep-mpa
expect "sweep with a pressure unit exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "sweep.csv's pressures carry the scene's unit" \
  has "mean_pressure \[MPa\],.*,stiffness \[MPa/" sweep-mpa/sweep.csv
expect "sweep's picture: the unit on its axis, the file's name in its title" bash -c \
  'grep -q "^set ylabel .mean pressure \[MPa\]" "$1" && grep -q "^set title .*(small.toml)" "$1"' \
  _ "$(script_of sweep-mpa sweep.png)"

time_script=$(script_of compare-adhesive error_vs_time.png)
expect "compare's title names the scene's file, not its path" \
  has "^set title 'error against time \(adhesive.toml\)'" "$time_script"
expect "... and draws the tolerance" has "title 'tolerance 1e-08'" "$time_script"
expect "... and says what the error is" has "force-balance residual" "$time_script"

echo "check_first_afternoon: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
