#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Every source file of the project (C, C++, Fortran, Python, shell, CMake) names its licence
# with an SPDX line among its first five lines; test data and documents are not source files.
#
#   check_spdx.sh SOURCE_DIR
set -uo pipefail
cd "$1" || exit 1
if [ -d .git ] && command -v git > /dev/null; then
  files=$(git ls-files)
else
  files=$(find . -path ./build -prune -o -type f -print | sed 's|^\./||')
fi
missing=0
while IFS= read -r file; do
  case $file in
    tests/io/data/*.py | tools/* | .ci/run) ;;
    tests/io/data/* | docs/benchmarks/* | abi/* | build/* | */build/*) continue ;;
  esac
  case $file in
    *.c | *.h | *.cpp | *.hpp | *.f90 | *.py | *.sh | *.cmake | *.in | *.map | */CMakeLists.txt | \
    CMakeLists.txt | tools/* | .ci/run) ;;
    *) continue ;;
  esac
  head -n 5 "$file" | grep -q "SPDX-License-Identifier: GPL-2.0-or-later" ||
    { echo "no SPDX line: $file"; missing=$((missing + 1)); }
done <<< "$files"
[ "$missing" -eq 0 ] && echo "every source file carries its SPDX line"
