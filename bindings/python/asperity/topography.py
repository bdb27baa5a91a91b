# SPDX-License-Identifier: GPL-2.0-or-later
"""Topography generators and tools (asp_topography_*).

Generators return a new array of the grid's field shape, ``(ny, nx)`` in C order (``(nx,)``
in 1D), so that ``h[y, x]`` is the height at x_i, y_j. Functions that read heights accept the
layouts of the package's rules (see ``asperity._arrays``): ``(ny, nx)`` C order or
``(nx, ny)`` Fortran order, float64, without a copy. On a grid distributed over MPI
(``Grid.mpi``), ny is the process's rows, ``grid.local_ny``: each process generates and passes
its own rows, and statistics and spectra are those of the whole surface.
"""
import collections
import ctypes
import os

import numpy as np

from . import _names
from ._arrays import copy_field, empty_field, field_pointer
from ._library import lib, check

__all__ = ["flat", "sphere", "paraboloid", "sinusoid", "double_sinewave", "self_affine",
           "statistics", "Statistics", "detrend", "power_spectrum", "export_wisdom",
           "import_wisdom"]


def _generate(function, grid, *args):
    heights = empty_field(grid)
    check(getattr(lib, function)(grid.handle, *args, heights.ctypes.data, grid.local_pixels),
          function)
    return heights


def flat(grid):
    """h = 0 everywhere (asp_topography_flat)."""
    return _generate("asp_topography_flat", grid)


def sphere(grid, radius):
    """A sphere of the radius centred on the box, apex at h = 0; a cylinder in 1D."""
    return _generate("asp_topography_sphere", grid, float(radius))


def paraboloid(grid, radius):
    """The paraboloid h = -r^2/(2R) centred on the box (Hertz's surface)."""
    return _generate("asp_topography_paraboloid", grid, float(radius))


def sinusoid(grid, amplitude, periods_x=1, periods_y=0):
    """h = amplitude cos(2 pi periods_x x/lx) cos(2 pi periods_y y/ly); periods_y = 0: along x."""
    return _generate("asp_topography_sinusoid", grid, float(amplitude), int(periods_x),
                     int(periods_y))


def double_sinewave(grid, amplitude=1.0, ripple_amplitude=0.05, ripple_periods=32):
    """amplitude cos(2 pi x/lx) + ripple_amplitude cos(2 pi ripple_periods x/lx)."""
    return _generate("asp_topography_double_sinewave", grid, float(amplitude),
                     float(ripple_amplitude), int(ripple_periods))


def self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff, normalise="rms_height",
                target=1.0, seed=0):
    """A self-affine Gaussian random surface (asp_topography_self_affine).

    Wavelengths short_cutoff < rolloff <= long_cutoff; ``normalise`` is "rms_height" or
    "rms_slope" (or the ASP_RMS_* constant) and ``target`` its value. The same seed and grid
    give the same surface on every platform.
    """
    return _generate("asp_topography_self_affine", grid, float(hurst), float(long_cutoff),
                     float(rolloff), float(short_cutoff),
                     _names.resolve(_names.NORMALISATION, normalise, "normalise"),
                     float(target), int(seed))


Statistics = collections.namedtuple("Statistics", "rms_height rms_slope rms_curvature")
Statistics.__doc__ = "rms height, slope and curvature of a topography (None if not asked)."


def statistics(grid, heights, rms_height=True, rms_slope=True, rms_curvature=True):
    """The rms height, slope and curvature of heights, computed spectrally.

    Returns a :class:`Statistics` named tuple; a quantity not asked for (False) is None and
    can never cause a refusal (a slope or curvature beyond the largest double is refused).
    """
    pointer = field_pointer(heights, grid, "heights")
    values = [ctypes.c_double() for _ in range(3)]
    wanted = (rms_height, rms_slope, rms_curvature)
    args = [ctypes.byref(v) if w else None for v, w in zip(values, wanted)]
    check(lib.asp_topography_statistics(grid.handle, pointer, grid.local_pixels, *args),
          "asp_topography_statistics")
    return Statistics(*(v.value if w else None for v, w in zip(values, wanted)))


def detrend(grid, heights, mode="plane", inplace=False):
    """Removes the mean ("mean"), tilt ("plane") or curvature ("curvature") of heights.

    Returns a detrended copy of shape (ny, nx), or with ``inplace=True`` detrends the array
    itself (which must then be writeable) and returns it.
    """
    code = _names.resolve(_names.DETREND, mode, "mode")
    if not inplace:
        field_pointer(heights, grid, "heights")
        heights = copy_field(heights, grid)
    pointer = field_pointer(heights, grid, "heights", writeable=True)
    check(lib.asp_topography_detrend(grid.handle, code, pointer, grid.local_pixels),
          "asp_topography_detrend")
    return heights


def power_spectrum(grid, heights, n_bins):
    """The radially averaged power spectrum: arrays (q, c) of n_bins values each."""
    pointer = field_pointer(heights, grid, "heights")
    n_bins = int(n_bins)
    q = np.zeros(max(n_bins, 0))
    c = np.zeros(max(n_bins, 0))
    check(lib.asp_topography_power_spectrum(grid.handle, pointer, grid.local_pixels, n_bins,
                                            q.ctypes.data, c.ctypes.data),
          "asp_topography_power_spectrum")
    return q, c


def export_wisdom(path):
    """Saves FFTW's planning knowledge of this process to a file (asp_fft_export_wisdom)."""
    check(lib.asp_fft_export_wisdom(os.fsencode(path)), "asp_fft_export_wisdom")


def import_wisdom(path):
    """Adds FFTW planning knowledge from a file (asp_fft_import_wisdom)."""
    check(lib.asp_fft_import_wisdom(os.fsencode(path)), "asp_fft_import_wisdom")

