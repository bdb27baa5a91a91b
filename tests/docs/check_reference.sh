#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Builds the API reference with Doxygen (warnings are errors) and checks that it documents
# every function and constant of the header, with the header's own text.
#
#   check_reference.sh DOXYGEN DOXYFILE OUTPUT_DIR HEADER
set -uo pipefail
doxygen=$1 doxyfile=$2 output=$3 header=$4
rm -rf "$output" && mkdir -p "$output"
"$doxygen" "$doxyfile" || { echo "FAIL: doxygen failed"; cat "$output/warnings.log"; exit 1; }
page=$output/html/asperity_8h.html
[ -f "$page" ] || { echo "FAIL: no page for asperity.h"; exit 1; }
missing=0
for name in $(grep -oE '^ASP_EXPORT [^(]*\(' "$header" | grep -oE 'asp_[a-z0-9_]+') \
            $(grep -oE '^#define ASP_[A-Z0-9_]+ ' "$header" | awk '{print $2}'); do
  grep -q "$name" "$page" || { echo "FAIL: the reference lacks $name"; missing=1; }
done
# The header's notes are there as written (one from the overview, one from a function).
grep -q "Units      Any consistent system" "$page" || { echo "FAIL: overview"; missing=1; }
grep -q "Whether the solver, with its current options" "$page" || { echo "FAIL: notes"; missing=1; }
[ "$missing" -eq 0 ] && echo "the API reference documents the whole header"
