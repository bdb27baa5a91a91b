// SPDX-License-Identifier: GPL-2.0-or-later
// Polonsky & Keer's constrained conjugate gradient (Wear 231, 1999; thesis section 3.1.1,
// Alg. 3) for the non-adhesive hard-wall contact, on the pressure (the dual formulation).
#pragma once

#include "solvers/algorithm.hpp"

namespace asp {

AlgorithmSpec polonsky_keer_algorithm();

}  // namespace asp
