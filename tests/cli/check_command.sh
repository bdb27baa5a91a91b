#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Checks the asperity command from the outside, as a user runs it:
#   - bad arguments and bad scenes exit with status 2 before any work, with a message on
#     standard error naming the file, line and key (or the argument) and what is wrong, nothing
#     on standard output and no output directory made;
#   - --help for each command documents the exit statuses; --version, --list-algorithms,
#     --describe and --print-scene (whose text is a valid scene);
#   - run: a converged solve exits 0, one cut short exits 1; summary.csv, history.csv with
#     their header lines, fields as .npy, PNG files that are PNG (or a note when pictures are
#     off);
#   - compare: two solvers on a tiny scene, their CSV columns and rows, the PNGs;
#   - sweep: a small Table 5 sweep whose unloading branch lies below the loading one;
#   - info and measured scenes: files written by NumPy (.npy and savetxt text), an .x3p, and a
#     field written by run read back; units and missing points;
#   - threads and FFT planning: bad values refused by every command; the FFTW wisdom file
#     written to the cache directory and read back, a damaged or foreign one or one that is
#     not a regular file passed over with a note (same results), --no-wisdom and --wisdom;
#   - the progress line only on a terminal; Ctrl-C cancels cleanly;
#   - defects found from outside: a value refused at solve time gives its reason; sizes and
#     surfaces the library refuses, or this machine cannot hold, are bad input (exit 2)
#     naming the key or file; a symbolic link at an output file's name is replaced, never
#     written through; a long, narrow surface is described in moments.
# Usage: check_command.sh PATH_TO_ASPERITY SOURCE_DIRECTORY WORK_DIRECTORY
set -u
cli=$1 source=$2 work=$3
scenes=$source/tests/cli/scenes data=$source/tests/io/data
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
# The command keeps FFTW wisdom in the user's cache directory: here, one of the test's own.
export XDG_CACHE_HOME=$work/cache
out=$work/stdout err=$work/stderr
small=$scenes/small.toml

passed=0 failed=0 skipped=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
pass() { passed=$((passed + 1)); }
skip() { echo "skipped: $*"; skipped=$((skipped + 1)); }
show() { local a s=asperity; for a in "$@"; do s+=" $(printf '%q' "$a")"; done; echo "$s"; }

# run ARGS...: runs the command; standard output and error go to files, the status to $rc.
run() { "$cli" "$@" > "$out" 2> "$err" < /dev/null; rc=$?; }

# bad WHAT PROBLEM ARGS...: the command run with ARGS exits 2 and says on standard error WHAT
# (literally: the place and key, or the argument) and PROBLEM (an extended regular
# expression), with nothing on standard output and no output directory left behind.
bad() {
  local what=$1 problem=$2
  shift 2
  rm -rf "$work/refused-output"
  run "$@" --output "$work/refused-output"
  local shown
  shown=$(show "$@")
  if [ "$rc" -ne 2 ]; then
    fail "$shown: exit status $rc, expected 2; stderr: $(cat "$err")"
  elif ! grep -qF -- "$what" "$err"; then
    fail "$shown: the message does not name '$what': $(cat "$err")"
  elif ! grep -qE -- "$problem" "$err"; then
    fail "$shown: the message does not say '$problem': $(cat "$err")"
  elif [ -s "$out" ]; then
    fail "$shown: printed on standard output: $(cat "$out")"
  elif [ -e "$work/refused-output" ]; then
    fail "$shown: made the output directory before refusing"
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
is_png() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }
is_npy() { [ "$(head -c 6 "$1" | od -An -c | tr -d ' \n')" = '223NUMPY' ]; }
header_of() { head -n 1 "$1"; }
# scene NAME <<EOF: a scene file in the work directory, from standard input.
scene() { cat > "$work/$1"; }
have_gnuplot=no
command -v gnuplot > /dev/null && have_gnuplot=yes

