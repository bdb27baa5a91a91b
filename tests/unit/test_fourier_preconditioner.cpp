// SPDX-License-Identifier: GPL-2.0-or-later
// The Fourier preconditioner (option preconditioner = fourier) of Polonsky-Keer and of
// Bugnicourt's solver on the pressure and on the gap: the same solution as the plain
// iteration, on closed forms and rough scenes, under both controls and on both substrates, in
// fewer iterations; with adhesion a stationary state, and "auto" the plain path there; bad
// values of the option refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "scene.hpp"

namespace {
using asp_test::pi;

struct Outcome {
  asp::SolveReport report;
  std::vector<double> pressure;
  double penetration;
  double mean_pressure;
};

// The preconditioned iterations: pk, and bugnicourt on either variable.
struct Variant {
  const char *algorithm;
  const char *variable;  // null: the algorithm has none
  const char *name;
};
const Variant variants[] = {{"pk", nullptr, "pk"},
                            {"bugnicourt", "pressure", "bugnicourt:pressure"},
                            {"bugnicourt", "gap", "bugnicourt:gap"}};

Outcome solve(asp::System &system, const Variant &variant, const std::string &preconditioner,
              asp::Control control, double value, double tolerance) {
  asp::Solver solver(variant.algorithm);
  if (variant.variable != nullptr) solver.set_option("variable", std::string(variant.variable));
  solver.set_option("tolerance", tolerance);
  solver.set_option("preconditioner", preconditioner);
  // The preconditioner alone: nested grids, the default of these solvers, have tests of their
  // own (test_nested_grids.cpp), and their coarse levels would take "auto" where the fine
  // grid's adhesion does not (their problem is the non-adhesive one).
  solver.set_option("levels", 0.0);
  system.reset_state();
  solver.solve(system, control, value);
  return {solver.report(), asp_test::field_vector(system.state().pressure),
          system.state().penetration, system.mean_pressure()};
}

// Both iterations stop when the largest projected gap residual, over the scene's length unit,
// is below the tolerance. Two such states differ in pressure by the stiffness applied to the
// difference of their residuals, a few pixel stiffnesses times 2 tolerances in the scene's
// pressure unit: relative to the largest pressure, 1e-8 at the tolerance 1e-10 is a bound of
// that size with a margin (measured below: 2e-11 to 2e-10). The penetrations differ by the
// residuals themselves.
constexpr double tolerance = 1e-10;
constexpr double pressure_agreement = 1e-8;

void expect_same_state(asp::System &system, const Variant &variant, asp::Control control,
                       double value, const std::string &scene_name) {
  const std::string scene = scene_name + ", " + variant.name;
  const Outcome plain = solve(system, variant, "none", control, value, tolerance);
  const Outcome fourier = solve(system, variant, "fourier", control, value, tolerance);
  ASSERT_TRUE(plain.report.converged()) << scene;
  ASSERT_TRUE(fourier.report.converged()) << scene;
  const double peak = asp_test::max_abs(plain.pressure);
  const double difference = asp_test::max_abs_difference(plain.pressure, fourier.pressure);
  std::printf("%s, %s control: iterations %lld (none) and %lld (fourier), max |dp|/max p "
              "%.1e, relative d(penetration) %.1e\n",
              scene.c_str(), control == asp::Control::penetration ? "penetration" : "load",
              static_cast<long long>(plain.report.iterations),
              static_cast<long long>(fourier.report.iterations), difference / peak,
              std::fabs(fourier.penetration / plain.penetration - 1.0));
  EXPECT_LE(difference, pressure_agreement * peak) << scene;
  // The penetration is given, or the multiplier of the load: its difference is the gap
  // residual's, a tolerance in the length unit; 1e-7 of its value is far above (measured
  // at most 4e-13).
  EXPECT_NEAR(fourier.penetration, plain.penetration, 1e-7 * std::fabs(plain.penetration))
      << scene;
  // The load is given, or the integral of the pressures compared above.
  EXPECT_NEAR(fourier.mean_pressure, plain.mean_pressure,
              pressure_agreement * std::fabs(plain.mean_pressure))
      << scene;
}

// ---- Westergaard: the closed form, reached as the plain iteration reaches it ---------------
// h = h0 cos(2 pi x/l) at p_mean = 0.3 p*, p* = pi E* h0/l: p_mean/p* = sin^2(pi a/l) and
// p(x) = 2 p_mean cos(pi x/l) sqrt(sin^2(pi a/l) - sin^2(pi x/l)) / sin^2(pi a/l). At 512
// pixels per wavelength the plain iteration's contact half-width is within a pixel and its
// pressure's rms error 4.1e-4 of the peak (test_contact_oracles.cpp); the preconditioned one
// must meet the same bounds.
void westergaard(const Variant &variant) {
  const std::int64_t n = 512;
  const double l = 1.0, h0 = 0.02, modulus = 1.0;
  auto grid = asp_test::grid_1d(n, l);
  std::vector<double> h(static_cast<std::size_t>(n));
  asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
  asp::System system(grid, modulus);
  system.set_topography(h.data());
  const double p_star = pi * modulus * h0 / l;
  const double mean = 0.3 * p_star;
  const Outcome fourier =
      solve(system, variant, "fourier", asp::Control::mean_pressure, mean, 1e-12);
  ASSERT_TRUE(fourier.report.converged()) << variant.name;

  const double s2 = mean / p_star;
  const double a = l / pi * std::asin(std::sqrt(s2));
  const double dx = l / n;
  EXPECT_LE(std::fabs(0.5 * system.contact_fraction() * n * dx - a) / dx, 1.0) << variant.name;
  const double peak = 2 * mean / s2 * std::sqrt(s2);
  double sum2 = 0.0;
  for (std::int64_t i = 0; i < n; ++i) {
    const double x = asp_test::periodic_distance(i * dx, l);
    const double sx = std::sin(pi * x / l);
    const double exact =
        x < a ? 2 * mean * std::cos(pi * x / l) * std::sqrt(s2 - sx * sx) / s2 : 0.0;
    const double d = fourier.pressure[static_cast<std::size_t>(i)] - exact;
    sum2 += d * d;
  }
  EXPECT_LT(std::sqrt(sum2 / n) / peak, 1e-3) << variant.name;

  expect_same_state(system, variant, asp::Control::mean_pressure, mean, "Westergaard");
  expect_same_state(system, variant, asp::Control::penetration, fourier.penetration,
                    "Westergaard");
}

TEST(FourierPreconditioner, WestergaardClosedForm) {
  for (const Variant &variant : variants) westergaard(variant);
}
// ---- a sphere: periodic and free substrates, both controls ---------------------------------
// A paraboloid of radius 1 at a contact radius of about 20 pixels (Hertz: a^3 = 3FR/(4E*)).
void sphere(asp::SubstrateKind kind, const char *name) {
  const std::int64_t n = 128;
  const double l = 1.0, radius = 1.0, modulus = 1.0, a = 20.0 / n;
  auto grid = asp_test::grid_2d(n, n, l, l);
  std::vector<double> h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, radius, h.data());
  asp::System system(grid, modulus, kind);
  system.set_topography(h.data());
  const double mean = 4 * modulus * a * a * a / (3 * radius) / (l * l);
  for (const Variant &variant : variants) {
    expect_same_state(system, variant, asp::Control::mean_pressure, mean, name);
    expect_same_state(system, variant, asp::Control::penetration, a * a / radius, name);
  }
}

