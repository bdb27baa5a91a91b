// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/periodic_halfspace.hpp"

#include <cfloat>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {

namespace {
bool normal(double v) { return std::isfinite(v) && v >= DBL_MIN; }
}  // namespace

PeriodicHalfSpace::PeriodicHalfSpace(const Grid &grid, double contact_modulus)
    : PeriodicHalfSpace(grid, (require_positive(contact_modulus, "contact_modulus"),
                               std::make_unique<HalfSpaceLaw>(contact_modulus))) {}

PeriodicHalfSpace::PeriodicHalfSpace(const Grid &grid, std::unique_ptr<const StiffnessLaw> law)
    : grid_(grid),
      law_(std::move(law)),
      layout_(grid.half_spectrum()),
      modulus_(law_->contact_modulus()) {
  const double n = static_cast<double>(grid.n_pixels());

  // Default K~(0), where the law has none of its own: mean of K~ at the lowest wavevector of
  // each axis with more than one pixel; a single pixel has none, and then the x box length
  // sets the scale.
  const double two_pi = 6.283185307179586476925286766559;
  if (law_->at_zero() > 0.0) {
    k0_ = law_->at_zero();
  } else {
    double sum = 0.0;
    int axes = 0;
    if (grid.nx() > 1) sum += law_->at(two_pi / grid.lx()), ++axes;
    if (grid.ny() > 1) sum += law_->at(two_pi / grid.ly()), ++axes;
    k0_ = axes > 0 ? sum / axes : law_->at(two_pi / grid.lx());
  }

  // Every mode's stiffness, its inverse with the 1/N of the transform, and the sums below
  // must be finite, normal doubles; otherwise the scene cannot be represented. A law need
  // not be monotonic (a layer's dips below its K~(0) before it rises), so the extremes are
  // taken over every mode.
  double extremes[2] = {-k0_, k0_};  // -(smallest), largest
  double sums[2] = {0.0, 0.0};  // of weight * K~(q) and weight / K~(q) over q != 0
  layout_.for_each([&](std::int64_t, double q, double weight) {
    if (!(q > 0.0)) return;
    const double k = stiffness_at(q);
    sums[0] += weight * k;
    sums[1] += weight / k;
    extremes[0] = std::fmax(extremes[0], -k);
    extremes[1] = std::fmax(extremes[1], k);
  });
  grid.reductions().combine_sums(sums, 2);
  grid.reductions().combine_maxima(extremes, 2);
  nonzero_stiffness_sum_ = sums[0];
  nonzero_compliance_sum_ = sums[1];
  pixel_stiffness_ = (nonzero_stiffness_sum_ + k0_) / n;
  self_compliance_ = (nonzero_compliance_sum_ + 1.0 / k0_) / n;

  const double k_min = -extremes[0];
  const double k_max = extremes[1];
  if (!normal(k_min) || !normal(n * k_max) || !normal(1.0 / (n * k_min)) ||
      !normal(pixel_stiffness_) || !normal(nonzero_stiffness_sum_ + k0_) ||
      !normal(self_compliance_))
    throw Error(Status::invalid_argument,
                "argument 'contact_modulus' is " + format_number(modulus_) +
                    ": on this grid the stiffness " + law_->formula() +
                    " of its modes ranges from " + format_number(k_min) + " to " +
                    format_number(k_max) +
                    ", which doubles cannot hold with their inverses; rescale the units");
}

void PeriodicHalfSpace::set_k0(double k0) {
  if (law_->at_zero() > 0.0)
    throw Error(Status::unsupported,
                std::string("argument 'system' is on a ") + law_->name() +
                    ", whose stiffness under a uniform pressure, K~(0) = " +
                    format_number(law_->at_zero()) +
                    ", is the body's own, not a convention to set");
  require_positive(k0, "k0");
  const double n = static_cast<double>(grid_.n_pixels());
  const double pixel = (nonzero_stiffness_sum_ + k0) / n;
  const double self = (nonzero_compliance_sum_ + 1.0 / k0) / n;
  if (!normal(n * k0) || !normal(1.0 / (n * k0)) || !normal(pixel) || !normal(self))
    throw Error(Status::invalid_argument,
                "argument 'k0' is " + format_number(k0) +
                    ": its inverse, the pixel stiffness or the pixel's own compliance would "
                    "not be a finite, normal double");
  k0_ = k0;
  pixel_stiffness_ = pixel;
  self_compliance_ = self;
  // The q = 0 entry is the first of the half spectrum (on the process holding it).
  if (layout_.is_mean(0)) {
    if (!compliance_.empty()) compliance_[0] = 1.0 / (n * k0_);
    if (!stiffness_.empty()) stiffness_[0] = k0_ / n;
  }
}

