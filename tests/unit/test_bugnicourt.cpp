// SPDX-License-Identifier: GPL-2.0-or-later
// Bugnicourt's constrained conjugate gradient on the dual formulation: it solves the same
// strictly convex problem as Polonsky-Keer, so both must reach the same unique solution; and
// it must meet the Hertz closed form on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "physics/topography.hpp"
#include "scene.hpp"

namespace {

using asp::Control;

struct Case {
  const char *name;
  int dimension;
  std::int64_t nx, ny;
  double mean_pressure;  // in units of E* h'_rms; the penetration cases use the load's
  Control control;
};

void PrintTo(const Case &c, std::ostream *os) {
  *os << c.name << ", " << c.nx << " x " << c.ny << ", "
      << (c.control == Control::mean_pressure ? "load" : "penetration") << " control";
}

class AgreesWithPolonskyKeer : public ::testing::TestWithParam<Case> {};

using asp_test::max_abs;
using asp_test::max_abs_difference;

// Both solvers to an error of 1e-11 (residual gaps below 1e-11 reference pressures over the
// pixel stiffness), above both rounding floors (Bugnicourt's levels off near 1.3e-12 on the
// heavy-load scene, where its mean is restored by rescaling every step; Polonsky-Keer's near
// 7e-13). The problem is a strictly convex quadratic, so the solutions differ only by what
// the two residuals allow: on these grids (condition numbers of K below 1e3) that is far
// below 1e-8 of the peak pressure and of the height range, the tolerance used here
// (measured: up to 4e-12 of the peak pressure and 1e-12 of the range).
TEST_P(AgreesWithPolonskyKeer, SameStateToTheTolerance) {
  const Case c = GetParam();
  const double slope = 0.1, modulus = 1.0;
  auto grid = c.dimension == 1 ? asp_test::grid_1d(c.nx, 1.0)
                               : asp_test::grid_2d(c.nx, c.ny, 1.0, 1.0 * c.ny / c.nx);
  std::vector<double> heights;
  if (c.dimension == 1 || c.ny > 1) {
    heights = asp_test::rough_surface(*grid, 7, slope);
  } else {
    heights = asp_test::rough_surface(*asp_test::grid_1d(c.nx, 1.0), 7, slope);
  }
  asp::System pk(grid, modulus), bug(grid, modulus);
  pk.set_topography(heights.data());
  bug.set_topography(heights.data());

  const double load = c.mean_pressure * modulus * slope;
  const double tolerance = 1e-11;
  const auto pk_load = asp_test::solve_pk(pk, Control::mean_pressure, load, tolerance);
  ASSERT_TRUE(pk_load.converged());
  double value = load;
  if (c.control == Control::penetration) {
    value = pk.state().penetration;
    pk.reset_state();
    ASSERT_TRUE(asp_test::solve_pk(pk, Control::penetration, value, tolerance).converged());
  }
  const auto report = asp_test::solve_with("bugnicourt", bug, c.control, value, tolerance);
  ASSERT_TRUE(report.converged()) << "error " << report.error << " after "
                                  << report.iterations << " iterations";
  const double dp = max_abs_difference(pk.state().pressure, bug.state().pressure);
  const double dg = max_abs_difference(pk.state().gap, bug.state().gap);
  std::printf("%s: bugnicourt %lld iterations, |dp|/p_max = %.1e, |dg|/range = %.1e\n", c.name,
              static_cast<long long>(report.iterations), dp / max_abs(pk.state().pressure),
              dg / bug.height_range());
  EXPECT_LE(dp, 1e-8 * max_abs(pk.state().pressure));
  EXPECT_LE(dg, 1e-8 * bug.height_range());
  EXPECT_NEAR(bug.mean_pressure(), pk.mean_pressure(), 1e-10 * pk.mean_pressure());
  EXPECT_NEAR(bug.state().penetration, pk.state().penetration, 1e-8 * bug.height_range());
  EXPECT_NEAR(bug.elastic_energy(), pk.elastic_energy(), 1e-8 * pk.elastic_energy());
  EXPECT_EQ(bug.contact_fraction(), pk.contact_fraction());
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, AgreesWithPolonskyKeer,
    ::testing::Values(Case{"light load", 2, 64, 64, 0.02, Control::mean_pressure},
                      Case{"heavy load", 2, 64, 64, 0.5, Control::mean_pressure},
                      Case{"odd sizes", 2, 31, 17, 0.1, Control::mean_pressure},
                      Case{"1D", 1, 257, 1, 0.1, Control::mean_pressure},
                      Case{"light penetration", 2, 64, 64, 0.02, Control::penetration},
                      Case{"heavy penetration", 2, 48, 40, 0.5, Control::penetration}),
    [](const ::testing::TestParamInfo<Case> &info) {
      std::string name = info.param.name;
      std::replace(name.begin(), name.end(), ' ', '_');
      return name;
    });

// A warm start from the solution converges at once, and a load sweep warm-started step by
// step converges at every step (the sweep that once stalled Polonsky-Keer).
TEST(Bugnicourt, WarmStartsConverge) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  std::vector<double> h(64 * 64);
  asp::sphere_topography(*grid, 0.5, h.data());
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  double last = 0.0;
  for (double load = 1e-7; load <= 3.2e-3; load *= 2) {
    last = load;
    const auto report = asp_test::solve_with("bugnicourt", system, Control::mean_pressure, load);
    ASSERT_TRUE(report.converged()) << "load " << load;
    const auto &g = system.state().gap;
    EXPECT_GT(*std::min_element(g.begin(), g.end()), -1e-8) << "load " << load;
  }
  const auto again = asp_test::solve_with("bugnicourt", system, Control::mean_pressure, last);
  EXPECT_TRUE(again.converged());
  EXPECT_EQ(again.iterations, 0);
}

