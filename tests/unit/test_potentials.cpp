// SPDX-License-Identifier: GPL-2.0-or-later
// The soft potentials (potential.hpp): the exponential soft wall and the Lennard-Jones 9-3
// wall against central differences and against their closed forms (minimum, depth, largest
// tensile stress), continuous through their continuation thresholds and finite down to
// -1e6 times their range; the same potentials in other units; the refusals of System's
// setters; the user's callback, whose failures throw Error(callback) and whose soft wall is the
// built-in one; and the units of a solve with each.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "physics/potential.hpp"
#include "physics/system.hpp"
#include "scene.hpp"
#include "formulations/scene_units.hpp"

namespace {

using Vector = std::vector<double>;
constexpr double epsilon = std::numeric_limits<double>::epsilon();

struct Values {
  Vector phi, dphi, d2phi;
};

Values evaluate(const asp::Potential &potential, const Vector &gap) {
  const auto n = static_cast<std::int64_t>(gap.size());
  Values v{Vector(gap.size()), Vector(gap.size()), Vector(gap.size())};
  potential.evaluate(n, gap.data(), v.phi.data(), v.dphi.data(), v.d2phi.data());
  return v;
}

struct Point {
  double phi, dphi, d2phi;
};

Point at(const asp::Potential &potential, double g) {
  const Values v = evaluate(potential, {g});
  return {v.phi[0], v.dphi[0], v.d2phi[0]};
}

// The largest |phi'| and |phi''| over [g - length, g + length], sampled at 41 points: the
// scale of the slope and curvature near g, also where one of them vanishes (at a minimum or
// an inflection).
Point scale_near(const asp::Potential &potential, double g, double length) {
  Vector gaps;
  for (int k = -20; k <= 20; ++k) gaps.push_back(g + length * k / 20.0);
  const Values v = evaluate(potential, gaps);
  Point s{0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    s.dphi = std::fmax(s.dphi, std::fabs(v.dphi[i]));
    s.d2phi = std::fmax(s.d2phi, std::fabs(v.d2phi[i]));
  }
  return s;
}

// phi' against (phi(g+h) - phi(g-h))/(2h), and phi'' against the same difference of phi', with
// h = 1e-4 of `length`, a gap over which the potential changes by a fraction of itself.
// The truncation error is (h^2/6) f''', about (h/length)^2/6 = 2e-9 of the largest slope
// (curvature) within `length` of g; rounding adds about eps |phi| / h, below 1e-11 of it for
// these potentials (|phi| is within a few `length` times the slope). Hence 1e-7 of that scale.
void expect_derivatives_match_differences(const asp::Potential &potential, double g,
                                          double length) {
  const double h = 1e-4 * length;
  const Point below = at(potential, g - h), here = at(potential, g), above = at(potential, g + h);
  const Point scale = scale_near(potential, g, length);
  EXPECT_NEAR(here.dphi, (above.phi - below.phi) / (2.0 * h), 1e-7 * scale.dphi) << "g = " << g;
  EXPECT_NEAR(here.d2phi, (above.dphi - below.dphi) / (2.0 * h), 1e-7 * scale.d2phi)
      << "g = " << g;
}

// phi, phi' and phi'' just below a threshold (one double lower) against their values on it,
// where the other branch is taken: equal to rounding (1e-13 of each; one ulp of the gap
// changes phi by phi' ulp, far less).
void expect_continuous_at(const asp::Potential &potential, double threshold) {
  const Point on = at(potential, threshold);
  const Point below = at(potential, std::nextafter(threshold, -INFINITY));
  EXPECT_NEAR(below.phi, on.phi, 1e-13 * std::fabs(on.phi)) << "threshold " << threshold;
  EXPECT_NEAR(below.dphi, on.dphi, 1e-13 * std::fabs(on.dphi)) << "threshold " << threshold;
  EXPECT_NEAR(below.d2phi, on.d2phi, 1e-13 * std::fabs(on.d2phi)) << "threshold " << threshold;
}

// Every value finite, for gaps from -1e6 range to 1e6 range, and the energy growing without
// bound inside the wall (phi' < 0 below the minimum) rather than falling.
void expect_finite_everywhere(const asp::Potential &potential, double range) {
  Vector gaps;
  for (double x = 1e-6; x <= 1e6; x *= 1.25) {
    gaps.push_back(-x * range);
    gaps.push_back(x * range);
  }
  gaps.push_back(0.0);
  const Values v = evaluate(potential, gaps);
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    EXPECT_TRUE(std::isfinite(v.phi[i]) && std::isfinite(v.dphi[i]) && std::isfinite(v.d2phi[i]))
        << "g = " << gaps[i] << ": " << v.phi[i] << ", " << v.dphi[i] << ", " << v.d2phi[i];
    if (gaps[i] < 0.0) EXPECT_LT(v.dphi[i], 0.0) << "g = " << gaps[i];
  }
  const Point deepest = at(potential, -1e6 * range);
  EXPECT_GT(deepest.phi, 0.0);
  EXPECT_GT(deepest.d2phi, 0.0);
}