# ---- bad arguments --------------------------------------------------------------------------
bad "frobnicate" "not a command" frobnicate
bad "--frobnicate" "unknown option" run "$small" --frobnicate
bad "--tolerance" "needs a value" run "$small" --tolerance
bad "--no-plots" "takes no value" run "$small" --no-plots=yes
bad "second.toml" "a second scene" run "$small" second.toml
bad "--tolerance abc" "solver.tolerance: expected a number, got a string" run "$small" --tolerance abc
bad "--set grid.nx=1" "grid.nx: must be >= 2" run "$small" --set grid.nx=1
bad "--set" "expected KEY=VALUE" run "$small" --set grid.nx
bad "--algorithm nosuch" "unknown algorithm|known" run "$small" --algorithm nosuch
bad "--option frob=1" "frob" run "$small" --option frob=1
bad "--option max_iterations=0" "max_iterations" run "$small" --option max_iterations=0
for command in run compare sweep info; do
  for threads in 0 -1 abc 1.5; do
    bad "--threads" "expected a whole number >= 1" $command "$small" --threads "$threads"
  done
  bad "--planning foo" "expected estimate, measure or patient" $command "$small" --planning foo
  bad "--wisdom" "needs a value" $command "$small" --wisdom
done
bad "--repeats 0" "expected a whole number >= 1" compare "$small" --repeats 0
bad "--repeats=two" "expected a whole number >= 1" compare "$small" --repeats=two

# ---- bad scenes: the file, line and key, and what is wrong ----------------------------------
bad "no-such-scene.toml" "cannot open the scene file" run no-such-scene.toml

scene broken.toml <<'S'
[grid]
nx = 64
ny = = 3
S
bad "broken.toml:3" "not a valid TOML file" run broken.toml

sed 's/^nx = 64$/nx = -4/' "$small" > negative.toml
bad "negative.toml:6:6: grid.nx" "must be >= 2, got -4" run negative.toml

sed 's/^nx = 64$/nx = "big"/' "$small" > string.toml
bad "string.toml:6:6: grid.nx" "expected a whole number, got a string" run string.toml

sed 's/^nx = 64$/nx = 64.5/' "$small" > fraction.toml
bad "fraction.toml:6:6: grid.nx" "expected a whole number, got a number" run fraction.toml

sed 's/^ny = 64$/nyy = 64/' "$small" > unknown.toml
bad "unknown.toml:7:7: grid.nyy" "unknown key" run unknown.toml

sed 's/^\[control\]$/[contrl]/' "$small" > unknown_table.toml
bad "unknown_table.toml" "contrl: unknown key; did you mean control\?" run unknown_table.toml

grep -v '^contact_modulus' "$small" > missing.toml
bad "substrate.contact_modulus" "missing" run missing.toml

sed 's/^unit = "um"$/unit = "furlong"/' "$small" > units.toml
bad "units.toml:9:8: grid.unit" "furlong" run units.toml

sed 's/^value = 0.01$/value = inf/' "$small" > infinite.toml
bad "infinite.toml" "control.value: expected a finite number" run infinite.toml

sed 's/^quantity = "mean_pressure"$/quantity = "force"/' "$small" > quantity.toml
bad "quantity.toml:23:12: control.quantity" "is not one of" run quantity.toml

sed 's/^rms_slope = 0.1$/rms_slope = 0.1\nrms_height = 0.01/' "$small" > both.toml
bad "topography.rms_height" "either 'rms_slope' or 'rms_height'" run both.toml

# A solver that does not serve the scene is refused before any work.
bad "solver.algorithm" "does not handle a soft wall" run "$small" \
  --set interaction.type=soft_wall --set interaction.gamma_r=1e-3 --set interaction.range=1e-3
bad "solver.algorithm" "does not offer mean_pressure" run "$small" --algorithm lbfgsb

# An output directory that cannot be made.
touch a-file
run "$small" --output a-file/below
expect "an output directory below a file exits 2" [ "$rc" -eq 2 ]
expect "the message names output.directory" has "output.directory" "$err"

# ---- information ----------------------------------------------------------------------------
for command in "" run compare sweep info; do
  run $command --help
  expect "asperity $command --help exits 0" [ "$rc" -eq 0 ]
  expect "asperity $command --help documents the exit statuses" has "^Exit status:" "$out"
done
run --version
expect "--version prints the version" has "^asperity [0-9]+\.[0-9]+\.[0-9]+$" "$out"
run --list-algorithms
expect "--list-algorithms lists pk and lbfgs_fourier" \
  bash -c 'grep -qx pk "$1" && grep -qx lbfgs_fourier "$1"' _ "$out"
run --describe bugnicourt
expect "--describe bugnicourt describes it" has "^bugnicourt: " "$out"
run --print-scene
cp "$out" printed.toml
run run printed.toml --check
expect "the printed built-in scene is a valid scene (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "--check solves nothing and writes nothing" [ ! -e printed-output ]
expect "the built-in scene is adhesive" has "^interaction +soft wall" "$out"

