#include "physics/system.hpp"

#include <algorithm>
#include <cmath>

#include "physics/surface_statistics.hpp"

namespace asp {

System::System(const Grid &grid, double contact_modulus)
    : grid_(grid),
      substrate_(grid, contact_modulus),
      heights_(grid.make_field()),
      state_{grid.make_field(), grid.make_field(), 0.0} {
  last_reference_pressure_ = reference_pressure(0.0);
  reset_state();
}

void System::set_topography(const double *heights) {
  std::copy(heights, heights + grid_.n_pixels(), heights_.begin());
  max_height_ = grid_.reductions().max(heights_.data(), grid_.n_pixels());
  slope_pressure_ =
      0.5 * substrate_.contact_modulus() * surface_statistics(grid_, heights_.data()).rms_slope;
  last_reference_pressure_ = reference_pressure(0.0);
  reset_state();
}

double System::reference_pressure(double control_scale) const {
  if (reference_pressure_override_ > 0.0) return reference_pressure_override_;
  if (slope_pressure_ > 0.0) return slope_pressure_;
  if (control_scale > 0.0) return control_scale;
  return substrate_.contact_modulus();
}

void System::reset_state() {
  // Zero pressure: the undeformed body touching the highest point, gap = max h - h.
  std::fill(state_.pressure.begin(), state_.pressure.end(), 0.0);
  for (std::int64_t k = 0; k < grid_.n_pixels(); ++k)
    state_.gap[static_cast<std::size_t>(k)] = max_height_ - heights_[static_cast<std::size_t>(k)];
  state_.penetration = 0.0;
}

double System::contact_fraction() const {
  double count = 0.0;
  for (double p : state_.pressure) count += p > 0.0 ? 1.0 : 0.0;
  grid_.reductions().combine_sums(&count, 1);
  return count / static_cast<double>(grid_.n_pixels());
}

double System::mean_pressure() const {
  return grid_.reductions().sum(state_.pressure.data(), grid_.n_pixels()) /
         static_cast<double>(grid_.n_pixels());
}

double System::mean_gap() const {
  return grid_.reductions().sum(state_.gap.data(), grid_.n_pixels()) /
         static_cast<double>(grid_.n_pixels());
}

void System::displacement(double *out) const {
  // u = g + h - max h + delta, from the definition of the gap.
  const double shift = state_.penetration - max_height_;
  for (std::int64_t k = 0; k < grid_.n_pixels(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    out[k] = state_.gap[i] + heights_[i] + shift;
  }
}

double System::mean_mode_energy() const {
  const double p_mean = mean_pressure();
  return 0.5 * grid_.area() * p_mean * (p_mean / substrate_.k0());
}

double System::elastic_energy() const {
  // E_el = (1/2) u.K u = (a/2) sum p_i u_i, since the state has p = K u.
  const double shift = state_.penetration - max_height_;
  double sum = 0.0;
  for (std::int64_t k = 0; k < grid_.n_pixels(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    sum += state_.pressure[i] * (state_.gap[i] + heights_[i] + shift);
  }
  grid_.reductions().combine_sums(&sum, 1);
  return 0.5 * grid_.pixel_area() * sum;
}

}  // namespace asp
