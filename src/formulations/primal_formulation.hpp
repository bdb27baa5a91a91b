// SPDX-License-Identifier: GPL-2.0-or-later
// The primal (gap) formulation of the hard-wall contact, with or without exponential adhesion
// or a user's potential acting on the open gap (asp_system_set_potential with the hard wall,
// evaluated over all pixels at once; L-BFGS-B takes it, Bugnicourt's solver does not)
// (thesis section 2.2): minimise the elastic energy of the displacement that the gap makes
// plus the interaction energy,
//     E(g) = (a/2) u.K u + a sum_i phi(g_i),   u = g + h - max h + delta,   over g >= 0,
// whose gradient is a times K u + phi'(g), the elastic pressure less the interaction's
// pressure -phi'(g). Without adhesion phi = 0, no potential is evaluated and the objective is
// quadratic; with it, it is not (phi'' depends on g, and is negative: the Hessian K + phi''
// can lose its positivity for strong adhesion). Under penetration control delta is given
// and K includes the q = 0 stiffness K~(0). Under mean-gap control the mean of g is fixed; the
// q = 0 term is left out (the mean displacement does not change the energy of the q != 0
// modes), and the mean pressure is the Lagrange multiplier of the constraint.
//
// On a free substrate the displacement lives on the zero-padded surface (Substrate::
// surface_size): the unknowns are the gap on the box, then the displacement of the surface
// outside it, free of the bound. At the optimum the pressure K u vanishes there, so that the
// energy and the pressure on the box are those of the free half-space (Love's coefficients);
// penetration and load control are offered there, not mean-gap control.
//
// Under load control (mean pressure pbar, total force F = pbar A) the equilibrium is a
// minimum of E(g, delta) - F delta over the gap and the penetration: the Legendre transform
// of the energy at given penetration, whose minima are the stable states (dF/d delta > 0)
// and whose other stationary states are saddles, so that a minimiser never settles on an
// unstable branch. delta moves the displacement of the whole surface uniformly, its q = 0
// mode only, once the unknowns beyond a free substrate's box are taken as the displacement
// less delta (as the gap is on the box). Minimising over delta in closed form leaves
//     E(g) = (1/2) u.K' u + a sum_i phi(g_i) + (F/M) sum over the M surface points of x_i,
// K' the stiffness without its q = 0 mode and x the unknowns (the gap on the box, the
// displacement less delta beyond it): the load is a uniform pressure F/(M a) on each
// unknown, pbar itself on a periodic substrate (M = N, the mean-gap formulation's objective
// with the work pbar A mean(g) and no constraint). It needs no K~(0), so that the pressure
// field does not depend on that convention, and no extra unknown or multiplier: the solvers
// see a plain bound-constrained objective, the mean pressure being the gradient's part
// that the load sets. The penetration comes back at the end from the stored pressure's
// displacement, as the mean of u - (h - max h) - g over the grid. Along the uniform
// separation of the surface the elastic energy is flat: past the pull-off force, with no
// pixel on the wall, the objective falls without bound (the adhesive energy is concave), and
// separates() says so, so that the solve ends there instead of following the surfaces apart.
// A user's potential is not taken under load control: nothing bounds its curvature, so
// that the separation could not be told.
//
// Units as for the dual formulation (SceneUnits): the gradient is the pressure over P, and the
// error is the largest residual of the optimality conditions in units of P.
//
// During a solve the system's gap array holds the scaled iterate; finish() stores it as the
// gap (>= 0, exactly 0 on the active set), the hard wall's reading of it as the pressure, and
// the penetration. With adhesion the pressure where the gap is open is the interaction's,
// -phi'(g) (tensile). The displacement K^-1 p of that pressure differs from the gap's by the
// residual of the iterate (asp_system_get_field in asperity.h says how much).
#pragma once

#include "physics/system.hpp"
#include "formulations/control.hpp"
#include "formulations/local_term.hpp"
#include "formulations/scaled_formulation.hpp"

namespace asp {

class PrimalFormulation final : public ScaledFormulation {
 public:
  // Checks that the scene and the target can be represented (throws Error, the state
  // untouched), allocates the work arrays, then loads the stored gap (negative values
  // clipped, and 0 where the stored pressure is compressive: those pixels are on the wall) as
  // the starting iterate, with its mean rescaled to the target under mean-gap control
  // (uniform if there is none).
  PrimalFormulation(System &system, Control control, double value);

