# SPDX-License-Identifier: GPL-2.0-or-later
"""Python callables behind the C callbacks: the potential of a System and a Solver's progress.

Each wrapper owns the ctypes function object that C calls (so it stays alive while set) and
records an exception the Python callable raised, because an exception cannot cross C: the
trampoline returns non-zero instead, and the caller re-raises after the C call returned.
"""
import ctypes

import numpy as np

from . import _constants as _c
from ._library import POTENTIAL_FN, PROGRESS_FN
from .errors import CallbackError


def _vector(address, n, writeable):
    """A NumPy view of n doubles at address, without a copy."""
    if n == 0 or not address:
        return np.zeros(0)
    array = np.ctypeslib.as_array((ctypes.c_double * n).from_address(address))
    if not writeable:
        array.flags.writeable = False
    return array


class _Failure:
    """The exception (with its traceback) a Python callback raised during a C call."""

    def __init__(self):
        self.exception = None

    def take(self):
        exception, self.exception = self.exception, None
        return exception

    def raise_from(self, error_message, function):
        """Raises CallbackError chained from the recorded exception (if any)."""
        exception = self.take()
        if isinstance(exception, (KeyboardInterrupt, SystemExit)):
            raise exception
        error = CallbackError(_c.ASP_ERR_CALLBACK, error_message if exception is None else
                              "%s (the Python callback raised %s: %s)" % (
                                  error_message, type(exception).__name__, exception),
                              function)
        error.exception = exception
        raise error from exception


class Potential:
    """fn(gap) -> (phi, dphi, d2phi or None) on NumPy arrays, as asp_potential_fn.

    gap is a read-only float64 array of all pixels' gaps (n values, in the system's units);
    fn returns phi(gap), phi'(gap) and phi''(gap) as arrays of n values (or scalars, which are
    broadcast). d2phi may be None (or fn may return two values) when the solver does not ask
    for it; when it does, a missing d2phi is an error.
    """

    def __init__(self, fn):
        if not callable(fn):
            raise TypeError("set_potential: fn must be callable, got %r" % (fn,))
        self.fn = fn
        self.failure = _Failure()
        failure = self.failure

        def trampoline(n, gap, phi, dphi, d2phi, _user_data):
            try:
                values = fn(_vector(gap, n, False))
                if not isinstance(values, tuple) or len(values) not in (2, 3):
                    raise TypeError("the potential must return (phi, dphi, d2phi or None), "
                                    "got %s" % type(values).__name__)
                _vector(phi, n, True)[:] = values[0]
                _vector(dphi, n, True)[:] = values[1]
                if d2phi:
                    if len(values) < 3 or values[2] is None:
                        raise ValueError("the solver needs phi'' but the potential returned "
                                         "None for it")
                    _vector(d2phi, n, True)[:] = values[2]
                return 0
            except BaseException as exc:  # noqa: B902 - nothing may cross the C frames
                failure.exception = exc
                return 1

        self.c_function = POTENTIAL_FN(trampoline)


class Progress:
    """fn(iteration, seconds, error) -> truthy to stop, as asp_progress_fn."""

    def __init__(self, fn):
        if not callable(fn):
            raise TypeError("progress: fn must be callable or None, got %r" % (fn,))
        self.fn = fn
        self.failure = _Failure()
        failure = self.failure

        def trampoline(iteration, seconds, error, _user_data):
            try:
                return 1 if fn(iteration, seconds, error) else 0
            except BaseException as exc:  # noqa: B902 - stops the solve cleanly
                failure.exception = exc
                return 1

        self.c_function = PROGRESS_FN(trampoline)