TEST(FourierPreconditioner, SphereOnThePeriodicSubstrate) {
  sphere(asp::SubstrateKind::periodic, "sphere, periodic");
}

TEST(FourierPreconditioner, SphereOnTheFreeSubstrate) {
  sphere(asp::SubstrateKind::free, "sphere, free");
}

// ---- rough periodic scenes ------------------------------------------------------------------
TEST(FourierPreconditioner, RoughPeriodicScene) {
  auto grid = asp_test::grid_2d(128, 128, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 7);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  // About 5 % and 30 % of the surface in contact.
  for (const Variant &variant : variants) {
    expect_same_state(system, variant, asp::Control::mean_pressure, 0.002, "rough 128^2");
    expect_same_state(system, variant, asp::Control::mean_pressure, 0.02, "rough 128^2");
    const Outcome reference =
        solve(system, variant, "none", asp::Control::mean_pressure, 0.01, tolerance);
    expect_same_state(system, variant, asp::Control::penetration, reference.penetration,
                      "rough 128^2");
  }
}

// A finer rough scene with 40 % and 60 % of the surface in contact, the cold start's uniform
// pressure far from the solution's contact set. pk's preconditioned iteration once let pixels off the
// contact set enter along the gap, -tau g, while the set's pixels moved along the
// preconditioned direction: the two disagreed, every step admitted and clipped pixels by
// the thousand, and the contact set stayed at 86 % of the surface for 1000 iterations (at
// 0.05; at 0.02 it converged after 72, by chance).
// Entering along the preconditioned direction, pixels whose gap is negative taken into it,
// it converges to the plain iteration's state.
TEST(FourierPreconditioner, RoughSceneWithALargeContactArea) {
  auto grid = asp_test::grid_2d(256, 256, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 1, 0.1, 0.25, 4.0);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  for (const Variant &variant : variants) {
    for (double mean : {0.02, 0.05}) {
      expect_same_state(system, variant, asp::Control::mean_pressure, mean, "rough 256^2");
      EXPECT_GT(system.contact_fraction(), 0.3) << variant.name;
    }
  }
}

