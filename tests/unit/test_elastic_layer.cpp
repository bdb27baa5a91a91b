// SPDX-License-Identifier: GPL-2.0-or-later
// The elastic layer on a rigid base: its stiffness law against its closed form and its two
// limits (the half-space for thick layers, uniaxial strain for thin ones), evaluated stably at
// both ends; the substrate it makes, with its own K~(0); and solves on it: a thick layer gives
// the half-space's answer, a thin one the Winkler foundation's, one wavevector in full
// contact p~ = K~(q) u~, and every solver that takes a periodic substrate agrees on it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "physics/periodic_halfspace.hpp"
#include "physics/stiffness_law.hpp"
#include "scene.hpp"

namespace {

using asp::Control;
using asp::LayerLaw;
using asp::System;
using asp_test::pi;

// M = E(1 - nu)/((1 + nu)(1 - 2 nu)), E = E*(1 - nu^2), the uniaxial-strain modulus.
double uniaxial(double e_star, double nu) {
  return e_star * (1.0 - nu * nu) * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

// K~(q) of E* = 2, nu = 0.3, t = 1 at s = qt, from the closed form evaluated with 50 digits
// (mpmath), rounded to 20.
struct Reference {
  double s, k;
};
const Reference references[] = {
    {1e-3, 2.449999825000277458},   {0.3, 2.4362794824718399414}, {0.4999, 2.4196459309473027172},
    {0.5, 2.4196379398572906836},   {1.0, 2.4052812368162361624}, {5.0, 5.0156759484814333942},
};

TEST(LayerLaw, MatchesTheClosedFormOnBothSidesOfItsSeriesBranch) {
  // The law is evaluated from a series below s = 1/2 and from the exp(-2s) form above: both
  // are a few roundings from the closed form (their worst cancellation, in the denominator at
  // s = 1/2, costs a factor below 10), so 1e-13 relative holds with room.
  const LayerLaw law(2.0, 0.3, 1.0);
  for (const Reference &r : references)
    EXPECT_NEAR(law.at(r.s), r.k, 1e-13 * r.k) << "s = " << r.s;
}

TEST(LayerLaw, TendsToUniaxialStrainForThinLayersAndToTheHalfSpaceForThickOnes) {
  for (double nu : {0.0, 0.3, 0.49, 0.4999}) {
    for (double t : {1e-3, 1.0, 7.0}) {
      const LayerLaw law(3.0, nu, t);
      const double k0 = uniaxial(3.0, nu) / t;
      EXPECT_NEAR(law.at_zero(), k0, 1e-14 * k0);
      // qt = 1e-8: K~/K~(0) - 1 is of order (qt)^2 = 1e-16, below rounding; no cancellation
      // even where kappa - 1 = 2(1 - 2 nu) is small.
      EXPECT_NEAR(law.at(1e-8 / t), k0, 1e-12 * k0) << "nu = " << nu << ", t = " << t;
      // qt = 1e3 and beyond: K~/(E*q/2) - 1 ~ (qt)^2 exp(-2qt), far below rounding; nothing
      // overflows.
      for (double s : {1e3, 1e6, 1e300}) {
        const double q = s / t;
        EXPECT_NEAR(law.at(q), 1.5 * q, 1e-12 * 1.5 * q) << "nu = " << nu << ", qt = " << s;
      }
    }
  }
}

TEST(LayerLaw, RefusesWhatItCannotRepresentNamingTheArgument) {
  struct Case {
    double e_star, nu, t;
    const char *argument;
  };
  const Case cases[] = {{0.0, 0.3, 1.0, "'contact_modulus'"}, {1.0, 0.5, 1.0, "'poisson_ratio'"},
                        {1.0, -0.1, 1.0, "'poisson_ratio'"},  {1.0, NAN, 1.0, "'poisson_ratio'"},
                        {1.0, 0.3, 0.0, "'thickness'"},       {1.0, 0.3, INFINITY, "'thickness'"},
                        {1.0, 0.3, 1e-320, "'thickness'"}};
  for (const Case &c : cases) {
    try {
      LayerLaw law(c.e_star, c.nu, c.t);
      ADD_FAILURE() << c.argument << " accepted";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::invalid_argument);
      EXPECT_NE(std::string(e.what()).find(c.argument), std::string::npos) << e.what();
    }
  }
}

TEST(PeriodicSubstrate, TheHalfSpaceLawIsEStarQOverTwoExactlyAndItsK0AConvention) {
  auto grid = asp_test::grid_2d(6, 5, 2.0, 3.0);
  const asp::PeriodicHalfSpace substrate(*grid, 1.7);
  const asp::Field &s = substrate.normalised_stiffness();
  const double n = 30.0;
  substrate.layout().for_each([&](std::int64_t k, double q, double) {
    if (q > 0.0) EXPECT_EQ(s[k], 0.5 * 1.7 * q / n) << k;
  });
  EXPECT_EQ(substrate.mean_stiffness(), asp::MeanStiffness::convention);
  EXPECT_EQ(substrate.k0(), 0.5 * (0.5 * 1.7 * (2 * pi / 2.0) + 0.5 * 1.7 * (2 * pi / 3.0)));
  EXPECT_STREQ(substrate.name(), "periodic half-space");
}

TEST(PeriodicSubstrate, ALayerHasItsOwnK0WhichCannotBeSet) {
  auto grid = asp_test::grid_2d(8, 8, 1.0, 1.0);
  System system(grid, std::make_unique<LayerLaw>(2.0, 0.3, 0.1));
  EXPECT_TRUE(system.substrate().periodic());
  EXPECT_EQ(system.substrate().mean_stiffness(), asp::MeanStiffness::physical);
  EXPECT_NEAR(system.substrate().k0(), uniaxial(2.0, 0.3) / 0.1, 1e-14 * 24.5);
  EXPECT_STREQ(system.substrate().name(), "periodic elastic layer");
  try {
    system.set_k0(3.0);
    ADD_FAILURE() << "set_k0 accepted on a layer";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::unsupported);
    EXPECT_NE(std::string(e.what()).find("periodic elastic layer"), std::string::npos);
  }
}

