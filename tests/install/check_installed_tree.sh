#!/usr/bin/env bash
# usage: check_installed_tree.sh BUILD_DIR SOURCE_DIR WORK_DIR C_COMPILER [FORTRAN_COMPILER]
#   FORTRAN_COMPILER  empty or absent when the Fortran module was not built; its part is skipped
set -euo pipefail
build=$1 source=$2 work=$3 cc=$4 fc=${5:-}
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
pc_file=$(find "$prefix" -name asperity.pc | head -n 1)
libdir=$(dirname "$(dirname "$pc_file")")
[ -n "$pc_file" ] || { echo "asperity.pc was not installed"; exit 1; }
export LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}

echo "== C example with pkg-config"
export PKG_CONFIG_PATH=$(dirname "$pc_file")
"$cc" -std=c99 -pedantic -Wall -Wextra -Werror -Wstrict-prototypes \
  "$source/examples/c/rough_contact.c" $(pkg-config --cflags --libs asperity) -lm \
  -o "$work/rough_contact_pkgconfig"
"$work/rough_contact_pkgconfig"

echo "== the README's C example with pkg-config"
# The first ```c block of the README, compiled and run as it stands.
awk '/^```c$/ {inside = 1; next} /^```$/ && inside {exit} inside' "$source/README.md" \
  > "$work/readme_example.c"
[ -s "$work/readme_example.c" ] || { echo "no C example found in README.md"; exit 1; }
"$cc" -std=c99 -pedantic -Wall -Werror -Wstrict-prototypes "$work/readme_example.c" \
  $(pkg-config --cflags --libs asperity) -o "$work/readme_example"
"$work/readme_example"

echo "== C example with find_package(asperity)"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" \
  -DCMAKE_PREFIX_PATH="$prefix" -DEXAMPLE_SOURCE="$source/examples/c/rough_contact.c" \
  > "$work/consumer-configure.log"
cmake --build "$work/consumer" > "$work/consumer-build.log"
"$work/consumer/rough_contact"

if [ -n "$fc" ]; then
  echo "== Fortran example from the installed module source"
  module_source=$(find "$prefix" -name asperity.f90 | head -n 1)
  [ -n "$module_source" ] || { echo "the Fortran module source was not installed"; exit 1; }
  mkdir -p "$work/fortran"
  (cd "$work/fortran" &&
    "$fc" -std=f2008 -Wall -Werror "$module_source" "$source/examples/fortran/rough_contact.f90" \
      -L"$libdir" -lasperity -o rough_contact_fortran &&
    ./rough_contact_fortran)
fi
echo "installed tree OK"