// The copy in units (length, pressure) at g/length gives phi/(pressure length),
// phi'/pressure and phi'' length/pressure: a few roundings, 1e-13 relative. Converting back
// gives the original values to the same rounding.
void expect_units_round_trip(const asp::Potential &potential, const Vector &gaps) {
  const double length = 3.7e-6, pressure = 2.9e8;
  const std::unique_ptr<asp::Potential> scaled = potential.in_units(length, pressure);
  const std::unique_ptr<asp::Potential> back = scaled->in_units(1.0 / length, 1.0 / pressure);
  Vector scaled_gaps;
  for (double g : gaps) scaled_gaps.push_back(g / length);
  const Values physical = evaluate(potential, gaps), in_units = evaluate(*scaled, scaled_gaps),
               again = evaluate(*back, gaps);
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    const double tolerance = 1e-13;
    EXPECT_NEAR(in_units.phi[i] * pressure * length, physical.phi[i],
                tolerance * std::fabs(physical.phi[i]));
    EXPECT_NEAR(in_units.dphi[i] * pressure, physical.dphi[i],
                tolerance * std::fabs(physical.dphi[i]));
    EXPECT_NEAR(in_units.d2phi[i] * pressure / length, physical.d2phi[i],
                tolerance * std::fabs(physical.d2phi[i]));
    EXPECT_NEAR(again.phi[i], physical.phi[i], tolerance * std::fabs(physical.phi[i]));
    EXPECT_NEAR(again.dphi[i], physical.dphi[i], tolerance * std::fabs(physical.dphi[i]));
    EXPECT_NEAR(again.d2phi[i], physical.d2phi[i], tolerance * std::fabs(physical.d2phi[i]));
  }
  EXPECT_NEAR(scaled->pressure_scale() * pressure, potential.pressure_scale(),
              1e-14 * potential.pressure_scale());
  EXPECT_NEAR(scaled->length_scale() * length, potential.length_scale(),
              1e-14 * potential.length_scale());
}

// ---- the exponential soft wall -----------------------------------------------------------------

// gamma_r = 1, rho_r = 1, gamma_a = 0.5, rho_a = 2: two ranges, thresholds at -20 (repulsion)
// and -80 (attraction).
asp::SoftWallPotential two_range_wall() { return asp::SoftWallPotential(1.0, 1.0, 0.5, 2.0); }

TEST(SoftWallPotential, DerivativesMatchCentralDifferences) {
  const asp::SoftWallPotential wall = two_range_wall();
  // The shortest range, rho_r/2 = 0.5, sets the step.
  const double length = 0.5;
  for (double g : {-200.0, -81.0, -80.05, -79.95, -50.0, -20.5, -20.05, -19.95, -19.5, -5.0,
                   -1.0, 0.0, 0.5, std::log(8.0) / 1.5, 2.0, 5.0, 20.0, 60.0})
    expect_derivatives_match_differences(wall, g, length);
}

TEST(SoftWallPotential, ContinuousAtItsThresholds) {
  const asp::SoftWallPotential wall = two_range_wall();
  // g = -largest_exponent * range for the repulsion (range rho_r/2) and the attraction.
  expect_continuous_at(wall, -asp::SoftWallPotential::largest_exponent * 0.5);
  expect_continuous_at(wall, -asp::SoftWallPotential::largest_exponent * 2.0);
  // Each exponential alone, so that one term cannot hide the other's jump.
  expect_continuous_at(asp::SoftWallPotential(1.0, 1.0, 0.0, 1.0), -20.0);
  const asp::SoftWallPotential::Exponential attraction = wall.attraction();
  const double t = -asp::SoftWallPotential::largest_exponent * attraction.range;
  const auto on = attraction.at(t), below = attraction.at(std::nextafter(t, -INFINITY));
  EXPECT_NEAR(below.value, on.value, 1e-13 * std::fabs(on.value));
  EXPECT_NEAR(below.slope, on.slope, 1e-13 * std::fabs(on.slope));
  EXPECT_NEAR(below.curvature, on.curvature, 1e-13 * std::fabs(on.curvature));
}

