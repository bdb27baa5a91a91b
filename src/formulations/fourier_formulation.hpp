// SPDX-License-Identifier: GPL-2.0-or-later
// The unconstrained problem of a soft potential (soft_formulation.hpp) in the thesis's
// preconditioned Fourier variables (section 4.2): the displacement's spectrum U (the
// substrate's r2c half spectrum; 1D and 2D, odd and even sizes), scaled mode by mode so that
// the elastic energy is half the squared norm of the variable,
//     v_k = sqrt(w_k s_k / N) U_k,   (1/2) u.K u = (1/2) sum_k |v_k|^2,
// with s_k = K~(q_k) over the pixel stiffness and w_k the entry's Parseval weight (2 for an
// entry that stands for itself and its mirror, 1 otherwise). The unknowns are the real and
// imaginary parts of v. The elastic Hessian is the identity; only the potential's part of the
// Hessian is left to the solver. (The thesis writes v = sqrt(K~) u~ and keeps the weights in
// the gradient, eqs. 62-66; folding them into the variable makes the plain inner product the
// right one.) Mass-weighted FIRE with masses proportional to K~(q) (Zhou et al. 2019) is FIRE
// with unit masses on this variable.
//
// The half spectrum holds a few more reals than the N of the field: the imaginary parts of
// the entries that stand for one real mode (q = 0, Nyquist), and in 2D the column kx = 0 (and
// kx = nx/2) whose entries ky and ny - ky are conjugates. The backward transform reads only
// the Hermitian part of these, and the gradient (a forward transform of a real field) is
// Hermitian: started from a real field's spectrum, the iterate stays in that subspace, where
// the variable is an orthogonal image of the field's N real degrees of freedom (FFTW's R2HC
// coefficients would give the same, at 2-3 times the transforms' cost).
//
// The q = 0 mode: under penetration control it is elastic like the others, with the
// stiffness K~(0) of the system's convention. Under mean-pressure control it has no elastic
// energy; its coefficient is still scaled with K~(0), which only sets the size of its steps,
// and the load's term pbar sum u = pbar Re U_0 drives it.
//
// One evaluation costs one backward transform (v to u, for the gaps) and one forward
// (phi' to the gradient): one FFT pair. The error measure, the largest force-balance residual
// in real space as for every formulation, costs one more backward transform. Periodic
// substrates only: a free substrate's stiffness is not diagonal in the box's spectrum.
#pragma once

#include "formulations/soft_formulation.hpp"

namespace asp {

class FourierFormulation final : public SoftFormulation {
 public:
  // Checks the scene (throws Error, the state untouched), allocates, and starts from the
  // displacement of the system's state.
  FourierFormulation(System &system, Control control, double value);

  Field &variable() override { return variable_; }
  double value_and_gradient(const double *v, double *gradient) override;
  bool quadratic() const override { return false; }
  // (I + A^T phi''(g) A) d at the iterate, A the map from v to u.
  void hessian_product(const double *direction, double *product) override;
  double gradient_at_zero(double *out) override;
  // 1 + (the largest phi'' at the iterate) / (the smallest s_k): |A|^2 = 1/min s_k.
  double largest_curvature(bool with_interaction = true) override;
  // The largest |K u + phi'(g) + pbar| in real space, from the gradient (one transform).
  double error(const double *v, const double *gradient) const override;
  bool finish() override;

  // The real-space displacement of a variable, scaled (for tests).
  void displacement_of(const double *v, double *u);

 private:
  // v's scaled spectrum U/N into spectrum_ (the backward transform's input for u).
  void spectrum_of(const double *v) const;
  // gradient = elastic v + to_gradient R2C(field), entry by entry; returns the elastic
  // energy (1/2) sum elastic |v|^2 from the same pass.
  double add_transformed(const double *v, const double *field, double *gradient);

  std::int64_t entries_;  // of the half spectrum
  Field variable_;        // (Re v_k, Im v_k) for each entry k
  Field to_spectrum_;     // U_k = to_spectrum_k v_k: sqrt(N/(w_k s_k))
  Field to_gradient_;     // the gradient's part from phi' is to_gradient_k R2C(phi' + pbar)_k,
                          // to_spectrum_k w_k / N
  Field elastic_;         // 1, or 0 for the q = 0 entry under mean-pressure control
  Field displacement_;    // u of the last evaluation
  mutable Spectrum spectrum_;  // work space (the backward transform destroys its input)
  mutable Field residual_;     // the error measure's residual in real space
  double largest_compliance_;  // max_k 1/s_k
};

}  // namespace asp
