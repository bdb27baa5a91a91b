// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/displacement_formulation.hpp"

#include <algorithm>
#include <cmath>

#include "core/loops.hpp"

namespace asp {

DisplacementFormulation::DisplacementFormulation(System &system, Control control, double value)
    : SoftFormulation(system, control, value) {
  unknowns_ = substrate_.surface_size();
  displacement_ = Field(static_cast<std::size_t>(unknowns_));
  spectrum_ = substrate_.make_spectrum();
  double *u = displacement_.data();
  starting_displacement(u);
  if (substrate_.surface_beyond_grid()) {
    // Outside the box, the displacement that the state's pressure makes there.
    Field surface(static_cast<std::size_t>(unknowns_));
    substrate_.compliance_onto_surface(state_.pressure.data(), surface.data(), spectrum_.data());
    counters_.transforms += 2;
    const double per_length = 1.0 / length_unit_;
    const double *outside = surface.data();
    loops::for_each(unknowns_ - n_,
                    [&](std::int64_t i) { u[n_ + i] = outside[n_ + i] * per_length; });
  }
}

void DisplacementFormulation::apply_stiffness(const double *x, double *out) {
  // Scaled (over the pixel stiffness); without the q = 0 mode under mean-pressure control.
  substrate_.apply_stiffness(x, out, spectrum_.data(),
                             Substrate::KernelTimes{1.0 / substrate_.pixel_stiffness(),
                                                    load_control()});
  counters_.transforms += 2;
}

double DisplacementFormulation::value_and_gradient(const double *x, double *gradient) {
  // E = (1/2) x.K x + sum_i phi(g_i) (+ pbar sum x_i); gradient K x + phi'(g) (+ pbar).
  apply_stiffness(x, gradient);
  counters_.evaluations += 1;
  const double outside = interaction(x);
  const double *dphi = dphi_.data();
  const double elastic = 0.5 * loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    const double e = x[i] * gradient[i];
    gradient[i] += dphi[i];
    return e;
  });
  const double beyond = 0.5 * loops::sum(grid_.reductions(), unknowns_ - n_, [&](std::int64_t i) {
    return x[n_ + i] * gradient[n_ + i];
  });
  return elastic + beyond + outside;
}

void DisplacementFormulation::hessian_product(const double *direction, double *product) {
  apply_stiffness(direction, product);
  interaction(displacement_.data(), true);
  const double *d2phi = d2phi_.data();
  loops::for_each(n_, [&](std::int64_t i) { product[i] += d2phi[i] * direction[i]; });
}

double DisplacementFormulation::gradient_at_zero(double *out) {
  const Field zero(static_cast<std::size_t>(unknowns_), 0.0);
  return value_and_gradient(zero.data(), out);
}

double DisplacementFormulation::largest_curvature(bool with_interaction) {
  // Gershgorin would need the stiffness's off-diagonal sums; the stiffness's largest
  // eigenvalue is its largest mode, and the potential adds at most its largest phi''.
  const double *k = substrate_.normalised_stiffness().data();
  const double factor = substrate_.transform_points() / substrate_.pixel_stiffness();
  const double largest_mode =
      loops::maximum(grid_.reductions(), static_cast<std::int64_t>(spectrum_.size()),
                     [&](std::int64_t q) { return factor * k[q]; });
  if (!with_interaction) return largest_mode;
  interaction(displacement_.data(), true);
  return largest_mode + largest_interaction_curvature();
}

double DisplacementFormulation::error(const double *, const double *gradient) const {
  return loops::maximum(grid_.reductions(), unknowns_,
                        [&](std::int64_t i) { return std::fabs(gradient[i]); });
}

}  // namespace asp