# Every example scene is valid and its solver serves it.
for example in "$source"/examples/scenes/*.toml; do
  run run "$example" --check
  expect "$(basename "$example") is a valid scene (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
done
run compare "$source/examples/scenes/measured_surface.toml" --output measured-compare
expect "the example measured scene compares (exit $rc; stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the example measured surface is read in um" has "box 20 um x 20 um" "$out"

# ---- run ------------------------------------------------------------------------------------
run run "$small" --output small-run
expect "a small solve exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the report says it converged" has "^termination +converged" "$out"
expect "the report gives the contact fraction" has "^contact fraction +0\.[0-9]+" "$out"
expect "the report shows no inf or nan" lacks "inf|nan" "$out"
expect "lengths are given in the scene's unit" has "^penetration +[0-9.e-]+ um$" "$out"
expect "summary.csv has its header" [ "$(header_of small-run/summary.csv)" = "quantity,value,unit" ]
expect "summary.csv gives the mean pressure asked for, in units of E*" awk -F, '
  $1 == "mean_pressure" { found = ($2 - 0.01 < 1e-15 && 0.01 - $2 < 1e-15 && $3 == "E* unit") }
  END { exit found ? 0 : 1 }' small-run/summary.csv
expect "summary.csv gives the penetration in um" has "^penetration,[0-9.e-]+,um$" small-run/summary.csv
expect "history.csv has its header" [ "$(header_of small-run/history.csv)" = \
  "iteration,evaluations,transforms,seconds [s],error,objective,contact_fraction" ]
expect "every history row has 7 numeric columns" awk -F, '
  NR > 1 {
    if (NF != 7) exit 1
    for (i = 1; i <= NF; ++i)
      if ($i !~ /^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/) exit 1
    rows++
  }
  END { exit rows > 0 ? 0 : 1 }' small-run/history.csv
for field in pressure gap contact; do
  expect "$field.npy is a NumPy file" is_npy "small-run/$field.npy"
done
expect "a .npy of 64 x 64 doubles has shape (64, 64)" \
  bash -c "head -c 128 small-run/gap.npy | grep -q \"'shape': (64, 64)\""
if [ "$have_gnuplot" = yes ]; then
  for png in pressure gap contact convergence; do
    expect "$png.png is a PNG file" is_png "small-run/$png.png"
  done
else
  skip "gnuplot is not installed: no PNG to check"
fi
# stderr is a file here: no progress line, and nothing else either.
expect "no progress line when stderr is not a terminal" [ ! -s "$err" ]

# An elastic layer on a rigid base (substrate.type = "layer"). Twenty box lengths thick it is
# the half-space to the last digit (K~ differs by (qt)^2 exp(-2qt), qt >= 40 pi): under load
# control, which does not involve K~(0), both give the same contact to the solve's tolerance.
run run "$small" --no-plots --tolerance 1e-11 --output halfspace-run
grep "^contact fraction" "$out" > halfspace-contact
run run "$small" --no-plots --tolerance 1e-11 --output thick-layer-run --set substrate.type=layer \
  --set substrate.thickness=20.0 --set substrate.poisson_ratio=0.3
expect "a layer solve exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the report names the layer" has "^substrate +periodic elastic layer on a rigid base, E\* = 1, thickness 20, Poisson's ratio 0.3" "$out"
expect "a thick layer has the half-space's contact" \
  [ "$(grep "^contact fraction" "$out")" = "$(cat halfspace-contact)" ]
bad "substrate.thickness" "missing" run "$small" --set substrate.type=layer \
  --set substrate.poisson_ratio=0.3
bad "substrate.poisson_ratio" "below 0.5" run "$small" --set substrate.type=layer \
  --set substrate.thickness=0.1 --set substrate.poisson_ratio=0.5
bad "substrate.k0" "its own" run "$small" --set substrate.type=layer \
  --set substrate.thickness=0.1 --set substrate.poisson_ratio=0.3 --set substrate.k0=2.0
bad "substrate.thickness" "layer" run "$small" --set substrate.thickness=0.1

# Pictures off, or no gnuplot: the run still succeeds and says why there is no PNG.
ASPERITY_GNUPLOT= "$cli" run "$small" --output no-pictures > "$out" 2> "$err" < /dev/null
rc=$?
expect "a run without gnuplot exits 0" [ "$rc" -eq 0 ]
expect "a run without gnuplot notes the skipped pictures" has "note: skipped .*pressure\.png" "$err"
expect "a run without gnuplot writes no PNG" bash -c '! ls no-pictures/*.png 2> /dev/null'
ASPERITY_GNUPLOT=/no/such/gnuplot "$cli" run "$small" --output bad-gnuplot > "$out" 2> "$err" < /dev/null
rc=$?
expect "a missing gnuplot program is not a failure (exit $rc)" [ "$rc" -eq 0 ]
expect "a missing gnuplot program is a note" has "note: skipped" "$err"

run run "$small" --option max_iterations=3 --output cut-short
expect "a solve cut short by the iteration limit exits 1" [ "$rc" -eq 1 ]
expect "the report says the iteration limit ended it" has "^termination +iteration limit" "$out"

# The built-in scene, smaller, with its default solver: the adhesive soft wall.
run --set grid.nx=128 --set grid.ny=128 --set topography.short_cutoff=0.0625 --output builtin
expect "the built-in scene on 128 x 128 converges (exit $rc; stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the built-in scene has tensile pressures (adhesion)" \
  python3 -c "
import struct, sys
data = open('builtin/pressure.npy', 'rb').read()
header = 10 + int.from_bytes(data[8:10], 'little')
values = struct.unpack('<%dd' % ((len(data) - header) // 8), data[header:])
sys.exit(0 if min(values) < 0 < max(values) else 1)"

# A write that fails after the solve is a failure of the system: exit 3. A file-size limit of 0
# makes every write to a file fail (EFBIG, with SIGXFSZ ignored); the report goes to a pipe.
( trap '' XFSZ && ulimit -f 0 && exec "$cli" run "$small" --output limited 2>&1 < /dev/null ) |
  cat > "$out"
rc=${PIPESTATUS[0]}
expect "outputs that cannot be written exit 3 (got $rc)" [ "$rc" -eq 3 ]
expect "a file that cannot be written is named" has "limited/.*: (writing failed|cannot)" "$out"

# ---- compare --------------------------------------------------------------------------------
run compare "$small" --solvers pk,bugnicourt --output compared
expect "comparing pk and bugnicourt exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the comparison lists pk" has "^pk +converged" "$out"
expect "the comparison lists bugnicourt" has "^bugnicourt:pressure +converged" "$out"
expect "the comparison names the fastest, or none within the spread of their repeats" \
  has "^fastest +(pk|bugnicourt|no winner: .* differ by less than the spread)" "$out"
expect "compare.csv has its header" [ "$(header_of compared/compare.csv)" = \
  "algorithm,iteration,evaluations,transforms,seconds [s],error,objective,contact_fraction" ]
expect "compare.csv has rows of both solvers" \
  bash -c 'grep -q "^pk,0," "$1" && grep -q "^bugnicourt:pressure,0," "$1"' _ compared/compare.csv
expect "compare_summary.csv has one row per variant (pk, bugnicourt on the pressure and the gap)" \
  [ "$(wc -l < compared/compare_summary.csv)" -eq 4 ]
expect "both bugnicourt variants agree with pk on the pressure field to 1e-5" awk '
  $1 ~ /^bugnicourt:/ { rows++; if (!($NF + 0 < 1e-5)) bad = 1 }
  END { exit (rows == 2 && !bad) ? 0 : 1 }' "$out"
run compare "$small" --solvers pk,bugnicourt --repeats 2 --output repeated
expect "compare --repeats 2 exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "compare_summary.csv ends with the repeats, CPU time and spread" bash -c \
  'head -n 1 "$1" | grep -q ",mean_gap \[um\],repeats,cpu_seconds \[s\],seconds_spread \[s\]$"' \
  _ repeated/compare_summary.csv
expect "each solver ran twice, with a CPU time and a spread >= 0" awk -F, '
  NR > 1 { if ($13 != 2 || !($14 > 0) || !($15 >= 0)) exit 1; rows++ }
  END { exit rows == 3 ? 0 : 1 }' repeated/compare_summary.csv
expect "the table shows the repeats" awk '$1 == "pk" && $7 == 2 { found = 1 } END { exit !found }' "$out"
if [ "$have_gnuplot" = yes ]; then
  expect "error_vs_time.png is a PNG file" is_png compared/error_vs_time.png
  expect "error_vs_iteration.png is a PNG file" is_png compared/error_vs_iteration.png
fi
bad "compare.solvers: lbfgs" "does not handle a non-adhesive hard wall|hard wall" \
  compare "$small" --solvers pk,lbfgs
run compare "$small" --output every
expect "compare without --solvers runs every solver that serves the scene (exit $rc)" \
  has "^bugnicourt:pressure +converged" "$out"
expect "compare without --solvers lists the others as skipped" has "^skipped +lbfgs: " "$out"

# ---- sweep ----------------------------------------------------------------------------------
run sweep "$scenes/hysteresis.toml" --output swept
expect "the Table 5 sweep exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "sweep.csv has its header" [ "$(header_of swept/sweep.csv)" = \
  "step,phase,target_penetration,mean_pressure [E* unit],penetration,mean_gap,contact_fraction,total_force [E* unit],iterations,seconds [s],error,termination,stiffness [E* unit/length],jump" ]
expect "the sweep loads 23 steps and unloads 22" [ "$(grep -c ',loading,' swept/sweep.csv),$(grep -c ',unloading,' swept/sweep.csv)" = "23,22" ]
# Hysteresis: at some penetration the unloading force lies clearly below the loading force.
expect "unloading lies below loading somewhere (hysteresis)" awk -F, '
  NR > 1 && $2 == "loading" { load[$3] = $4 }
  NR > 1 && $2 == "unloading" && ($3 in load) && load[$3] - $4 > 0.005 { found = 1 }
  END { exit found ? 0 : 1 }' swept/sweep.csv
# The stiffness d(mean pressure)/d(penetration) of the deepest step, the ripples all in
# contact. (This scene's cohesive zone is one pixel: at some steps a pixel next to the wall has
# phi'' below -K_ii, the state is not a stable equilibrium, and the cell is empty.)
expect "the deepest step of the sweep is stiff" awk -F, '
  NR > 1 && $2 == "loading" { last = $13 } END { exit last > 0 ? 0 : 1 }' swept/sweep.csv
[ "$have_gnuplot" = yes ] && expect "sweep.png is a PNG file" is_png swept/sweep.png
run sweep "$small" --quantity penetration --from 0 --to 0.002 --steps 2 --no-unload \
  --algorithm lbfgsb --output swept-options
expect "a sweep from options exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "a sweep from options has 3 steps" [ "$(wc -l < swept-options/sweep.csv)" -eq 4 ]
# The stiffness holds the contact set the state reports: positive with pixels in contact, 0
# at the touching start, where a pressure solver (lbfgsb's default) has none.
expect "every converged step of a hard-wall sweep has a positive stiffness, 0 without contact" \
  [ "$(awk -F, 'NR > 1 && $12 == "converged" && (($7 > 0 && $13 > 0) || ($7 == 0 && $13 == 0))' \
      swept-options/sweep.csv | wc -l)" -eq 3 ]
bad "control" "a sweep needs control.sweep" sweep "$small"

# ---- threads, FFT planning and wisdom -------------------------------------------------------
run run "$small" --threads 1 --planning estimate --output one-thread
expect "run --threads 1 --planning estimate exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
run compare "$small" --solvers pk --threads 1 --planning patient --repeats 1 --output one-thread-compare
expect "compare --threads 1 --planning patient exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
run sweep "$small" --quantity penetration --from 0 --to 0.002 --steps 1 --algorithm lbfgsb \
  --threads 1 --planning estimate --output one-thread-sweep
expect "sweep --threads 1 --planning estimate exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
run info "$small" --threads 1 --planning measure --output one-thread-info
expect "info --threads 1 --planning measure exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]

# The summary without its time: what two runs that plan alike must agree on to the bit.
results() { grep -v '^seconds,' "$1/summary.csv"; }
starts_as_wisdom() { [ "$(head -c 6 "$1")" = "(fftw-" ]; }
fresh=$work/fresh-cache wisdom=$work/fresh-cache/asperity/fftw-wisdom
XDG_CACHE_HOME=$fresh run run "$small" --output wisdom-first
expect "a first run with an empty cache exits 0 without a note (stderr: $(cat "$err"))" \
  bash -c '[ "$1" -eq 0 ] && [ ! -s "$2" ]' _ "$rc" "$err"
expect "a run writes the wisdom file in \$XDG_CACHE_HOME/asperity" starts_as_wisdom "$wisdom"
expect "the directories it makes are the user's only" \
  [ "$(stat -c %a "$fresh")$(stat -c %a "$fresh/asperity")" = 700700 ]
expect "no temporary file is left beside it" [ "$(ls -A "$fresh/asperity")" = fftw-wisdom ]
XDG_CACHE_HOME=$fresh run run "$small" --output wisdom-second
expect "a second run reads it without a note (exit $rc; stderr: $(cat "$err"))" \
  bash -c '[ "$1" -eq 0 ] && [ ! -s "$2" ]' _ "$rc" "$err"

XDG_CACHE_HOME=$fresh run run "$small" --planning estimate --no-wisdom --output no-wisdom
for damage in foreign random; do
  if [ $damage = foreign ]; then
    printf '(fftw-3.3.10 fftw_wisdom #x12 garbage' > "$wisdom"
  else
    head -c 4096 /dev/urandom > "$wisdom"
  fi
  XDG_CACHE_HOME=$fresh run run "$small" --planning estimate --output "damaged-$damage"
  expect "a $damage wisdom file does not stop the run (exit $rc)" [ "$rc" -eq 0 ]
  expect "a $damage wisdom file gets one note" \
    bash -c '[ "$(grep -c "note: FFTW wisdom .* ignored: " "$1")" -eq 1 ]' _ "$err"
  expect "a $damage wisdom file leaves the results as without wisdom" \
    cmp -s <(results "damaged-$damage") <(results no-wisdom)
done
XDG_CACHE_HOME=$fresh run run "$small" --output damaged-replaced
expect "a measuring run replaces a damaged wisdom file (exit $rc)" starts_as_wisdom "$wisdom"
run run "$small" --wisdom /dev/null --output wisdom-device
expect "--wisdom /dev/null (not a regular file) does not stop the run (exit $rc)" [ "$rc" -eq 0 ]
expect "--wisdom /dev/null gets a note" has "note: FFTW wisdom /dev/null ignored: " "$err"
expect "--wisdom /dev/null is left alone" [ -c /dev/null ]

mkdir -p empty-cache
XDG_CACHE_HOME=$work/empty-cache run run "$small" --no-wisdom --output no-wisdom-run
expect "--no-wisdom exits 0 without a note" bash -c '[ "$1" -eq 0 ] && [ ! -s "$2" ]' _ "$rc" "$err"
expect "--no-wisdom writes nothing in the cache" [ -z "$(ls -A empty-cache)" ]
run run "$small" --wisdom "$work/chosen/wisdom" --output chosen-wisdom
expect "--wisdom PATH that does not exist yet is a note (exit $rc)" \
  bash -c '[ "$1" -eq 0 ] && grep -q "note: FFTW wisdom .*chosen/wisdom does not exist" "$2"' _ "$rc" "$err"
expect "--wisdom PATH writes PATH" starts_as_wisdom "$work/chosen/wisdom"
XDG_CACHE_HOME=$work/info-cache run info "$small" --output info-wisdom
expect "info plans at once by default and writes no wisdom" [ ! -e "$work/info-cache" ]
env -u XDG_CACHE_HOME HOME="$work/home" "$cli" run "$small" --output home-wisdom > "$out" 2> "$err" < /dev/null
expect "without XDG_CACHE_HOME the wisdom goes to \$HOME/.cache/asperity" \
  starts_as_wisdom "$work/home/.cache/asperity/fftw-wisdom"
XDG_CACHE_HOME=relative HOME="$work/home2" run run "$small" --output relative-wisdom
expect "a relative XDG_CACHE_HOME is passed over for \$HOME/.cache" \
  starts_as_wisdom "$work/home2/.cache/asperity/fftw-wisdom"
expect "a relative XDG_CACHE_HOME is not written" [ ! -e relative ]
env -u XDG_CACHE_HOME -u HOME "$cli" run "$small" --output homeless > "$out" 2> "$err" < /dev/null
rc=$?
expect "without HOME or XDG_CACHE_HOME a run exits 0 without wisdom or a note (exit $rc)" \
  bash -c '[ "$1" -eq 0 ] && [ ! -s "$2" ]' _ "$rc" "$err"

# ---- measured surfaces and info -------------------------------------------------------------
# Files written by NumPy: .npy in C and Fortran order, float32; text from numpy.savetxt.
for file in c_order.npy fortran_order.npy float32.npy savetxt_comments.txt gwyddion.txt surface.x3p; do
  run info "$data/$file" --output "info-$file"
  expect "info reads $file (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
  expect "info on $file prints the rms slope" has "^rms slope +[0-9]" "$out"
  expect "info on $file writes the power spectrum" [ -s "info-$file/power_spectrum.csv" ]
done
run info "$data/surface.x3p" --output info-x3p
expect "an .x3p gives its size in metres" has "^surface .*x3p.* m$" "$out"
run info "$data/gwyddion.txt" --output info-gwy
expect "Gwyddion's header gives the size in um" has "box 10 um x 7.5 um" "$out"
bad "ragged.txt" "line" info "$data/ragged.txt"
bad "truncated.npy" "truncated" info "$data/truncated.npy"
bad "wrong_md5.x3p" "MD5|md5|checksum" info "$data/wrong_md5.x3p"
bad "savetxt_nan.txt" "missing" info "$data/savetxt_nan.txt"
run info "$data/savetxt_nan.txt" --missing interpolate --output info-filled
expect "info --missing interpolate fills the missing points" has "^note +filled" "$out"

# A field written by run, read back as a measured surface: the free substrate by default.
cp small-run/gap.npy measured.npy
scene measured.toml <<'S'
[topography]
type = "file"
path = "measured.npy"
height_unit = "um"
pixel_size = 0.015625

[grid]
unit = "um"

[substrate]
contact_modulus = 1.0

[control]
quantity = "mean_pressure"
value = 0.001
S
run run measured.toml --output measured-run
expect "a measured scene solves (exit $rc; stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "a measured scene defaults to the free substrate" has "^substrate +free" "$out"
expect "the measured surface is 64 x 64 pixels, 1 um x 1 um" has "64 x 64 pixels, box 1 um x 1 um" "$out"
sed 's/^height_unit = "um"$/height_unit = "nm"/' measured.toml > measured_nm.toml
run info measured.toml --output info-um
um=$(awk '/^rms height/ { print $3 }' "$out")
run info measured_nm.toml --output info-nm
nm=$(awk '/^rms height/ { print $3 }' "$out")
expect "the same file read in nm has an rms height 1000 times smaller ($um um, $nm um)" \
  awk -v a="$um" -v b="$nm" 'BEGIN { r = a / b; exit (r > 999.999 && r < 1000.001) ? 0 : 1 }' 
sed '/^pixel_size/d' measured.toml > no_size.toml
bad "topography.path" "does not give its physical size" run no_size.toml
sed 's/^path = .*/path = "absent.npy"/' measured.toml > absent.toml
bad "absent.npy" "cannot open .* No such file" run absent.toml
# Round trip: the topography run writes, read back by info, has the statistics info gives for
# the scene itself (the .npy keeps every bit; the pixel size and unit are the scene's).
run run "$small" --set output.fields='["topography"]' --output topo
run info topo/topography.npy --pixel-size 0.015625 --height-unit um --output info-topo
grep -E '^rms (height|slope|curvature)' "$out" > from-file.txt
run info "$small" --output info-scene
grep -E '^rms (height|slope|curvature)' "$out" > from-scene.txt
expect "info gives three statistics" [ "$(wc -l < from-scene.txt)" -eq 3 ]
expect "info of a scene and of its written topography agree" cmp -s from-file.txt from-scene.txt

