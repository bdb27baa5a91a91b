// SPDX-License-Identifier: GPL-2.0-or-later
// Polonsky-Keer against contact problems with closed-form solutions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "physics/surface_statistics.hpp"
#include "physics/topography.hpp"
#include "scene.hpp"

namespace {
using asp_test::pi;

// ---- full contact of a single Fourier mode --------------------------------------------------
// Above the full-contact load the pressure is p_mean + (E* q h0/2) cos(q x) exactly; PK must
// find it to the precision of its stopping rule (tolerance 1e-13 relative to E* h'_rms/2).
TEST(FullContact, SingleModePressureAmplitudeIsEStarQHOverTwo) {
  for (std::int64_t n : {128, 127}) {
    auto grid = asp_test::grid_1d(n, 1.0);
    const double modulus = 2.0, h0 = 0.01, q = 2 * pi * 3;
    std::vector<double> h(static_cast<std::size_t>(n));
    asp::sinusoid_topography(*grid, h0, 3, 0, h.data());
    asp::System system(grid, modulus);
    system.set_topography(h.data());
    const double amplitude = 0.5 * modulus * q * h0;
    const double mean = 2.0 * amplitude;  // twice what full contact needs
    auto report = asp_test::solve_pk(system, asp::Control::mean_pressure, mean, 1e-13);
    ASSERT_TRUE(report.converged());
    EXPECT_DOUBLE_EQ(system.contact_fraction(), 1.0);
    const auto &p = system.state().pressure;
    for (std::int64_t i = 0; i < n; ++i)
      EXPECT_NEAR(p[i], mean + amplitude * std::cos(q * i / n), 1e-12 * amplitude) << i;
  }
}

// ---- Westergaard: 1D periodic sinusoid in partial contact ----------------------------------
// h = h0 cos(2 pi x/l), p* = pi E* h0/l, p_mean/p* = sin^2(pi a/l) and
// p(x) = 2 p_mean cos(pi x/l) sqrt(sin^2(pi a/l) - sin^2(pi x/l)) / sin^2(pi a/l).
struct WestergaardErrors {
  double half_width_error;  // |a_measured - a| in pixels
  double pressure_rms;      // rms of p - p_exact over the box, relative to the peak pressure
  double pressure_max_inner;  // max |p - p_exact| over |x| < a/2, relative to the peak
};

WestergaardErrors westergaard(std::int64_t n) {
  const double l = 1.0, h0 = 0.02, modulus = 1.0;
  auto grid = asp_test::grid_1d(n, l);
  std::vector<double> h(static_cast<std::size_t>(n));
  asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
  asp::System system(grid, modulus);
  system.set_topography(h.data());
  const double p_star = pi * modulus * h0 / l;
  const double mean = 0.3 * p_star;
  // The tolerance sits above the rounding floor of the scaled gap at 4096 pixels: the
  // preconditioned iteration reaches about 3e-12 by its 23rd iteration and then hovers
  // between 1e-12 and 6e-12, so that 1e-12 is met or not by chance. The errors checked below
  // are the discretisation's, 1e-7 of the peak pressure and more.
  auto report = asp_test::solve_pk(system, asp::Control::mean_pressure, mean, 1e-11);
  EXPECT_TRUE(report.converged());

  const double s2 = mean / p_star;
  const double a = l / pi * std::asin(std::sqrt(s2));
  const double dx = l / n;
  const double contact_pixels = system.contact_fraction() * n;
  WestergaardErrors e{};
  e.half_width_error = std::fabs(0.5 * contact_pixels * dx - a) / dx;
  const double peak = 2 * mean / s2 * std::sqrt(s2);
  double sum2 = 0.0;
  for (std::int64_t i = 0; i < n; ++i) {
    const double x = asp_test::periodic_distance(i * dx, l);
    const double sx = std::sin(pi * x / l);
    const double exact =
        x < a ? 2 * mean * std::cos(pi * x / l) * std::sqrt(s2 - sx * sx) / s2 : 0.0;
    const double diff = system.state().pressure[i] - exact;
    sum2 += diff * diff;
    if (x < 0.5 * a) e.pressure_max_inner = std::max(e.pressure_max_inner, std::fabs(diff) / peak);
  }
  e.pressure_rms = std::sqrt(sum2 / n) / peak;
  return e;
}

TEST(Westergaard, HalfWidthAndPressureProfileConvergeWithResolution) {
  const WestergaardErrors coarse = westergaard(512);
  const WestergaardErrors fine = westergaard(4096);
  std::printf("Westergaard n=512:  |da| = %.3f px, rms dp = %.2e, inner max dp = %.2e\n",
              coarse.half_width_error, coarse.pressure_rms, coarse.pressure_max_inner);
  std::printf("Westergaard n=4096: |da| = %.3f px, rms dp = %.2e, inner max dp = %.2e\n",
              fine.half_width_error, fine.pressure_rms, fine.pressure_max_inner);
  // The contact edge is resolved to a pixel: counting contact pixels gives a to within one
  // pixel at any resolution.
  EXPECT_LE(coarse.half_width_error, 1.0);
  EXPECT_LE(fine.half_width_error, 1.0);
  // The pressure is smooth inside the contact and has a square-root edge. Collocation on the
  // grid converges at least to first order: 8 times finer must divide the errors by >= 8
  // (measured: ~19 for the rms, edge-dominated, ~40 inside, i.e. second order there).
  EXPECT_LT(fine.pressure_rms, coarse.pressure_rms / 8.0);
  EXPECT_LT(fine.pressure_max_inner, coarse.pressure_max_inner / 8.0);
  // And in absolute terms at 512 pixels per wavelength (measured 4.1e-4 and 4.7e-6).
  EXPECT_LT(coarse.pressure_rms, 1e-3);
  EXPECT_LT(coarse.pressure_max_inner, 1e-5);
}

// ---- Hertz: a paraboloid on a periodic substrate at small contact radius --------------------
// Every solver of the non-adhesive hard wall meets it (bugnicourt on the pressure and on the
// gap, the latter under mean-gap control at the gap pk's solution leaves; lbfgsb on either,
// under penetration control at pk's penetration).
struct HertzSolver {
  const char *algorithm;
  const char *variable;  // nullptr: the algorithm has no such option
  bool penetration;      // solved under penetration control
};
void PrintTo(const HertzSolver &s, std::ostream *os) {
  *os << s.algorithm << (s.variable ? std::string(" on the ") + s.variable : std::string())
      << (s.penetration ? " under penetration control" : "");
}
class Hertz : public ::testing::TestWithParam<HertzSolver> {};

TEST_P(Hertz, PeriodicParaboloidAtSmallContactRadius) {
  const HertzSolver solver_case = GetParam();
  const std::int64_t n = 256;
  const double l = 1.0, radius = 1.0, modulus = 1.0;
  const double a = l / 12;  // about 21 pixels, and a/l small enough that images hardly matter
  auto grid = asp_test::grid_2d(n, n, l, l);
  std::vector<double> h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, radius, h.data());
  asp::System system(grid, modulus);
  system.set_topography(h.data());
  const double force = 4 * modulus * a * a * a / (3 * radius);
  asp::Control control = asp::Control::mean_pressure;
  double value = force / (l * l);
  const bool on_the_gap =
      solver_case.variable != nullptr && std::string(solver_case.variable) == "gap";
  if (on_the_gap || solver_case.penetration) {
    // The primal takes the mean gap, and penetration control the penetration, of the
    // pressure-controlled solution.
    asp::System reference(grid, modulus);
    reference.set_topography(h.data());
    ASSERT_TRUE(asp_test::solve_pk(reference, control, value, 1e-10).converged());
    control = solver_case.penetration ? asp::Control::penetration : asp::Control::mean_gap;
    value = solver_case.penetration ? reference.state().penetration : reference.mean_gap();
  }
  asp::Solver solver(solver_case.algorithm);
  solver.set_option("tolerance", 1e-10);
  if (solver_case.variable != nullptr)
    solver.set_option("variable", std::string(solver_case.variable));
  solver.solve(system, control, value);
  ASSERT_TRUE(solver.report().converged());

