// SPDX-License-Identifier: GPL-2.0-or-later
// Limited-memory BFGS (Nocedal, Math. Comp. 35, 1980; Nocedal & Wright, Numerical Optimization,
// Algorithms 7.4 and 7.5; thesis section 3.1.6 without the bounds) for an unconstrained
// objective: the two-loop recursion turns the gradient into a quasi-Newton direction from the
// last `memory` step and gradient-change pairs, with the initial matrix scaled by
// s.y/y.y of the newest pair, and a line search for the strong Wolfe conditions (More &
// Thuente) chooses the step, the unit step first. It runs on any formulation without bounds:
// the displacement (`lbfgs`) or the preconditioned Fourier variable (`lbfgs_fourier`).
#pragma once

#include "formulations/formulation.hpp"
#include "solvers/monitor.hpp"

namespace asp {

// Leaves the last iterate in f.variable().
void lbfgs(Formulation &f, Monitor &monitor, int memory);

}  // namespace asp
