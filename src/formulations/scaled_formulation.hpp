// SPDX-License-Identifier: GPL-2.0-or-later
// What every formulation of a system holds: the system's parts it reads, the control, and the
// dimensionless units of the solve (SceneUnits), with the parts of the Formulation interface
// that do not depend on the unknown (size, plain inner product over pixels, energy unit,
// reductions).
#pragma once

#include "core/loops.hpp"
#include "physics/system.hpp"
#include "formulations/control.hpp"
#include "formulations/formulation.hpp"
#include "formulations/scene_units.hpp"

namespace asp {

class ScaledFormulation : public Formulation {
 public:
  std::int64_t size() const override { return unknowns_; }
  double dot(const double *a, const double *b) const override {
    return loops::sum(grid_.reductions(), unknowns_,
                      [&](std::int64_t i) { return a[i] * b[i]; });
  }
  // Converts scaled objective values to the physical energy (per unit length in 1D).
  double energy_unit() const override { return energy_unit_; }
  const Reductions &reductions() const override { return grid_.reductions(); }

 protected:
  // Called by a formulation that works on the system's state in place, after its work arrays
  // are made and before it first changes the state (System::state_held_by_solve).
  void hold_state() { system_.set_state_held_by_solve(true); }

  // Throws Error when the solve cannot be represented (scene_units); touches nothing.
  ScaledFormulation(System &system, Control control, double value)
      : system_(system),
        substrate_(system.substrate()),
        grid_(system.grid()),
        state_(system.state()),
        heights_(system.heights().data()),
        max_height_(system.max_height()),
        control_(control),
        n_(system.grid().local_pixels()),
        unknowns_(n_),
        pixels_(static_cast<double>(system.grid().n_pixels())) {
    const SceneUnits units = scene_units(system, control, value);
    pressure_unit_ = units.pressure;
    length_unit_ = units.length;
    energy_unit_ = units.energy;
    target_ = units.target;
    adhesive_ = exponential_adhesion(system.interaction()) != nullptr;
    adhesion_ = {units.adhesion_work, units.adhesion_range};
  }

  System &system_;
  const Substrate &substrate_;
  const Grid &grid_;
  ContactState &state_;
  const double *heights_;
  double max_height_;
  Control control_;
  std::int64_t n_;         // pixels of the grid (of this process's rows)
  std::int64_t unknowns_;  // n_, or more where the unknowns reach beyond the grid
  double pixels_;          // pixels of the whole grid, for means

  double pressure_unit_;  // P
  double length_unit_;    // P/k
  double energy_unit_;    // a P^2/k
  double target_;         // the control's value, scaled
  bool adhesive_;                 // the hard wall with exponential adhesion
  ExponentialPotential adhesion_;  // its potential in scaled units, phi(x) of the scaled gap
};

}  // namespace asp
