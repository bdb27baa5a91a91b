# SPDX-License-Identifier: GPL-2.0-or-later
"""Loading of libasperity and the table of its C functions.

The library is looked for, in this order:

1. the path in the environment variable ``ASPERITY_LIBRARY``, if it is set (and then only
   there: a wrong path is an error, not a reason to look elsewhere);
2. the shared object by its soname, ``libasperity.so.<ABI>`` (``libasperity.<ABI>.dylib`` on
   macOS), through the system's loader (``LD_LIBRARY_PATH``, the loader cache, ...), ABI being
   ``ASP_ABI_VERSION`` of the header the package was built from;
3. ``ctypes.util.find_library("asperity")``.

When none loads, ``import asperity`` raises ImportError naming what was tried. A library of
another ABI number is refused the same way.

Every C function is declared once, in :data:`FUNCTIONS` (name -> (restype, argtypes)); the
loaded library object :data:`lib` has exactly these functions bound with their types, but for
the :data:`OPTIONAL_FUNCTIONS` a build may leave out (asperity_mpi.h's, in a build without
MPI), which then raise UnsupportedError when called. The
rest of the package calls them as ``lib.asp_...`` and checks statuses with :func:`check`.
"""
import ctypes
import ctypes.util
import os
import sys

from . import _constants as _c
from .errors import error_for_status

__all__ = ["lib", "FUNCTIONS", "OPTIONAL_FUNCTIONS", "C_FUNCTIONS", "PROGRESS_FN",
           "POTENTIAL_FN", "check", "read_string", "library_path"]

_i64 = ctypes.c_int64
_int = ctypes.c_int
_dbl = ctypes.c_double
_ptr = ctypes.c_void_p        # handles and arrays are passed as addresses
_str = ctypes.c_char_p
_p_int = ctypes.POINTER(ctypes.c_int)
_p_i64 = ctypes.POINTER(ctypes.c_int64)
_p_dbl = ctypes.POINTER(ctypes.c_double)
_p_ptr = ctypes.POINTER(ctypes.c_void_p)

#: int (*)(int64_t iteration, double seconds, double error, void *user_data)
PROGRESS_FN = ctypes.CFUNCTYPE(_int, _i64, _dbl, _dbl, _ptr)
#: int (*)(int64_t n, const double *gap, double *phi, double *dphi, double *d2phi, void *)
POTENTIAL_FN = ctypes.CFUNCTYPE(_int, _i64, _ptr, _ptr, _ptr, _ptr, _ptr)