// With one range rho: phi = gamma_r x^2 - gamma_a x in x = exp(-g/rho), least at
// x = gamma_a/(2 gamma_r): g* = rho ln(2 gamma_r/gamma_a), phi(g*) = -gamma_a^2/(4 gamma_r),
// phi''(g*) = gamma_a^2/(2 gamma_r rho^2). With two ranges phi' = 0 where
// exp(g (2/rho_r - 1/rho_a)) = 2 gamma_r rho_a/(gamma_a rho_r). Each to a few roundings of
// the terms (1e-14 of gamma_a, 1e-14 of the slopes' scale gamma_a/rho).
TEST(SoftWallPotential, MinimumMatchesClosedForm) {
  const double gamma_r = 2.0, gamma_a = 0.3, rho = 0.7;
  const asp::SoftWallPotential wall(gamma_r, rho, gamma_a, rho);
  const double g_star = rho * std::log(2.0 * gamma_r / gamma_a);
  const Point minimum = at(wall, g_star);
  EXPECT_NEAR(minimum.phi, -gamma_a * gamma_a / (4.0 * gamma_r), 1e-14 * gamma_a);
  EXPECT_NEAR(minimum.dphi, 0.0, 1e-14 * gamma_a / rho);
  EXPECT_NEAR(minimum.d2phi, gamma_a * gamma_a / (2.0 * gamma_r * rho * rho),
              1e-13 * gamma_a / (rho * rho));
  // The least of phi over a fine sampling is no lower.
  for (double g = -50.0 * rho; g < 50.0 * rho; g += 1e-3 * rho)
    EXPECT_GE(at(wall, g).phi, minimum.phi - 1e-15) << "g = " << g;

  const asp::SoftWallPotential two = two_range_wall();
  const double g_two = std::log(2.0 * 1.0 * 2.0 / (0.5 * 1.0)) / (2.0 / 1.0 - 1.0 / 2.0);
  EXPECT_NEAR(at(two, g_two).dphi, 0.0, 1e-14 * 0.5 / 2.0);
  EXPECT_GT(at(two, g_two).d2phi, 0.0);
}

TEST(SoftWallPotential, FiniteDownToAMillionRanges) {
  expect_finite_everywhere(two_range_wall(), 2.0);
  expect_finite_everywhere(asp::SoftWallPotential(1.0, 1e-3, 0.9, 1e-3), 1e-3);
}

TEST(SoftWallPotential, InUnitsRoundTrip) {
  expect_units_round_trip(two_range_wall(), {-300.0, -80.0, -20.0, -1.0, 0.0, 0.3, 2.0, 40.0});
}

// ---- the Lennard-Jones 9-3 wall -----------------------------------------------------------------

// The largest tensile stress max phi'(g), which sets the units of a solve on a surface without
// slope: gamma_a^2/(8 gamma_r rho) with one range (the thesis's gamma_r/gamma_a = 1024 makes
// it 8192 times smaller than the attraction's own gamma_a/rho, which the scale once was, so
// that errors divided by it hid imbalances of thousands of tolerances), and the largest
// sampled phi' (step 1e-5 of the shorter range: short of the maximum by about the third
// derivative times step^2/8, below 1e-9 of it) with two ranges.
TEST(SoftWallPotential, PressureScaleIsTheLargestTensileStress) {
  const double gamma_r = 23188.1388, gamma_a = 22.6360403, rho = 0.03125;
  const asp::SoftWallPotential one(gamma_r, rho, gamma_a, rho);
  const double closed_form = gamma_a * gamma_a / (8.0 * gamma_r * rho);
  EXPECT_NEAR(one.pressure_scale(), closed_form, 1e-13 * closed_form);
  const double ranges[][2] = {{rho, rho}, {0.5, 0.8}, {1.0, 3.0}};
  for (const auto &r : ranges) {
    const asp::SoftWallPotential wall(2.0, r[0], 0.5, r[1]);
    const double step = 1e-5 * std::fmin(r[0], r[1]);
    double largest = -HUGE_VAL;
    for (double g = -5.0 * r[1]; g < 20.0 * r[1]; g += step)
      largest = std::fmax(largest, at(wall, g).dphi);
    EXPECT_NEAR(wall.pressure_scale(), largest, 1e-9 * largest) << r[0] << ", " << r[1];
  }
  // Without attraction, the repulsion's stress at the wall.
  EXPECT_DOUBLE_EQ(asp::SoftWallPotential(2.0, 0.5, 0.0, 0.5).pressure_scale(), 2.0 * 2.0 / 0.5);
}