# ---- defects found from outside -------------------------------------------------------------
# A value the library refuses only when the solve starts (a load doubles cannot hold in the
# solve's units): exit 2 with the library's reason, naming control.value (the reason was
# once lost, read after another call of the library had emptied it).
for command in run compare; do
  run $command "$small" --set control.value=1e308 --output huge-load-$command
  expect "$command: a load refused at solve time exits 2 (got $rc)" [ "$rc" -eq 2 ]
  expect "$command: the refusal names control.value and gives the reason: $(cat "$err")" \
    has "control\.value.*: argument 'value' is 1e\+308" "$err"
done

# Surfaces and grids the library refuses, or that this machine cannot hold: bad input,
# named (they were exit 3, "out of memory" or a message of the C++ library).
printf '1e308 -1e308 1\n2 3 4\n5 6 7\n' > huge-heights.txt
bad "huge-heights.txt" "overflows" info huge-heights.txt
printf '# Value units: furlong\n1 2 3\n4 5 6\n' > furlong-heights.txt
bad "furlong-heights.txt" "unknown length unit 'furlong'" info furlong-heights.txt
printf '# Width: 3 furlong\n1 2 3\n4 5 6\n' > furlong-width.txt
bad "furlong-width.txt" "unknown length unit 'furlong'" info furlong-width.txt
sed 's/^path = .*/path = "furlong-heights.txt"/' measured.toml > furlong.toml
bad "furlong.toml: topography.path" "unknown length unit 'furlong'" run furlong.toml
printf '5\n' > one-point.txt
bad "one-point.txt" "one point" info one-point.txt
printf '1 2 3 4 5 6\n' > six-points.txt
bad "--bins 7" "more bins than the surface's 6 pixels" info six-points.txt --bins 7
bad "grid.nx" "machine's memory" run "$small" --set grid.nx=2147483648
bad "grid.nx" "machine's memory" run "$small" --set grid.nx=3037000500 --set grid.ny=3037000500
bad "grid.nx" "machine's memory" run --set grid.nx=1000000000
bad "grid.nx" "2147483648.*(more than FFTW can transform|machine's memory)" \
  run "$small" --set grid.nx=2147483648 --set grid.ny=1

