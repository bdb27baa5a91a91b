// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/potential.hpp"

#include <cfloat>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"
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
      attraction_{-attraction, attraction_range},
      one_range_(repulsion_range == attraction_range) {}

namespace {

// One exponential c exp(t), t = -g/r, continued beyond t0 = largest_exponent by
// c e^t0 (1 + s + s^2/2), s = t - t0 (as SoftWallPotential::Exponential::at), without a branch:
// e = exp(min(t, t0)) and s = max(t - t0, 0) give both parts.
struct ExponentialTerm {
  double value, slope, curvature;
};
inline ExponentialTerm exponential_term(double coefficient, double per_range, double e,
                                        double s) {
  const double ce = coefficient * e;
  return {ce * (1.0 + s + 0.5 * s * s), -ce * (1.0 + s) * per_range,
          ce * per_range * per_range};
}

}  // namespace

template <bool with_curvature, bool one_range>
void SoftWallPotential::evaluate_terms(std::int64_t n, const double *gap, double *phi,
                                       double *dphi, double *d2phi) const {
  // Without branches (a select each) or divisions. With one range, the repulsion's exponent is
  // twice the attraction's: while it is below the threshold its exponential is the square of
  // the attraction's, beyond it e^t0.
  // Reciprocals, so that the loop multiplies instead of dividing.
  const double cr = repulsion_.coefficient, per_rr = 1.0 / repulsion_.range;
  const double ca = attraction_.coefficient, per_ra = 1.0 / attraction_.range;
  const double t0 = largest_exponent, e0 = std::exp(largest_exponent);
  loops::for_each(n, [&](std::int64_t i) {
    const double ta = -gap[i] * per_ra, tr = -gap[i] * per_rr;
    const double ea = std::exp(ta < t0 ? ta : t0);
    const double er = one_range ? (tr < t0 ? ea * ea : e0) : std::exp(tr < t0 ? tr : t0);
    const ExponentialTerm a = exponential_term(ca, per_ra, ea, ta > t0 ? ta - t0 : 0.0);
    const ExponentialTerm r = exponential_term(cr, per_rr, er, tr > t0 ? tr - t0 : 0.0);
    phi[i] = a.value + r.value;
    dphi[i] = a.slope + r.slope;
    if (with_curvature) d2phi[i] = a.curvature + r.curvature;
  });
}