TEST(LennardJonesPotential, DerivativesMatchCentralDifferences) {
  const double w = 0.04, z0 = 1.5;
  const asp::LennardJonesPotential lj(w, z0);
  const double start = asp::LennardJonesPotential::threshold * z0;
  // Inside the continuation the potential is a parabola, whose differences are exact; above
  // it the powers change by a fraction of themselves over g/20.
  for (double g : {-1e3 * z0, -10.0 * z0, -z0, 0.0, 0.3 * z0, start - 0.01 * z0})
    expect_derivatives_match_differences(lj, g, z0);
  for (double g : {start + 0.002 * z0, start + 0.05 * z0, 0.8 * z0, z0,
                   z0 * std::pow(2.5, 1.0 / 6.0), 2.0 * z0, 5.0 * z0, 30.0 * z0})
    expect_derivatives_match_differences(lj, g, 0.05 * g);
}

TEST(LennardJonesPotential, ContinuousAtItsThreshold) {
  const double z0 = 1.5;
  const asp::LennardJonesPotential lj(0.04, z0);
  expect_continuous_at(lj, asp::LennardJonesPotential::threshold * z0);
  // The values there: phi = 244 w, phi' = -4536 w/z0, phi'' = 91584 w/z0^2 (u = z0/g = 2).
  const Point on = at(lj, 0.5 * z0);
  EXPECT_NEAR(on.phi, 244 * 0.04, 1e-13 * 244 * 0.04);
  EXPECT_NEAR(on.dphi, -4536 * 0.04 / z0, 1e-13 * 4536 * 0.04 / z0);
  EXPECT_NEAR(on.d2phi, 91584 * 0.04 / (z0 * z0), 1e-13 * 91584 * 0.04 / (z0 * z0));
}

// phi(z0) = -w, phi'(z0) = 0, phi''(z0) = 27 w/z0^2, and no lower value anywhere.
TEST(LennardJonesPotential, MinimumIsMinusWorkAtEquilibriumDistance) {
  const double w = 0.04, z0 = 1.5;
  const asp::LennardJonesPotential lj(w, z0);
  const Point minimum = at(lj, z0);
  EXPECT_NEAR(minimum.phi, -w, 1e-15);
  EXPECT_NEAR(minimum.dphi, 0.0, 1e-14 * w / z0);
  EXPECT_NEAR(minimum.d2phi, 27.0 * w / (z0 * z0), 1e-13 * w / (z0 * z0));
  for (double g = -10.0 * z0; g < 20.0 * z0; g += 1e-3 * z0)
    EXPECT_GE(at(lj, g).phi, -w * (1.0 + 1e-15)) << "g = " << g;
}

// The largest tensile stress: phi' = (9w/(2 z0)) u^4 (1 - u^6), u = z0/g, is largest where
// phi'' = 0, u^6 = 2/5, g = z0 (5/2)^(1/6), and is (27/10) (2/5)^(2/3) w/z0 there. The
// sampled maximum over g > z0 (step 1e-4 z0) falls short of it by at most
// phi''' step^2/8, far below 1e-6 of it.
TEST(LennardJonesPotential, PressureScaleIsTheLargestTensileStress) {
  const double w = 0.04, z0 = 1.5;
  const asp::LennardJonesPotential lj(w, z0);
  const double closed_form = 2.7 * std::pow(0.4, 2.0 / 3.0) * w / z0;
  EXPECT_NEAR(lj.pressure_scale(), closed_form, 1e-15 * closed_form);
  EXPECT_NEAR(lj.pressure_scale(), 1.4658 * w / z0, 1e-4 * w / z0);
  const Point inflection = at(lj, z0 * std::pow(2.5, 1.0 / 6.0));
  EXPECT_NEAR(inflection.dphi, closed_form, 1e-14 * closed_form);
  EXPECT_NEAR(inflection.d2phi, 0.0, 1e-13 * w / (z0 * z0));
  double largest = 0.0;
  for (double g = z0; g < 10.0 * z0; g += 1e-4 * z0) largest = std::fmax(largest, at(lj, g).dphi);
  EXPECT_LE(largest, closed_form * (1.0 + 1e-14));
  EXPECT_GE(largest, closed_form * (1.0 - 1e-6));
  EXPECT_EQ(lj.length_scale(), z0);
}

