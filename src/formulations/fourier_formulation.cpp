// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/fourier_formulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {

FourierFormulation::FourierFormulation(System &system, Control control, double value)
    : SoftFormulation(system, control, value) {
  if (!substrate_.periodic())
    throw Error(Status::unsupported,
                "the Fourier formulation works on a periodic substrate only: on a " +
                    std::string(substrate_.name()) +
                    " the stiffness is not diagonal in the box's spectrum");
  const SpectralLayout &layout = substrate_.layout();
  entries_ = layout.size();
  unknowns_ = 2 * entries_;
  const auto entries = static_cast<std::size_t>(entries_);
  variable_ = Field(2 * entries);
  to_spectrum_ = Field(entries);
  to_gradient_ = Field(entries);
  elastic_ = Field(entries, 1.0);
  displacement_ = Field(static_cast<std::size_t>(n_));
  spectrum_ = substrate_.make_spectrum();
  residual_ = Field(static_cast<std::size_t>(n_));

  // s_k from the substrate's stiffness, which includes the transform's 1/N.
  const double *stiffness = substrate_.normalised_stiffness().data();
  const double points = substrate_.transform_points();
  const double per_pixel = points / substrate_.pixel_stiffness();
  double *a = to_spectrum_.data(), *b = to_gradient_.data();
  largest_compliance_ = 0.0;
  layout.for_each([&](std::int64_t k, double, double weight) {
    const double s = stiffness[k] * per_pixel;
    a[k] = std::sqrt(points / (weight * s));
    b[k] = a[k] * weight / points;
    largest_compliance_ = std::max(largest_compliance_, 1.0 / s);
  });
  grid_.reductions().combine_maxima(&largest_compliance_, 1);
  if (load_control() && layout.is_mean(0)) elastic_[0] = 0.0;

  // The start: the state's displacement, transformed and scaled.
  double *u = displacement_.data();
  starting_displacement(u);
  substrate_.forward(u, spectrum_.data());
  counters_.transforms += 1;
  const Complex *U = spectrum_.data();
  double *v = variable_.data();
  loops::for_each(entries_, [&](std::int64_t k) {
    v[2 * k] = U[k].real() / a[k];
    v[2 * k + 1] = U[k].imag() / a[k];
  });
}

void FourierFormulation::spectrum_of(const double *v) const {
  // U = to_spectrum v, over N for the unnormalised backward transform.
  Complex *U = spectrum_.data();
  const double *a = to_spectrum_.data();
  const double per_point = 1.0 / substrate_.transform_points();
  loops::for_each(entries_, [&](std::int64_t k) {
    U[k] = Complex(v[2 * k], v[2 * k + 1]) * (a[k] * per_point);
  });
}

void FourierFormulation::displacement_of(const double *v, double *u) {
  spectrum_of(v);
  substrate_.backward(spectrum_.data(), u);
  counters_.transforms += 1;
}

double FourierFormulation::add_transformed(const double *v, const double *field,
                                           double *gradient) {
  // Since the backward transform is the forward one's adjoint times the weights, the
  // gradient of sum_i f(u_i) with respect to U_k is w_k R2C(f')_k / N (eqs. 69-73).
  substrate_.forward(field, spectrum_.data());
  counters_.transforms += 1;
  const Complex *F = spectrum_.data();
  const double *b = to_gradient_.data(), *elastic = elastic_.data();
  return 0.5 * loops::sum(grid_.reductions(), entries_, [&](std::int64_t k) {
    const double re = elastic[k] * v[2 * k], im = elastic[k] * v[2 * k + 1];
    gradient[2 * k] = re + b[k] * F[k].real();
    gradient[2 * k + 1] = im + b[k] * F[k].imag();
    return re * v[2 * k] + im * v[2 * k + 1];
  });
}

double FourierFormulation::value_and_gradient(const double *v, double *gradient) {
  // E = (1/2) sum_k elastic_k |v_k|^2 + sum_i phi(g_i) + pbar sum_i u_i.
  double *u = displacement_.data();
  displacement_of(v, u);
  counters_.evaluations += 1;
  const double outside = interaction(u);
  return add_transformed(v, dphi_.data(), gradient) + outside;
}

void FourierFormulation::hessian_product(const double *direction, double *product) {
  // phi'' at the iterate, then A d in real space, times phi'', back: A^T = to_gradient R2C.
  interaction(displacement_.data(), true);
  Field real(static_cast<std::size_t>(n_));
  displacement_of(direction, real.data());
  const double *d2phi = d2phi_.data();
  double *r = real.data();
  loops::for_each(n_, [&](std::int64_t i) { r[i] *= d2phi[i]; });
  add_transformed(direction, r, product);
}

double FourierFormulation::gradient_at_zero(double *out) {
  const Field zero(static_cast<std::size_t>(unknowns_), 0.0);
  return value_and_gradient(zero.data(), out);
}

double FourierFormulation::largest_curvature(bool with_interaction) {
  if (!with_interaction) return 1.0;
  interaction(displacement_.data(), true);
  return 1.0 + largest_interaction_curvature() * largest_compliance_;
}

double FourierFormulation::error(const double *, const double *gradient) const {
  // The residual's spectrum is gradient_k N/(to_spectrum_k w_k) = gradient_k/to_gradient_k,
  // and the residual its backward transform over N.
  Complex *R = spectrum_.data();
  const double *b = to_gradient_.data();
  const double per_point = 1.0 / substrate_.transform_points();
  loops::for_each(entries_, [&](std::int64_t k) {
    R[k] = Complex(gradient[2 * k], gradient[2 * k + 1]) * (per_point / b[k]);
  });
  substrate_.backward(spectrum_.data(), residual_.data());
  counters_.transforms += 1;
  const double *r = residual_.data();
  return loops::maximum(grid_.reductions(), n_, [&](std::int64_t i) { return std::fabs(r[i]); });
}

bool FourierFormulation::finish() {
  // The state from the variable's own spectrum U = to_spectrum v, as the error measure reads
  // it (the elastic pressure s_k U_k mode by mode), not from a transform of the real-space
  // displacement: under mean-pressure control that holds the penetration in its mean, whose
  // rounding the transform would spread over every mode.
  Complex *U = spectrum_.data();
  const double *a = to_spectrum_.data();
  const double *v = variable_.data();
  loops::for_each(entries_, [&](std::int64_t k) {
    U[k] = Complex(v[2 * k], v[2 * k + 1]) * a[k];
  });
  return store_state_from_spectrum(U);
}

}  // namespace asp
