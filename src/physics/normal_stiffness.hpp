// SPDX-License-Identifier: GPL-2.0-or-later
// The normal contact stiffness of a solved state: the derivative dp/d(delta) of the mean
// pressure with respect to the penetration, at the system's current state, as the linearised
// equilibrium about that state gives it. It is the consistent tangent that a Newton iteration
// of a finite-element code needs, and, by Barber's analogy, the contact conductance
// (docs/guide.md).
//
// Two linear problems, each solved by conjugate gradients, one application of the elastic
// operator (a forward and a backward transform) per step:
//  - the plain hard wall: the contact set C is held (the pixels on the wall, g <= 0, and those
//    that carry pressure): a unit increase of delta moves the surface by 1 on C, and the
//    pressure increment vanishes off C. In the pressure increment dp on C:
//        (K^-1 dp)_i = 1 on C,  dp = 0 off C,
//    K^-1 restricted to C being symmetric positive definite (the compliance; on a periodic
//    substrate with the system's K~(0), on a free one the padded convolution). No potential
//    is evaluated.
//  - every interaction with a potential (hard wall with adhesion, soft walls, a user's
//    potential with or without the wall): the energy's Hessian K + phi''(g) in the
//    displacement increment du, du = 1 held on C (hard walls only; C = the pixels on the
//    wall, g <= 0), and on the other points of the surface
//        (K du)_i + phi''(g_i) (du_i - 1) = 0,
//    (outside the box of a free substrate phi'' = 0: the padded surface is unloaded there),
//    then dp = K du on the box. Jacobi-preconditioned (the diagonal of K plus phi''). The
//    restricted Hessian must be positive definite, which a stable equilibrium's is; conjugate
//    gradients meeting a direction of non-positive curvature (or a non-positive diagonal)
//    refuse the state as unstable with Error(invalid_state).
// Either way dp/d(delta) = the mean of dp over the grid's pixels.
#pragma once

#include <cstdint>

#include "physics/system.hpp"

namespace asp {

struct NormalStiffness {
  double value = 0.0;            // d(mean pressure)/d(penetration): pressure per length
  std::int64_t iterations = 0;   // conjugate-gradient steps
  std::int64_t transforms = 0;   // forward or backward FFTs
};

// The stiffness of the system's current state, which should be an equilibrium (the caller
// says whether it is: asp_solver_normal_stiffness checks that the solver's last solve on the
// system converged). Relative accuracy about 1e-10 (the conjugate gradients stop at a residual
// of 1e-12 relative to the right-hand side). Throws Error(invalid_state) naming the reason
// when the linearised problem is not positive definite (an unstable state) or its conjugate
// gradients do not converge, Error(callback) when a user's potential fails. Collective on a
// distributed grid.
NormalStiffness normal_stiffness(const System &system);

}  // namespace asp