TEST(LennardJonesPotential, FiniteDownToAMillionRanges) {
  expect_finite_everywhere(asp::LennardJonesPotential(0.04, 1.5), 1.5);
  expect_finite_everywhere(asp::LennardJonesPotential(1e3, 1e-9), 1e-9);
}

TEST(LennardJonesPotential, InUnitsRoundTripAndDescription) {
  const asp::LennardJonesPotential lj(0.04, 1.5);
  expect_units_round_trip(lj, {-1e3, -1.0, 0.0, 0.5, 0.75, 0.76, 1.5, 1.8, 10.0});
  EXPECT_EQ(lj.description(),
            "Lennard-Jones 9-3 wall potential (work of adhesion 0.04, equilibrium distance 1.5)");
}

// ---- System's setters refuse what they cannot represent -------------------------------------------

// The interaction is unchanged by a refused call.
template <class Call>
void expect_refused(asp::System &system, Call &&call, asp::Status status, const std::string &name) {
  const asp::InteractionKind before = system.interaction().kind();
  try {
    call();
    ADD_FAILURE() << "not refused; expected a message naming " << name;
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), status) << e.what();
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
  EXPECT_EQ(system.interaction().kind(), before);
}

TEST(PotentialSetters, RefuseBadParametersNamingThem) {
  asp::System system(asp_test::grid_2d(8, 8, 1.0, 1.0), 1.0);
  const double nan = std::nan(""), inf = INFINITY;
  const auto invalid = asp::Status::invalid_argument;
  for (double bad : {0.0, -1.0, nan, inf}) {
    expect_refused(system, [&] { system.set_soft_wall(bad, 1.0, 0.1, 1.0); }, invalid,
                   "'gamma_r'");
    expect_refused(system, [&] { system.set_soft_wall(1.0, bad, 0.1, 1.0); }, invalid, "'rho_r'");
    expect_refused(system, [&] { system.set_soft_wall(1.0, 1.0, 0.1, bad); }, invalid, "'rho_a'");
    expect_refused(system, [&] { system.set_lennard_jones(bad, 1.0); }, invalid,
                   "'work_of_adhesion'");
    expect_refused(system, [&] { system.set_lennard_jones(1.0, bad); }, invalid,
                   "'equilibrium_distance'");
  }
  for (double bad : {-1.0, nan, inf})
    expect_refused(system, [&] { system.set_soft_wall(1.0, 1.0, bad, 1.0); }, invalid,
                   "'gamma_a'");
  // An attraction stiffer than the repulsion inside the wall has no lower bound.
  expect_refused(system, [&] { system.set_soft_wall(1.0, 2.0, 5.0, 1.0); }, invalid,
                 "4 gamma_r/rho_r^2");
  // 91584 w/z0^2 overflows; 1.466 w/z0 underflows.
  expect_refused(system, [&] { system.set_lennard_jones(1e300, 1e-10); }, invalid,
                 "'equilibrium_distance'");
  expect_refused(system, [&] { system.set_lennard_jones(1e-300, 1e10); }, invalid,
                 "'work_of_adhesion'");
  expect_refused(system, [&] { system.set_user_potential(nullptr, nullptr, false); },
                 asp::Status::null_pointer, "'fn'");

  system.set_soft_wall(1.0, 1.0, 0.1, 1.0);
  EXPECT_EQ(system.interaction().kind(), asp::InteractionKind::soft_wall);
  system.set_lennard_jones(0.04, 1.5);
  EXPECT_EQ(system.interaction().kind(), asp::InteractionKind::lennard_jones);
  system.set_hard_wall();
  EXPECT_EQ(system.interaction().kind(), asp::InteractionKind::hard_wall);
}

// ---- the user's callback ---------------------------------------------------------------------------

// What the test callbacks read and record through user_data.
struct CallbackData {
  asp::SoftWallPotential::Exponential repulsion, attraction;  // the wall they compute
  int status = 0;                    // returned
  std::int64_t nan_index = -1;       // where phi (or d2phi) is made NaN (< 0: nowhere)
  bool nan_in_curvature = false;
  int calls = 0;
  Vector gaps;                       // the gaps of the last call
};

