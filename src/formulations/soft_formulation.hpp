// SPDX-License-Identifier: GPL-2.0-or-later
// What the unconstrained formulations of a soft potential share (thesis section 2.2.1): the
// objective
//     E(u) = (1/2) u.K u + sum_i phi(g_i) + pbar sum_i u_i,   g = u - (h - max h) - delta,
// over the displacement u, with no bound: the potential phi itself keeps the surfaces apart.
// Its gradient K u + phi'(g) + pbar is the force-balance residual: the elastic pressure and
// the load against the interaction's pressure -phi'(g).
//
// The two controls:
//  - penetration: delta is given, pbar = 0, and K includes the q = 0 stiffness K~(0), so that
//    the mean displacement is an elastic mode like the others;
//  - mean pressure: pbar is given and the rigid-body penetration is folded into the mean
//    displacement (delta = 0 in the objective): the q = 0 mode has no elastic energy. The
//    load does the work pbar N delta as the body advances by delta, which is -pbar sum u
//    up to a constant when delta is folded into u; its term balances the interaction's mean
//    pressure. The physical penetration follows at the end from the state's convention
//    mean u = pbar/K~(0).
//
// This class holds the potential in the solve's units and evaluates it on the gaps of a
// displacement; it writes the result back into the system. The formulations differ in their
// variable: the displacement itself (DisplacementFormulation) or its spectrum scaled by the
// square root of the stiffness (FourierFormulation).
#pragma once

#include <memory>

#include "physics/potential.hpp"
#include "formulations/scaled_formulation.hpp"

namespace asp {

class SoftFormulation : public ScaledFormulation {
 public:
  double lower_bound() const override;
  bool constrains_mean() const override { return false; }
  double mean_target() const override { return 0.0; }
  // The pixels whose interaction pushes the surfaces apart (phi'(g) < 0) at the last point
  // the potential was evaluated at, which is the iterate every solver reports.
  double contact_fraction(const double *x, const double *gradient) const override;
  double reported_objective(const double *, const double *, double value) const override {
    return value;
  }

 protected:
  // Throws Error (the state untouched) for a system without a soft potential or a control the
  // formulation cannot keep; allocates the gap and potential arrays.
  SoftFormulation(System &system, Control control, double value);

  // The scaled displacement of the system's state on the grid (under mean-pressure control
  // less the penetration, which the objective folds into it), into u: a warm start.
  void starting_displacement(double *u) const;

  // phi and phi' (and phi'' if curvature) of the gaps of the displacement u on the grid, into
  // phi_, dphi_ (d2phi_); under mean-pressure control dphi_ holds phi' + pbar. Returns
  // sum_i phi(g_i) + pbar sum_i u_i, the objective's part outside the elastic energy. A user's
  // potential may throw Error(callback).
  double interaction(const double *u, bool curvature = false);
  // The largest phi'' over the last evaluation with curvature, and 0 if it is negative.
  double largest_interaction_curvature() const;

  // Writes the state for the displacement u over the substrate's surface: the elastic pressure
  // K u (with pbar as its mean under mean-pressure control), the gap it makes, the
  // penetration. Returns false if a physical value is not finite.
  bool store_state(const double *u);
  // The same from the displacement's spectrum (the substrate's surface_forward of it, which
  // this overwrites). Under mean-pressure control the displacement's mean holds the
  // penetration, which can exceed its variations by any factor; a formulation that holds the
  // spectrum itself passes it here, so that the stored pressure is the one its error measure
  // saw, without the rounding of that mean that a transform of the real-space displacement
  // spreads over every mode (1e-16 of the mean, times K~ at the largest q).
  bool store_state_from_spectrum(Complex *spectrum);

  bool load_control() const { return control_ == Control::mean_pressure; }

  std::unique_ptr<Potential> potential_;  // in the solve's units
  double load_;                           // pbar, scaled (0 under penetration control)
  double penetration_;                    // delta, scaled (0 under mean-pressure control)
  Field gap_, phi_, dphi_, d2phi_;        // over the grid's pixels
};

}  // namespace asp
