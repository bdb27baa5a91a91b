// SPDX-License-Identifier: GPL-2.0-or-later
// The unconstrained problem of a soft potential (soft_formulation.hpp) over the displacement
// itself, in real space: the variable of plain L-BFGS and FIRE (thesis sections 2.2.1, 3.1.3,
// 3.1.4). The Hessian K + phi'' is as ill-conditioned as the stiffness and the potential make
// it; the Fourier formulation removes the stiffness's part of that.
//
// On a free substrate the displacement lives on the zero-padded surface (Substrate::
// surface_size): the unknowns are the displacement on the box, where the potential acts, then
// outside it, where the gradient K u asks the pressure to vanish. Only penetration control is
// offered there.
//
// Units as for every formulation (SceneUnits); the gradient is the force-balance residual in
// units of P, and the error its largest magnitude.
#pragma once

#include "formulations/soft_formulation.hpp"

namespace asp {

class DisplacementFormulation final : public SoftFormulation {
 public:
  // Checks the scene (throws Error, the state untouched), allocates, and starts from the
  // displacement of the system's state.
  DisplacementFormulation(System &system, Control control, double value);

  Field &variable() override { return displacement_; }
  double value_and_gradient(const double *x, double *gradient) override;
  bool quadratic() const override { return false; }
  // (K + phi''(g)) d at the iterate.
  void hessian_product(const double *direction, double *product) override;
  double gradient_at_zero(double *out) override;
  // The largest stiffness of a mode plus the largest phi'' at the iterate.
  double largest_curvature(bool with_interaction = true) override;
  double error(const double *x, const double *gradient) const override;
  bool finish() override { return store_state(displacement_.data()); }

 private:
  // K x over the surface, scaled, into out (the q = 0 mode only under penetration control).
  void apply_stiffness(const double *x, double *out);

  Field displacement_;
  Spectrum spectrum_;
};

}  // namespace asp
