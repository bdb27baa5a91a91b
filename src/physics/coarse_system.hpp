// SPDX-License-Identifier: GPL-2.0-or-later
// The physics of nested grids: a system restricted to a grid coarser by 2 per axis, and a
// coarse state prolonged to the finer system, so that a solve can start from the solution of
// a coarser problem (solvers/nested_grids.cpp).
//
// Restriction keeps the box, the substrate (its kind, contact modulus and K~(0)) and the
// interaction with its parameters, and truncates the spectrum of
// the heights to the coarse grid's: exact for a surface whose spectrum lies strictly below
// the coarse grid's Nyquist wavevector. The coarse grid's Nyquist modes (kx = nx/2 or
// ky = ny/2 of the coarse sizes) are dropped: on the coarse grid they alias the fine modes
// +q and -q into one.
// On a free substrate the heights need not be periodic; their truncation then rings near the
// box's edges (Gibbs), which moves the coarse problem but not the fine one, solved after it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "physics/system.hpp"

namespace asp {

// Why the grid cannot be coarsened by 2 per axis into one of at least `smallest` pixels a
// side (along x only on a 1D grid), or the empty text if it can.
std::string coarsening_obstacle(const Grid &grid, std::int64_t smallest);

// The fine system restricted to the coarse grid (see above), with the state reset. The
// coarse grid has the fine one's threads and FFT planning, and is distributed over the fine
// one's processes (collective then). Throws Error(unsupported) where
// coarsening_obstacle(fine.grid(), 2) is not empty.
std::unique_ptr<System> coarse_system(const System &fine);

// Sets the fine system's state from the coarse one's (which must come from
// coarse_system(fine)), consistent with the fine system's heights and interaction:
//   - the pressure by linear interpolation per axis (prolong_pressure), which keeps its sign,
//     its mean (on a periodic substrate) and, within a fine pixel, its support: spectral
//     zero-padding would ring around every contact patch, and half of that ringing, being
//     compressive, would put pixels far from any contact on the wall;
//   - the penetration keeps the rigid body where the coarse solve left it: it moves by the
//     difference of the highest heights, max h - max h_coarse;
//   - the gap is the one the pressure makes, g = K^-1 p - (h - max h) - penetration; with a
//     hard wall a pixel with compressive pressure is on the wall (g = 0) and every other gap
//     is max(g, 0).
// Every formulation's warm start reads a part of this state (the dual ones the pressure and
// the penetration, the primal ones the gap, the pressure's contact set and, under load
// control, the penetration), so the rule serves all of them. Costs one FFT pair.
void prolong_state(const System &coarse, System &fine);

// The coarse pressure on the fine grid (2 pixels per coarse one along each axis): a coarse
// pixel's value at the fine pixel it shares its corner with, the mean of the two or four
// neighbours at the others; beyond the last coarse pixel the first one (periodic) or the
// last one again (free: pressure does not wrap around the box). Collective on distributed
// grids, whose coarse rows under this process's fine rows other processes may hold.
void prolong_pressure(const Grid &coarse, const Grid &fine, bool periodic, const double *in,
                      double *out);

// A field of one grid on another of the same box and dimension, distributed over the same
// processes or both serial, by its spectrum: the modes both grids hold below the smaller
// one's Nyquist wavevector are kept, the others are zero. Restriction and prolongation in
// one. Collective on distributed grids.
void resample_field(const Grid &from, const Grid &to, const double *in, double *out);

}  // namespace asp
