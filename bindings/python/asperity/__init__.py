# SPDX-License-Identifier: GPL-2.0-or-later
"""asperity: rough-surface contact mechanics with FFT-based boundary elements (Python).

A ctypes binding of the C library libasperity. The C header asperity.h is the manual; this
package mirrors it:

* :class:`Grid` -- ``Grid(nx, lx)`` (1D) or ``Grid(nx, ny, lx, ly)`` (2D); with MPI
  (asperity_mpi.h), ``Grid.mpi(comm, nx, ny, lx, ly)`` shares a 2D grid among the processes
  of an mpi4py communicator, each passing and receiving arrays of its own rows (``Grid.slab``);
* :class:`System` -- ``System(grid, contact_modulus, substrate="periodic"|"free")``, or
  ``substrate="layer", thickness=t, poisson_ratio=nu`` for an elastic layer on a rigid base:
  the topography, the interaction and the state (fields ``pressure``, ``gap``, ...);
* :class:`Solver` -- ``Solver("pk", tolerance=1e-10)``; ``solve(system, control, value)``
  returns a :class:`Report`;
* :mod:`asperity.topography` -- generators and tools returning NumPy arrays (also exported
  here: ``asperity.paraboloid(grid, R)``, ...);
* exceptions -- :class:`Error` and its subclasses (:mod:`asperity.errors`).

Constants: every ``#define ASP_*`` of the header is available under its name
(``asperity.ASP_CONTROL_PENETRATION``) and, for asperity.h's, without the prefix
(``asperity.CONTROL_PENETRATION``). Methods take the lower-case names instead
(``control="penetration"``); ``asperity.CONTROLS``, ``FIELDS``, ``SCALARS``,
``HISTORY_COLUMNS``, ``TERMINATIONS``, ``DETREND_MODES``, ``FFT_PLANNINGS`` and
``NORMALISATIONS`` map those names to the integer constants.

Fields: arrays of shape (ny, nx) in C order or (nx, ny) in Fortran order, float64, are
passed without a copy; results are (ny, nx) C-order arrays (``a[y, x]``); (nx,) in 1D.
"""
from . import _constants
from . import _names
from ._constants import *  # noqa: F401,F403 - every ASP_* constant of the headers
from ._library import (C_FUNCTIONS, FUNCTIONS, OPTIONAL_FUNCTIONS, lib as _lib, library_path,
                       last_error_message)
from .errors import *  # noqa: F401,F403
from .errors import __all__ as _error_names
from .grid import Grid, set_fft_planning
from .solver import Report, Solver, algorithms
from .system import System
from . import topography
from .topography import (flat, sphere, paraboloid, sinusoid, double_sinewave, self_affine,
                         statistics, detrend, power_spectrum, export_wisdom, import_wisdom)

globals().update(_names.NICE_CONSTANTS)

CONTROLS = dict(_names.FAMILIES[_names.CONTROL])
FIELDS = dict(_names.FAMILIES[_names.FIELD])
SCALARS = dict(_names.FAMILIES[_names.SCALAR])
HISTORY_COLUMNS = dict(_names.FAMILIES[_names.HISTORY])
TERMINATIONS = dict(_names.FAMILIES[_names.TERMINATION])
REPORT_KEYS = dict(_names.FAMILIES[_names.REPORT])
DETREND_MODES = dict(_names.FAMILIES[_names.DETREND])
FFT_PLANNINGS = dict(_names.FAMILIES[_names.FFT_PLANNING])
NORMALISATIONS = dict(_names.FAMILIES[_names.NORMALISATION])

__version__ = _constants.ASP_VERSION_STRING


def version():
    """The C library's version string (asp_version_string), e.g. "0.2.0"."""
    return _lib.asp_version_string().decode()


def abi_version():
    """The C library's ABI number (asp_abi_version)."""
    return _lib.asp_abi_version()


def status_string(status):
    """A short English description of a status code (asp_status_string)."""
    return _lib.asp_status_string(int(status)).decode()


__all__ = (["Grid", "System", "Solver", "Report", "algorithms", "version", "abi_version",
            "status_string", "last_error_message", "set_fft_planning", "topography", "flat",
            "sphere", "paraboloid", "sinusoid", "double_sinewave", "self_affine", "statistics",
            "detrend", "power_spectrum", "export_wisdom", "import_wisdom", "C_FUNCTIONS",
            "FUNCTIONS", "OPTIONAL_FUNCTIONS", "library_path", "CONTROLS", "FIELDS", "SCALARS", "HISTORY_COLUMNS",
            "TERMINATIONS", "DETREND_MODES", "FFT_PLANNINGS", "NORMALISATIONS"]
           + list(_error_names) + list(_constants.HEADER_CONSTANTS)
           + list(_names.NICE_CONSTANTS))
