#include "physics/potential.hpp"

#include <cmath>

#include "core/checks.hpp"
#include "core/loops.hpp"

namespace asp {

SoftWallPotential::Exponential::Terms SoftWallPotential::Exponential::at(double g) const {
  // Beyond the threshold t0 = largest_exponent, with t = -g/r: the Taylor expansion of
  // c e^t about t0, c e^t0 (1 + s + s^2/2) with s = t - t0, and its derivatives in g.
  const double t = -g / range;
  if (t <= largest_exponent) {
    const double value = coefficient * std::exp(t);
    return {value, -value / range, value / (range * range)};
  }
  const double s = t - largest_exponent;
  const double base = coefficient * std::exp(largest_exponent);
  return {base * (1.0 + s + 0.5 * s * s), -base * (1.0 + s) / range, base / (range * range)};
}

SoftWallPotential::SoftWallPotential(double repulsion, double repulsion_range, double attraction,
                                     double attraction_range)
    : repulsion_{repulsion, 0.5 * repulsion_range},
      attraction_{-attraction, attraction_range} {}

void SoftWallPotential::evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                                 double *d2phi) const {
  const Exponential r = repulsion_, a = attraction_;
  if (d2phi != nullptr) {
    loops::for_each(n, [&](std::int64_t i) {
      const Exponential::Terms tr = r.at(gap[i]), ta = a.at(gap[i]);
      phi[i] = tr.value + ta.value;
      dphi[i] = tr.slope + ta.slope;
      d2phi[i] = tr.curvature + ta.curvature;
    });
  } else {
    loops::for_each(n, [&](std::int64_t i) {
      const Exponential::Terms tr = r.at(gap[i]), ta = a.at(gap[i]);
      phi[i] = tr.value + ta.value;
      dphi[i] = tr.slope + ta.slope;
    });
  }
}

std::unique_ptr<Potential> SoftWallPotential::in_units(double length, double pressure) const {
  const double energy = pressure * length;
  return std::make_unique<SoftWallPotential>(repulsion_.coefficient / energy,
                                             2.0 * repulsion_.range / length,
                                             -attraction_.coefficient / energy,
                                             attraction_.range / length);
}

double SoftWallPotential::pressure_scale() const {
  if (attraction_.coefficient < 0.0) return -attraction_.coefficient / attraction_.range;
  return repulsion_.coefficient / repulsion_.range;
}

double SoftWallPotential::length_scale() const {
  return attraction_.coefficient < 0.0 ? std::fmax(repulsion_.range, attraction_.range)
                                       : repulsion_.range;
}

std::string SoftWallPotential::description() const {
  return "soft wall (repulsion " + format_number(repulsion_.coefficient) + ", range " +
         format_number(2.0 * repulsion_.range) + "; attraction " +
         format_number(-attraction_.coefficient) + ", range " +
         format_number(attraction_.range) + ")";
}

}  // namespace asp