// A layer 20 box lengths thick: at the lowest wavevector qt = 40 pi, and K~ differs from
// E*q/2 by about (qt)^2 exp(-2qt) = 1e-106 relative, nothing in doubles; under load control
// (which does not involve K~(0)) pressure and gap are the half-space's to the solves'
// tolerance: both stop at an error of 1e-11 of the reference pressure, and the contact
// problem's condition on this grid leaves the fields within 1e-8 of their scale (measured:
// 4e-16, rounding).
TEST(LayerSolves, AThickLayerGivesTheHalfSpacesAnswer) {
  auto grid = asp_test::grid_2d(48, 48, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 7, 0.1);
  System half_space(grid, 1.0);
  System layer(grid, std::make_unique<LayerLaw>(1.0, 0.3, 20.0));
  half_space.set_topography(h.data());
  layer.set_topography(h.data());
  const double load = 0.01;
  for (System *s : {&half_space, &layer})
    ASSERT_TRUE(asp_test::solve_pk(*s, Control::mean_pressure, load, 1e-11).converged());
  const double p_scale = asp_test::max_abs(half_space.state().pressure);
  const double g_scale = asp_test::max_abs(half_space.state().gap);
  EXPECT_LT(asp_test::max_abs_difference(layer.state().pressure, half_space.state().pressure),
            1e-8 * p_scale);
  EXPECT_LT(asp_test::max_abs_difference(layer.state().gap, half_space.state().gap),
            1e-8 * g_scale);
  EXPECT_EQ(layer.contact_fraction(), half_space.contact_fraction());
  EXPECT_NEAR(layer.elastic_energy(), half_space.elastic_energy(),
              1e-8 * half_space.elastic_energy());
}

