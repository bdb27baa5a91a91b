// SPDX-License-Identifier: GPL-2.0-or-later
// Removal of a measured surface's form before it is solved: its mean, its tilt (a plane) or
// its curvature (a quadratic surface), fitted by least squares over the pixels. A tilt left on
// a periodic substrate becomes a ridge where the surface wraps around, and changes the contact
// without a warning (seen: a 3 % tilt took a contact of 4.8 % to 2.5 %).
#pragma once

#include "core/grid.hpp"

namespace asp {

enum class Detrend {
  mean,       // h - mean h
  plane,      // h less its best fit a + b x + c y (in 1D a + b x)
  curvature,  // h less its best fit by a polynomial of degree 2 in x and y (in 1D in x)
};

// Subtracts the fit from the grid's n_pixels() heights (x fastest). Refuses heights that are
// not finite, or whose result would not be (Error(invalid_argument) naming 'heights'), leaving
// them as they were. On a grid too small to determine a term (a quadratic along an axis of two
// pixels, say) that term is left out of the fit.
void detrend_topography(const Grid &grid, Detrend mode, double *heights);

}  // namespace asp
