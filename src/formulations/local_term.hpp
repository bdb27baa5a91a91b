// SPDX-License-Identifier: GPL-2.0-or-later
// The local part of a separable objective f(x) = Q(x) + sum_i psi(x_i), Q quadratic: psi of
// each unknown, offered as a value type with inline functions so that a solver fuses it into
// its own passes without a call per unknown. The one local term that exists is exponential,
// psi(x) = -work exp(-x/range) (the scaled hard wall with adhesion): its value, slope and
// curvature are fixed multiples of one number per unknown, its state exp(-x/range), so that a
// solver keeps one array of states and one exponential per unknown serves all three.
#pragma once

#include <cmath>

#include "physics/interaction.hpp"

namespace asp {

class LocalTerm {
 public:
  explicit LocalTerm(const ExponentialPotential &potential)
      : value_per_state_(potential.phi(0.0)),
        slope_per_state_(potential.dphi(0.0)),
        curvature_per_state_(potential.d2phi(0.0)),
        range_(potential.range),
        // The slope is a exp(-x/range) with a = slope_per_state; beyond this x it is below
        // 2^-60 (in the formulation's pressure unit P), and the state is taken as 0 there,
        // which saves the exponential of every unknown far from the wall. What that changes
        // is bounded: the gradient by less than 2^-60 P per unknown (the error measure is
        // absolute in units of P: a hundred times below the rounding of a pressure of the
        // order of P, far below any tolerance it can meet), the value by less than
        // range 2^-60 per unknown, the curvature by less than 2^-60/range per unknown
        // (against the unit pixel stiffness of the scaled Hessian).
        negligible_beyond_(potential.range *
                           (std::log(potential.dphi(0.0)) + 60.0 * std::log(2.0))) {}

  // exp(-x/range), or 0 where that makes no difference (above).
  double state(double x) const { return x > negligible_beyond_ ? 0.0 : std::exp(-x / range_); }
  // psi, psi' and psi'' are these multiples of the state.
  double value_per_state() const { return value_per_state_; }
  double slope_per_state() const { return slope_per_state_; }
  double curvature_per_state() const { return curvature_per_state_; }
  double negligible_beyond() const { return negligible_beyond_; }
  // Whether an unknown in this state is unstable on its own: psi'' below minus the scaled
  // Hessian's unit pixel stiffness, so that, the others held, its own curvature is negative
  // (strong adhesion near the wall, whose cohesive zone the grid does not resolve).
  bool unstable_alone(double state) const { return 1.0 + curvature_per_state_ * state < 0.0; }

 private:
  double value_per_state_, slope_per_state_, curvature_per_state_, range_;
  double negligible_beyond_;
};

}  // namespace asp
