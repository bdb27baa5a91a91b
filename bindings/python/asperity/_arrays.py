# SPDX-License-Identifier: GPL-2.0-or-later
"""Fields in and out: the layout rules between NumPy arrays and the library's x-fastest arrays.

The library stores a field of a 2D grid x fastest, ``f[i + nx*j]``. Two NumPy forms have
exactly that memory, and both are accepted without a copy (the pointer is passed):

* shape ``(ny, nx)`` in C order (one scan line of nx values per row: ``a[y, x]``);
* shape ``(nx, ny)`` in Fortran order (``a[x, y]``).

Precisely: the array must be a ``numpy.ndarray`` of dtype float64 (native byte order) whose
axis along x has a stride of 8 bytes and whose axis along y a stride of ``8*nx`` bytes, where
the axis along x is the last one for shape (ny, nx) and the first one for shape (nx, ny). For
a square grid both shapes are (n, n); the strides then decide. A stride along an axis of
length 1 is not looked at. Everything else is refused, with the argument's name, the shape,
strides and dtype received and what was expected: other dtypes (float32, ...), (nx, ny) in C
order or (ny, nx) in Fortran order when nx != ny (their memory is y fastest), strided views
(``a[:, ::2]``), a flattened array of nx*ny values, other shapes. On a 1D grid the shape is
``(nx,)`` with a stride of 8 bytes.

On a grid distributed over MPI (``Grid.mpi``) each process passes and receives its own rows
only: ny above is then the process's row count, ``grid.local_ny`` (``Grid.slab``), for inputs
and outputs alike.

Alignment: the header says caller arrays need no alignment (the library copies them before
any transform), so misaligned arrays are passed as they are. Read-only arrays are accepted
wherever the library only reads; an array the library writes into must be writeable.

Outputs made by the package are new arrays of shape ``(ny, nx)`` in C order, so that
``out[y, x]`` is the pixel at x_i, y_j (shape ``(nx,)`` in 1D).
"""
import numpy as np

from . import _constants as _c
from .errors import InvalidArgumentError, SizeMismatchError

_F8 = np.dtype(np.float64)


def field_shape(grid):
    """The shape of the arrays the package returns for a field on ``grid`` (this process's
    rows, (local_ny, nx), on a grid distributed over MPI)."""
    return grid.shape


def empty_field(grid):
    """A new C-order float64 array of the grid's output shape."""
    return np.empty(field_shape(grid), dtype=_F8)


def copy_field(array, grid):
    """A new C-order copy, of the field shape, of a field already checked by field_pointer."""
    return np.array(np.ravel(array, order="K").reshape(field_shape(grid)), dtype=_F8)


def _describe(array):
    return "shape %s, strides %s, dtype %s, %s order" % (
        array.shape, array.strides, array.dtype,
        "C" if array.flags.c_contiguous else ("Fortran" if array.flags.f_contiguous
                                              else "non-contiguous"))


def _expected(grid):
    if grid.dimension == 1:
        return "a float64 array of shape (nx,) = (%d,) with stride 8" % grid.nx
    rows = "ny" if grid.local_ny == grid.ny else "local_ny"
    return ("a float64 array of shape (%s, nx) = (%d, %d) in C order or (nx, %s) = (%d, %d) in "
            "Fortran order (x fastest, contiguous)"
            % (rows, grid.local_ny, grid.nx, rows, grid.nx, grid.local_ny))


def _layout_ok(array, grid):
    item = _F8.itemsize
    if grid.dimension == 1:
        return array.ndim == 1 and array.shape[0] == grid.nx and (
            grid.nx == 1 or array.strides[0] == item)
    if array.ndim != 2:
        return False
    nx, ny = grid.nx, grid.local_ny
    for x_axis, y_axis in ((1, 0), (0, 1)):  # (ny, nx) C order, then (nx, ny) Fortran order
        if array.shape[x_axis] != nx or array.shape[y_axis] != ny:
            continue
        if (nx == 1 or array.strides[x_axis] == item) and (
                ny == 1 or array.strides[y_axis] == item * nx):
            return True
    return False


def _shape_ok(array, grid):
    if grid.dimension == 1:
        return array.shape == (grid.nx,)
    return array.shape in ((grid.local_ny, grid.nx), (grid.nx, grid.local_ny))


def field_pointer(array, grid, argument, writeable=False):
    """The address of ``array`` as a field on ``grid``, after checking the layout rules."""
    if not isinstance(array, np.ndarray):
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: expected %s, got %s (convert with numpy.ascontiguousarray(x, dtype=float))"
            % (argument, _expected(grid), type(array).__name__), "asperity (Python)")
    if array.dtype != _F8:
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: dtype %s refused (%s); expected %s" % (argument, array.dtype,
                                                       _describe(array), _expected(grid)),
            "asperity (Python)")
    if not _shape_ok(array, grid):
        raise SizeMismatchError(
            _c.ASP_ERR_SIZE_MISMATCH,
            "%s: %s does not fit the grid of %d x %d pixels%s; expected %s" % (
                argument, _describe(array), grid.nx, grid.ny,
                "" if grid.local_ny == grid.ny else " (this process: %d rows)" % grid.local_ny,
                _expected(grid)),
            "asperity (Python)")
    if not _layout_ok(array, grid):
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: %s is not laid out x fastest and contiguous; expected %s" % (
                argument, _describe(array), _expected(grid)), "asperity (Python)")
    if writeable and not array.flags.writeable:
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: the array is read-only, but the call writes into it" % argument,
            "asperity (Python)")
    return array.ctypes.data


def vector_pointer(array, n, argument, writeable=False):
    """The address of a contiguous float64 vector of n values (power spectra, history)."""
    if not isinstance(array, np.ndarray) or array.dtype != _F8 or array.shape != (n,) or (
            n > 1 and array.strides[0] != _F8.itemsize):
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: expected a contiguous float64 array of shape (%d,)" % (argument, n),
            "asperity (Python)")
    if writeable and not array.flags.writeable:
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT, "%s: the array is read-only" % argument,
            "asperity (Python)")
    return array.ctypes.data
