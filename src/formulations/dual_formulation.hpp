// SPDX-License-Identifier: GPL-2.0-or-later
// The dual (pressure) formulation of the non-adhesive hard-wall contact (thesis section
// 3.1.1): minimise the complementary energy
//     Pi(p) = (a/2) p.K^-1 p - a p.(h - max h + delta)   over p >= 0,
// whose gradient is a times the gap g = K^-1 p - (h - max h) - delta. Under mean-pressure
// control the mean of p is fixed and the penetration delta is the Lagrange multiplier of that
// constraint; under penetration control delta is given. At the optimum Pi = -(a/2) p.K^-1 p,
// minus the elastic energy including the q = 0 term.
//
// Units: pressures are divided by the reference pressure P and lengths by P/k, k the pixel
// stiffness, so that the scaled pixel stiffness is 1 and the error is simply the largest
// projected gap violation. The constructor refuses scenes whose scaled numbers or whose results
// doubles cannot hold.
//
// It works on any substrate with a compliance: the transforms, the compliance and the
// Parseval sums (p.K^-1 p and t.K^-1 t from one spectrum) are the substrate's. On a free
// substrate's padded grid the Parseval sums still hold, because the pressure and the search
// direction are zero outside the box.
//
// Besides the generic Formulation interface it offers the steps of Polonsky & Keer's
// algorithm, fused into as few passes over memory as the algorithm allows; during such a solve
// the system's pressure and gap arrays hold the scaled iterate.
#pragma once

#include "physics/system.hpp"
#include "formulations/control.hpp"
#include "formulations/scaled_formulation.hpp"

namespace asp {

// Whether the formulation will run Polonsky & Keer's steps, which keep a search direction and
// the pressure's spectrum between iterations (16 bytes per pixel a generic solver does not
// need), and with the Fourier preconditioner, which keeps the preconditioned residual (8 more).
enum class DualSteps { generic, polonsky_keer, polonsky_keer_fourier };

class DualFormulation final : public ScaledFormulation {
 public:
  // Checks that the scene and the target can be represented (throws Error naming the
  // argument, the state untouched), allocates the work arrays, then loads the system's state
  // as the starting iterate, in place and in scaled units: the stored pressure (negative
  // values clipped), rescaled to the target mean under load control (uniform if there is
  // none), and the stored or given penetration. finish() writes it back in physical units.
  DualFormulation(System &system, Control control, double value,
                  DualSteps steps = DualSteps::generic);

  // ---- Formulation
  Field &variable() override;
  double value_and_gradient(const double *x, double *gradient) override;
  void gradient(const double *x, double *gradient) override { gap_of(x, 1.0, gradient); }
  void hessian_product(const double *direction, double *product) override;
  // K^-1 d, with d.K^-1 d summed in the pass over the spectrum (Parseval).
  double quadratic_part_product(const double *direction, double *product) override;
  // z <- K z / k on the grid (k K^-1 is the quadratic part's Hessian, scaled).
  bool precondition(double *z) override;
  double gradient_at_zero(double *out) override;
  double lower_bound() const override { return 0.0; }
  bool constrains_mean() const override { return control_ == Control::mean_pressure; }
  double mean_target() const override { return target_; }
  double error(const double *x, const double *gradient) const override;

  double contact_fraction(const double *x, const double *) const override;
  double reported_objective(const double *x, const double *gradient,
                            double value) const override;

  // ---- Polonsky & Keer's steps (the constructor has loaded the starting iterate; all but
  // evaluate_gap need DualSteps::polonsky_keer)

  struct Gap {
    double norm;       // sum over the contact set of (g - mean)^2 (load) or g^2 (penetration)
    double contacts;   // number of pixels with p > 0
    double objective;  // Pi, scaled, when asked for (else 0)
  };
  // The gap of the current pressure (one transform pair). Under load control the penetration
  // becomes the one that closes the mean gap over the contact set.
  Gap evaluate_gap(bool with_objective);

  // The new search direction t = g + beta t_old on the contact set (0 elsewhere), with t_old
  // made mean-free there under load control. Returns the error of the current iterate.
  // Called again with beta = 0 it restarts from steepest descent (t_old is then ignored).
  double update_direction(double beta);
  // g.t, the descent of the energy along t.
  double descent() const { return descent_; }
  // beta g.t_old, the part of the descent the old direction brought: 0 after an exact line
  // search that kept the contact set, so its size tells how far conjugacy was lost.
  double old_slope() const { return old_slope_; }
  // t.K^-1 t, the curvature of the energy along t (one forward transform, by Parseval).
  double curvature();
  // p <- max(p - tau t, 0) on the contact set; pixels outside it with a negative gap enter
  // with pressure -tau g (with the Fourier preconditioner's steps: with max(-tau t, 0), t
  // covering them). Under load control the result is rescaled to the target mean.
  // Returns true if pixels entered the contact set.
  bool step(double tau);
  // When the direction vanishes (no contact, or a gap already uniform on the contact set)
  // but pixels interpenetrate: each such pixel gets the pressure that closes its own gap if
  // it were alone, k (-g).
  void admit_interpenetrating_pixels();

