// SPDX-License-Identifier: GPL-2.0-or-later
// Every solver of a scene finds the same state: on a free (non-periodic) rough scene pk,
// bugnicourt and lbfgsb on the pressure and on the gap; with adhesion bugnicourt and lbfgsb on
// the gap; and the primal and dual optima have one energy. The gap formulation on the free
// substrate (whose unknowns reach over the padded surface) is checked against finite
// differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scene.hpp"
#include "formulations/primal_formulation.hpp"

namespace {

using asp::Control;

struct Request {
  const char *algorithm;
  const char *variable;
};

struct Outcome {
  std::vector<double> pressure, gap;
  double energy, objective, contact;
};

// Solves cold under penetration control to the tolerance, with the history on for the
// objective of the last iteration.
Outcome solve(asp::System &system, const Request &r, double penetration, double tolerance) {
  asp::Solver solver(r.algorithm);
  if (std::string(r.algorithm) != "pk") solver.set_option("variable", std::string(r.variable));
  solver.set_option("tolerance", tolerance);
  solver.set_option("max_iterations", 20000.0);
  solver.set_history(true);
  system.reset_state();
  solver.solve(system, Control::penetration, penetration);
  EXPECT_TRUE(solver.report().converged())
      << r.algorithm << " on the " << r.variable << ": "
      << asp::termination_name(solver.report().termination) << " at error "
      << solver.report().error;
  Outcome o;
  o.pressure = asp_test::field_vector(system.state().pressure);
  o.gap = asp_test::field_vector(system.state().gap);
  o.energy = system.elastic_energy() + system.mean_mode_energy() + system.interaction_energy();
  o.objective = solver.history().back()[static_cast<int>(asp::HistoryColumn::objective)];
  o.contact = system.contact_fraction();
  return o;
}

using asp_test::max_abs;
using asp_test::max_abs_difference;

// A rough surface on a free 48^2 box at about 10 % contact. The problem is a strictly convex
// quadratic on either variable, so the states differ only by what residuals of 1e-11 (of the
// reference pressure, or of a length over the pixel stiffness) allow: with the contact
// operator's condition number below 1e3 on this grid, far below 1e-8 of the peak pressure
// and of the height range, the tolerances here. The primal objective is the elastic energy
// at the optimum and the dual one its negative (p.g = 0 there): they agree to 1e-9.
TEST(SolverAgreement, FreeSubstrateEverySolverEveryVariable) {
  auto grid = asp_test::grid_2d(48, 48, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 3, 0.1, 0.5, 3.0);
  asp::System system(grid, 1.0, asp::SubstrateKind::free);
  system.set_topography(h.data());
  ASSERT_TRUE(asp_test::solve_pk(system, Control::mean_pressure, 0.01, 1e-11).converged());
  const double penetration = system.state().penetration;
  const double range = system.height_range();

  const Outcome reference = solve(system, {"pk", "pressure"}, penetration, 1e-11);
  ASSERT_GT(reference.contact, 0.03);
  ASSERT_LT(reference.contact, 0.3);
  const double peak = max_abs(reference.pressure);
  for (const Request r : {Request{"bugnicourt", "pressure"}, Request{"bugnicourt", "gap"},
                          Request{"lbfgsb", "pressure"}, Request{"lbfgsb", "gap"}}) {
    const Outcome o = solve(system, r, penetration, 1e-11);
    const std::string name = std::string(r.algorithm) + " on the " + r.variable;
    EXPECT_LE(max_abs_difference(o.pressure, reference.pressure), 1e-8 * peak) << name;
    EXPECT_LE(max_abs_difference(o.gap, reference.gap), 1e-8 * range) << name;
    EXPECT_NEAR(o.energy, reference.energy, 1e-9 * reference.energy) << name;
    EXPECT_EQ(o.contact, reference.contact) << name;
    const bool primal = std::string(r.variable) == "gap";
    // pk's objective is the dual's, -E at the optimum; the primal's is +E.
    EXPECT_NEAR(primal ? o.objective : -o.objective, reference.energy, 1e-9 * reference.energy)
        << name;
  }
  EXPECT_NEAR(-reference.objective, reference.energy, 1e-9 * reference.energy);
}

// A rough periodic 64^2 scene with moderate adhesion (w/rho a fifth of the reference pressure,
// rho two pixels): its energy has one minimum near the solution, which bugnicourt and lbfgsb
// on the gap find from the same cold start. Both stop at a residual of 1e-10 of the reference
// pressure; the Hessian K + phi'' stays positive there, so the gaps agree to 1e-7 of the
// height range and the energies to 1e-9.
TEST(SolverAgreement, AdhesiveRoughSceneOnTheGap) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 5, 0.1, 0.5, 4.0);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  const double rho = 2.0 / 64.0, reference_pressure = 0.5 * 0.1;
  system.set_adhesion(0.2 * reference_pressure * rho, rho);
  const double penetration = 0.3 * system.height_range();
  const Outcome bugnicourt = solve(system, {"bugnicourt", "gap"}, penetration, 1e-10);
  const Outcome lbfgsb = solve(system, {"lbfgsb", "gap"}, penetration, 1e-10);
  EXPECT_GT(bugnicourt.contact, 0.01);
  EXPECT_LE(max_abs_difference(bugnicourt.gap, lbfgsb.gap), 1e-7 * system.height_range());
  EXPECT_NEAR(bugnicourt.energy, lbfgsb.energy, 1e-9 * std::fabs(bugnicourt.energy));
  EXPECT_EQ(bugnicourt.contact, lbfgsb.contact);
  EXPECT_LT(system.interaction_energy(), 0.0);
}

// The gap formulation on the free substrate: its objective's gradient, over the gap on the
// box and the displacement of the padded surface outside it, against central differences.
// The objective is quadratic, so a central difference is exact up to rounding: with steps of
// 1e-4 and values of order 1, 1e-9 relative to the gradient's largest entry.
TEST(SolverAgreement, FreeGapFormulationGradientByFiniteDifferences) {
  auto grid = asp_test::grid_2d(12, 10, 1.0, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 7, 0.1, 0.5, 2.0);
  asp::System system(grid, 1.0, asp::SubstrateKind::free);
  system.set_topography(h.data());
  asp::PrimalFormulation f(system, Control::penetration, 0.2 * system.height_range());
  const std::int64_t n = f.size();
  ASSERT_EQ(n, 4 * grid->n_pixels());
  ASSERT_EQ(f.bounded_size(), grid->n_pixels());
  std::vector<double> x(static_cast<std::size_t>(n)), g(x.size()), scratch(x.size());
  for (std::int64_t i = 0; i < n; ++i) x[i] = 0.1 * std::sin(0.7 * static_cast<double>(i));
  f.value_and_gradient(x.data(), g.data());
  const double scale = max_abs(g), step = 1e-4;
  for (std::int64_t i = 0; i < n; i += 7) {
    std::vector<double> plus = x, minus = x;
    plus[i] += step;
    minus[i] -= step;
    const double fp = f.value_and_gradient(plus.data(), scratch.data());
    const double fm = f.value_and_gradient(minus.data(), scratch.data());
    EXPECT_NEAR((fp - fm) / (2 * step), g[i], 1e-9 * scale) << "unknown " << i;
  }
}

}  // namespace