# Symbolic links at the names of the output files are replaced, not followed: what they
# point to is left as it was, or not made.
mkdir -p linked
echo precious > precious.txt
for name in summary.csv pressure.npy pressure.png; do ln -sf "$work/precious.txt" "linked/$name"; done
ln -sf "$work/made-through-a-link.csv" linked/history.csv
run run "$small" --output linked
expect "a run over planted links exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
expect "the file a link pointed to is unchanged" [ "$(cat precious.txt)" = precious ]
expect "a dangling link did not make its target" [ ! -e made-through-a-link.csv ]
expect "summary.csv is a file of its own, with its header" \
  bash -c '[ ! -L "$1" ] && [ "$(head -n 1 "$1")" = quantity,value,unit ]' _ linked/summary.csv
expect "history.csv is a file of its own" bash -c '[ -f "$1" ] && [ ! -L "$1" ]' _ linked/history.csv
expect "pressure.npy is a file of its own" bash -c '[ ! -L "$1" ]' _ linked/pressure.npy
expect "pressure.npy is a NumPy file" is_npy linked/pressure.npy
if [ "$have_gnuplot" = yes ]; then
  expect "pressure.png is a picture of its own" bash -c '[ ! -L "$1" ]' _ linked/pressure.png
fi
expect "no temporary file is left in the output directory" [ -z "$(ls -A linked | grep '^\.')" ]

