// SPDX-License-Identifier: GPL-2.0-or-later
// L-BFGS-B of Byrd, Lu, Nocedal & Zhu (SIAM J. Sci. Comput. 16, 1995; thesis section 3.1.6)
// for an objective over x >= lower bound: a limited-memory BFGS model in compact form, the
// generalized Cauchy point along the projected steepest-descent path, minimisation of the
// model over the variables the Cauchy point left free (the direct primal method, with Morales
// & Nocedal's projection, ACM TOMS 38, 2011), and a line search for the strong Wolfe
// conditions. Without a bound (lower bound -infinity) it is plain L-BFGS. It needs only the
// generic Formulation: here it runs on the primal (gap) or dual (pressure) formulation of the
// hard wall under penetration control.
#pragma once

#include "formulations/formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/algorithm.hpp"
#include "solvers/cauchy_point.hpp"

namespace asp {

AlgorithmSpec lbfgsb_algorithm();

// The algorithm on any formulation without a mean-value constraint whose error is the
// bound's residual (Formulation::error's contract), keeping at most `memory` pairs; leaves
// its last iterate in f.variable() (open for tests on small problems). After iteration 0 it
// gathers that residual in its own pass rather than calling f.error.
void lbfgsb(Formulation &f, Monitor &monitor, int memory);

}  // namespace asp