  const double area = system.contact_fraction() * l * l;
  const double a_measured = std::sqrt(area / pi);
  const auto &p = system.state().pressure;
  const double p_max = *std::max_element(p.begin(), p.end());
  const double p0 = 2 * modulus * a / (pi * radius);
  std::printf("Hertz: a = %.5f (exact %.5f, %+.2f%%), p_max = %.5f (exact %.5f, %+.2f%%)\n",
              a_measured, a, 100 * (a_measured / a - 1), p_max, p0, 100 * (p_max / p0 - 1));
  // a from the pixel count: the edge ring of ~2 pi a/dx pixels is decided pixel by pixel, a
  // bias below half a pixel on a = 21 pixels, so within 2% (measured +0.7%). The peak
  // pressure is smooth: its error is discretisation of the interior plus the periodic images,
  // of relative size (a/l)^3 ~ 6e-4; 1% is ample (measured +0.07%).
  EXPECT_NEAR(a_measured / a, 1.0, 0.02);
  EXPECT_NEAR(p_max / p0, 1.0, 0.01);
  // Under mean-gap or penetration control the load is a result: that of the reference
  // solve, to the tolerance's effect on the multiplier or the pressures.
  EXPECT_NEAR(system.mean_pressure(), force / (l * l), 1e-6 * force / (l * l));
}