void SoftWallPotential::evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                                 double *d2phi) const {
  // Each case its own loop, without a test inside.
  if (d2phi != nullptr) {
    if (one_range_)
      evaluate_terms<true, true>(n, gap, phi, dphi, d2phi);
    else
      evaluate_terms<true, false>(n, gap, phi, dphi, d2phi);
  } else {
    if (one_range_)
      evaluate_terms<false, true>(n, gap, phi, dphi, nullptr);
    else
      evaluate_terms<false, false>(n, gap, phi, dphi, nullptr);
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
  // Without attraction, the repulsion's stress at g = 0. With it, the largest tensile stress
  // phi'(g) = b u - a u^m over u = exp(-g/r_a), with a = c_r/r_r, b = gamma_a/r_a and
  // m = r_a/r_r: where the repulsion fades faster (m > 1) it is b u* (1 - 1/m) at
  // u* = (b/(a m))^(1/(m-1)); with one range (m = 2) gamma_a^2/(8 gamma_r rho). The
  // attraction's own scale b stands in where that maximum is not a finite, positive double.
  if (!(attraction_.coefficient < 0.0)) return repulsion_.coefficient / repulsion_.range;
  const double a = repulsion_.coefficient / repulsion_.range;
  const double b = -attraction_.coefficient / attraction_.range;
  const double m = attraction_.range / repulsion_.range;
  if (!(m > 1.0)) return b;
  const double u = std::pow(b / (a * m), 1.0 / (m - 1.0));
  const double largest = b * u * (1.0 - 1.0 / m);
  return std::isfinite(largest) && largest >= DBL_MIN ? largest : b;
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

namespace {

struct Terms {
  double value, slope, curvature;
};

// The 9-3 potential itself, for g > 0, from u = z0/g:
//   phi = (w/2)(u^9 - 3u^3), phi' = (9w/(2 z0)) u^4 (1 - u^6), phi'' = (9w/z0^2) u^5 (5u^6 - 2).
Terms lennard_jones_at(double work, double distance, double g) {
  const double u = distance / g, u3 = u * u * u, u6 = u3 * u3;
  return {0.5 * work * u3 * (u6 - 3.0), 4.5 * work / distance * u3 * u * (1.0 - u6),
          9.0 * work / (distance * distance) * u3 * u * u * (5.0 * u6 - 2.0)};
}

}  // namespace

LennardJonesPotential::LennardJonesPotential(double work_of_adhesion, double equilibrium_distance)
    : work_(work_of_adhesion), equilibrium_distance_(equilibrium_distance) {}

void LennardJonesPotential::evaluate(std::int64_t n, const double *gap, double *phi,
                                     double *dphi, double *d2phi) const {
  const double w = work_, z0 = equilibrium_distance_;
  const double start = threshold * z0;
  const Terms at_start = lennard_jones_at(w, z0, start);
  auto at = [=](double g) -> Terms {
    if (g >= start) return lennard_jones_at(w, z0, g);
    const double s = g - start;
    return {at_start.value + s * (at_start.slope + 0.5 * s * at_start.curvature),
            at_start.slope + s * at_start.curvature, at_start.curvature};
  };
  if (d2phi != nullptr) {
    loops::for_each(n, [&](std::int64_t i) {
      const Terms t = at(gap[i]);
      phi[i] = t.value;
      dphi[i] = t.slope;
      d2phi[i] = t.curvature;
    });
  } else {
    loops::for_each(n, [&](std::int64_t i) {
      const Terms t = at(gap[i]);
      phi[i] = t.value;
      dphi[i] = t.slope;
    });
  }
}

std::unique_ptr<Potential> LennardJonesPotential::in_units(double length, double pressure) const {
  return std::make_unique<LennardJonesPotential>(work_ / (pressure * length),
                                                 equilibrium_distance_ / length);
}

double LennardJonesPotential::pressure_scale() const {
  // phi' = (9w/(2 z0)) u^4 (1 - u^6) is largest where 4u^3 = 10u^9, u^6 = 2/5: there
  // (9w/(2 z0)) (2/5)^(2/3) (3/5).
  return 2.7 * std::pow(0.4, 2.0 / 3.0) * work_ / equilibrium_distance_;
}

std::string LennardJonesPotential::description() const {
  return "Lennard-Jones 9-3 wall potential (work of adhesion " + format_number(work_) +
         ", equilibrium distance " + format_number(equilibrium_distance_) + ")";
}

namespace {

// The index of the first entry of phi, dphi or d2phi (if not null) that is not finite, or n.
// A search that stops at the first, not an element-wise pass.
std::int64_t first_not_finite(std::int64_t n, const double *phi, const double *dphi,
                              const double *d2phi) {
  for (std::int64_t i = 0; i < n; ++i)
    if (!std::isfinite(phi[i]) || !std::isfinite(dphi[i]) ||
        (d2phi != nullptr && !std::isfinite(d2phi[i])))
      return i;
  return n;
}

// "phi = nan" for the first output of entry i that is not finite.
std::string bad_output(std::int64_t i, const double *phi, const double *dphi,
                       const double *d2phi) {
  if (!std::isfinite(phi[i])) return "phi = " + format_number(phi[i]);
  if (!std::isfinite(dphi[i])) return "dphi = " + format_number(dphi[i]);
  return "d2phi = " + format_number(d2phi[i]);
}

}  // namespace

CallbackPotential::CallbackPotential(PotentialFunction function, void *user_data,
                                     const Reductions *processes)
    : function_(function), user_data_(user_data), processes_(processes) {}

CallbackPotential::CallbackPotential(PotentialFunction function, void *user_data,
                                     const Reductions *processes, double length,
                                     double pressure)
    : function_(function),
      user_data_(user_data),
      processes_(processes),
      length_(length),
      pressure_(pressure) {}

std::string CallbackPotential::failure(std::int64_t n, const double *physical, const double *phi,
                                       const double *dphi, const double *d2phi,
                                       int status) const {
  if (status != 0)
    return "the potential callback returned " + std::to_string(status) + " instead of 0";
  const std::int64_t bad = first_not_finite(n, phi, dphi, d2phi);
  if (bad < n)
    return "the potential callback wrote " + bad_output(bad, phi, dphi, d2phi) + " at index " +
           std::to_string(bad) + " (gap " + format_number(physical[bad]) + ")";
  return std::string();
}

void CallbackPotential::evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                                 double *d2phi) const {
  const double *physical = gap;
  if (length_ != 1.0) {
    if (static_cast<std::int64_t>(physical_gap_.size()) != n) physical_gap_.assign(n, 0.0);
    double *g = physical_gap_.data();
    const double length = length_;
    loops::for_each(n, [&](std::int64_t i) { g[i] = gap[i] * length; });
    physical = g;
  }
  const int status = function_(n, physical, phi, dphi, d2phi, user_data_);
  std::string failed = failure(n, physical, phi, dphi, d2phi, status);
  if (failed.empty() && (length_ != 1.0 || pressure_ != 1.0)) {
    const double energy = 1.0 / (pressure_ * length_), stress = 1.0 / pressure_,
                 stiffness = length_ / pressure_;
    if (d2phi != nullptr) {
      loops::for_each(n, [&](std::int64_t i) {
        phi[i] *= energy;
        dphi[i] *= stress;
        d2phi[i] *= stiffness;
      });
    } else {
      loops::for_each(n, [&](std::int64_t i) {
        phi[i] *= energy;
        dphi[i] *= stress;
      });
    }
    // Finite values of the callback can still overflow in small units.
    const std::int64_t bad = first_not_finite(n, phi, dphi, d2phi);
    if (bad < n)
      failed = "the potential callback's values at index " + std::to_string(bad) + " (gap " +
               format_number(physical[bad]) + ") overflow in the units of the solve (" +
               bad_output(bad, phi, dphi, d2phi) +
               "); rescale the potential or set a reference pressure";
  }
  if (processes_ != nullptr) {
    double any = failed.empty() ? 0.0 : 1.0;
    processes_->combine_maxima(&any, 1);
    if (any > 0.0 && failed.empty())
      throw Error(Status::callback, "the potential callback failed on another process");
  }
  if (!failed.empty()) throw Error(Status::callback, failed);
}

std::unique_ptr<Potential> CallbackPotential::in_units(double length, double pressure) const {
  return std::unique_ptr<Potential>(
      new CallbackPotential(function_, user_data_, processes_, length_ * length,
                            pressure_ * pressure));
}

}  // namespace asp
