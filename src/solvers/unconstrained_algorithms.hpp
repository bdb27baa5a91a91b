// SPDX-License-Identifier: GPL-2.0-or-later
// The registry's entries for the unconstrained solvers of soft potentials: each pairs an
// algorithm with a formulation.
//   lbfgs              L-BFGS on the displacement
//   lbfgs_fourier      L-BFGS on the preconditioned Fourier variable (thesis section 4.2)
//   fire               FIRE on the displacement (equal masses)
//   fire_mass_weighted FIRE on the Fourier variable (masses proportional to K~(q))
//   gfmd               damped dynamics on the Fourier variable (mass-weighted GFMD)
#pragma once

#include "solvers/algorithm.hpp"

namespace asp {

AlgorithmSpec lbfgs_algorithm();
AlgorithmSpec lbfgs_fourier_algorithm();
AlgorithmSpec fire_algorithm();
AlgorithmSpec fire_mass_weighted_algorithm();
AlgorithmSpec gfmd_algorithm();

}  // namespace asp