// The soft wall by thesis eqs. 12-13 in the operations SoftWallPotential uses (no
// continuation: the tests stay above its thresholds), or the failures asked for.
int soft_wall_callback(std::int64_t n, const double *gap, double *phi, double *dphi,
                       double *d2phi, void *user_data) {
  CallbackData &data = *static_cast<CallbackData *>(user_data);
  ++data.calls;
  data.gaps.assign(gap, gap + n);
  const auto r = data.repulsion, a = data.attraction;
  for (std::int64_t i = 0; i < n; ++i) {
    const double vr = r.coefficient * std::exp(-gap[i] / r.range);
    const double va = a.coefficient * std::exp(-gap[i] / a.range);
    phi[i] = vr + va;
    dphi[i] = -vr / r.range + -va / a.range;
    if (d2phi != nullptr) d2phi[i] = vr / (r.range * r.range) + va / (a.range * a.range);
  }
  if (data.nan_index >= 0 && data.nan_index < n) {
    if (!data.nan_in_curvature)
      phi[data.nan_index] = std::nan("");
    else if (d2phi != nullptr)
      d2phi[data.nan_index] = std::nan("");
  }
  return data.status;
}

CallbackData data_for(const asp::SoftWallPotential &wall) {
  CallbackData data;
  data.repulsion = wall.repulsion();
  data.attraction = wall.attraction();
  return data;
}

TEST(CallbackPotential, SoftWallCallbackGivesTheBuiltInValues) {
  const asp::SoftWallPotential wall = two_range_wall();
  CallbackData data = data_for(wall);
  const asp::CallbackPotential callback(soft_wall_callback, &data);
  const Vector gaps = {-19.0, -5.0, -1.0, 0.0, 0.25, std::log(8.0) / 1.5, 3.0, 50.0};
  const Values expected = evaluate(wall, gaps), got = evaluate(callback, gaps);
  EXPECT_EQ(data.calls, 1);  // once for all gaps
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    EXPECT_EQ(got.phi[i], expected.phi[i]) << "g = " << gaps[i];
    EXPECT_EQ(got.dphi[i], expected.dphi[i]) << "g = " << gaps[i];
    EXPECT_EQ(got.d2phi[i], expected.d2phi[i]) << "g = " << gaps[i];
  }
  // Without d2phi.
  Vector phi(gaps.size()), dphi(gaps.size());
  callback.evaluate(static_cast<std::int64_t>(gaps.size()), gaps.data(), phi.data(), dphi.data(),
                    nullptr);
  EXPECT_EQ(phi, expected.phi);
  EXPECT_EQ(dphi, expected.dphi);
  EXPECT_EQ(callback.pressure_scale(), 0.0);
  EXPECT_EQ(callback.length_scale(), 0.0);
}

// The copy in other units hands the callback physical gaps and converts its values: the
// same round trip as the built-ins; and it evaluates any number of gaps, one call each.
TEST(CallbackPotential, InUnitsCallsWithPhysicalGaps) {
  const asp::SoftWallPotential wall = two_range_wall();
  CallbackData data = data_for(wall);
  const asp::CallbackPotential callback(soft_wall_callback, &data);
  const Vector gaps = {-10.0, -1.0, 0.0, 0.3, 2.0, 40.0};
  expect_units_round_trip(callback, gaps);

  const double length = 0.25;
  const std::unique_ptr<asp::Potential> scaled = callback.in_units(length, 4.0);
  for (std::size_t n : {std::size_t(3), std::size_t(6), std::size_t(1), std::size_t(6)}) {
    Vector scaled_gaps(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(n));
    for (double &g : scaled_gaps) g /= length;
    data.calls = 0;
    const Values v = evaluate(*scaled, scaled_gaps);
    EXPECT_EQ(data.calls, 1);
    ASSERT_EQ(data.gaps.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_EQ(data.gaps[i], gaps[i]);
      EXPECT_NEAR(v.phi[i], at(wall, gaps[i]).phi / (4.0 * length),
                  1e-15 * std::fabs(at(wall, gaps[i]).phi));
    }
  }
}

template <class Call>
void expect_callback_error(Call &&call, const std::vector<std::string> &texts) {
  try {
    call();
    ADD_FAILURE() << "no Error(callback)";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::callback) << e.what();
    for (const std::string &text : texts)
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos)
          << "'" << e.what() << "' lacks '" << text << "'";
  }
}

