// SPDX-License-Identifier: GPL-2.0-or-later
// What "in contact" means, and that every part of the library says the same: with the hard
// wall the pixels where the gap is 0 (the solver's active set, which every write-back stores
// as exact zeros), with adhesion the JKR/Maugis-Dugdale area rather than its compressive core;
// for a soft wall where phi'(g) < 0. The contact map, the contact fraction, the last row of
// the history and the compressive fraction agree for every ending of a solve, and a hard-wall
// solve stopped short of its tolerance leaves no interpenetration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "physics/topography.hpp"
#include "scene.hpp"

namespace {

using asp::Control;
using asp_test::pi;

double count_on_wall(const asp::System &system, double threshold) {
  const auto &g = system.state().gap;
  return static_cast<double>(
      std::count_if(g.begin(), g.end(), [&](double v) { return v <= threshold; }));
}

std::vector<double> contact_map(const asp::System &system) {
  std::vector<double> map(static_cast<std::size_t>(system.grid().local_pixels()));
  system.contact_map(map.data());
  return map;
}

double mean(const std::vector<double> &v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

// ---- the adhesive sphere -------------------------------------------------------------------
// JKR: F = 4E* a^3/(3R) - sqrt(8 pi w E* a^3), the force at contact radius a.
double jkr_force(double a, double radius, double work, double modulus) {
  return 4 * modulus * a * a * a / (3 * radius) - std::sqrt(8 * pi * work * modulus * a * a * a);
}

// The scene of JKRSphere.ContactRadiusAgainstLoadAndPullOffAtTaborFive (test_adhesion.cpp):
// E* = R = 1, w = 1e-3, Tabor parameter 5 (rho = 2e-3), a free box of 0.6 on 256 pixels, the
// cohesive zone 1.7 pixels wide. There the radius of the pixels on the wall (gap <= 1e-3
// rho) satisfies JKR's force-radius relation within 0.05 pi w R at every penetration
// (measured 0.005-0.04; Maugis-Dugdale at Tabor 5 is within 1 % of JKR): the contact
// fraction must give that radius. The compressive core's radius (p > 0, what the fraction
// counted before) is 0.63 to 0.75 of it at the three penetrations here, 10 to 20 pixels
// short. The two radii from the pixels may differ by the ring of pixels whose gap lies in
// (0, 1e-3 rho]: at most a pixel of radius (the half-pixel rounding of the edge, twice;
// measured: none).
TEST(ContactDefinition, AdhesiveSphereContactRadiusIsTheJKRMaugisOne) {
  const double radius = 1.0, modulus = 1.0, work = 1e-3, box = 0.6;
  const std::int64_t n = 256;
  const double rho = std::cbrt(radius * work * work / (modulus * modulus)) / 5.0;
  auto grid = asp_test::grid_2d(n, n, box, box);
  std::vector<double> h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, radius, h.data());
  asp::System system(grid, modulus, asp::SubstrateKind::free);
  system.set_topography(h.data());
  system.set_adhesion(work, rho);
  asp::Solver solver("bugnicourt");
  solver.set_option("variable", std::string("gap"));
  solver.set_option("tolerance", 1e-7);
  solver.set_option("max_iterations", 20000);
  const double pixel_area = grid->pixel_area(), pixel = box / static_cast<double>(n);
  const double scale = pi * work * radius;
  for (double delta : {0.004, 0.0, -0.006}) {
    solver.solve(system, Control::penetration, delta);
    ASSERT_TRUE(solver.report().converged()) << "delta " << delta;
    const double from_key = std::sqrt(system.contact_fraction() * grid->area() / pi);
    const double from_gap = std::sqrt(count_on_wall(system, 1e-3 * rho) * pixel_area / pi);
    const double core = std::sqrt(system.compressive_fraction() * grid->area() / pi);
    const double force = system.total_force();
    std::printf("delta %+.4f: F/(pi w R) %+.4f, a %.4f (gap <= 1e-3 rho: %.4f, p > 0: %.4f), "
                "JKR F(a) %+.4f\n",
                delta, force / scale, from_key, from_gap, core,
                jkr_force(from_key, radius, work, modulus) / scale);
    EXPECT_NEAR(from_key, from_gap, pixel) << "delta " << delta;
    EXPECT_NEAR(force / scale, jkr_force(from_key, radius, work, modulus) / scale, 0.05)
        << "delta " << delta;
    // The compressive core lies inside the contact, and with adhesion is smaller.
    EXPECT_LT(core, from_key) << "delta " << delta;
    EXPECT_EQ(mean(contact_map(system)), system.contact_fraction());
  }
}

// ---- solves stopped short of the tolerance -------------------------------------------------
struct Stopped {
  const char *algorithm;
  const char *variable;  // "" for pk
  bool adhesive;
  Control control;
};

std::string name_of(const ::testing::TestParamInfo<Stopped> &info) {
  std::string name = std::string(info.param.algorithm) +
                     (info.param.variable[0] ? std::string("_") + info.param.variable : "") +
                     (info.param.adhesive ? "_adhesive" : "") +
                     (info.param.control == Control::mean_pressure ? "_load" : "_penetration");
  return name;
}

class StoppedHardWallSolve : public ::testing::TestWithParam<Stopped> {};

// A rough 64^2 surface pressed to about a tenth of its height range, a solve cut at a few
// iterations (far from its tolerance of 1e-12) or, with a small stall window, stalled. The
// state left: no gap below 0 anywhere (the gap a pressure iterate makes interpenetrates off
// its active set, and a gap solve used to store that gap), the gap exactly 0 where a
// pressure solve left compressive pressure (its active set), the contact map's mean the
// contact fraction, the compressive pixels a part of the contact, and the last history row
// the contact fraction of the state, for every ending. Exact comparisons: all are counts
// of the same pixels.
TEST_P(StoppedHardWallSolve, LeavesNoInterpenetrationAndOneContactSet) {
  const Stopped &c = GetParam();
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 11);
  const double range =
      *std::max_element(h.begin(), h.end()) - *std::min_element(h.begin(), h.end());
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  if (c.adhesive) system.set_adhesion(1e-4, 2e-3);  // w/rho = 0.05, a tenth of E* h'_rms
  // The mean pressure of the penetration 0.1 range, about 0.01 E*.
  const double value = c.control == Control::penetration ? 0.1 * range : 0.01;
  for (const int iterations : {1, 3, 10}) {
    system.reset_state();
    asp::Solver solver(c.algorithm);
    if (c.variable[0]) solver.set_option("variable", std::string(c.variable));
    solver.set_option("tolerance", 1e-12);
    solver.set_option("max_iterations", static_cast<double>(iterations));
    solver.set_history(true);
    solver.solve(system, c.control, value);
    const asp::SolveReport &report = solver.report();
    SCOPED_TRACE(std::string(asp::termination_name(report.termination)) + " after " +
                 std::to_string(report.iterations) + " iterations");
    ASSERT_NE(report.termination, asp::Termination::breakdown);
    EXPECT_FALSE(report.converged());
    const auto &g = system.state().gap;
    const auto &p = system.state().pressure;
    EXPECT_GE(*std::min_element(g.begin(), g.end()), 0.0);
    if (c.variable[0] != 'g')
      for (std::size_t i = 0; i < g.size(); ++i)
        if (p[i] > 0.0) ASSERT_EQ(g[i], 0.0) << "pixel " << i;
    const double fraction = system.contact_fraction();
    EXPECT_GT(fraction, 0.0);
    EXPECT_EQ(mean(contact_map(system)), fraction);
    EXPECT_EQ(count_on_wall(system, 0.0) / static_cast<double>(g.size()), fraction);
    EXPECT_LE(system.compressive_fraction(), fraction);
    ASSERT_FALSE(solver.history().empty());
    EXPECT_EQ(solver.history().back()[static_cast<int>(asp::HistoryColumn::contact_fraction)],
              fraction);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Solvers, StoppedHardWallSolve,
    ::testing::Values(Stopped{"pk", "", false, Control::mean_pressure},
                      Stopped{"pk", "", false, Control::penetration},
                      Stopped{"bugnicourt", "pressure", false, Control::mean_pressure},
                      Stopped{"bugnicourt", "gap", false, Control::penetration},
                      Stopped{"bugnicourt", "gap", true, Control::penetration},
                      Stopped{"lbfgsb", "pressure", false, Control::penetration},
                      Stopped{"lbfgsb", "gap", false, Control::penetration},
                      Stopped{"lbfgsb", "gap", true, Control::penetration}),
    name_of);

// The same for an adhesive gap solve that stalls: a stall window of 2 iterations on a strongly
// adhesive scene (w/rho = 5 E* h'_rms), the case where the stored gap used to go below 0 and
// the history and the contact fraction disagreed (0.88 and 0.39 on the command's scene).
TEST(ContactDefinition, StalledAdhesiveSolveAgreesWithItsHistory) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 5);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  system.set_adhesion(1e-3, 2e-4);
  int stalled = 0;
  for (const char *algorithm : {"bugnicourt", "lbfgsb"}) {
    for (const int window : {1, 2, 5}) {
      system.reset_state();
      asp::Solver solver(algorithm);
      solver.set_option("variable", std::string("gap"));
      solver.set_option("tolerance", 1e-14);
      solver.set_option("stall_window", static_cast<double>(window));
      solver.set_option("max_iterations", 200);
      solver.set_history(true);
      solver.solve(system, Control::penetration, 0.0);
      const asp::SolveReport &report = solver.report();
      SCOPED_TRACE(std::string(algorithm) + ": " + asp::termination_name(report.termination));
      ASSERT_NE(report.termination, asp::Termination::breakdown);
      stalled += report.termination == asp::Termination::stalled ? 1 : 0;
      const auto &g = system.state().gap;
      EXPECT_GE(*std::min_element(g.begin(), g.end()), 0.0);
      EXPECT_EQ(solver.history().back()[static_cast<int>(asp::HistoryColumn::contact_fraction)],
                system.contact_fraction());
    }
  }
  EXPECT_GT(stalled, 0);
}

