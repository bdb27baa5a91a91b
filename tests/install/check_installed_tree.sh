#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# usage: check_installed_tree.sh BUILD_DIR SOURCE_DIR WORK_DIR C_COMPILER FORTRAN_COMPILER CLI
#   FORTRAN_COMPILER  empty when the Fortran module was not built; its part is then skipped
#   CLI               relocatable: bin/asperity must start on its own from any prefix
#                     system: it was built for a system library directory, so has no RPATH
#                     none: the command was not built
set -euo pipefail
build=$1 source=$2 work=$3 cc=$4 fc=$5 cli=$6
rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
pc_file=$(find "$prefix" -name asperity.pc | head -n 1)
[ -n "$pc_file" ] || { echo "asperity.pc was not installed"; exit 1; }
libdir=$(dirname "$(dirname "$pc_file")")
libdir_in_prefix=${libdir#"$prefix"/}

# The built-in scene made small, its outputs kept in the work directory.
small_scene=(--set grid.nx=64 --set grid.ny=64 --set topography.short_cutoff=0.125
             --output "$work/cli-output")

# run_installed_cli DIR: runs DIR/bin/asperity on a small scene without LD_LIBRARY_PATH and,
# for a shared build, checks that libasperity is loaded from DIR and not from wherever else the
# loader might find one.
run_installed_cli() {
  local dir=$1 loaded
  env -u LD_LIBRARY_PATH "$dir/bin/asperity" "${small_scene[@]}"
  if compgen -G "$dir/$libdir_in_prefix/libasperity.so*" > /dev/null && command -v ldd > /dev/null
  then
    loaded=$(env -u LD_LIBRARY_PATH ldd "$dir/bin/asperity" | awk '$1 ~ /^libasperity\./ {print $3}')
    if [ -z "$loaded" ] ||
       [ "$(realpath "$(dirname "$loaded")")" != "$(realpath "$dir/$libdir_in_prefix")" ]; then
      echo "bin/asperity does not load libasperity from $dir/$libdir_in_prefix (it loads '$loaded')"
      exit 1
    fi
  fi
}

case $cli in
  relocatable)
    echo "== the installed command, without LD_LIBRARY_PATH"
    run_installed_cli "$prefix"
    echo "== the installed command, from a moved prefix"
    # Moved rather than copied, so that nothing is left at the place it was installed to.
    mkdir -p "$work/elsewhere"
    mv "$prefix" "$work/elsewhere/moved"
    run_installed_cli "$work/elsewhere/moved"
    mv "$work/elsewhere/moved" "$prefix"
    ;;
  system)
    # Configured for a system library directory, where the loader looks anyway, so the command
    # has no RPATH; from this temporary prefix it has to be told where the library is.
    echo "== the installed command (no RPATH: configured for a system libdir)"
    LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} "$prefix/bin/asperity" \
      "${small_scene[@]}"
    ;;
  none) ;;
  *) echo "unknown CLI mode '$cli'"; exit 1 ;;
esac

# The consumer programs below are built against a temporary prefix the loader does not search.
# pkg-config rightly adds no RPATH (where the library lies at run time is the user's business),
# so they are linked with one to the installed libdir; CMake gives the find_package() consumer
# its build-tree RPATH by itself. No LD_LIBRARY_PATH is needed anywhere.
rpath_flag=-Wl,-rpath,$libdir

echo "== C example with pkg-config"
export PKG_CONFIG_PATH=$(dirname "$pc_file")
"$cc" -std=c99 -pedantic -Wall -Wextra -Werror -Wstrict-prototypes \
  "$source/examples/c/rough_contact.c" $(pkg-config --cflags --libs asperity) -lm "$rpath_flag" \
  -o "$work/rough_contact_pkgconfig"
"$cc" -std=c99 -pedantic -Wall -Wextra -Werror -Wstrict-prototypes \
  "$source/examples/c/fem_coupling.c" $(pkg-config --cflags --libs asperity) -lm "$rpath_flag" \
  -o "$work/fem_coupling_pkgconfig"