# A long, narrow text surface (2 columns of 200000 rows, and 2 rows of 200000 columns) is
# described in moments: its transforms are planned at once (planning them once took minutes
# at ten times the size).
awk 'BEGIN { srand(1); for (i = 0; i < 200000; ++i) printf "%.6f %.6f\n", rand(), rand() }' > narrow.txt
{ cut -d' ' -f1 narrow.txt | paste -sd' '; cut -d' ' -f2 narrow.txt | paste -sd' '; } > wide.txt
for shape in narrow wide; do
  started=$SECONDS
  run info $shape.txt --output info-$shape --no-plots
  took=$((SECONDS - started))
  expect "info on a $shape surface of 2 x 200000 points exits 0 (stderr: $(cat "$err"))" [ "$rc" -eq 0 ]
  expect "info on a $shape surface of 2 x 200000 points takes seconds, not minutes (took $took s)" \
    [ "$took" -lt 30 ]
done

# ---- terminal and interruption --------------------------------------------------------------
# script(1) from util-linux runs the command on a pseudo-terminal.
if script -qefc true /dev/null > /dev/null 2>&1; then
  script -qefc "$(printf '%q' "$cli") run $(printf '%q' "$small") --output tty" /dev/null > "$out" 2>&1 < /dev/null
  expect "a progress line is drawn on a terminal" has $'\riteration 0 +error ' "$out"
