// SPDX-License-Identifier: GPL-2.0-or-later
// Bugnicourt, Sainsot, Dureisseix, Gauthier & Lubrecht's constrained conjugate gradient
// (Tribology Letters 66:29, 2018, their OUT-LIN algorithm; thesis section 3.1.2, Alg. 4) for a
// bound-constrained objective with an optional mean-value constraint. It needs only the
// generic Formulation: here it runs on the dual (pressure) formulation of the non-adhesive
// hard wall, and on the primal (gap) formulation of the hard wall with or without
// exponential adhesion (whose objective is not quadratic).
#pragma once

#include "solvers/algorithm.hpp"

namespace asp {

AlgorithmSpec bugnicourt_algorithm();

}  // namespace asp