// ---- soft walls ----------------------------------------------------------------------------
// A soft wall's contact is where phi'(g) < 0; far from contact the pressure is an attraction
// of rounding size whose sign is noise, so the map is not the sign of the pressure. The map's
// mean is the contact fraction, and the compressive pixels lie inside the contact.
TEST(ContactDefinition, SoftWallMapIsWherePhiPrimeIsNegative) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 3);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  const double rho = 1e-3;
  system.set_soft_wall(1e-4, rho, 1e-4, rho);
  const auto report =
      asp_test::solve_with("lbfgs", system, Control::mean_pressure, 0.005, 1e-8);
  ASSERT_TRUE(report.converged());
  const std::vector<double> map = contact_map(system);
  // phi'(g) = -(2 gamma_r/rho) e^(-2g/rho) + (gamma_a/rho) e^(-g/rho) < 0 for g < rho ln 2.
  const auto &g = system.state().gap;
  for (std::size_t i = 0; i < g.size(); ++i)
    if (std::fabs(g[i] - rho * std::log(2.0)) > 1e-9 * rho)
      ASSERT_EQ(map[i], g[i] < rho * std::log(2.0) ? 1.0 : 0.0) << "pixel " << i;
  EXPECT_EQ(mean(map), system.contact_fraction());
  EXPECT_GT(system.contact_fraction(), 0.0);
  EXPECT_LT(system.contact_fraction(), 0.5);
  EXPECT_LE(system.compressive_fraction(), system.contact_fraction());
}

// A hard-wall state that no solve made: after a reset the undeformed body touches the highest
// point, whose gap is 0: those pixels are in contact (with zero pressure, so not compressive).
TEST(ContactDefinition, ResetStateTouchesAtTheHighestPoint) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 7);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  const double top = *std::max_element(h.begin(), h.end());
  const double highest = static_cast<double>(std::count(h.begin(), h.end(), top));
  EXPECT_EQ(system.contact_fraction(), highest / static_cast<double>(h.size()));
  EXPECT_EQ(system.compressive_fraction(), 0.0);
}

}  // namespace