// The history's objective is the same function for both solvers: at their converged states
// (error 1e-11) the last rows agree to the solution's accuracy, under both controls.
TEST(Bugnicourt, HistoryObjectiveIsPolonskyKeers) {
  auto grid = asp_test::grid_2d(48, 40, 1.0, 40.0 / 48.0);
  const auto h = asp_test::rough_surface(*grid, 5, 0.1);
  double penetration = 0.0;
  for (Control control : {Control::mean_pressure, Control::penetration}) {
    double last[2] = {0.0, 0.0};
    int k = 0;
    for (const char *algorithm : {"pk", "bugnicourt"}) {
      asp::System system(grid, 1.0);
      system.set_topography(h.data());
      asp::Solver solver(algorithm);
      solver.set_option("tolerance", 1e-11);
      solver.set_history(true);
      solver.solve(system, control, control == Control::mean_pressure ? 0.01 : penetration);
      ASSERT_TRUE(solver.report().converged()) << algorithm;
      last[k++] = solver.history().back()[static_cast<int>(asp::HistoryColumn::objective)];
      if (control == Control::mean_pressure) penetration = system.state().penetration;
    }
    EXPECT_NEAR(last[1], last[0], 1e-9 * std::fabs(last[0]))
        << (control == Control::mean_pressure ? "load" : "penetration");
  }
}

// On the gap (the primal): the same unique solution again, under penetration control and
// under mean-gap control with the mean gap of Polonsky-Keer's solution; tolerances as above.
TEST_P(AgreesWithPolonskyKeer, OnTheGapToo) {
  const Case c = GetParam();
  const double slope = 0.1, modulus = 1.0, tolerance = 1e-11;
  auto grid = c.dimension == 1 ? asp_test::grid_1d(c.nx, 1.0)
                               : asp_test::grid_2d(c.nx, c.ny, 1.0, 1.0 * c.ny / c.nx);
  const auto heights = c.dimension == 1 || c.ny > 1
                           ? asp_test::rough_surface(*grid, 7, slope)
                           : asp_test::rough_surface(*asp_test::grid_1d(c.nx, 1.0), 7, slope);
  asp::System pk(grid, modulus);
  pk.set_topography(heights.data());
  ASSERT_TRUE(
      asp_test::solve_pk(pk, Control::mean_pressure, c.mean_pressure * modulus * slope, tolerance)
          .converged());
  const Control control = c.control == Control::mean_pressure ? Control::mean_gap : c.control;
  const double value =
      control == Control::mean_gap ? pk.mean_gap() : pk.state().penetration;
  asp::System primal(grid, modulus);
  primal.set_topography(heights.data());
  asp::Solver solver("bugnicourt");
  solver.set_option("variable", std::string("gap"));
  solver.set_option("tolerance", tolerance);
  solver.solve(primal, control, value);
  ASSERT_TRUE(solver.report().converged()) << "error " << solver.report().error;
  const double dp = max_abs_difference(pk.state().pressure, primal.state().pressure);
  const double dg = max_abs_difference(pk.state().gap, primal.state().gap);
  std::printf("%s on the gap: %lld iterations, |dp|/p_max = %.1e, |dg|/range = %.1e\n", c.name,
              static_cast<long long>(solver.report().iterations),
              dp / max_abs(pk.state().pressure), dg / primal.height_range());
  EXPECT_LE(dp, 1e-8 * max_abs(pk.state().pressure));
  EXPECT_LE(dg, 1e-8 * primal.height_range());
  EXPECT_NEAR(primal.mean_pressure(), pk.mean_pressure(), 1e-8 * pk.mean_pressure());
  EXPECT_NEAR(primal.state().penetration, pk.state().penetration, 1e-8 * primal.height_range());
  EXPECT_NEAR(primal.mean_gap(), pk.mean_gap(), 1e-8 * primal.height_range());
  EXPECT_EQ(primal.contact_fraction(), pk.contact_fraction());
}

