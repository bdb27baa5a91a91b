# SPDX-License-Identifier: GPL-2.0-or-later
"""The exceptions raised by asperity.

Every non-OK status of the C library is raised as an instance of :class:`Error` (or of the
subclass for its status), carrying the status code in ``.status``, the library's detail
message (``asp_last_error_message()``) in ``.message`` and the C function that failed in
``.function``. The subclasses also derive from the built-in exception that fits, so that
``except ValueError`` or ``except MemoryError`` catch them too:

====================  ==========================  ==========================
status                class                       also a
====================  ==========================  ==========================
ASP_ERR_NULL_POINTER  NullPointerError            TypeError
ASP_ERR_INVALID_...   InvalidArgumentError        ValueError
ASP_ERR_SIZE_MISMATCH SizeMismatchError           ValueError
ASP_ERR_OUT_OF_MEMORY OutOfMemoryError            MemoryError
ASP_ERR_UNSUPPORTED   UnsupportedError            NotImplementedError
ASP_ERR_INVALID_STATE InvalidStateError           RuntimeError
ASP_ERR_FFT           FFTError                    RuntimeError
ASP_ERR_CALLBACK      CallbackError               --
ASP_ERR_INTERNAL      InternalError               RuntimeError
ASP_ERR_IO            FileError                   OSError
====================  ==========================  ==========================

A status the package does not know (a newer library) is raised as :class:`Error` itself.
Refusals made by the Python layer before calling the library (an array of the wrong shape,
dtype or layout; an unknown name for a constant) use the same classes with the status the
library would have given and ``function`` naming the Python call.
"""
from . import _constants as _c

__all__ = [
    "Error", "NullPointerError", "InvalidArgumentError", "SizeMismatchError",
    "OutOfMemoryError", "UnsupportedError", "InvalidStateError", "FFTError", "CallbackError",
    "InternalError", "FileError", "ERROR_CLASSES", "error_for_status",
]


class Error(Exception):
    """Base class of every error of asperity.

    Attributes:
        status: the library's status code (an ``ASP_ERR_*`` value).
        message: the library's detail of the failure (function, argument, value, reason).
        function: the C function (or Python call) that failed.
    """

    def __init__(self, status, message, function=None):
        self.status = int(status)
        self.message = str(message)
        self.function = function
        super().__init__(self.message)

    def __str__(self):
        return self.message

    def __reduce__(self):
        return (type(self), (self.status, self.message, self.function))


class NullPointerError(Error, TypeError):
    """ASP_ERR_NULL_POINTER: a required handle or pointer was missing (e.g. a closed object)."""


class InvalidArgumentError(Error, ValueError):
    """ASP_ERR_INVALID_ARGUMENT: a value out of its domain (also a ValueError)."""


class SizeMismatchError(Error, ValueError):
    """ASP_ERR_SIZE_MISMATCH: an array's size or shape does not fit the grid (a ValueError)."""


class OutOfMemoryError(Error, MemoryError):
    """ASP_ERR_OUT_OF_MEMORY: the library could not allocate its arrays (a MemoryError)."""


class UnsupportedError(Error, NotImplementedError):
    """ASP_ERR_UNSUPPORTED: a valid request the algorithm or build does not provide."""


class InvalidStateError(Error, RuntimeError):
    """ASP_ERR_INVALID_STATE: a call out of order, e.g. a report before any solve."""


class FFTError(Error, RuntimeError):
    """ASP_ERR_FFT: FFTW could not make a plan."""


class CallbackError(Error):
    """ASP_ERR_CALLBACK: a user callback failed.

    When the callback was a Python function that raised, that exception is chained as
    ``__cause__`` (and kept in ``.exception``).
    """

    exception = None


class InternalError(Error, RuntimeError):
    """ASP_ERR_INTERNAL: a bug in asperity; please report it with the message."""


class FileError(Error, OSError):
    """ASP_ERR_IO: a file could not be read or written (an OSError)."""

    def __init__(self, status, message, function=None):
        Error.__init__(self, status, message, function)


# Status code -> class, for every ASP_ERR_* constant of the header that has a class.
ERROR_CLASSES = {
    _c.ASP_ERR_NULL_POINTER: NullPointerError,
    _c.ASP_ERR_INVALID_ARGUMENT: InvalidArgumentError,
    _c.ASP_ERR_SIZE_MISMATCH: SizeMismatchError,
    _c.ASP_ERR_OUT_OF_MEMORY: OutOfMemoryError,
    _c.ASP_ERR_UNSUPPORTED: UnsupportedError,
    _c.ASP_ERR_INVALID_STATE: InvalidStateError,
    _c.ASP_ERR_FFT: FFTError,
    _c.ASP_ERR_CALLBACK: CallbackError,
    _c.ASP_ERR_INTERNAL: InternalError,
    _c.ASP_ERR_IO: FileError,
}


def error_for_status(status, message, function=None):
    """The exception instance for a status code (Error itself for an unknown code)."""
    return ERROR_CLASSES.get(int(status), Error)(status, message, function)