const Field &PeriodicHalfSpace::normalised_compliance() const {
  if (compliance_.empty()) {
    Field c(static_cast<std::size_t>(layout_.size()));
    const double n = static_cast<double>(grid_.n_pixels());
    layout_.for_each([&](std::int64_t k, double q, double) { c[k] = 1.0 / (n * stiffness_at(q)); });
    compliance_ = std::move(c);
  }
  return compliance_;
}

const Field &PeriodicHalfSpace::normalised_stiffness() const {
  if (stiffness_.empty()) {
    Field s(static_cast<std::size_t>(layout_.size()));
    const double n = static_cast<double>(grid_.n_pixels());
    layout_.for_each([&](std::int64_t k, double q, double) { s[k] = stiffness_at(q) / n; });
    stiffness_ = std::move(s);
  }
  return stiffness_;
}

void PeriodicHalfSpace::forward(const double *field, Complex *spectrum) const {
  grid_.fft().forward(field, spectrum);
}

void PeriodicHalfSpace::backward(Complex *spectrum, double *field) const {
  grid_.fft().backward(spectrum, field);
}

void PeriodicHalfSpace::displacement_from_pressure(const double *pressure,
                                                   double *displacement) const {
  apply_compliance(pressure, displacement);
}

void PeriodicHalfSpace::pressure_from_displacement(const double *displacement,
                                                   double *pressure) const {
  apply_stiffness(displacement, pressure);
}

double PeriodicHalfSpace::elastic_energy_of_pressure(const double *pressure) const {
  // From the pressure, u = K^-1 p, rather than from the system's g + h - max h + delta: the
  // latter cancels the heights, and its round-off, squared in the energy, can dwarf small
  // deformations of tall surfaces. The q = 0 mode is left out either way.
  const std::int64_t n = grid_.local_pixels();
  if (loops::maximum(grid_.reductions(), n,
                     [&](std::int64_t i) { return std::fabs(pressure[i]); }) == 0.0)
    return 0.0;
  Field u = grid_.make_field();
  apply_compliance(pressure, u.data(), nullptr,
                   [](Complex *s, const double *compliance, const SpectralLayout &layout) {
                     layout.for_each([&](std::int64_t k, double q, double) {
                       s[k] = q > 0.0 ? s[k] * compliance[k] : Complex(0.0);
                     });
                   });
  return elastic_energy(u.data());
}

double PeriodicHalfSpace::elastic_energy(const double *displacement) const {
  // (A/2) sum_q K~ |u^_q|^2 with u^ = FFT(u)/N. The displacement is divided by its largest
  // magnitude first, so that squares cannot overflow for any representable field.
  const std::int64_t local = grid_.local_pixels();
  const double largest = loops::maximum(grid_.reductions(), local,
                                        [&](std::int64_t i) { return std::fabs(displacement[i]); });
  if (!(largest > 0.0)) return 0.0;
  Field u = grid_.make_field();
  loops::for_each(local, [&](std::int64_t i) { u[i] = displacement[i] / largest; });
  Spectrum s = make_spectrum();
  forward(u.data(), s.data());
  const double n = static_cast<double>(grid_.n_pixels());
  double sum = 0.0;
  layout_.for_each([&](std::int64_t k, double q, double weight) {
    if (q > 0.0) sum += weight * (stiffness_at(q) / n) * (std::norm(s[k]) / n);
  });
  grid_.reductions().combine_sums(&sum, 1);
  return 0.5 * grid_.area() * sum * largest * largest;
}

}  // namespace asp