// A layer much thinner than the surface's wavelengths is a Winkler foundation: each pixel is
// a column under uniaxial strain, p = (M/t) max(0, h - (max h - delta)). The law differs from
// M/t by at most eps = max |K~(q)/K~(0) - 1| over the grid's modes (about 0.06 (qt)^2 at the
// Nyquist wavevector, 2e-4 here); the pressure differs from the Winkler one by that fraction
// of its peak, up to a factor of order one: the test allows 3 eps (measured: 1.1e-6 of the
// peak, most of the pressure being carried by the long wavelengths, where K~ is closer to
// M/t still; a K~(0) off by 1 % would miss by 40 times the bound).
TEST(LayerSolves, AThinLayerIsAWinklerFoundation) {
  const std::int64_t n = 128;
  auto grid = asp_test::grid_2d(n, n, 1.0, 1.0);
  const double t = 1e-4, nu = 0.3, e_star = 1.0;
  auto law = std::make_unique<LayerLaw>(e_star, nu, t);
  const double k0 = law->at_zero();
  double eps = 0.0;
  grid->half_spectrum().for_each([&](std::int64_t, double q, double) {
    if (q > 0.0) eps = std::fmax(eps, std::fabs(law->at(q) / k0 - 1.0));
  });
  ASSERT_LT(eps, 5e-4);
  ASSERT_GT(eps, 1e-6);  // the layer's own stiffness still varies: the test is not trivial
  System layer(grid, std::move(law));
  // A smooth bump: two cosines, tallest at the centre.
  std::vector<double> h(static_cast<std::size_t>(n * n));
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t i = 0; i < n; ++i)
      h[i + n * j] = 1e-5 * (std::cos(2 * pi * i / n) + 0.5 * std::cos(2 * pi * j / n));
  layer.set_topography(h.data());
  const double delta = 1e-5;
  // The reference pressure E* h'_rms/2 of this surface is about 1e-4 of the pressures the
  // stiff layer makes: a tolerance of 1e-8 of it is 1e-12 of the peak pressure.
  const asp::SolveReport report = asp_test::solve_pk(layer, Control::penetration, delta, 1e-8);
  ASSERT_TRUE(report.converged()) << asp::termination_name(report.termination) << " at "
                                  << report.error;
  const double top = layer.max_height();
  double peak = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double winkler = k0 * std::fmax(0.0, h[i] - (top - delta));
    peak = std::fmax(peak, winkler);
    worst = std::fmax(worst, std::fabs(layer.state().pressure[i] - winkler));
  }
  EXPECT_GT(layer.contact_fraction(), 0.1);
  EXPECT_LT(layer.contact_fraction(), 0.9);
  EXPECT_LT(worst, 3.0 * eps * peak) << "eps = " << eps;
}

// h = h0 cos(q.x) pressed into full contact: the displacement is h - max h + delta, so the
// pressure is K~(0)(delta - h0) + K~(q) h0 cos(q.x), exactly (p~ = K~ u~ per mode), to the
// solve's tolerance (1e-12 of the reference pressure).
TEST(LayerSolves, OneWavevectorInFullContactCarriesKOfQTimesItsAmplitude) {
  for (double t : {0.02, 0.3, 3.0}) {
    const std::int64_t nx = 32, ny = 16;
    auto grid = asp_test::grid_2d(nx, ny, 1.0, 0.5);
    auto law = std::make_unique<LayerLaw>(2.0, 0.35, t);
    const double kx = 2 * pi * 2 / 1.0, ky = 2 * pi * 1 / 0.5;
    const double kq = law->at(std::hypot(kx, ky)), k0 = law->at_zero();
    System layer(grid, std::move(law));
    const double h0 = 1e-3;
    std::vector<double> h(static_cast<std::size_t>(nx * ny));
    for (std::int64_t j = 0; j < ny; ++j)
      for (std::int64_t i = 0; i < nx; ++i)
        h[i + nx * j] = h0 * std::cos(kx * i * (1.0 / nx) + ky * j * (0.5 / ny));
    layer.set_topography(h.data());
    // Full contact needs K~(0)(delta - h0) > K~(q) h0: twice that.
    const double delta = h0 + 2.0 * kq * h0 / k0;
    for (const char *algorithm : {"pk", "bugnicourt"}) {
      layer.reset_state();
      ASSERT_TRUE(asp_test::solve_with(algorithm, layer, Control::penetration, delta, 1e-12)
                      .converged());
      EXPECT_EQ(layer.contact_fraction(), 1.0);
      double worst = 0.0;
      for (std::size_t i = 0; i < h.size(); ++i) {
        const double expected = k0 * (delta - h0) + kq * (h[i]);
        worst = std::fmax(worst, std::fabs(layer.state().pressure[i] - expected));
      }
      EXPECT_LT(worst, 1e-9 * k0 * (delta - h0)) << algorithm << ", t = " << t;
    }
  }
}