#: Every function of asperity.h: name -> (restype, argtypes). The completeness test compares
#: these names with the ASP_EXPORT declarations of the header, and the argument counts with
#: their parameter lists.
FUNCTIONS = {
    # status and version
    "asp_status_string": (_str, [_int]),
    "asp_last_error_message": (_str, []),
    "asp_version_string": (_str, []),
    "asp_abi_version": (_int, []),
    # grid
    "asp_grid_create_1d": (_int, [_i64, _dbl, _p_ptr]),
    "asp_grid_create_2d": (_int, [_i64, _i64, _dbl, _dbl, _p_ptr]),
    "asp_grid_destroy": (None, [_ptr]),
    "asp_grid_get_shape": (_int, [_ptr, _p_int, _p_i64, _p_i64, _p_i64]),
    "asp_grid_get_box": (_int, [_ptr, _p_dbl, _p_dbl]),
    "asp_grid_set_fft_planning": (_int, [_ptr, _int]),
    "asp_grid_set_threads": (_int, [_ptr, _int]),
    "asp_grid_get_threads": (_int, [_ptr, _p_int]),
    "asp_grid_get_slab": (_int, [_ptr, _p_i64, _p_i64, _p_i64]),
    "asp_fft_export_wisdom": (_int, [_str]),
    "asp_fft_import_wisdom": (_int, [_str]),
    # topographies
    "asp_topography_flat": (_int, [_ptr, _ptr, _i64]),
    "asp_topography_sphere": (_int, [_ptr, _dbl, _ptr, _i64]),
    "asp_topography_paraboloid": (_int, [_ptr, _dbl, _ptr, _i64]),
    "asp_topography_sinusoid": (_int, [_ptr, _dbl, _i64, _i64, _ptr, _i64]),
    "asp_topography_double_sinewave": (_int, [_ptr, _dbl, _dbl, _i64, _ptr, _i64]),
    "asp_topography_self_affine": (_int, [_ptr, _dbl, _dbl, _dbl, _dbl, _int, _dbl, _i64,
                                          _ptr, _i64]),
    "asp_topography_statistics": (_int, [_ptr, _ptr, _i64, _p_dbl, _p_dbl, _p_dbl]),
    "asp_topography_detrend": (_int, [_ptr, _int, _ptr, _i64]),
    "asp_topography_power_spectrum": (_int, [_ptr, _ptr, _i64, _i64, _ptr, _ptr]),
    # system
    "asp_system_create": (_int, [_ptr, _dbl, _p_ptr]),
    "asp_system_create_free": (_int, [_ptr, _dbl, _p_ptr]),
    "asp_system_create_layer": (_int, [_ptr, _dbl, _dbl, _dbl, _p_ptr]),
    "asp_system_destroy": (None, [_ptr]),
    "asp_system_set_topography": (_int, [_ptr, _ptr, _i64]),
    "asp_system_set_k0": (_int, [_ptr, _dbl]),
    "asp_system_set_adhesion": (_int, [_ptr, _dbl, _dbl]),
    "asp_system_set_soft_wall": (_int, [_ptr, _dbl, _dbl, _dbl, _dbl]),
    "asp_system_set_lennard_jones": (_int, [_ptr, _dbl, _dbl]),
    "asp_system_set_hard_wall": (_int, [_ptr]),
    "asp_system_set_potential": (_int, [_ptr, POTENTIAL_FN, _ptr, _int]),
    "asp_system_set_reference_pressure": (_int, [_ptr, _dbl]),
    "asp_system_reset": (_int, [_ptr]),
    "asp_system_get": (_int, [_ptr, _int, _p_dbl]),
    "asp_system_get_field": (_int, [_ptr, _int, _ptr, _i64]),
    "asp_system_check_resolution": (_int, [_ptr, _p_dbl, _p_int, _ptr, _i64, _p_i64]),
    # algorithms and solver
    "asp_algorithms": (_int, [_ptr, _i64, _p_i64]),
    "asp_solver_create": (_int, [_str, _p_ptr]),
    "asp_solver_destroy": (None, [_ptr]),
    "asp_solver_describe": (_int, [_ptr, _ptr, _i64, _p_i64]),
    "asp_solver_set_option": (_int, [_ptr, _str, _dbl]),
    "asp_solver_set_option_string": (_int, [_ptr, _str, _str]),
    "asp_solver_get_option": (_int, [_ptr, _str, _p_dbl]),
    "asp_solver_get_option_string": (_int, [_ptr, _str, _ptr, _i64, _p_i64]),
    "asp_solver_set_tolerance": (_int, [_ptr, _dbl]),
    "asp_solver_set_max_iterations": (_int, [_ptr, _i64]),
    "asp_solver_set_progress": (_int, [_ptr, PROGRESS_FN, _ptr]),
    "asp_solver_set_history": (_int, [_ptr, _int]),
    "asp_solver_solve": (_int, [_ptr, _ptr, _int, _dbl]),
    "asp_solver_supports": (_int, [_ptr, _ptr, _int]),
    "asp_solver_get": (_int, [_ptr, _int, _p_dbl]),
    "asp_solver_termination": (_int, [_ptr, _p_int]),
    "asp_solver_iterations": (_int, [_ptr, _p_i64]),
    "asp_solver_evaluations": (_int, [_ptr, _p_i64]),
    "asp_solver_transforms": (_int, [_ptr, _p_i64]),
    "asp_solver_final_error": (_int, [_ptr, _p_dbl]),
    "asp_solver_converged": (_int, [_ptr, _p_int]),
    "asp_solver_elapsed_seconds": (_int, [_ptr, _p_dbl]),
    "asp_solver_history_length": (_int, [_ptr, _p_i64]),
    "asp_solver_normal_stiffness": (_int, [_ptr, _ptr, _p_dbl]),
    "asp_solver_get_history": (_int, [_ptr, _int, _ptr, _i64]),
    # asperity_mpi.h (asp_grid_create_mpi takes a C MPI_Comm, which Python cannot hold; an
    # mpi4py communicator gives its Fortran handle, MPI_Fint, an int in Open MPI and MPICH)
    "asp_grid_create_mpi_f": (_int, [_int, _i64, _i64, _dbl, _dbl, _p_ptr]),
}

