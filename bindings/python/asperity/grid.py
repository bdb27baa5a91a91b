# SPDX-License-Identifier: GPL-2.0-or-later
"""The Grid: a 1D or 2D periodic discretisation (asp_grid)."""
import ctypes

from . import _constants as _c
from . import _names
from ._handles import OwnedHandle
from ._library import lib, check
from .errors import InvalidArgumentError

__all__ = ["Grid", "set_fft_planning"]


class Grid(OwnedHandle):
    """A periodic grid: ``Grid(nx, lx)`` in 1D, ``Grid(nx, ny, lx, ly)`` in 2D, and
    ``Grid.mpi(comm, nx, ny, lx, ly)`` shared among the processes of an mpi4py communicator.

    nx (and ny) pixels on a length lx (a box lx x ly); pixel i sits at x_i = i*lx/nx. A 1 x N
    strip is a valid 2D grid. ``fft_planning`` ("measure", the default, or "estimate") is
    passed to :meth:`set_fft_planning` right after creation.

    Fields on the grid are NumPy arrays of shape ``(ny, nx)`` in C order (``a[y, x]``) or
    ``(nx, ny)`` in Fortran order, ``(nx,)`` in 1D; see :attr:`shape`. The grid owns its
    handle; :meth:`close` (or leaving a ``with`` block) gives it up, and systems made on the
    grid keep it alive as long as they need it.
    """

    def __init__(self, *args, fft_planning=None):
        handle = ctypes.c_void_p()
        if len(args) == 2:
            nx, lx = args
            check(lib.asp_grid_create_1d(int(nx), float(lx), ctypes.byref(handle)),
                  "asp_grid_create_1d")
        elif len(args) == 4:
            nx, ny, lx, ly = args
            check(lib.asp_grid_create_2d(int(nx), int(ny), float(lx), float(ly),
                                         ctypes.byref(handle)), "asp_grid_create_2d")
        else:
            raise TypeError("Grid(nx, lx) or Grid(nx, ny, lx, ly), got %d arguments" % len(args))
        self._adopt(handle, fft_planning)

    def _adopt(self, handle, fft_planning):
        """Takes the new handle and reads the grid's shape, box and slab."""
        self._handle = handle.value
        dimension, nx, ny, n = ctypes.c_int(), ctypes.c_int64(), ctypes.c_int64(), ctypes.c_int64()
        check(lib.asp_grid_get_shape(self._handle, ctypes.byref(dimension), ctypes.byref(nx),
                                     ctypes.byref(ny), ctypes.byref(n)), "asp_grid_get_shape")
        lx, ly = ctypes.c_double(), ctypes.c_double()
        check(lib.asp_grid_get_box(self._handle, ctypes.byref(lx), ctypes.byref(ly)),
              "asp_grid_get_box")
        self._dimension, self._nx, self._ny, self._n = dimension.value, nx.value, ny.value, n.value
        self._lx, self._ly = lx.value, ly.value
        rows, offset, local = ctypes.c_int64(), ctypes.c_int64(), ctypes.c_int64()
        check(lib.asp_grid_get_slab(self._handle, ctypes.byref(rows), ctypes.byref(offset),
                                    ctypes.byref(local)), "asp_grid_get_slab")
        self._local_ny, self._row_offset, self._local_n = rows.value, offset.value, local.value
        if fft_planning is not None:
            self.set_fft_planning(fft_planning)

    @classmethod
    def mpi(cls, comm, nx, ny, lx, ly, fft_planning=None):
        """A 2D grid of nx x ny pixels on lx x ly shared among the processes of ``comm``.

        ``comm`` is an mpi4py communicator (``mpi4py.MPI.COMM_WORLD``, ...); its Fortran handle
        (``comm.py2f()``) goes to asp_grid_create_mpi_f, so this package never imports mpi4py
        itself. Collective, as is every later call on the grid and on the systems and solvers
        made on it: every process makes the same calls in the same order, with the same
        scalars. Each process holds a slab of whole rows, :attr:`slab`; every array passed for
        the grid or returned for it has shape ``(local_ny, nx)`` (:attr:`shape`), while sizes
        and scalar results (means, forces, statistics, reports) are the whole grid's, the same
        on every process. A call that fails on one process raises the same error on all.

        Raises UnsupportedError when libasperity was built without MPI.
        """
        try:
            handle_f = comm.py2f()
        except AttributeError:
            raise InvalidArgumentError(
                _c.ASP_ERR_INVALID_ARGUMENT,
                "comm: expected an mpi4py communicator (with py2f()), got %s"
                % type(comm).__name__, "Grid.mpi") from None
        handle = ctypes.c_void_p()
        check(lib.asp_grid_create_mpi_f(int(handle_f), int(nx), int(ny), float(lx), float(ly),
                                        ctypes.byref(handle)), "asp_grid_create_mpi_f")
        grid = cls.__new__(cls)
        grid._distributed = True
        grid._adopt(handle, fft_planning)
        return grid

    @classmethod
    def one_d(cls, nx, lx, **kwargs):
        """A 1D grid of nx pixels on a length lx (the same as ``Grid(nx, lx)``)."""
        return cls(nx, lx, **kwargs)

    @classmethod
    def two_d(cls, nx, ny, lx, ly, **kwargs):
        """A 2D grid of nx x ny pixels on lx x ly (the same as ``Grid(nx, ny, lx, ly)``)."""
        return cls(nx, ny, lx, ly, **kwargs)

    _destroy = lib.asp_grid_destroy
    _what = "grid"
    _distributed = False

    # -- shape (read once at creation: a grid is immutable) --------------------------------
    @property
    def dimension(self):
        """1 or 2."""
        return self._dimension

    @property
    def nx(self):
        """Pixels along x."""
        return self._nx

    @property
    def ny(self):
        """Pixels along y (1 in 1D)."""
        return self._ny

    @property
    def n_pixels(self):
        """nx*ny."""
        return self._n

    @property
    def lx(self):
        """Box length along x."""
        return self._lx

    @property
    def ly(self):
        """Box length along y (1 in 1D, so that lx*ly/(nx*ny) is the pixel size)."""
        return self._ly

    @property
    def shape(self):
        """The shape of the field arrays the package takes and returns: (ny, nx), or (nx,) in
        1D; (local_ny, nx) on a grid distributed over MPI (see :attr:`slab`)."""
        return (self._nx,) if self._dimension == 1 else (self._local_ny, self._nx)

    @property
    def local_ny(self):
        """This process's rows: ny unless the grid is distributed over MPI."""
        return self._local_ny

    @property
    def local_pixels(self):
        """The values in every array passed for the grid: nx*local_ny (n_pixels unless the
        grid is distributed over MPI)."""
        return self._local_n

    @property
    def box(self):
        """(lx, ly)."""
        return (self._lx, self._ly)

    def coordinates(self):
        """The pixel positions: x of shape (nx,) in 1D; (x, y) of the field shape in 2D (this
        process's rows on a distributed grid)."""
        import numpy as np
        x = np.arange(self._nx) * (self._lx / self._nx)
        if self._dimension == 1:
            return x
        y = np.arange(self._row_offset, self._row_offset + self._local_ny) * (self._ly / self._ny)
        xx, yy = np.meshgrid(x, y)  # (ny, nx)
        return xx, yy

    def set_fft_planning(self, planning):
        """How hard FFTW looks for fast plans: "measure" (default) or "estimate".

        Call it right after creating the grid: once plans exist the library raises
        InvalidStateError (asp_grid_set_fft_planning).
        """
        check(lib.asp_grid_set_fft_planning(
            self.handle, _names.resolve(_names.FFT_PLANNING, planning, "planning")),
            "asp_grid_set_fft_planning")

    @property
    def threads(self):
        """The threads of the grid's FFTs and of the solves on it (asp_grid_get_threads).

        Set it right after creating the grid, before any solve (asp_grid_set_threads: a
        count >= 1; once the FFT plans exist the library raises InvalidStateError). The
        default is OMP_NUM_THREADS if set, else the number of processors.
        """
        value = ctypes.c_int(0)
        check(lib.asp_grid_get_threads(self.handle, ctypes.byref(value)), "asp_grid_get_threads")
        return value.value

    @threads.setter
    def threads(self, count):
        check(lib.asp_grid_set_threads(self.handle, int(count)), "asp_grid_set_threads")

    @property
    def slab(self):
        """This process's rows of the grid, ``(local_ny, row_offset)`` (asp_grid_get_slab).

        Every array passed for the grid, or returned for it, holds these rows, shape
        ``(local_ny, nx)``. The whole grid, ``(ny, 0)``, unless it is distributed over MPI
        (:meth:`mpi`); a process may hold no rows (local_ny 0) when there are fewer rows than
        processes.
        """
        self.handle  # noqa: B018 - a closed grid raises, as when this asked the library
        return self._local_ny, self._row_offset

    def __repr__(self):
        if self._distributed:
            return "Grid.mpi(<comm>, %d, %d, %r, %r)" % (self._nx, self._ny, self._lx, self._ly)
        if self._dimension == 1:
            return "Grid(%d, %r)" % (self._nx, self._lx)
        return "Grid(%d, %d, %r, %r)" % (self._nx, self._ny, self._lx, self._ly)


def set_fft_planning(grid, planning):
    """The same as ``grid.set_fft_planning(planning)``."""
    grid.set_fft_planning(planning)
