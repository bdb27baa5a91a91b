#include "physics/periodic_halfspace.hpp"

#include <cmath>

#include "core/checks.hpp"

namespace asp {

PeriodicHalfSpace::PeriodicHalfSpace(const Grid &grid, double contact_modulus)
    : grid_(grid), modulus_(contact_modulus) {
  require_positive(contact_modulus, "contact_modulus");
  k0_ = default_k0();
}

double PeriodicHalfSpace::default_k0() const {
  // Mean of K~ at the lowest wavevector of each axis that has one; a single pixel has none,
  // and then the x box length sets the scale.
  double sum = 0.0;
  int axes = 0;
  if (grid_.nx() > 1) {
    sum += 0.5 * modulus_ * grid_.qx(1);
    ++axes;
  }
  if (grid_.ny() > 1) {
    sum += 0.5 * modulus_ * grid_.qy(1);
    ++axes;
  }
  return axes > 0 ? sum / axes : 0.5 * modulus_ * grid_.qx(1);
}

void PeriodicHalfSpace::set_k0(double k0) {
  require_positive(k0, "k0");
  const double n = static_cast<double>(grid_.n_pixels());
  if (!compliance_.empty()) compliance_[0] = 1.0 / (n * k0);
  if (pixel_stiffness_ >= 0.0) pixel_stiffness_ += (k0 - k0_) / n;
  k0_ = k0;
}

double PeriodicHalfSpace::stiffness(std::int64_t kx, std::int64_t ky) const {
  if (kx == 0 && ky == 0) return k0_;
  const double qx = grid_.qx(kx), qy = grid_.qy(ky);
  return 0.5 * modulus_ * std::sqrt(qx * qx + qy * qy);
}

double PeriodicHalfSpace::pixel_stiffness() const {
  if (pixel_stiffness_ < 0.0) {
    double sum = 0.0;
    for (std::int64_t ky = 0; ky < grid_.ny(); ++ky)
      for (std::int64_t kx = 0; kx < grid_.spectral_nx(); ++kx)
        sum += grid_.hermitian_weight(kx) * stiffness(kx, ky);
    pixel_stiffness_ = sum / static_cast<double>(grid_.n_pixels());
  }
  return pixel_stiffness_;
}

const Field &PeriodicHalfSpace::normalised_compliance() const {
  if (compliance_.empty()) {
    Field c(static_cast<std::size_t>(grid_.n_spectral()));
    const double n = static_cast<double>(grid_.n_pixels());
    const std::int64_t snx = grid_.spectral_nx();
    for (std::int64_t ky = 0; ky < grid_.ny(); ++ky)
      for (std::int64_t kx = 0; kx < snx; ++kx)
        c[static_cast<std::size_t>(kx + snx * ky)] = 1.0 / (n * stiffness(kx, ky));
    compliance_ = std::move(c);
  }
  return compliance_;
}

void PeriodicHalfSpace::apply_kernel(const double *in, double *out, Complex *scratch,
                                     bool inverse) const {
  const FftEngine &fft = grid_.fft();
  fft.forward(in, scratch);
  const double n = static_cast<double>(grid_.n_pixels());
  const std::int64_t snx = grid_.spectral_nx();
  for (std::int64_t ky = 0; ky < grid_.ny(); ++ky)
    for (std::int64_t kx = 0; kx < snx; ++kx) {
      const double k = stiffness(kx, ky);
      scratch[kx + snx * ky] *= inverse ? 1.0 / (n * k) : k / n;
    }
  fft.backward(scratch, out);
}

void PeriodicHalfSpace::displacement_from_pressure(const double *pressure, double *displacement,
                                                   Complex *scratch) const {
  apply_kernel(pressure, displacement, scratch, true);
}

void PeriodicHalfSpace::pressure_from_displacement(const double *displacement, double *pressure,
                                                   Complex *scratch) const {
  apply_kernel(displacement, pressure, scratch, false);
}

double PeriodicHalfSpace::elastic_energy(const double *displacement, Complex *scratch) const {
  grid_.fft().forward(displacement, scratch);
  const double n = static_cast<double>(grid_.n_pixels());
  const std::int64_t snx = grid_.spectral_nx();
  double sum = 0.0;
  for (std::int64_t ky = 0; ky < grid_.ny(); ++ky)
    for (std::int64_t kx = 0; kx < snx; ++kx)
      sum += grid_.hermitian_weight(kx) * stiffness(kx, ky) * std::norm(scratch[kx + snx * ky]);
  grid_.reductions().combine_sums(&sum, 1);
  return 0.5 * grid_.area() * sum / (n * n);
}

}  // namespace asp
