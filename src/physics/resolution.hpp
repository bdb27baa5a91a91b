// SPDX-License-Identifier: GPL-2.0-or-later
// Whether a system's grid resolves its interaction: the length over which an adhesive
// interaction acts at the edge of a contact, its cohesive zone, against the pixel size.
//
// A contact edge under adhesion is a crack tip with a cohesive zone (Dugdale 1960, Barenblatt
// 1962). With a work of adhesion w (the depth of the potential's well) and a largest tensile
// stress s, the zone's length in the Dugdale model is
//     l = (pi/4) E* w / s^2,
// from the zone's stress intensity K = s sqrt(8 l/pi) and the energy release rate
// G = K^2/(2 E*) at the edge of a contact (Maugis, J. Colloid Interface Sci. 150, 243 (1992);
// Maugis, Contact, Adhesion and Rupture of Elastic Solids, 2000), at G = w. For the
// exponential adhesion phi = -w exp(-g/rho), s = w/rho and l = (pi/4) E* rho^2/w.
// The same number compares the potential's largest curvature, w/rho^2, with the stiffness of
// one pixel, of order E*/dx (about 0.89 E*/dx for a square pixel of a free half-space): below
// about one pixel, a single pixel can rest both on and off the wall, and the discrete problem
// has many metastable states, the lattice trapping of a crack (Thomson, Hsieh and Rana,
// J. Appl. Phys. 42, 3154 (1971)). No solver can then be expected to converge cleanly.
#pragma once

#include <string>

namespace asp {

class System;

struct Resolution {
  // The cohesive zone l over the smaller pixel size (lx/nx, ly/ny; lx/nx in 1D), finite:
  // 0 when the interaction has no such length (the plain hard wall, a soft wall without an
  // adhesive well) or when none is known (a user's potential); clamped to the positive
  // doubles otherwise.
  double ratio = 0.0;
  // ratio >= threshold, or nothing to resolve. False also when the length is not known.
  bool resolved = true;
  // One sentence for a person: what was compared, the numbers, and what to do.
  std::string sentence;
};

// The cohesive zone, in pixels, below which the grid is said not to resolve the interaction.
constexpr double resolution_threshold = 1.0;
// The cohesive zone, in pixels, at or below which the grid is far from resolving it: the
// adhesive curvature at the wall is then several pixel stiffnesses, and the contact lines
// settle a pixel at a time. Two treatments act only there, where they were measured to help:
// the continuation in the range's "auto" (solvers/range_continuation.hpp) and the eager
// jumps of bugnicourt's pixels near the wall (PrimalFormulation::snaps_eagerly).
constexpr double far_from_resolved = 0.5;

// The resolution of the system's interaction on its grid. Reads parameters only: no
// transform, no potential callback.
Resolution resolution(const System &system);

}  // namespace asp
