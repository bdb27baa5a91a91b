// SPDX-License-Identifier: GPL-2.0-or-later
// A formulation is what a solver sees instead of the physics: a vector of unknowns, an
// objective with its gradient and Hessian product, bounds, the error measure, the inner
// product, and the way back into the system's state. Primal (gap), dual (pressure),
// unconstrained (displacement) and Fourier-preconditioned formulations implement it; a solver
// never sees the substrate, the interaction or the heights.
//
// Formulations work in the dimensionless units of their scene (pressures divided by the
// reference pressure, lengths by the reference pressure over the pixel stiffness), so that a
// scene and the same scene in other units take the same arithmetic path, and nothing
// overflows for any scene the constructor accepts.
#pragma once

#include <cstdint>

#include "core/aligned_field.hpp"
#include "core/reductions.hpp"

namespace asp {

class LocalTerm;  // solvers/local_term.hpp

// Work done so far, for the monitor's history.
struct Counters {
  std::int64_t evaluations = 0;  // objective or gradient evaluations
  std::int64_t transforms = 0;   // forward or backward FFTs
};

class Formulation {
 public:
  virtual ~Formulation() = default;

  // Number of unknowns and the current iterate, which a solver reads and writes in place.
  virtual std::int64_t size() const = 0;
  // The number of unknowns over all processes (size() on one), for means.
  double total_size() const {
    double total = static_cast<double>(size());
    reductions().combine_sums(&total, 1);
    return total;
  }
  virtual Field &variable() = 0;

  // The objective at x and its gradient (in the inner product below).
  virtual double value_and_gradient(const double *x, double *gradient) = 0;
  // The gradient alone, for solvers that need no value (a formulation may save a pass).
  virtual void gradient(const double *x, double *gradient) { value_and_gradient(x, gradient); }
  // Whether the objective is quadratic. Without adhesion every formulation's is; with it the
  // primal's is not, and then the Hessian depends on the point and a solver must evaluate
  // the gradient wherever it needs it.
  virtual bool quadratic() const { return true; }
  // The Hessian at the current iterate (variable()) times a direction.
  virtual void hessian_product(const double *direction, double *product) = 0;
  // For a quadratic objective, f(x) = x.Hx/2 + c.x + f(0): writes c, the gradient at 0,
  // into out and returns f(0). A solver that keeps c can follow the gradient along a step
  // from Hessian products, g(s(x + a d)) = s (g(x) + a H d) + (1 - s) c, instead of
  // evaluating it. (Of a formulation that is not quadratic it is only the gradient at 0.)
  virtual double gradient_at_zero(double *out) = 0;
  // ---- The quadratic part. Of a quadratic objective it is all of it; of a separable one,
  // f(x) = Q(x) + sum_i psi(x_i), it is Q (local_term() gives psi). A solver that keeps Q's
  // gradient q can follow it along a step from Q's Hessian products exactly as above, and
  // add the local term's slope element by element.
  // Q's value at x and its gradient, into gradient (one evaluation).
  virtual double quadratic_part(const double *x, double *gradient) {
    return value_and_gradient(x, gradient);
  }
  // Q's gradient at 0, into out; returns Q(0).
  virtual double quadratic_part_at_zero(double *out) { return gradient_at_zero(out); }
  // Q's Hessian times a direction, into product; returns the curvature d.product. A
  // formulation whose product passes through a spectrum sums the curvature there (Parseval),
  // so that a solver needs no pass of its own for it.
  virtual double quadratic_part_product(const double *direction, double *product) {
    hessian_product(direction, product);
    return dot(direction, product);
  }
  // The local term psi of a separable objective that is not quadratic; null for a quadratic
  // objective (or one that is not separable). It acts on the bounded unknowns (the first
  // bounded_size()) only.
  virtual const LocalTerm *local_term() const { return nullptr; }

  // A preconditioner for the quadratic part: applies the inverse of the elastic operator
  // that makes Q's Hessian (the compliance where the Hessian is the stiffness, the stiffness
  // where it is the compliance), which is diagonal in Fourier space and removes the growth of
  // the Hessian's condition number with the grid, to z in place (size() unknowns; one
  // transform pair). Returns false, z untouched, where the formulation offers none.
  virtual bool precondition(double *z) {
    (void)z;
    return false;
  }

