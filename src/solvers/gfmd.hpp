// SPDX-License-Identifier: GPL-2.0-or-later
// Damped Green's function molecular dynamics (Campana & Muser, Phys. Rev. B 74, 2006;
// Prodanov, Dapp & Muser, Tribol. Lett. 53, 2014; thesis Alg. 5): Verlet integration of the
// equations of motion with a damping force proportional to the velocity,
//     x_new = 2 x - x_old + dt^2 (F(x) - damping (x - x_old)/dt),
// run on the preconditioned Fourier variable, where every elastic mode has unit mass-weighted
// frequency: the masses are proportional to K~(q) (mass-weighted GFMD), and one damping
// coefficient, 2 by default, damps every elastic mode critically.
//
// The time step is, by default, 1/sqrt of the formulation's bound on the largest curvature at
// the iterate (at most 1, the elastic modes' step; taken again every 10 steps and at every
// restart): the stability rule of a fixed-step run, taken where the dynamics are rather than
// at the start, whose curvature a start deep inside a stiff wall makes orders of magnitude
// larger. A step that raises the energy is undone and
// the motion restarts from rest (FIRE's downhill check); a step from rest that raises it is
// halved. docs/algorithms.md has the measurements behind both.
#pragma once

#include "formulations/formulation.hpp"
#include "solvers/monitor.hpp"

namespace asp {

struct GfmdParameters {
  double time_step = 0.0;  // > 0: fixed; 0: min(1, 1/sqrt(f.largest_curvature())) as it goes
  double damping = 2.0;    // eta, per unit time
};

// Leaves the last iterate in f.variable().
void gfmd(Formulation &f, Monitor &monitor, const GfmdParameters &parameters);

}  // namespace asp