"$work/fem_coupling_pkgconfig" > "$work/fem_coupling.log" ||
  { cat "$work/fem_coupling.log"; echo "fem_coupling failed"; exit 1; }
"$work/rough_contact_pkgconfig"

echo "== the README's C example with pkg-config"
# The first ```c block of the README, compiled and run as it stands.
awk '/^```c$/ {inside = 1; next} /^```$/ && inside {exit} inside' "$source/README.md" \
  > "$work/readme_example.c"
[ -s "$work/readme_example.c" ] || { echo "no C example found in README.md"; exit 1; }
"$cc" -std=c99 -pedantic -Wall -Werror -Wstrict-prototypes "$work/readme_example.c" \
  $(pkg-config --cflags --libs asperity) "$rpath_flag" -o "$work/readme_example"
"$work/readme_example"

echo "== C example with find_package(asperity)"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" \
  -DCMAKE_PREFIX_PATH="$prefix" -DEXAMPLE_SOURCE="$source/examples/c/rough_contact.c" \
  > "$work/consumer-configure.log"
cmake --build "$work/consumer" > "$work/consumer-build.log"
"$work/consumer/rough_contact"

if [ -n "$fc" ]; then
  fortran_examples=(rough_contact adhesive_sweep user_potential fem_coupling)
  installed_module=$(find "$prefix" -name asperity.f90 | head -n 1)
  [ -n "$installed_module" ] || { echo "the Fortran module source was not installed"; exit 1; }
  # Both ways of finding it are relative to the installed files, so that a moved prefix works.
  config_file=$(find "$prefix" -name asperityConfig.cmake | head -n 1)
  if grep -n "$prefix" "$config_file" "$pc_file"; then
    echo "the installed asperityConfig.cmake or asperity.pc holds the absolute prefix"; exit 1
  fi

  echo "== Fortran examples with find_package(asperity) and asperity_FORTRAN_SOURCE"
  cmake -S "$source/tests/install/consumer_fortran" -B "$work/consumer_fortran" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_Fortran_COMPILER="$fc" \
    -DEXAMPLES_DIR="$source/examples/fortran" > "$work/consumer-fortran-configure.log"
  grep "asperity_FORTRAN_SOURCE: $prefix/" "$work/consumer-fortran-configure.log" ||
    { echo "asperity_FORTRAN_SOURCE is not in the installed tree"; exit 1; }
  cmake --build "$work/consumer_fortran" > "$work/consumer-fortran-build.log"
  for example in "${fortran_examples[@]}"; do
    "$work/consumer_fortran/$example" > "$work/consumer-fortran-$example.log" ||
      { cat "$work/consumer-fortran-$example.log"; echo "$example failed"; exit 1; }
    echo "$example OK"
  done

  echo "== Fortran examples with pkg-config's fortran_source"
  module_source=$(pkg-config --variable=fortran_source asperity)
  [ -f "$module_source" ] ||
    { echo "pkg-config's fortran_source '$module_source' is not a file"; exit 1; }
  [ "$(realpath "$module_source")" = "$(realpath "$installed_module")" ] ||
    { echo "pkg-config's fortran_source '$module_source' is not the installed module"; exit 1; }
  mkdir -p "$work/fortran"
  (cd "$work/fortran" &&
    "$fc" -std=f2008 -Wall -Werror -c "$module_source" &&
    for example in "${fortran_examples[@]}"; do
      "$fc" -std=f2008 -Wall -Werror "$source/examples/fortran/$example.f90" asperity.o \
        $(pkg-config --libs asperity) "$rpath_flag" -o "$example" &&
      ./"$example" > "$example.log" ||
        { cat "$example.log"; echo "$example failed"; exit 1; }
      echo "$example OK"
    done)
fi
echo "installed tree OK"
