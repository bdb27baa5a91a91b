# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared helpers of the Python package's tests."""
import os
import re

HEADER = os.environ.get("ASPERITY_HEADER") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "include", "asperity", "asperity.h")

_FUNCTION = re.compile(r"ASP_EXPORT\s+[^;()]*?\b(asp_\w+)\s*\(([^)]*)\)\s*;", re.S)
_DEFINE = re.compile(r"^\s*#\s*define\s+(ASP_\w+)\s+(-?\d+)\b", re.M)


def read_header(path=HEADER):
    with open(path, encoding="utf-8") as header:
        return header.read()


def header_functions(text):
    """{name: number of parameters} of the ASP_EXPORT declarations."""
    functions = {}
    for name, params in _FUNCTION.findall(text):
        params = " ".join(params.split())
        functions[name] = 0 if params in ("", "void") else params.count(",") + 1
    return functions


def header_constants(text):
    """{name: int} of the #define ASP_* <integer> lines."""
    return {name: int(value) for name, value in _DEFINE.findall(text)}