TEST(CallbackPotential, FailuresThrowCallbackErrors) {
  const asp::SoftWallPotential wall = two_range_wall();
  CallbackData data = data_for(wall);
  const asp::CallbackPotential callback(soft_wall_callback, &data);
  const Vector gaps = {0.0, 0.5, 1.0, 1.5, 2.0};

  data.status = 7;
  expect_callback_error([&] { evaluate(callback, gaps); }, {"returned 7"});
  data.status = -1;
  expect_callback_error([&] { evaluate(callback, gaps); }, {"returned -1"});

  data.status = 0;
  data.nan_index = 3;
  expect_callback_error([&] { evaluate(callback, gaps); }, {"phi = nan", "index 3", "gap 1.5"});
  // The same through a copy in other units: the message gives the physical gap.
  const std::unique_ptr<asp::Potential> scaled = callback.in_units(0.5, 2.0);
  expect_callback_error([&] { evaluate(*scaled, {0.0, 1.0, 2.0, 3.0, 4.0}); },
                        {"index 3", "gap 1.5"});

  data.nan_in_curvature = true;
  expect_callback_error([&] { evaluate(callback, gaps); }, {"d2phi = nan", "index 3"});
  // Without d2phi the curvature is not asked for, and nothing is wrong.
  Vector phi(gaps.size()), dphi(gaps.size());
  EXPECT_NO_THROW(callback.evaluate(5, gaps.data(), phi.data(), dphi.data(), nullptr));

  // Values finite for the callback but beyond doubles in the solve's units.
  data.nan_index = -1;
  const std::unique_ptr<asp::Potential> tiny = callback.in_units(1e-200, 1e-200);
  expect_callback_error([&] { evaluate(*tiny, {0.0}); }, {"overflow", "index 0"});
}

// Through a System: its interaction energy is the built-in wall's, and a failing callback
// makes it throw Error(callback).
TEST(CallbackPotential, SystemEnergyMatchesTheBuiltInWall) {
  const double gamma_r = 1.0, rho_r = 1.0, gamma_a = 0.5, rho_a = 2.0;
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  asp::System system(grid, 1.0);
  system.set_topography(asp_test::rough_surface(*grid, 5, 0.3).data());
  system.set_soft_wall(gamma_r, rho_r, gamma_a, rho_a);
  const double built_in = system.interaction_energy();

  CallbackData data = data_for(two_range_wall());
  system.set_user_potential(soft_wall_callback, &data, false);
  EXPECT_EQ(system.interaction().kind(), asp::InteractionKind::user_potential);
  EXPECT_EQ(system.interaction_energy(), built_in);
  system.set_user_potential(soft_wall_callback, &data, true);
  EXPECT_EQ(system.interaction().kind(), asp::InteractionKind::user_potential_hard_wall);

  data.status = 3;
  expect_callback_error([&] { system.interaction_energy(); }, {"returned 3"});
}

// ---- the units of a solve -----------------------------------------------------------------------

// A flat surface under penetration control takes the larger of K~(0) delta and the potential's
// pressure scale; a user's potential has neither a pressure scale nor a range (both 0), and
// its range is not checked against the length scale, which would refuse any solve.
TEST(PotentialSceneUnits, EachPotentialGivesUnitsOfASolve) {
  auto grid = asp_test::grid_2d(16, 16, 1.0, 1.0);
  asp::System system(grid, 1.0);
  const double delta = 1e-3;
  const asp::SceneUnits hard = asp::scene_units(system, asp::Control::penetration, delta);

  const double w = 0.5, z0 = 1e-3;
  system.set_lennard_jones(w, z0);
  const asp::SceneUnits lj = asp::scene_units(system, asp::Control::penetration, delta);
  const double stress = asp::LennardJonesPotential(w, z0).pressure_scale();
  ASSERT_GT(stress, hard.pressure);
  EXPECT_NEAR(lj.pressure, stress, 1e-14 * stress);

  CallbackData data = data_for(two_range_wall());
  system.set_user_potential(soft_wall_callback, &data, false);
  const asp::SceneUnits user = asp::scene_units(system, asp::Control::penetration, delta);
  EXPECT_EQ(user.pressure, hard.pressure);
  EXPECT_EQ(user.length, hard.length);
  EXPECT_EQ(data.calls, 0);  // units are made without evaluating the potential
}

}  // namespace