#: The functions a library may lack, with what their absence means: they are bound when the
#: library has them, and otherwise calling ``lib.<name>`` raises UnsupportedError saying why.
#: (A library built without MPI exports asp_grid_create_mpi_f and refuses there itself; one
#: older than distributed grids lacks it.)
OPTIONAL_FUNCTIONS = {
    "asp_grid_create_mpi_f": "libasperity was built without MPI (no asperity_mpi.h): "
                             "distributed grids need a build with MPI and libfftw3-mpi",
}


def _soname():
    abi = _c.ASP_ABI_VERSION
    if sys.platform == "darwin":
        return "libasperity.%d.dylib" % abi
    if sys.platform.startswith(("win", "cygwin")):
        return "asperity.dll"
    return "libasperity.so.%d" % abi


def _candidates():
    """(description, path) in the order of the loading rule; None path: nothing to try."""
    explicit = os.environ.get("ASPERITY_LIBRARY")
    if explicit:
        yield "ASPERITY_LIBRARY=%s" % explicit, explicit
        return
    yield "the soname %s through the system loader" % _soname(), _soname()
    found = ctypes.util.find_library("asperity")
    yield "ctypes.util.find_library('asperity') = %s" % found, found


def _load():
    tried = []
    for what, path in _candidates():
        if path is None:
            tried.append("%s: nothing found" % what)
            continue
        try:
            library = ctypes.CDLL(path)
        except OSError as exc:
            tried.append("%s: %s" % (what, exc))
            continue
        try:
            abi = library.asp_abi_version()
        except AttributeError:
            tried.append("%s: not libasperity (no asp_abi_version)" % what)
            continue
        if abi != _c.ASP_ABI_VERSION:
            tried.append("%s: ABI %d, but this package was built for ABI %d"
                         % (what, abi, _c.ASP_ABI_VERSION))
            continue
        return library, path
    raise ImportError("asperity: could not load the C library libasperity; tried\n  "
                      + "\n  ".join(tried)
                      + "\nSet ASPERITY_LIBRARY to the path of libasperity.so.%d, or add its "
                        "directory to LD_LIBRARY_PATH." % _c.ASP_ABI_VERSION)


def _absent(name, reason):
    """Stands in for an optional function the library lacks: raises UnsupportedError."""
    def call(*args):
        raise error_for_status(_c.ASP_ERR_UNSUPPORTED, "%s: %s" % (name, reason), name)
    call.__name__ = name
    return call


def _bind(library):
    """Binds FUNCTIONS on the library; returns the names bound."""
    missing, bound = [], set()
    for name, (restype, argtypes) in FUNCTIONS.items():
        try:
            function = getattr(library, name)
        except AttributeError:
            if name in OPTIONAL_FUNCTIONS:
                setattr(library, name, _absent(name, OPTIONAL_FUNCTIONS[name]))
            else:
                missing.append(name)
            continue
        function.restype = restype
        function.argtypes = argtypes
        bound.add(name)
    if missing:
        raise ImportError("asperity: the library lacks %s (older than the header the package "
                          "was built from?)" % ", ".join(missing))
    return frozenset(bound)


lib, library_path = _load()
#: The names of the C functions bound from the library: the keys of FUNCTIONS but the
#: OPTIONAL_FUNCTIONS it lacks.
C_FUNCTIONS = _bind(lib)


def last_error_message():
    """The detail of the last failed library call of this thread (asp_last_error_message)."""
    return lib.asp_last_error_message().decode("utf-8", "replace")


def check(status, function):
    """Raises the Error subclass for status (with the library's message) unless it is ASP_OK."""
    if status != _c.ASP_OK:
        message = last_error_message() or lib.asp_status_string(status).decode()
        raise error_for_status(status, message, function)


def read_string(function, *args):
    """Calls a C function that fills a string buffer (asp_algorithms' rules) and returns str.

    ``function`` is the name in FUNCTIONS; ``args`` precede (buffer, size, length).
    """
    c_function = getattr(lib, function)
    length = ctypes.c_int64(0)
    check(c_function(*args, None, 0, ctypes.byref(length)), function)
    for _ in range(4):  # the text could grow between the two calls; retry a few times
        buffer = ctypes.create_string_buffer(length.value + 1)
        status = c_function(*args, buffer, len(buffer), ctypes.byref(length))
        if status == _c.ASP_ERR_SIZE_MISMATCH and length.value + 1 > len(buffer):
            continue
        check(status, function)
        return buffer.value.decode("utf-8", "replace")
    check(status, function)
    return buffer.value.decode("utf-8", "replace")
