// The dimensionless units a formulation works in: pressures over the scene's reference
// pressure P, lengths over P/k (k the stiffness of one pixel), energies over a P^2/k (a the
// pixel area), so that a scene and the same scene in other units take the same arithmetic
// path. Made only for scenes and targets whose numbers doubles can hold in these units.
#pragma once

#include "physics/system.hpp"
#include "solvers/control.hpp"

namespace asp {

struct SceneUnits {
  double pressure;  // P
  double length;    // P/k
  double energy;    // a P^2/k (per unit length in 1D)
  double target;    // the control's value in these units
};

// Throws Error(invalid_argument) naming 'value' or the scene's scales when the solve cannot
// be represented; touches nothing.
SceneUnits scene_units(const System &system, Control control, double value);

}  // namespace asp
