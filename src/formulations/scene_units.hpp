// SPDX-License-Identifier: GPL-2.0-or-later
// The dimensionless units a formulation works in: pressures over the scene's reference
// pressure P, lengths over P/k (k the stiffness of one pixel), energies over a P^2/k (a the
// pixel area), so that a scene and the same scene in other units take the same arithmetic
// path. Made only for scenes and targets whose numbers doubles can hold in these units.
#pragma once

#include "physics/system.hpp"
#include "formulations/control.hpp"

namespace asp {

struct SceneUnits {
  double pressure;  // P
  double length;    // P/k
  double energy;    // a P^2/k (per unit length in 1D)
  double target;    // the control's value in these units
  // The exponential adhesion in these units (0 and 1 without adhesion): phi(g)/(P l) as a
  // function of g/l is -work exp(-(g/l)/range), l = P/k.
  double adhesion_work = 0.0;   // w/(P l)
  double adhesion_range = 1.0;  // rho/l
};

// The reference pressure P is the system's (System::reference_pressure); with adhesion or a
// soft potential, a surface without slope takes the larger of the control's own scale and the
// potential's pressure scale (the largest tensile stress w/rho, say), so that a purely
// adhesive scene is measured in its own pressures. A soft potential in these units is
// potential().in_units(length, pressure).
//
// Throws Error(invalid_argument) naming 'value' or the scene's scales when the solve cannot
// be represented; touches nothing.
SceneUnits scene_units(const System &system, Control control, double value);

}  // namespace asp