  // For solvers that integrate dynamics (FIRE, GFMD) and take their time step from it: an
  // upper bound on the largest eigenvalue of the Hessian at the current iterate, in this
  // inner product (the quadratic part's largest stiffness plus the largest curvature of the
  // interaction at the iterate), or of the quadratic (elastic) part alone. A formulation that
  // cannot bound it returns 0.
  virtual double largest_curvature(bool with_interaction = true) {
    (void)with_interaction;
    return 0.0;
  }

  // The inner product of the variable's space (weighted for packed spectra).
  virtual double dot(const double *a, const double *b) const = 0;
  // Bound constraints x >= lower_bound() (-infinity: none) on the first bounded_size()
  // unknowns; the others are free of the bound and of the mean constraint (the displacement
  // of a free substrate's surface outside the box, say).
  virtual double lower_bound() const = 0;
  virtual std::int64_t bounded_size() const { return size(); }
  // The mean-value constraint of the control, if it imposes one: the mean of the bounded
  // unknowns must equal mean_target(). A solver that moves the iterate restores it (for
  // example by rescaling, or by removing the gradient's mean over the free unknowns).
  virtual bool constrains_mean() const = 0;
  virtual double mean_target() const = 0;
  // Restores the constraints on x (size() unknowns) after a step that left them: the bound,
  // x_i <- max(x_i, lower_bound()) on the first bounded_size(); then, under a mean
  // constraint, the mean of those unknowns, by scaling them with mean_target() total /
  // sum x_i (which keeps the bound: every formulation with a mean constraint has the lower
  // bound 0), or, where nothing is left above the bound, by setting them all to
  // mean_target(). It is the rule of Bugnicourt's fused step (bugnicourt_passes.hpp); a
  // projected solver calls it after each step. A feasible x changes at most by the rounding
  // of that scale (by nothing without a mean constraint). Unknowns past
  // bounded_size() are left as they are. Collective on a distributed grid.
  void project(double *x) const;
  // The error measure of DESIGN.md section 2 at x with this gradient: the largest projected
  // force-balance residual, divided by the reference pressure. With bounds it is
  // bound_residual (bound_residual.hpp) with lower_bound() and, under a mean constraint,
  // relative to the gradient's mean over the free unknowns; solvers that gather it in their
  // own passes rely on that.
  virtual double error(const double *x, const double *gradient) const = 0;

  // For the monitor's history: the fraction of pixels in contact at x, by the rule the state
  // written back from x would follow (System::contact_fraction), given the gradient at x; the objective
  // as histories report it, from value_and_gradient's value and gradient at x (under a mean
  // constraint its constant multiplier term uses the multiplier's current estimate, so that
  // all solvers report the same number for the same iterate); and the factor that turns
  // objective values into the physical energy.
  virtual double contact_fraction(const double *x, const double *gradient) const = 0;
  virtual double reported_objective(const double *x, const double *gradient,
                                    double value) const = 0;
  virtual double energy_unit() const = 0;
  // Combines a solver's own sums and maxima over the unknowns this process holds.
  virtual const Reductions &reductions() const = 0;

  // An array of size() doubles that the formulation holds but neither reads nor needs kept
  // until finish() writes it (the gap formulation's is the system's pressure, which it
  // writes at the end), or null. A solver may take it for one of its work arrays, so that
  // the largest scenes need one array fewer; its values at the start are undefined.
  virtual double *spare_array() { return nullptr; }

  // Under load control, whether the iterate x shows that the load pulls the surfaces apart
  // for good, so that no stable state lies ahead (the monitor then ends the solve as
  // separated: a minimiser would follow the separation without end). Each formulation that
  // can tell says by what rule; false where that cannot happen (other controls, compressive
  // loads, no adhesion to hold the surfaces together).
  virtual bool separates(const double *x) const {
    (void)x;
    return false;
  }

  // Writes the iterate back into the system's state in physical units, with everything that
  // follows from it (gap, penetration), through System::store_solved_state. Returns false if
  // a physical value is not finite (the caller then resets the state).
  virtual bool finish() = 0;

  const Counters &counters() const { return counters_; }

 protected:
  // Mutable: a spectral formulation's error measure (a const query) transforms too.
  mutable Counters counters_;
};

}  // namespace asp