else
  skip "no script(1) to run the command on a terminal"
fi
if command -v timeout > /dev/null; then
  # Two seconds: on a loaded machine the command may still be starting after half of one.
  timeout --preserve-status -s INT 2 "$cli" run "$small" --tolerance 1e-300 \
    --option stall_window=0 --option max_iterations=1e15 --output endless > "$out" 2> "$err" < /dev/null
  rc=$?
  expect "Ctrl-C ends the solve with exit 1 (got $rc)" [ "$rc" -eq 1 ]
  expect "Ctrl-C is reported as cancelled" has "^termination +cancelled" "$out"
  # timeout(1) sends its signal to the command and to its process group, a moment apart: one
  # Ctrl-C that arrives twice. Whenever it comes, the run is cancelled, never killed.
  for after in 1 1.3 1.6 1.9; do
    timeout --preserve-status -s INT $after "$cli" run "$small" --tolerance 1e-300 \
      --option stall_window=0 --option max_iterations=1e15 --output "endless-$after" \
      > "$out" 2> "$err" < /dev/null
    rc=$?
    expect "Ctrl-C after $after s (sent twice) ends the solve with exit 1 (got $rc)" [ "$rc" -eq 1 ]
  done
else
  skip "no timeout(1) to interrupt the command"
fi

echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