  // ---- The Fourier preconditioner (dual_preconditioner.cpp; needs
  // DualSteps::polonsky_keer_fourier)
  //
  // The compliance K^-1 is a Fourier multiplier 2/(E*|q|) on a periodic substrate, so the
  // condition number of the system on the contact set grows like the grid's size. Its
  // inverse, the stiffness, applied to the residual r and restricted again, z = P K P r,
  // undoes most of that (Vollebregt, J. Comput. Phys. 257 (2014) 333). P restricts to the free
  // set N: the contact set and the pixels off it whose gap is negative, which enter along the
  // direction (step() then gives them max(-tau t, 0), not -tau g: entering along the gap
  // while the set moves along z, the two disagree, and on rough scenes at large contact the
  // set stalled). r is the centred gap on N. Under load control z is made mean-free on N, so
  // that a step along it keeps the mean pressure. On a free substrate K is the stiffness of
  // the padded surface, and P also restricts to the box.

  // z of the current gap (one transform pair); returns r.z, the norm that replaces |r|^2 in
  // the conjugate-gradient coefficient beta.
  double precondition();
  // As update_direction, with z in place of the gap and N in place of the contact set:
  // t = z + beta t_old on N. Returns the error of the current iterate.
  double update_preconditioned_direction(double beta);

  bool finish() override;

 private:
  double scaled_height(std::int64_t i) const { return (heights_[i] - max_height_) / length_unit_; }
  // Whether a pixel is in the preconditioned iteration's free set N: in contact, or off it
  // with a negative (centred) gap.
  static bool in_free_set(double pressure, double centred_gap) {
    return (pressure > 0.0) | (centred_gap < 0.0);
  }
  // Whether the steps are the preconditioned ones (z allocated), whose pixels off the contact
  // set enter along the direction.
  bool preconditioned_steps() const { return !preconditioned_.empty(); }
  void gap_of(const double *pressure, double pressure_scale, double *gap);
  // The gap of the current iterate into gap (scaled, before centring); with_energy also
  // returns sum_i p_i u_i, p the pressure array and u the scaled displacement it makes.
  double gap_of_iterate(double *gap, bool with_energy);
  void load_state();
  // The pass of update_direction and update_preconditioned_direction: t = source(i, g_i) +
  // beta (t_old - t_mean) on the pixels that are members, member(p_i, g_i) (of the contact
  // set, or of N), 0
  // elsewhere, g_i the centred gap; the descent g.t into descent_ and beta g.t_old into
  // old_slope_; returns the error of the current iterate.
  template <class Source, class Member>
  double update_direction_from(Source source, Member member, double t_mean, double beta);

  double compliance_factor_;  // k: turns the substrate's K^-1 into the scaled one

  Field direction_;         // t
  Field preconditioned_;    // z = P K P r (the Fourier preconditioner's residual)
  double preconditioned_mean_ = 0.0;  // mean of z on N, removed under load control
  double free_direction_mean_ = 0.0;  // mean of t_old on N, removed under load control
  Spectrum spectrum_;       // work; holds the spectrum of t between curvature() and the next gap
  Spectrum pressure_spectrum_;  // the spectrum of the pressure array
  Spectrum height_spectrum_;  // FFT of the scaled (h - max h), over the transform's points
  const Field &compliance_;

  // The arrays hold p/scale and g + shift: rescaling and centring are carried as numbers and
  // folded into the next pass over the data.
  double scale_ = 1.0;
  double shift_ = 0.0;
  double delta_ = 0.0;            // scaled penetration
  double contacts_ = 0.0;         // pixels in the contact set at the last evaluation
  double descent_ = 0.0;
  double old_slope_ = 0.0;
  double direction_sum_on_contact_ = 0.0;  // sum of t over the contact set after a step
  // The last step p <- step_scale p - step_length t, and whether it was that exactly.
  double step_scale_ = 1.0;
  double step_length_ = 0.0;
  bool linear_update_ready_ = false;
  // Whether the state's gap array holds the gap of the current iterate (evaluate_gap was the
  // last to touch either); finish() evaluates it otherwise.
  bool gap_is_current_ = false;
  int linear_updates_ = 0;
};

}  // namespace asp
