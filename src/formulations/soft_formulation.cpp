// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/soft_formulation.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {

SoftFormulation::SoftFormulation(System &system, Control control, double value)
    : ScaledFormulation(system, control, value) {
  const PotentialInteraction *soft = potential_interaction(system.interaction());
  if (soft == nullptr || soft->has_hard_wall())
    throw Error(Status::internal, "an unconstrained formulation needs a soft potential");
  if (control == Control::mean_gap)
    throw Error(Status::unsupported,
                "the unconstrained formulations offer penetration and mean-pressure control");
  if (control == Control::mean_pressure && !substrate_.has_k0())
    throw Error(Status::unsupported,
                "mean-pressure control of an unconstrained formulation is offered on a "
                "periodic substrate only: on a " + std::string(substrate_.name()) +
                    " the rigid-body penetration is not a free mode of the displacement; use "
                    "penetration control");
  load_ = control == Control::mean_pressure ? target_ : 0.0;
  penetration_ = control == Control::penetration ? target_ : 0.0;
  potential_ = soft->potential().in_units(length_unit_, pressure_unit_);
  gap_ = Field(static_cast<std::size_t>(n_));
  phi_ = Field(static_cast<std::size_t>(n_));
  dphi_ = Field(static_cast<std::size_t>(n_));
  d2phi_ = Field(static_cast<std::size_t>(n_));
}

double SoftFormulation::lower_bound() const { return -std::numeric_limits<double>::infinity(); }

void SoftFormulation::starting_displacement(double *u) const {
  // The displacement of the state's gap, u = g + (h - max h) + delta; under mean-pressure
  // control less the penetration, which the objective folds into it, so that the gap carries
  // over. There it is g + (h - max h) itself: adding the penetration and taking it away again
  // would cost the gap its rounding at the penetration's size.
  const double per_length = 1.0 / length_unit_, top = max_height_;
  const double shift = load_control() ? 0.0 : state_.penetration;
  const double *g = state_.gap.data();
  loops::for_each(n_, [&](std::int64_t i) {
    u[i] = (g[i] + (heights_[i] - top) + shift) * per_length;
  });
}

double SoftFormulation::interaction(const double *u, bool curvature) {
  double *g = gap_.data();
  const double per_length = 1.0 / length_unit_, top = max_height_, delta = penetration_;
  loops::for_each(n_, [&](std::int64_t i) {
    g[i] = u[i] - (heights_[i] - top) * per_length - delta;
  });
  potential_->evaluate(n_, g, phi_.data(), dphi_.data(), curvature ? d2phi_.data() : nullptr);
  const double *phi = phi_.data();
  double *dphi = dphi_.data();
  const double load = load_;
  if (load == 0.0)
    return loops::sum(grid_.reductions(), n_, [&](std::int64_t i) { return phi[i]; });
  return loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    dphi[i] += load;
    return phi[i] + load * u[i];
  });
}

double SoftFormulation::largest_interaction_curvature() const {
  const double *d2phi = d2phi_.data();
  const double largest =
      loops::maximum(grid_.reductions(), n_, [&](std::int64_t i) { return d2phi[i]; });
  return largest > 0.0 ? largest : 0.0;
}

double SoftFormulation::contact_fraction(const double *, const double *) const {
  const double *dphi = dphi_.data();
  const double load = load_;
  return loops::sum(grid_.reductions(), n_,
                    [&](std::int64_t i) { return dphi[i] - load < 0.0 ? 1.0 : 0.0; }) /
         pixels_;
}

bool SoftFormulation::store_state(const double *u) {
  Spectrum spectrum = substrate_.make_spectrum();
  substrate_.surface_forward(u, spectrum.data());
  counters_.transforms += 1;
  return store_state_from_spectrum(spectrum.data());
}

bool SoftFormulation::store_state_from_spectrum(Complex *s) {
  // Under mean-pressure control the mean displacement (scaled), U_0/N, which sets the
  // penetration below; it is read before the pass that overwrites the spectrum.
  double mean_u = 0.0;
  if (load_control()) {
    if (substrate_.layout().is_mean(0)) mean_u = s[0].real() / substrate_.transform_points();
    grid_.reductions().combine_sums(&mean_u, 1);
  }
  // The elastic pressure K u over the surface (scaled: the normalised stiffness over the
  // pixel stiffness), without the q = 0 mode under mean-pressure control, where pbar is its
  // mean instead.
  const std::int64_t surface = substrate_.surface_size();
  Field elastic(static_cast<std::size_t>(surface));
  substrate_.stiffness_of_spectrum(
      s, elastic.data(),
      Substrate::KernelTimes{1.0 / substrate_.pixel_stiffness(), load_control()});

  // The state: that pressure in physical units, then the gap it makes, so that gap =
  // K^-1 p - (h - max h) - delta holds to rounding (on a free substrate K u outside the box,
  // the residual, is left out).
  double *p = state_.pressure.data();
  const double *e = elastic.data();
  const double pressure = pressure_unit_, load = load_, n = pixels_;
  const double mean_pressure = loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    p[i] = (e[i] + load) * pressure;
    return p[i] / n;
  });
  double *displacement = elastic.data();
  substrate_.apply_compliance(p, displacement, s);
  counters_.transforms += 3;
  // Under mean-pressure control the convention mean u = pbar/K~(0) sets the penetration that
  // keeps the iterate's gap: delta = pbar/K~(0) - l mean(u).
  const double delta = load_control() ? mean_pressure / substrate_.k0() - length_unit_ * mean_u
                                      : penetration_ * length_unit_;
  const double top = max_height_;
  return system_.store_solved_state(
      [&](std::int64_t i) {
        return SolvedPixel{p[i], displacement[i] - (heights_[i] - top) - delta, false};
      },
      [&](double) { return delta; }, pressure_unit_);
}

}  // namespace asp