  // The gap on the grid; on a free substrate followed by the displacement of the padded
  // surface outside the box, unknowns free of the bound.
  Field &variable() override {
    return substrate_.surface_beyond_grid() ? surface_unknowns_ : state_.gap;
  }
  std::int64_t bounded_size() const override { return n_; }
  bool quadratic() const override { return !adhesive_ && potential_ == nullptr; }
  double value_and_gradient(const double *x, double *gradient) override;
  // Without adhesion, the elastic pressure without the energy's pass.
  void gradient(const double *x, double *gradient) override;
  // K d (+ phi''(x) d at the iterate x with adhesion).
  void hessian_product(const double *direction, double *product) override;
  double gradient_at_zero(double *out) override;
  // The quadratic part is the elastic energy (1/2) u.K u; with adhesion the local term is the
  // interaction's phi.
  double quadratic_part(const double *x, double *gradient) override;
  double quadratic_part_at_zero(double *out) override;
  double quadratic_part_product(const double *direction, double *product) override;
  // z <- k K^-1 z over the surface (K/k is the quadratic part's Hessian, scaled), the q = 0
  // mode included wherever the substrate has a compliance there.
  bool precondition(double *z) override;
  const LocalTerm *local_term() const override { return adhesive_ ? &local_term_ : nullptr; }
  double lower_bound() const override { return 0.0; }
  bool constrains_mean() const override { return control_ == Control::mean_gap; }
  double mean_target() const override { return target_; }
  // Under a tensile load on the adhesive wall: no pixel on the wall, and the objective
  // falling along the uniform separation of the whole surface (where it then falls without
  // bound: the adhesive energy is concave).
  bool separates(const double *x) const override;
  double error(const double *x, const double *gradient) const override;
  double contact_fraction(const double *x, const double *gradient) const override;
  double reported_objective(const double *, const double *, double value) const override {
    return value;
  }
  bool finish() override;
  // The system's pressure, which finish() writes without reading it, on a substrate whose
  // surface is the grid (beyond the grid there are more unknowns than pressures).
  double *spare_array() override {
    return substrate_.surface_beyond_grid() ? nullptr : state_.pressure.data();
  }

 private:
  // K u (scaled) of a field, into out; the q = 0 mode only under penetration control.
  // Returns u.K u (by Parseval, from the same pass over the spectrum).
  double apply_stiffness(const double *field, double *out);
  // The scaled elastic pressure K u of the displacement u the gap x makes, into out (which
  // may be x itself); returns u.K u.
  double elastic_pressure(const double *x, double *out);
  // value_and_gradient with a user's potential and the hard wall.
  double value_and_gradient_of_potential(const double *x, double *gradient);
  // phi'(g) of the interaction at the gaps (clipped at the wall) into slope; returns phi'(0).
  double interaction_slopes(const double *gap, double *slope);
  // For finish() under load control without adhesion at zero load: the iterate moved
  // uniformly until it touches the wall (its energy unchanged).
  void touch_at_zero_load();
  // Whether the pixels near the adhesion's instability jump eagerly (LocalTerm::eager): on
  // a cold solve (a start without pressure, or a state that an earlier stage of the same
  // solve left: coarse levels, a continuation in the range) of a scene whose cohesive zone is
  // at most half a pixel (far_from_resolved). No branch is to be kept there, and the eager
  // jumps reach states of lower energy in fewer iterations. On a warm start the pixels jump
  // as before, so that a sweep's solve stays on the branch its start is on; nearer to
  // resolved, too, where the eager jumps cost iterations (docs/algorithms.md, "The pixels
  // near the wall").
  bool snaps_eagerly() const;

  // Scaled, in u (0 under mean-gap and load control, where it does not matter).
  double penetration_;
  // Under load control, the scaled pressure the load puts on each unknown of the surface (0
  // otherwise).
  double load_ = 0.0;

  Spectrum spectrum_;
  LocalTerm local_term_;
  // A user's potential with the hard wall, in the solve's units (null otherwise), and its
  // work arrays over the grid.
  std::unique_ptr<Potential> potential_;
  Field phi_, dphi_, d2phi_;
  // Only where the surface reaches beyond the grid (a free substrate): the unknowns, and the
  // pressure over the whole surface for finish().
  Field surface_unknowns_;
  Field surface_pressure_;
};

}  // namespace asp