// The preconditioner's purpose: fewer iterations on a fine rough grid. On this 256^2 scene
// (4 % contact) it takes about half the plain iteration's count at the tolerances below
// (measured 24 against 47 and 31 against 70), the ratio falling with the grid as the
// compliance's condition number grows; 0.8 leaves room for another FFT library's rounding to
// change a few iterations, and fails if the preconditioner stops doing its work.
TEST(FourierPreconditioner, FewerIterationsOnAFineRoughScene) {
  auto grid = asp_test::grid_2d(256, 256, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 1, 0.1, 0.25, 8.0);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  for (const Variant &variant : variants) {
    for (double tol : {1e-6, 1e-10}) {
      const Outcome plain =
          solve(system, variant, "none", asp::Control::mean_pressure, 0.002, tol);
      const Outcome fourier =
          solve(system, variant, "fourier", asp::Control::mean_pressure, 0.002, tol);
      ASSERT_TRUE(plain.report.converged()) << variant.name;
      ASSERT_TRUE(fourier.report.converged()) << variant.name;
      std::printf("256^2 rough, %s, tolerance %.0e: %lld iterations (none), %lld (fourier)\n",
                  variant.name, tol, static_cast<long long>(plain.report.iterations),
                  static_cast<long long>(fourier.report.iterations));
      EXPECT_LE(static_cast<double>(fourier.report.iterations),
                0.8 * static_cast<double>(plain.report.iterations))
          << variant.name << ", tolerance " << tol;
      // The default, "auto", is "fourier" on the hard wall without adhesion.
      const Outcome automatic =
          solve(system, variant, "auto", asp::Control::mean_pressure, 0.002, tol);
      EXPECT_EQ(automatic.report.iterations, fourier.report.iterations) << variant.name;
      EXPECT_EQ(automatic.pressure, fourier.pressure) << variant.name;
    }
  }
}