// Every solver that takes the periodic half-space takes the layer, and they agree: the hard
// wall on a rough surface (pk, bugnicourt and lbfgsb on both variables, under penetration and
// load control where offered), adhesion on the gap, a soft wall (the five unconstrained
// solvers). All solve to 1e-10 of the reference pressure; the fields agree within 1e-7 of
// their scale, what that leaves on these small, well-conditioned grids with a margin
// (measured: below 4e-11 absolute).
struct Request {
  const char *algorithm;
  const char *variable;  // null: no such option
};

std::vector<double> solved_pressure(System &system, const Request &r, Control control,
                                    double value) {
  asp::Solver solver(r.algorithm);
  if (r.variable != nullptr) solver.set_option("variable", std::string(r.variable));
  solver.set_option("tolerance", 1e-10);
  solver.set_option("max_iterations", 200000.0);
  system.reset_state();
  solver.solve(system, control, value);
  EXPECT_TRUE(solver.report().converged())
      << r.algorithm << (r.variable ? r.variable : "") << ": "
      << asp::termination_name(solver.report().termination) << " at "
      << solver.report().error;
  return asp_test::field_vector(system.state().pressure);
}

void expect_agreement(System &system, const std::vector<Request> &requests, Control control,
                      double value) {
  const std::vector<double> reference = solved_pressure(system, requests.front(), control, value);
  const double scale = asp_test::max_abs(reference);
  ASSERT_GT(scale, 0.0);
  for (const Request &r : requests) {
    const std::vector<double> p = solved_pressure(system, r, control, value);
    EXPECT_LT(asp_test::max_abs_difference(p, reference), 1e-7 * scale)
        << r.algorithm << " " << (r.variable ? r.variable : "") << " under "
        << asp::control_name(control);
  }
}

TEST(LayerSolves, EverySolverOfThePeriodicHalfSpaceAgreesOnALayer) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 3, 0.1, 0.5, 2.0);
  // t a tenth of the box: the layer is neither half-space nor Winkler.
  System layer(grid, std::make_unique<LayerLaw>(1.0, 0.4, 0.1));
  layer.set_topography(h.data());
  const double delta = 0.3 * layer.height_range();
  expect_agreement(layer,
                   {{"pk", nullptr},
                    {"bugnicourt", "pressure"},
                    {"bugnicourt", "gap"},
                    {"lbfgsb", "pressure"},
                    {"lbfgsb", "gap"}},
                   Control::penetration, delta);
  expect_agreement(layer, {{"pk", nullptr}, {"bugnicourt", "pressure"}, {"bugnicourt", "gap"},
                           {"lbfgsb", "gap"}},
                   Control::mean_pressure, 0.01);
  layer.set_adhesion(1e-4, 0.02);
  expect_agreement(layer, {{"bugnicourt", "gap"}, {"lbfgsb", "gap"}}, Control::penetration,
                   delta);
  // The soft wall of the unconstrained solvers' own agreement test, its lengths scaled to
  // this box (pixel 1/32): range 0.3 pixels, with attraction.
  const double pixel = 1.0 / 32.0;
  layer.set_soft_wall(0.05 * pixel, 0.3 * pixel, 0.01 * pixel, 0.3 * pixel);
  for (Control control : {Control::penetration, Control::mean_pressure})
    expect_agreement(layer,
                     {{"lbfgs_fourier", nullptr},
                      {"lbfgs", nullptr},
                      {"gfmd", nullptr},
                      {"fire", nullptr},
                      {"fire_mass_weighted", nullptr}},
                     control, control == Control::penetration ? -0.45 * pixel : 3e-4);
}

TEST(LayerSolves, ThePeriodicOnlySolversNameTheSubstratesTheyTake) {
  auto grid = asp_test::grid_2d(8, 8, 1.0, 1.0);
  System free_substrate(grid, 1.0, asp::SubstrateKind::free);
  free_substrate.set_soft_wall(0.05, 0.3, 0.01, 0.3);
  asp::Solver solver("gfmd");
  try {
    solver.check_supported(free_substrate, Control::penetration);
    ADD_FAILURE() << "gfmd accepted a free half-space";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::unsupported);
    EXPECT_NE(std::string(e.what()).find("does not work on a free half-space (it works on "
                                         "periodic substrates (half-space, elastic layer) "
                                         "only)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
