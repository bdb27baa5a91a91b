// SPDX-License-Identifier: GPL-2.0-or-later
// Statistics of a topography (thesis eqs. 52-54, after Jacobs et al. 2017), computed from the
// spectrum so that they are exact for the band-limited surface the FFT represents.
#pragma once

#include <cstdint>

#include "core/grid.hpp"

namespace asp {

struct SurfaceStatistics {
  double rms_height = 0.0;     // sqrt(<(h - <h>)^2>)
  double rms_slope = 0.0;      // sqrt(<|grad h|^2>)
  double rms_curvature = 0.0;  // 2D: sqrt(<(laplacian h)^2>/4); 1D: sqrt(<h''^2>)
};

// Any finite heights, at any address. A statistic whose value overflows a double is +inf
// (never NaN); rms_height never overflows.
SurfaceStatistics surface_statistics(const Grid &grid, const double *heights);

// The rms slope sqrt(<|grad h|^2>) from the differences between neighbouring pixels inside
// the box, without the pair across its edges: the slope of a surface that is not periodic
// (under a free substrate), whose spectral slope would count the step between its opposite
// edges. Any finite heights with a finite range; +inf if the slope overflows a double.
double rms_slope_within_box(const Grid &grid, const double *heights);

// The statistics whose pointers are not null, written only if all of them are finite;
// otherwise throws Error(invalid_argument) naming 'heights' and the statistic, and writes
// nothing. What asp_topography_statistics does.
void surface_statistics(const Grid &grid, const double *heights, double *rms_height,
                        double *rms_slope, double *rms_curvature);

// Radially averaged power spectrum into q and c, n_bins doubles each; see
// asp_topography_power_spectrum in the public header. Throws Error(invalid_argument) naming
// 'n_bins' unless 1 <= n_bins <= grid.n_pixels(), or naming 'heights' if a C(q) overflows a
// double; q and c are written only on success.
void radial_power_spectrum(const Grid &grid, const double *heights, std::int64_t n_bins,
                           double *q, double *c);

}  // namespace asp
