#include "solvers/fourier_formulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {

FourierFormulation::FourierFormulation(System &system, Control control, double value)
    : SoftFormulation(system, control, value), fft_(system.grid().half_complex_fft()) {
  if (substrate_.kind() != SubstrateKind::periodic)
    throw Error(Status::unsupported,
                "the Fourier formulation works on a periodic half-space only: on a " +
                    std::string(substrate_name(substrate_.kind())) +
                    " the stiffness is not diagonal in the box's spectrum");
  const auto n = static_cast<std::size_t>(n_);
  variable_ = Field(n);
  to_spectrum_ = Field(n);
  to_gradient_ = Field(n);
  elastic_ = Field(n, 1.0);
  displacement_ = Field(n);
  coefficients_ = Field(n);
  residual_ = Field(n);

  // s_k from the substrate's half spectrum: the coefficient (kx, ky) carries the frequencies
  // (+-fx, +-fy), fx = min(kx, nx - kx), all of one |q|, stored at (fx, fy) of the r2c
  // spectrum (whose stiffness includes the transform's 1/N).
  const Grid &grid = grid_;
  const SpectralLayout layout(Packing::half_complex, grid.nx(), grid.ny(), grid.lx(), grid.ly());
  const std::int64_t nx = grid.nx(), ny = grid.ny(), row = nx / 2 + 1;
  const double *stiffness = substrate_.normalised_stiffness().data();
  const double points = static_cast<double>(n_);
  const double per_pixel = points / substrate_.pixel_stiffness();
  double *a = to_spectrum_.data(), *b = to_gradient_.data();
  largest_compliance_ = 0.0;
  layout.for_each([&](std::int64_t k, double, double weight) {
    const std::int64_t kx = k % nx, ky = k / nx;
    const std::int64_t fx = std::min(kx, nx - kx), fy = std::min(ky, ny - ky);
    const double s = stiffness[fx + row * fy] * per_pixel;
    a[k] = std::sqrt(points / (weight * s));
    b[k] = a[k] * weight / points;
    largest_compliance_ = std::max(largest_compliance_, 1.0 / s);
  });
  if (load_control()) elastic_[0] = 0.0;

  // The start: the state's displacement, transformed and scaled.
  double *u = displacement_.data();
  starting_displacement(u);
  fft_.forward(u, coefficients_.data());
  counters_.transforms += 1;
  const double *c = coefficients_.data();
  double *v = variable_.data();
  loops::for_each(n_, [&](std::int64_t k) { v[k] = c[k] / a[k]; });
}

void FourierFormulation::displacement_of(const double *v, double *u) {
  // u = HC2R(c)/N, c = to_spectrum v (HC2R is unnormalised).
  double *c = coefficients_.data();
  const double *a = to_spectrum_.data();
  const double inverse_points = 1.0 / static_cast<double>(n_);
  loops::for_each(n_, [&](std::int64_t k) { c[k] = a[k] * v[k] * inverse_points; });
  fft_.backward(c, u);
  counters_.transforms += 1;
}

double FourierFormulation::value_and_gradient(const double *v, double *gradient) {
  // E = (1/2) sum_k elastic_k v_k^2 + sum_i phi(g_i) + pbar sum_i u_i. Since HC2R is R2HC's
  // transpose times the weights, the gradient of the potential's part with respect to c_k is
  // w_k R2HC(phi' + pbar)_k / N (eqs. 69-73).
  double *u = displacement_.data();
  displacement_of(v, u);
  counters_.evaluations += 1;
  const double outside = interaction(u);
  fft_.forward(dphi_.data(), gradient);
  counters_.transforms += 1;
  const double *b = to_gradient_.data(), *elastic = elastic_.data();
  const double energy = 0.5 * loops::sum(grid_.reductions(), n_, [&](std::int64_t k) {
    const double e = elastic[k] * v[k];
    gradient[k] = e + b[k] * gradient[k];
    return e * v[k];
  });
  return energy + outside;
}

void FourierFormulation::hessian_product(const double *direction, double *product) {
  // phi'' at the iterate, then A d in real space, times phi'', back: A^T = to_gradient R2HC.
  interaction(displacement_.data(), true);
  Field real(static_cast<std::size_t>(n_));
  displacement_of(direction, real.data());
  const double *d2phi = d2phi_.data();
  double *r = real.data();
  loops::for_each(n_, [&](std::int64_t i) { r[i] *= d2phi[i]; });
  fft_.forward(r, product);
  counters_.transforms += 1;
  const double *b = to_gradient_.data(), *elastic = elastic_.data();
  loops::for_each(n_, [&](std::int64_t k) {
    product[k] = elastic[k] * direction[k] + b[k] * product[k];
  });
}

double FourierFormulation::gradient_at_zero(double *out) {
  const Field zero(static_cast<std::size_t>(n_), 0.0);
  return value_and_gradient(zero.data(), out);
}

double FourierFormulation::largest_curvature(bool with_interaction) {
  if (!with_interaction) return 1.0;
  interaction(displacement_.data(), true);
  return 1.0 + largest_interaction_curvature() * largest_compliance_;
}

double FourierFormulation::error(const double *, const double *gradient) const {
  // The residual's spectrum is gradient_k N/(to_spectrum_k w_k) = gradient_k/to_gradient_k,
  // and the residual HC2R of it over N.
  double *c = coefficients_.data();
  const double *b = to_gradient_.data();
  const double inverse_points = 1.0 / static_cast<double>(n_);
  loops::for_each(n_, [&](std::int64_t k) { c[k] = gradient[k] / b[k] * inverse_points; });
  fft_.backward(c, residual_.data());
  counters_.transforms += 1;
  const double *r = residual_.data();
  return loops::maximum(grid_.reductions(), n_, [&](std::int64_t i) { return std::fabs(r[i]); });
}

bool FourierFormulation::finish() {
  displacement_of(variable_.data(), displacement_.data());
  return store_state(displacement_.data());
}

}  // namespace asp
