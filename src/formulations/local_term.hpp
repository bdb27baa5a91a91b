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
  // eager: whether the pixels near the instability jump eagerly (eager(), below);
  // relaxed_stiffness: then the stiffness of falls_to_wall's one-pixel model, a pixel's with
  // the surface around it relaxing, in units of the scaled Hessian's pixel stiffness
  // (Substrate::self_compliance): 1 on a free substrate and 0.74 on a large periodic
  // half-space.
  LocalTerm(const ExponentialPotential &potential, bool eager, double relaxed_stiffness)
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
                           (std::log(potential.dphi(0.0)) + 60.0 * std::log(2.0))),
        eager_(eager),
        relaxed_stiffness_(relaxed_stiffness),
        // psi''(t) = -relaxed_stiffness there; none (-inf) where psi'' never reaches it.
        relaxed_instability_(
            -potential.d2phi(0.0) > relaxed_stiffness
                ? potential.range * std::log(-potential.d2phi(0.0) / relaxed_stiffness)
                : -HUGE_VAL) {}

  // exp(-x/range), or 0 where that makes no difference (above).
  double state(double x) const { return x > negligible_beyond_ ? 0.0 : std::exp(-x / range_); }
  // psi, psi' and psi'' are these multiples of the state.
  double value_per_state() const { return value_per_state_; }
  double slope_per_state() const { return slope_per_state_; }
  double curvature_per_state() const { return curvature_per_state_; }
  double negligible_beyond() const { return negligible_beyond_; }
  // Whether the pixels near the instability jump eagerly: in every step of a solve, cut or
  // not, onto the wall where falls_to_wall's one-pixel model with the relaxed stiffness has
  // no rest off it. Otherwise only after steps that were not cut, and onto the wall only the
  // pixels unstable on their own. The formulation decides (PrimalFormulation::
  // snaps_eagerly): eagerly on cold solves far from resolving the cohesive zone.
  bool eager() const { return eager_; }
  double relaxed_stiffness() const { return relaxed_stiffness_; }
  // An unknown's own curvature in this state, the others held: the scaled Hessian's unit
  // pixel stiffness plus psi''. Below 1 near the wall, where the adhesion pulls the harder the
  // closer the surface comes.
  double own_curvature(double state) const { return 1.0 + curvature_per_state_ * state; }
  // Whether an unknown in this state is unstable on its own: its own curvature is negative
  // (strong adhesion near the wall, whose cohesive zone the grid does not resolve).
  bool unstable_alone(double state) const { return own_curvature(state) < 0.0; }

  // The correction of a Fourier preconditioner's diagonal for an unknown in this state, by
  // which a preconditioned solver lengthens its move along its own residual (bugnicourt.cpp):
  // M moves an unknown along its own residual about as if its own curvature were the unit
  // pixel stiffness (exactly on a free substrate, where the unit is M's diagonal; 1.35 times
  // that on a periodic one); where the adhesion lowers that curvature to c in (0, 1), the
  // one-unknown Newton step r / c is longer, and (1/c - 1) r adds the difference, in the
  // manner of the one-unknown blocks of an additive Schwarz preconditioner. c is taken at
  // least smallest_own_curvature, so that the unknowns nearest the instability do not swamp
  // the direction (the correction is at most 19); an unknown unstable on its own (c <= 0) or
  // out of the adhesion's reach (c = 1) has none. Never negative, so that M plus it stays
  // positive definite.
  static constexpr double smallest_own_curvature = 0.05;
  double preconditioner_correction(double state) const {
    const double own = own_curvature(state);
    if (!(own > 0.0 && own < 1.0)) return 0.0;
    return 1.0 / (own > smallest_own_curvature ? own : smallest_own_curvature) - 1.0;
  }

  // Whether an unknown at x above the bound lower, in this state and with the quadratic
  // part's gradient q there, goes onto the wall in a jump. Not eager: where it is unstable on
  // its own and the objective falls toward the wall (a positive gradient). Eager: where it
  // has no rest above the bound in the one-unknown model with the relaxed stiffness k:
  // whether that model's slope
  //     m'(t) = q + k (t - x) + psi'(t)
  // is positive all the way from x down to the bound, so that the objective falls along the
  // way and the unknown comes to rest on the wall. m' is convex (psi''' > 0) with its minimum
  // where psi''(t*) = -k, psi'(t*) = k range there; so the test is m'(x) > 0 below t*, and
  // m'(t*) = q + k (t* - x + range) > 0 above it. Where t* is not above the bound the model
  // has no instability on the feasible side: nothing jumps, and a pixel reaches the wall by
  // moving along the direction, as without adhesion. Above
  // t* this finds the pixels that have lost their rest off the wall before they become
  // unstable on their own: a conjugate gradient moves them there over many iterations, their
  // curvature along its directions falling to nothing on the way (docs/algorithms.md, "The
  // pixels near the wall").
  bool falls_to_wall(double x, double q, double state, double lower) const {
    if (!eager_) return unstable_alone(state) && q + slope_per_state_ * state > 0.0;
    if (!(relaxed_instability_ > lower)) return false;
    if (x < relaxed_instability_) return q + slope_per_state_ * state > 0.0;
    return q + relaxed_stiffness_ * (relaxed_instability_ - x + range_) > 0.0;
  }

  // Where an unknown at x, with the quadratic part's gradient q there, comes to rest beyond
  // the instability when the objective falls away from the wall (q + psi'(x) < 0): the root
  // of m'(t) = q + k (t - x) + psi'(t), the derivative of the one-unknown model
  //     m(t) = q (t - x) + k (t - x)^2 / 2 + psi(t),
  // on the side where m is convex, with k = 1 (the others held), or the relaxed stiffness
  // where the term is eager, so that a pixel peeled off the wall lands where falls_to_wall
  // does not send it back. m' is decreasing while k + psi'' < 0 and convex increasing beyond
  // (psi''' > 0), so that root is its only one above x. Newton's method starts from
  // t = x - q/k, the rest point without the adhesion, where m' = psi'(t) > 0: from the right
  // of the root of a convex increasing function it falls monotonically onto the root, every
  // iterate a point where m' > 0 still. Twelve steps reach rounding from the starts the
  // formulation's units produce; where the root is a near-double one (the outer minimum
  // about to vanish) Newton's method slows, and the last iterate lies right of it.
  double rest_beyond_instability(double x, double q) const {
    const double k = eager_ ? relaxed_stiffness_ : 1.0;
    double t = x - q / k;
    for (int step = 0; step < 12; ++step) {
      const double s = state(t);
      const double curvature = k + curvature_per_state_ * s;
      if (!(curvature > 0.0)) break;
      t -= (q + k * (t - x) + slope_per_state_ * s) / curvature;
    }
    return t;
  }

 private:
  double value_per_state_, slope_per_state_, curvature_per_state_, range_;
  double negligible_beyond_;
  bool eager_;
  double relaxed_stiffness_, relaxed_instability_;
};

}  // namespace asp