INSTANTIATE_TEST_SUITE_P(Solvers, Hertz,
                         ::testing::Values(HertzSolver{"pk", nullptr, false},
                                           HertzSolver{"bugnicourt", "pressure", false},
                                           HertzSolver{"bugnicourt", "gap", false},
                                           HertzSolver{"lbfgsb", "pressure", true},
                                           HertzSolver{"lbfgsb", "gap", true}),
                         [](const ::testing::TestParamInfo<HertzSolver> &info) {
                           return std::string(info.param.algorithm) +
                                  (info.param.variable ? std::string("_") + info.param.variable
                                                       : std::string());
                         });

// ---- rough contact at small load: area grows linearly, A/A0 = kappa p/(E* h'_rms) ----------
// kappa depends on how well the surface is resolved: with a short cutoff of 8 pixels and a
// self-affine band of 32 (roll-off at half the box) it measures 2.2-2.3 over seeds; coarser
// sampling (4 pixels) or a narrower band push it up towards 2.5, as the literature reports.
TEST(RoughContact, ContactFractionIsLinearInLoadWithKappaNearTwo) {
  const std::int64_t n = 512;
  auto grid = asp_test::grid_2d(n, n, 1.0, 1.0);
  const double modulus = 1.0, slope = 0.1;
  double kappa_sum = 0.0;
  const int seeds = 4;
  for (int seed = 1; seed <= seeds; ++seed) {
    // Roll-off at half the box, short cutoff at 8 pixels.
    const auto h =
        asp_test::rough_surface(*grid, static_cast<std::uint64_t>(seed), slope, 0.5, 8.0);
    asp::System system(grid, modulus);
    system.set_topography(h.data());
    const double mean = 0.01 * modulus * slope;
    auto report = asp_test::solve_pk(system, asp::Control::mean_pressure, mean, 1e-8);
    ASSERT_TRUE(report.converged());
    const double kappa = system.contact_fraction() * modulus * slope / mean;
    std::printf("seed %d: contact fraction %.4f, kappa %.3f, %lld iterations\n", seed,
                system.contact_fraction(), kappa, static_cast<long long>(report.iterations));
    kappa_sum += kappa;
  }
  const double kappa = kappa_sum / seeds;
  EXPECT_GE(kappa, 1.8);
  EXPECT_LE(kappa, 2.4);
}

}  // namespace