// After steps the bound did not cut, the gradient follows from the Hessian product: fewer
// than two pairs of transforms per iteration on a rough scene (four if every gradient were
// evaluated), and still the same converged state (the agreement tests above). The Fourier
// preconditioner adds one pair per iteration.
TEST(Bugnicourt, FollowsTheGradientBetweenEvaluations) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 5, 0.1);
  for (const char *preconditioner : {"none", "fourier"})
  for (const char *variable : {"pressure", "gap"}) {
    asp::System system(grid, 1.0);
    system.set_topography(h.data());
    asp::Solver solver("bugnicourt");
    solver.set_option("variable", std::string(variable));
    solver.set_option("preconditioner", std::string(preconditioner));
    solver.set_history(true);
    const Control control =
        std::string(variable) == "gap" ? Control::penetration : Control::mean_pressure;
    solver.solve(system, control, control == Control::penetration ? 0.004 : 0.002);
    ASSERT_TRUE(solver.report().converged()) << variable;
    const auto &last = solver.history().back();
    const double iterations = last[static_cast<int>(asp::HistoryColumn::iteration)];
    const double evaluations = last[static_cast<int>(asp::HistoryColumn::evaluations)];
    const double transforms = last[static_cast<int>(asp::HistoryColumn::transforms)];
    std::printf("%s, %s: %g iterations, %g evaluations, %.2f transforms per iteration\n",
                variable, preconditioner, iterations, evaluations, transforms / iterations);
    const double pairs = std::string(preconditioner) == "none" ? 0.0 : 1.0;
    EXPECT_LT(evaluations, iterations) << variable;
    EXPECT_LT(transforms / iterations, 3.8 + 2.0 * pairs) << variable << ", " << preconditioner;
  }
}

// On the gap with adhesion the solve's trial point is the system's pressure array, which the
// gap formulation writes only when it finishes: the largest scenes then need 8 bytes per
// pixel fewer. Counted by the allocator at 64^2 with the default preconditioner: seven
// solver arrays (the preconditioned residual among them, 56 B/pixel), the formulation's half
// spectrum (33 x 64 complex, 8.25), the substrate's stiffness on it (4.125) and its inverse
// (4.125), 72.5 in all; with an array of its own the trial point made it 80.5.
TEST(Bugnicourt, OnTheGapWithAdhesionItsTrialPointIsTheSystemsPressure) {
  EXPECT_LE(asp_test::adhesive_gap_solve_bytes_per_pixel("bugnicourt"), 72.5);
}

TEST(Bugnicourt, RefusesWhatItCannotServe) {
  asp::Solver solver("bugnicourt");
  EXPECT_THROW(solver.set_option("variable", std::string("displacement")), asp::Error);
  auto grid = asp_test::grid_2d(8, 8, 1.0, 1.0);
  asp::System system(grid, 1.0);
  // On the pressure, mean-gap control; on the gap (which takes mean-pressure control as a
  // work term), mean-gap control on a free substrate.
  asp::System free(grid, 1.0, asp::SubstrateKind::free);
  for (const char *variable : {"pressure", "gap"}) {
    solver.set_option("variable", std::string(variable));
    const Control control = Control::mean_gap;
    asp::System &target = std::string(variable) == "gap" ? free : system;
    try {
      solver.solve(target, control, 0.1);
      ADD_FAILURE() << variable << ": a control it does not offer was accepted";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported);
      EXPECT_NE(std::string(e.what()).find(std::string("variable = ") + variable),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW(solver.solve(system, Control::mean_gap, -0.1), asp::Error);
}

}  // namespace
