// SPDX-License-Identifier: GPL-2.0-or-later
// FIRE, the fast inertial relaxation engine (Bitzek, Koskinen, Gahler, Moseler & Gumbsch,
// Phys. Rev. Lett. 97, 2006; thesis section 3.1.4 and Alg. 6), with the corrections of
// FIRE 2.0 (Guenole et al., Comput. Mater. Sci. 175, 2020): molecular dynamics of unit masses
// in the force -grad E, integrated by semi-implicit Euler, whose velocity is mixed towards
// the force's direction,
//     v <- (1 - alpha) v + alpha |v| F/|F|;
// while the power P = F.v stays positive for more than `delay` steps the time step grows by
// `growth` (up to the largest) and alpha decays by `mixing_decay`; when P <= 0 the step
// shrinks by `shrink`, alpha returns to `mixing`, the position moves half a step back and the
// velocity is zeroed. On the displacement (`fire`) the masses are equal; on the
// preconditioned Fourier variable (`fire_mass_weighted`) they are proportional to K~(q), the
// mass-weighting of Zhou, Moseler & Muser (Phys. Rev. B 99, 2019; thesis section 3.1.5,
// Alg. 7).
#pragma once

#include "formulations/formulation.hpp"
#include "solvers/monitor.hpp"

namespace asp {

struct FireParameters {
  double time_step = 0.0;      // the first step; 0: 1/sqrt(f.largest_curvature()) at the start
  double largest_step = 0.0;   // 0: 10/sqrt(the largest elastic curvature) (Bitzek et al.'s
                               // ten times a stable step, of the elastic modes)
  double growth = 1.1;         // f_inc
  double shrink = 0.5;         // f_dec
  double mixing = 0.1;         // alpha_start
  double mixing_decay = 0.99;  // f_alpha
  int delay = 5;               // N_min: steps of positive power before the step grows
};

// Leaves the last iterate in f.variable().
void fire(Formulation &f, Monitor &monitor, const FireParameters &parameters);

// The automatic time step of the dynamics solvers (fire's first step, gfmd's bound at the
// iterate): 1/sqrt of an upper bound on the largest curvature at f's current state, half the
// stability limit 2/omega of the integrators for the stiffest mode.
// 0 where the bound is not a finite, positive number: a curvature that overflows, at a state
// inside a wall too stiff for a double, allows no step.
double automatic_time_step(Formulation &f);

}  // namespace asp
