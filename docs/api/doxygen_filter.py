#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Doxygen input filter for include/asperity/asperity.h.

The header is written as a manual in plain C comments. This filter hands them to Doxygen
without changing their text: the file's opening comment becomes the file's documentation, a
comment right before a declaration (ASP_EXPORT function, typedef, #define ASP_...) becomes
that declaration's documentation, and a comment after a #define on its line documents the
constant. Each is kept verbatim, as it reads in the header."""
import re
import sys

DECLARATION = re.compile(r"^(ASP_EXPORT|typedef|#define ASP_)")


def filtered(lines):
    out = list(lines)
    i = 0
    first = True
    while i < len(out):
        line = out[i]
        trailing = re.match(r"^(#define ASP_\w+\s+\S+\s*)/\*(.*)$", line, re.DOTALL)
        if trailing:
            # A constant's own comment, possibly over several lines.
            out[i] = trailing.group(1) + "/**< " + trailing.group(2)
            i += 1
            continue
        if "SPDX-License-Identifier" in line:
            i += 1
            continue
        if line.startswith("/*") and not line.startswith("/* ===="):
            end = i
            while "*/" not in out[end]:
                end += 1
            following = end + 1
            while following < len(out) and not out[following].strip():
                following += 1
            documents = following < len(out) and DECLARATION.match(out[following])
            if first or documents:
                opening = "/** \\file\n" if first else "/**"
                body = out[i][2:]
                out[i] = opening + " \\verbatim\n" + (body if body.strip() else "")
                out[end] = out[end].replace("*/", "\\endverbatim */", 1)
            first = False
            i = end + 1
            continue
        i += 1
    return out


if __name__ == "__main__":
    with open(sys.argv[1], encoding="utf-8") as header:
        sys.stdout.write("".join(filtered(header.readlines())))
