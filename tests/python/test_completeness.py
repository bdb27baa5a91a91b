# SPDX-License-Identifier: GPL-2.0-or-later
"""Every function and integer constant of asperity.h and asperity_mpi.h has its Python counterpart.

The headers are parsed here (ASPERITY_HEADER, set by CTest, names the source tree's asperity.h;
asperity_mpi.h is read next to it, whether or not the library was built with MPI):
* every ASP_EXPORT function must be a key of asperity.FUNCTIONS, the one table from which
  _library.py binds the library (so C_FUNCTIONS is what is actually bound), with as many
  argtypes as the declaration has parameters, and must be called somewhere in the package
  outside _library.py (so it is reachable through a method or function); a function taking a
  C MPI_Comm (asp_grid_create_mpi), which ctypes cannot pass, is served by its twin taking
  the Fortran handle (asp_grid_create_mpi_f, from mpi4py's comm.py2f()): that twin must be
  declared and bound instead;
* every #define ASP_<NAME> <integer> must be asperity.ASP_<NAME> with the same value, and
  asperity.<NAME> too; each of a family (1xx..9xx) must be accepted by name where methods
  take it; each status ASP_ERR_* must have its exception class.

A function or constant added to the header without its binding makes test_header_is_covered
fail, naming it: test_a_new_function_or_constant_is_noticed shows it by appending a
declaration and a define to the header's text and running the same check on it.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile
import types
import unittest

import asperity
from asperity import _names, errors

import support


def _package_sources():
    directory = os.path.dirname(asperity.__file__)
    text = ""
    for path in glob.glob(os.path.join(directory, "*.py")):
        if os.path.basename(path) not in ("_library.py", "_constants.py"):
            with open(path, encoding="utf-8") as source:
                text += source.read()
    return text


def problems(header_text):
    """What of the header the package lacks, as a list of messages (empty: complete)."""
    found = []
    functions = support.header_functions(header_text)
    comm_functions = support.header_comm_functions(header_text)
    sources = _package_sources()
    for name, count in sorted(functions.items()):
        if name in comm_functions:
            if name in asperity.FUNCTIONS:
                found.append("%s takes a C MPI_Comm, which ctypes cannot pass, but is bound"
                             % name)
            elif name + "_f" not in functions:
                found.append("%s takes a C MPI_Comm and the header has no %s_f (Fortran "
                             "handle) to serve it" % (name, name))
            continue
        if name not in asperity.FUNCTIONS:
            found.append("%s has no binding in asperity.FUNCTIONS" % name)
            continue
        if len(asperity.FUNCTIONS[name][1]) != count:
            found.append("%s takes %d arguments in the header, %d in the binding"
                         % (name, count, len(asperity.FUNCTIONS[name][1])))
        if not re.search(r'"%s"|lib\.%s\b' % (name, name), sources):
            found.append("%s is bound but no function or method of the package calls it"
                         % name)
    for name in sorted(set(asperity.FUNCTIONS) - set(functions)):
        found.append("%s is bound but not declared in the header" % name)
    for name, value in sorted(support.header_constants(header_text).items()):
        nice = name[len("ASP_"):]
        if getattr(asperity, name, None) != value:
            found.append("asperity.%s is missing or not %d" % (name, value))
        if getattr(asperity, nice, None) != value:
            found.append("asperity.%s is missing or not %d" % (nice, value))
        if 100 <= value < 1000:
            family = _names.FAMILIES.get(value // 100, {})
            if value not in family.values():
                found.append("%s = %d has no string name in its family" % (name, value))
        elif name.startswith("ASP_ERR_") and value not in errors.ERROR_CLASSES:
            found.append("%s = %d has no exception class" % (name, value))
    return found


class Completeness(unittest.TestCase):
    def test_header_is_covered(self):
        self.assertEqual(problems(support.read_headers()), [])

    def test_mpi_header_is_read(self):
        text = support.read_headers()
        self.assertEqual(support.header_functions(text)["asp_grid_create_mpi_f"], 6)
        self.assertEqual(support.header_comm_functions(text), {"asp_grid_create_mpi"})

    def test_an_unserved_mpi_function_is_noticed(self):
        text = support.read_headers() + (
            "\nASP_EXPORT int asp_system_create_mpi(MPI_Comm comm, asp_system **out);\n")
        self.assertIn("asp_system_create_mpi takes a C MPI_Comm and the header has no "
                      "asp_system_create_mpi_f (Fortran handle) to serve it", problems(text))
        text = support.read_headers().replace("asp_grid_create_mpi_f(", "asp_grid_create_mpi_g(")
        found = "\n".join(problems(text))
        self.assertIn("asp_grid_create_mpi_f is bound but not declared in the header", found)

    def test_header_parse_finds_the_interface(self):
        text = support.read_header()
        self.assertGreaterEqual(len(support.header_functions(text)), 55)
        self.assertEqual(support.header_functions(text)["asp_solver_get_history"], 4)
        self.assertEqual(support.header_constants(text)["ASP_ERR_IO"], 10)

    def test_bound_table_is_what_is_loaded(self):
        self.assertLessEqual(asperity.C_FUNCTIONS, frozenset(asperity.FUNCTIONS))
        self.assertLessEqual(frozenset(asperity.FUNCTIONS) - asperity.C_FUNCTIONS,
                             frozenset(asperity.OPTIONAL_FUNCTIONS))
        for name in asperity.C_FUNCTIONS:
            restype, argtypes = asperity.FUNCTIONS[name]
            function = getattr(asperity._lib, name)
            self.assertEqual(function.argtypes, argtypes, name)
            self.assertIs(function.restype, restype, name)

    def test_a_library_without_mpi_still_loads(self):
        # A stand-in for a library built without MPI: every function but asperity_mpi.h's.
        library = types.SimpleNamespace(**{
            name: getattr(asperity._lib, name) for name in asperity.C_FUNCTIONS
            if name not in asperity.OPTIONAL_FUNCTIONS})
        bound = asperity._library._bind(library)
        self.assertEqual(bound, frozenset(asperity.FUNCTIONS) - {"asp_grid_create_mpi_f"})
        with self.assertRaises(asperity.UnsupportedError) as caught:
            library.asp_grid_create_mpi_f(0, 8, 8, 1.0, 1.0, None)
        self.assertIn("built without MPI", str(caught.exception))
        self.assertEqual(caught.exception.status, asperity.ASP_ERR_UNSUPPORTED)
        del library.asp_solver_solve
        with self.assertRaisesRegex(ImportError, "lacks asp_solver_solve"):
            asperity._library._bind(library)

    def test_mpi4py_is_not_imported_by_the_package(self):
        # Importing mpi4py.MPI initialises MPI: only a program that passes a communicator
        # should pay for it (and may want to choose how).
        code = "import sys, asperity; sys.exit('mpi4py' in sys.modules)"
        subprocess.run([sys.executable, "-c", code], check=True)

    def test_grid_mpi_refuses_what_is_not_a_communicator(self):
        with self.assertRaisesRegex(asperity.InvalidArgumentError, "mpi4py communicator"):
            asperity.Grid.mpi(0, 8, 8, 1.0, 1.0)

    def test_a_new_function_or_constant_is_noticed(self):
        text = support.read_header() + (
            "\nASP_EXPORT int asp_system_new_thing(asp_system *system, double x);\n"
            "#define ASP_CONTROL_NEW_THING 599\n#define ASP_ERR_NEW_THING 11\n")
        found = "\n".join(problems(text))
        self.assertIn("asp_system_new_thing has no binding", found)
        self.assertIn("asperity.ASP_CONTROL_NEW_THING is missing", found)
        self.assertIn("asperity.ASP_ERR_NEW_THING is missing", found)

    def test_a_changed_signature_is_noticed(self):
        text = support.read_header().replace(
            "int asp_system_reset(asp_system *system);",
            "int asp_system_reset(asp_system *system, int how);")
        self.assertIn("asp_system_reset takes 2 arguments in the header, 1 in the binding",
                      problems(text))

    def test_constants_module_is_generated_from_the_header(self):
        generator = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                 "bindings", "python", "generate_constants.py")
        with tempfile.TemporaryDirectory() as work:
            header = os.path.join(work, "asperity.h")
            with open(header, "w", encoding="utf-8") as out:
                out.write(support.read_header() + "\n#define ASP_FIELD_NEW_THING 499 /* x */\n")
            output = os.path.join(work, "_constants.py")
            subprocess.run([sys.executable, generator, output, header], check=True)
            namespace = {}
            with open(output, encoding="utf-8") as generated:
                exec(generated.read(), namespace)  # noqa: S102 - our own generated file
        self.assertEqual(namespace["ASP_FIELD_NEW_THING"], 499)
        for name, value in support.header_constants(support.read_header()).items():
            self.assertEqual(namespace[name], value, name)

    def test_every_public_name_has_a_docstring(self):
        for name in asperity.__all__:
            value = getattr(asperity, name)
            if callable(value) or isinstance(value, type(asperity)):
                self.assertTrue((value.__doc__ or "").strip(), name)
        for cls in (asperity.Grid, asperity.System, asperity.Solver):
            for attribute, value in vars(cls).items():
                if attribute.startswith("_"):
                    continue
                self.assertTrue((getattr(value, "__doc__", None) or "").strip(),
                                "%s.%s" % (cls.__name__, attribute))


if __name__ == "__main__":
    unittest.main()
