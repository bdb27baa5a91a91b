#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the Debian packages (tools/make-packages.sh), checks their names, contents and
# dependencies, unpacks them into a scratch root (dpkg -x: nothing is installed on the
# machine) and builds and runs consumers against that root only: C with pkg-config, C with
# find_package(asperity), Fortran from the packaged module source, Python from the packaged
# module, and the packaged command.
#
#   check_packages.sh SOURCE_DIR WORK_DIR C_COMPILER FORTRAN_COMPILER PYTHON
set -euo pipefail
source=$1 work=$2 cc=$3 fc=$4 python=$5
rm -rf "$work" && mkdir -p "$work"

echo "== building the packages"
"$source/tools/make-packages.sh" "$work/debs" "$work/build"
abi=$(sed -n 's/^set(ASPERITY_ABI_VERSION \([0-9]*\)).*/\1/p' "$source/CMakeLists.txt")
version=$(sed -n '/^project(asperity/,/)/s/^ *VERSION \([0-9.]*\)$/\1/p' "$source/CMakeLists.txt")
expected=("libasperity$abi" libasperity-dev asperity python3-asperity)

deb_of() { ls "$work/debs/$1"_"$version"_*.deb; }
# has PACKAGE PATTERN: the package's file list has a line matching the extended pattern (the
# list goes through a file: grep -q on a pipe would cut dpkg-deb short, a failure here).
has() { dpkg-deb -c "$(deb_of "$1")" > "$work/contents.txt" && grep -qE "$2" "$work/contents.txt"; }
field() { dpkg-deb -f "$(deb_of "$1")" "$2"; }
fail() { echo "FAIL: $*"; exit 1; }

echo "== names, dependencies, contents"
for package in "${expected[@]}"; do
  [ -f "$(deb_of "$package")" ] || fail "no package $package"
  has "$package" "usr/share/doc/$package/copyright" ||
    fail "$package carries no copyright file"
done
grep -qF libfftw3-double3 <<< "$(field "libasperity$abi" Depends)" || fail "the library does not depend on FFTW"
grep -qF "libasperity$abi (= $version)" <<< "$(field libasperity-dev Depends)" ||
  fail "libasperity-dev does not depend on libasperity$abi (= $version)"
grep -qF libfftw3-dev <<< "$(field libasperity-dev Depends)" || fail "libasperity-dev lacks libfftw3-dev"
grep -qF "libasperity$abi (= $version)" <<< "$(field asperity Depends)" || fail "asperity lacks the library"
grep -qF python3-numpy <<< "$(field python3-asperity Depends)" || fail "python3-asperity lacks NumPy"
grep -qF "libasperity$abi (= $version)" <<< "$(field python3-asperity Depends)" ||
  fail "python3-asperity lacks the library"
has "libasperity$abi" "libasperity\.so\.$abi( |$)" ||
  fail "the runtime package lacks libasperity.so.$abi"
has libasperity-dev "libasperity\.so( |$)" ||
  fail "the development package lacks the libasperity.so link"
# apt resolves every dependency (a simulation: nothing is installed).
debs=()
for package in "${expected[@]}"; do debs+=("$(deb_of "$package")"); done
apt-get install -s "${debs[@]}" > "$work/apt.log" 2>&1 ||
  fail "apt cannot install the packages: $(cat "$work/apt.log")"

echo "== unpacking into a scratch root"
root=$work/root
for deb in "${debs[@]}"; do dpkg -x "$deb" "$root"; done
libdir=$(dirname "$(find "$root" -name "libasperity.so.$abi" | head -n 1)")
[ -d "$libdir" ] || fail "no libasperity.so.$abi in the packages"
export LD_LIBRARY_PATH=$libdir

echo "== C with pkg-config"
export PKG_CONFIG_PATH=$libdir/pkgconfig
[ "$(pkg-config --variable=license asperity)" = GPL-2.0-or-later ] || fail "the .pc file's licence"
"$cc" -std=c99 -Wall -Werror "$source/examples/c/rough_contact.c" \
  $(pkg-config --cflags --libs asperity) -lm -o "$work/c_pkgconfig"
"$work/c_pkgconfig" > "$work/c_pkgconfig.out"
loaded=$(ldd "$work/c_pkgconfig")
grep -qF "$libdir/libasperity.so.$abi" <<< "$loaded" ||
  fail "the C consumer does not load the packaged library: $loaded"

echo "== C with find_package(asperity)"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$root/usr" \
  -DEXAMPLE_SOURCE="$source/examples/c/rough_contact.c" > "$work/consumer.log"
cmake --build "$work/consumer" >> "$work/consumer.log"
grep -q 'asperity_LICENSE "GPL-2.0-or-later"' "$libdir/cmake/asperity/asperityConfig.cmake" ||
  fail "the CMake package's licence"
"$work/consumer/rough_contact" > /dev/null

if [ -n "$fc" ]; then
  echo "== Fortran from the packaged module source"
  module_source=$root/usr/share/asperity/fortran/asperity.f90
  [ -f "$module_source" ] || fail "no Fortran module source in libasperity-dev"
  mkdir -p "$work/fortran"
  (cd "$work/fortran" &&
    "$fc" "$module_source" "$source/examples/fortran/rough_contact.f90" -L"$libdir" -lasperity \
      -o rough_contact && ./rough_contact > /dev/null)
fi

echo "== Python from the packaged module"
init=$(find "$root" -path '*/asperity/__init__.py' | head -n 1)
[ -n "$init" ] || fail "no Python package in python3-asperity"
PYTHONPATH=$(dirname "$(dirname "$init")") "$python" "$source/tests/package/python_consumer.py"

echo "== the packaged command"
[ "$("$root/usr/bin/asperity" --version)" = "asperity $version" ] || fail "asperity --version"
(cd "$work" && "$root/usr/bin/asperity" --set grid.nx=64 --set grid.ny=64 \
  --set topography.short_cutoff=0.125 --no-plots --output command > /dev/null)
echo "packages OK"
