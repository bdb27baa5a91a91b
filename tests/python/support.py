# SPDX-License-Identifier: GPL-2.0-or-later
"""Shared helpers of the Python package's tests."""
import os
import re

HEADER = os.environ.get("ASPERITY_HEADER") or os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "include", "asperity", "asperity.h")

# asperity_mpi.h, next to asperity.h: its functions are part of the interface to cover, whether
# or not the library was built with MPI.
MPI_HEADER = os.environ.get("ASPERITY_MPI_HEADER") or os.path.join(
    os.path.dirname(HEADER), "asperity_mpi.h")

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


def header_comm_functions(text):
    """The names of the ASP_EXPORT functions with a C MPI_Comm parameter."""
    return {name for name, params in _FUNCTION.findall(text)
            if re.search(r"\bMPI_Comm\b", params)}


def read_headers():
    """asperity.h and asperity_mpi.h, one text."""
    return read_header() + "\n" + read_header(MPI_HEADER)
