# SPDX-License-Identifier: GPL-2.0-or-later
"""The Solver: an algorithm, its options, and the report and history of its last run."""
import ctypes
import dataclasses

import numpy as np

from . import _constants as _c
from . import _names
from ._callbacks import Progress
from ._handles import OwnedHandle
from ._library import PROGRESS_FN, lib, check, read_string
from .errors import Error, NullPointerError, UnsupportedError

__all__ = ["Solver", "Report", "algorithms"]


def algorithms():
    """The names of the algorithms of this build (asp_algorithms), as a list of str."""
    return [name for name in read_string("asp_algorithms").splitlines() if name]


@dataclasses.dataclass(frozen=True)
class Report:
    """The report of a solve (what asp_solver_termination, ... return after it).

    termination is the reason's name ("converged", "iteration_limit", "cancelled",
    "stalled", "breakdown", "separated"; the int code if unknown), termination_code its
    ASP_TERMINATION_* value.
    """

    termination: object
    termination_code: int
    iterations: int
    evaluations: int
    transforms: int
    final_error: float
    converged: bool
    elapsed_seconds: float


class Solver(OwnedHandle):
    """An algorithm by name: ``Solver("pk", tolerance=1e-10, variable="gap", ...)``.

    Keyword arguments are options set with :meth:`set_option` (numbers or strings; see
    :meth:`describe` for the algorithm's options). ``asperity.algorithms()`` lists the names.
    One solver may solve many systems; the report and history are those of its last solve.

    :meth:`solve` returns a :class:`Report`; each figure of the report is read by name with
    :meth:`get` (asp_solver_get: ``solver.get("iterations")``, the names of
    ``asperity.REPORT_KEYS``), and the same values are properties of the solver
    (termination, iterations, evaluations, transforms, final_error, converged,
    elapsed_seconds, history_length), which raise InvalidStateError before the first solve.
    """

    def __init__(self, algorithm="pk", **options):
        handle = ctypes.c_void_p()
        check(lib.asp_solver_create(str(algorithm).encode(), ctypes.byref(handle)),
              "asp_solver_create")
        self._handle = handle.value
        self._algorithm = str(algorithm)
        self._progress = None
        self._history = False
        for name, value in options.items():
            self.set_option(name, value)

    _destroy = lib.asp_solver_destroy
    _what = "solver"

    def _forget(self):
        """Drops the progress callback the handle kept alive."""
        self._progress = None

    @property
    def name(self):
        """The algorithm's name."""
        return self._algorithm

    def describe(self):
        """What the algorithm does and its options, as text (asp_solver_describe)."""
        return read_string("asp_solver_describe", self.handle)

    # -- options -----------------------------------------------------------------------------
    def set_option(self, name, value):
        """Sets an option: a str value sets a string option, a number a numeric one."""
        if isinstance(value, str):
            check(lib.asp_solver_set_option_string(self.handle, name.encode(), value.encode()),
                  "asp_solver_set_option_string")
        else:
            check(lib.asp_solver_set_option(self.handle, name.encode(), float(value)),
                  "asp_solver_set_option")

    def get_option(self, name):
        """An option's value: a float for numeric options, a str for string options, and the
        word a numeric option holds where it holds one ("auto" for "levels" and
        "range_continuation")."""
        value = ctypes.c_double()
        status = lib.asp_solver_get_option(self.handle, name.encode(), ctypes.byref(value))
        if status == _c.ASP_OK:
            try:
                return read_string("asp_solver_get_option_string", self.handle, name.encode())
            except Error:
                return value.value
        try:
            return read_string("asp_solver_get_option_string", self.handle, name.encode())
        except Error:
            check(lib.asp_solver_get_option(self.handle, name.encode(), ctypes.byref(value)),
                  "asp_solver_get_option")
            raise

    @property
    def tolerance(self):
        """The "tolerance" option (asp_solver_set_tolerance)."""
        return self.get_option("tolerance")

    @tolerance.setter
    def tolerance(self, value):
        check(lib.asp_solver_set_tolerance(self.handle, float(value)), "asp_solver_set_tolerance")

    @property
    def max_iterations(self):
        """The "max_iterations" option (asp_solver_set_max_iterations)."""
        return int(self.get_option("max_iterations"))

    @max_iterations.setter
    def max_iterations(self, value):
        check(lib.asp_solver_set_max_iterations(self.handle, int(value)),
              "asp_solver_set_max_iterations")

    # -- callbacks and history ---------------------------------------------------------------
    def set_progress(self, fn):
        """``fn(iteration, seconds, error)`` called every iteration; truthy return stops.

        None removes it. The solver keeps fn alive while it is set. A stop leaves the state
        of that iteration in the system and the termination "cancelled". An exception
        raised by fn also stops the solve cleanly (state kept, report available); solve()
        then raises :class:`asperity.CallbackError` chained from it (KeyboardInterrupt and
        SystemExit are re-raised as they are).
        """
        progress = None if fn is None else Progress(fn)
        check(lib.asp_solver_set_progress(
            self.handle, PROGRESS_FN() if progress is None else progress.c_function, None),
            "asp_solver_set_progress")
        self._progress = progress

    progress = property(lambda self: None if self._progress is None else self._progress.fn,
                        set_progress, doc="The progress callable (None if none); settable.")

    def set_history(self, on=True):
        """Records one row per iteration of the next solves (asp_solver_set_history)."""
        check(lib.asp_solver_set_history(self.handle, 1 if on else 0), "asp_solver_set_history")
        self._history = bool(on)

    record_history = property(lambda self: self._history, set_history,
                              doc="Whether solves record their history; settable.")

    @property
    def history(self):
        """The last solve's history: dict column name -> float64 array, one row per iteration.

        Columns: iteration, evaluations, transforms, seconds, error, objective,
        contact_fraction (ASP_HISTORY_*). Empty arrays when recording was off.
        """
        length = ctypes.c_int64()
        check(lib.asp_solver_history_length(self.handle, ctypes.byref(length)),
              "asp_solver_history_length")
        n = length.value
        columns = {}
        for name, code in _names.FAMILIES[_names.HISTORY].items():
            values = np.empty(n)
            check(lib.asp_solver_get_history(self.handle, code,
                                             values.ctypes.data if n else None, n),
                  "asp_solver_get_history")
            columns[name] = values
        return columns

    def history_array(self):
        """The history as a structured NumPy array (one field per column)."""
        columns = self.history
        n = len(next(iter(columns.values()))) if columns else 0
        out = np.empty(n, dtype=[(name, np.float64) for name in columns])
        for name, values in columns.items():
            out[name] = values
        return out

    # -- solving -----------------------------------------------------------------------------
    def supports(self, system, control):
        """Whether this solver serves the system under the control, without solving."""
        return self.unsupported_reason(system, control) is None

    def unsupported_reason(self, system, control):
        """None if supported, else the library's message saying why not."""
        code = _names.resolve(_names.CONTROL, control, "control")
        status = lib.asp_solver_supports(self.handle, system.handle, code)
        if status == _c.ASP_ERR_UNSUPPORTED:
            return lib.asp_last_error_message().decode("utf-8", "replace")
        check(status, "asp_solver_supports")
        return None

    def solve(self, system, control, value):
        """Solves the system for control = "mean_pressure", "penetration" or "mean_gap".

        Starts from the system's current state (warm start) and leaves the solution there.
        Returns a :class:`Report`. Every way a solve ends (converged or not) returns; an
        error status raises (the system then keeps its previous state): InvalidStateError
        for a system whose topography was never set.
        """
        code = _names.resolve(_names.CONTROL, control, "control")
        progress = self._progress
        if progress is not None:
            progress.failure.take()
        status = lib.asp_solver_solve(self.handle, system.handle, code, float(value))
        potential = system._potential
        if status == _c.ASP_ERR_CALLBACK and potential is not None and \
                potential.failure.exception is not None:
            potential.failure.raise_from(
                lib.asp_last_error_message().decode("utf-8", "replace"), "asp_solver_solve")
        if potential is not None:
            potential.failure.take()
        check(status, "asp_solver_solve")
        if progress is not None and progress.failure.exception is not None:
            progress.failure.raise_from(
                "the progress callback raised; the solve stopped at iteration %d with the "
                "state of that iteration in the system" % self.iterations, "asp_solver_solve")
        return self.report()

    def normal_stiffness(self, system):
        """d(mean pressure)/d(penetration) of the state this solver's last solve left in system.

        Pressure per length (times the box area: dF/d(delta)); the consistent tangent of a
        Newton iteration on the penetration (asp_solver_normal_stiffness). Raises
        InvalidStateError unless that solve converged on this system and nothing changed it
        since, or when the state is not a stable equilibrium; a potential callback that
        raises is re-raised.
        """
        value = ctypes.c_double()
        status = lib.asp_solver_normal_stiffness(self.handle, system.handle,
                                                 ctypes.byref(value))
        potential = system._potential
        if status == _c.ASP_ERR_CALLBACK and potential is not None and \
                potential.failure.exception is not None:
            potential.failure.raise_from(
                lib.asp_last_error_message().decode("utf-8", "replace"),
                "asp_solver_normal_stiffness")
        if potential is not None:
            potential.failure.take()
        check(status, "asp_solver_normal_stiffness")
        return value.value

    def report(self):
        """The Report of the last solve (InvalidStateError before any)."""
        code = self.termination_code
        return Report(_names.name_of(_names.TERMINATION, code), code, self.iterations,
                      self.evaluations, self.transforms, self.final_error, self.converged,
                      self.elapsed_seconds)

    #: The report keys whose figures are whole numbers: get() gives them as int.
    _WHOLE_REPORT_KEYS = frozenset(
        _names.FAMILIES[_names.REPORT][name]
        for name in ("termination", "converged", "iterations", "evaluations", "transforms",
                     "history_length"))

    def get(self, key):
        """A figure of the last solve's report by name ("iterations", ...) or ASP_REPORT_* key.

        asp_solver_get. Counts, the termination code and the converged flag come back as int
        (the library gives them as doubles that hold them exactly), the final error and the
        elapsed seconds as float. Raises InvalidStateError before the first solve, or after a
        solve that returned an error; InvalidArgumentError for a name or key of no report
        figure.
        """
        code = _names.resolve(_names.REPORT, key, "key")
        value = ctypes.c_double()
        check(lib.asp_solver_get(self.handle, code, ctypes.byref(value)), "asp_solver_get")
        return int(value.value) if code in self._WHOLE_REPORT_KEYS else value.value

    @property
    def history_length(self):
        """Rows of the last solve's history (0 when it was not recorded)."""
        return self.get("history_length")

    def _get(self, function, ctype):
        value = ctype()
        check(getattr(lib, function)(self.handle, ctypes.byref(value)), function)
        return value.value

    @property
    def termination_code(self):
        """ASP_TERMINATION_* of the last solve."""
        return self._get("asp_solver_termination", ctypes.c_int)

    @property
    def termination(self):
        """The termination reason's name of the last solve ("converged", ...)."""
        return _names.name_of(_names.TERMINATION, self.termination_code)

    @property
    def iterations(self):
        """Iterations of the last solve."""
        return self._get("asp_solver_iterations", ctypes.c_int64)

    @property
    def evaluations(self):
        """Objective or gradient evaluations of the last solve."""
        return self._get("asp_solver_evaluations", ctypes.c_int64)

    @property
    def transforms(self):
        """FFTs of the last solve."""
        return self._get("asp_solver_transforms", ctypes.c_int64)

    @property
    def final_error(self):
        """The error of the state the last solve left."""
        return self._get("asp_solver_final_error", ctypes.c_double)

    @property
    def converged(self):
        """Whether the last solve met the tolerance."""
        return bool(self._get("asp_solver_converged", ctypes.c_int))

    @property
    def elapsed_seconds(self):
        """Wall-clock seconds of the last solve."""
        return self._get("asp_solver_elapsed_seconds", ctypes.c_double)

    def __repr__(self):
        return "Solver(%r)" % self._algorithm


del UnsupportedError
