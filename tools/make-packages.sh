#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds asperity's Debian packages (libasperity<ABI>, libasperity-dev, asperity,
# python3-asperity) into OUTPUT_DIR: a tree configured for /usr, so that the library goes to
# Debian's multiarch directory, built and packaged by CPack.
#
#   tools/make-packages.sh OUTPUT_DIR [BUILD_DIR]
#
# Then, as root: apt-get install ./OUTPUT_DIR/*.deb
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 OUTPUT_DIR [BUILD_DIR]" >&2; exit 2; }
source=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$1"
out=$(cd "$1" && pwd)
build=${2:-$out/build}

cmake -S "$source" -B "$build" -DCMAKE_INSTALL_PREFIX=/usr -DCMAKE_BUILD_TYPE=Release \
  -DASPERITY_BUILD_TESTS=OFF -DASPERITY_BUILD_BENCHMARKS=OFF > "$out/configure.log"
cmake --build "$build" -j2 > "$out/build.log"
(cd "$build" && cpack -G DEB -B "$out" > "$out/cpack.log")
rm -rf "$out/_CPack_Packages"
ls "$out"/*.deb