// ---- stiff and extreme scenes: converge, never NaN, and agree with the plain iteration -----
// The scenes of test_polonsky_keer.cpp's ExtremeScenes, solved both ways to 1e-9: the same
// pressure to 1e-7 of its peak (100 times the tolerance, as above; measured at most 5e-10).
// In full contact the preconditioner is the exact inverse and one step solves.
struct Extreme {
  const char *name;
  int dimension;
  std::int64_t nx, ny;
  double modulus, slope, pressure_over_modulus_slope;
};
void PrintTo(const Extreme &e, std::ostream *os) {
  *os << e.name << ", " << e.nx << " x " << e.ny << ", E* " << e.modulus << ", slope "
      << e.slope << ", pressure " << e.pressure_over_modulus_slope << " E* slope";
}
class FourierPreconditionerExtremeScenes : public ::testing::TestWithParam<Extreme> {};

TEST_P(FourierPreconditionerExtremeScenes, ConvergeWithoutNaNToThePlainSolution) {
  const Extreme e = GetParam();
  auto grid = asp::Grid::create(e.dimension, e.nx, e.ny, 1.0, 1.0 * e.ny / e.nx);
  grid->set_fft_planning(asp::FftPlanning::estimate);
  std::vector<double> h(static_cast<std::size_t>(grid->n_pixels()));
  if (e.nx == 1)
    h = asp_test::rough_surface(*asp_test::grid_1d(e.ny, 1.0), 11, e.slope);
  else
    h = asp_test::rough_surface(*grid, 11, e.slope);
  asp::System system(grid, e.modulus);
  system.set_topography(h.data());
  const double mean = e.pressure_over_modulus_slope * e.modulus * e.slope;
  for (const Variant &variant : variants) {
    const Outcome plain =
        solve(system, variant, "none", asp::Control::mean_pressure, mean, 1e-9);
    const Outcome fourier =
        solve(system, variant, "fourier", asp::Control::mean_pressure, mean, 1e-9);
    ASSERT_TRUE(fourier.report.converged())
        << e.name << ", " << variant.name << ": error " << fourier.report.error;
    for (std::size_t i = 0; i < h.size(); ++i) {
      ASSERT_TRUE(std::isfinite(system.state().pressure[i])) << e.name;
      ASSERT_TRUE(std::isfinite(system.state().gap[i])) << e.name;
    }
    // On the pressure the load is the mean of the unknowns, exact to rounding; on the gap it
    // is the gradient's part the load sets, and the stored pressure's mean meets it to the
    // residual, as the plain solve's does (the pressures are compared below).
    if (variant.variable == nullptr || std::string(variant.variable) == "pressure")
      EXPECT_NEAR(fourier.mean_pressure, mean, 1e-12 * mean) << variant.name;
    else
      EXPECT_NEAR(fourier.mean_pressure, plain.mean_pressure,
                  1e-7 * asp_test::max_abs(plain.pressure))
          << variant.name;
    std::printf("%s, %s: iterations %lld (none) and %lld (fourier), max |dp|/max p %.1e\n",
                e.name, variant.name, static_cast<long long>(plain.report.iterations),
                static_cast<long long>(fourier.report.iterations),
                asp_test::max_abs_difference(plain.pressure, fourier.pressure) /
                    asp_test::max_abs(plain.pressure));
    EXPECT_LE(asp_test::max_abs_difference(plain.pressure, fourier.pressure),
              1e-7 * asp_test::max_abs(plain.pressure))
        << variant.name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, FourierPreconditionerExtremeScenes,
    ::testing::Values(Extreme{"tiny modulus", 2, 64, 64, 1e-9, 0.1, 0.01},
                      Extreme{"huge modulus", 2, 64, 64, 1e9, 0.1, 0.01},
                      Extreme{"near zero contact", 2, 64, 64, 1.0, 0.1, 1e-5},
                      Extreme{"near full contact", 2, 64, 64, 1.0, 0.1, 5.0},
                      Extreme{"steep surface", 2, 64, 64, 1.0, 10.0, 0.01},
                      Extreme{"prime sizes", 2, 67, 71, 1.0, 0.1, 0.01},
                      Extreme{"1 x N strip", 2, 1, 257, 1.0, 0.1, 0.05},
                      Extreme{"N x 1 strip", 2, 257, 1, 1.0, 0.1, 0.05},
                      Extreme{"odd 1D", 1, 999, 1, 1.0, 0.1, 0.05}),
    [](const ::testing::TestParamInfo<Extreme> &info) {
      std::string name = info.param.name;
      for (char &c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

// ---- adhesion -------------------------------------------------------------------------------
// An adhesive sphere whose adhesion is weak against its elasticity (a Maugis parameter well
// below 1, a DMT-like contact with one stable state at this penetration): the preconditioned
// gap solve reaches the plain one's state, to 1e-6 of the largest pressure at the tolerance
// 1e-10 (the adhesive Hessian amplifies residual differences more than the hard wall's; measured
// below). "auto" takes the preconditioned path with adhesion too: the same iterations and
// state as "fourier", bit for bit.
TEST(FourierPreconditioner, AdhesiveSphereOnTheGap) {
  const std::int64_t n = 128;
  const double l = 1.0, radius = 1.0, modulus = 1.0, a = 16.0 / n;
  auto grid = asp_test::grid_2d(n, n, l, l);
  std::vector<double> h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, radius, h.data());
  asp::System system(grid, modulus);
  system.set_topography(h.data());
  system.set_adhesion(1e-4, 2.0 * l / n);
  const Variant gap = variants[2];
  const Outcome plain = solve(system, gap, "none", asp::Control::penetration, a * a / radius, 1e-10);
  const Outcome fourier =
      solve(system, gap, "fourier", asp::Control::penetration, a * a / radius, 1e-10);
  ASSERT_TRUE(plain.report.converged());
  ASSERT_TRUE(fourier.report.converged());
  const double peak = asp_test::max_abs(plain.pressure);
  std::printf("adhesive sphere: iterations %lld (none) and %lld (fourier), max |dp|/max p %.1e\n",
              static_cast<long long>(plain.report.iterations),
              static_cast<long long>(fourier.report.iterations),
              asp_test::max_abs_difference(plain.pressure, fourier.pressure) / peak);
  EXPECT_LE(asp_test::max_abs_difference(plain.pressure, fourier.pressure), 1e-6 * peak);
  const Outcome automatic =
      solve(system, gap, "auto", asp::Control::penetration, a * a / radius, 1e-10);
  EXPECT_EQ(automatic.report.iterations, fourier.report.iterations);
  EXPECT_EQ(automatic.pressure, fourier.pressure);
}

// ---- the option -------------------------------------------------------------------------------
TEST(FourierPreconditioner, OptionDefaultsToAutoAndRefusesBadValues) {
  for (const char *algorithm : {"pk", "bugnicourt"}) {
    asp::Solver solver(algorithm);
    EXPECT_EQ(solver.option_text("preconditioner"), "auto") << algorithm;
  }
  asp::Solver solver("pk");
  solver.set_option("preconditioner", std::string("fourier"));
  EXPECT_EQ(solver.option_text("preconditioner"), "fourier");
  for (const char *bad : {"diagonal", "Fourier", "", "none "}) {
    try {
      solver.set_option("preconditioner", std::string(bad));
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::invalid_argument);
      const std::string message = e.what();
      EXPECT_NE(message.find("'preconditioner'"), std::string::npos) << message;
      EXPECT_NE(message.find("fourier"), std::string::npos) << message;
    }
    EXPECT_EQ(solver.option_text("preconditioner"), "fourier");  // a refusal changes nothing
  }
  EXPECT_THROW(solver.set_option("preconditioner", 1.0), asp::Error);
  EXPECT_EQ(solver.option_text("preconditioner"), "fourier");
}

}  // namespace
