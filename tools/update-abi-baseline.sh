#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Writes the ABI baseline abi/libasperity.abi from a built shared library: the C API's
# functions with their parameter and return types, as libabigail's abidw sees them.
#
#   tools/update-abi-baseline.sh BUILD_DIR
#
# Run it only when the ABI changes on purpose: after removing or changing something in the C
# interface, bump ASPERITY_ABI_VERSION in CMakeLists.txt (the soname follows), rebuild, run
# this and commit the new baseline with the change (docs/abi.md). Additions need no new
# baseline: the check allows them.
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
source=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
library=$(ls "$build"/src/libasperity.so.*.*.* | head -n 1)
abidw --exported-interfaces-only --headers-dir "$source/include" --headers-dir "$build/include" \
  --drop-private-types --no-show-locs --no-comp-dir-path --no-corpus-path \
  --out-file "$source/abi/libasperity.abi" "$library"
echo "wrote abi/libasperity.abi from $library"
