// L-BFGS-B on the dual (pressure) and primal (gap) formulations: the same unique solution as
// Polonsky-Keer and Bugnicourt on rough scenes, the bound kept exactly, warm starts, and on
// small quadratics whose answers are known, the generalized Cauchy point and the whole solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/reductions.hpp"
#include "solvers/compact_bfgs.hpp"
#include "solvers/lbfgsb.hpp"
#include "scene.hpp"

namespace {

using asp::Control;

double max_abs_difference(const asp::Field &a, const asp::Field &b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
  return m;
}

double max_abs(const asp::Field &a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}

struct Case {
  const char *name;
  int dimension;
  std::int64_t nx, ny;
  double mean_pressure;  // of the reference solve, in units of E* h'_rms
  const char *variable;
};

void PrintTo(const Case &c, std::ostream *os) {
  *os << c.name << ", " << c.nx << " x " << c.ny << ", on the " << c.variable;
}

class LbfgsbAgrees : public ::testing::TestWithParam<Case> {};

// The reference is pk under load control, then its penetration given to pk, bugnicourt and
// lbfgsb, all to an error of 1e-11 (residuals below 1e-11 reference pressures or lengths
// over the pixel stiffness). The problem is a strictly convex quadratic, so the states differ
// only by what the residuals allow: on these grids (condition numbers of K below 1e3) far
// below 1e-8 of the peak pressure and the height range, the tolerance used here, as for
// bugnicourt against pk.
TEST_P(LbfgsbAgrees, WithPolonskyKeerAndBugnicourt) {
  const Case c = GetParam();
  const double slope = 0.1, modulus = 1.0, tolerance = 1e-11;
  auto grid = c.dimension == 1 ? asp_test::grid_1d(c.nx, 1.0)
                               : asp_test::grid_2d(c.nx, c.ny, 1.0, 1.0 * c.ny / c.nx);
  const auto heights = asp_test::rough_surface(*grid, 7, slope);
  asp::System pk(grid, modulus), bug(grid, modulus), lb(grid, modulus);
  for (asp::System *s : {&pk, &bug, &lb}) s->set_topography(heights.data());
  ASSERT_TRUE(asp_test::solve_pk(pk, Control::mean_pressure, c.mean_pressure * modulus * slope,
                                 tolerance)
                  .converged());
  const double penetration = pk.state().penetration;
  pk.reset_state();
  ASSERT_TRUE(asp_test::solve_pk(pk, Control::penetration, penetration, tolerance).converged());

  asp::Solver bugnicourt("bugnicourt"), lbfgsb("lbfgsb");
  for (asp::Solver *s : {&bugnicourt, &lbfgsb}) {
    s->set_option("variable", std::string(c.variable));
    s->set_option("tolerance", tolerance);
  }
  lbfgsb.set_history(true);
  bugnicourt.solve(bug, Control::penetration, penetration);
  ASSERT_TRUE(bugnicourt.report().converged());
  lbfgsb.solve(lb, Control::penetration, penetration);
  const asp::SolveReport report = lbfgsb.report();
  ASSERT_TRUE(report.converged()) << asp::termination_name(report.termination) << ", error "
                                  << report.error << " after " << report.iterations
                                  << " iterations";
  const double evaluations =
      lbfgsb.history().back()[static_cast<int>(asp::HistoryColumn::evaluations)];
  for (const asp::System *reference : {&pk, &bug}) {
    const double dp = max_abs_difference(reference->state().pressure, lb.state().pressure);
    const double dg = max_abs_difference(reference->state().gap, lb.state().gap);
    std::printf("%s on the %s: %lld iterations, %g evaluations; against %s |dp|/p_max = %.1e, "
                "|dg|/range = %.1e\n",
                c.name, c.variable, static_cast<long long>(report.iterations), evaluations,
                reference == &pk ? "pk" : "bugnicourt",
                dp / max_abs(reference->state().pressure), dg / lb.height_range());
    EXPECT_LE(dp, 1e-8 * max_abs(reference->state().pressure));
    EXPECT_LE(dg, 1e-8 * lb.height_range());
    EXPECT_NEAR(lb.mean_pressure(), reference->mean_pressure(),
                1e-8 * reference->mean_pressure());
    EXPECT_NEAR(lb.elastic_energy(), reference->elastic_energy(),
                1e-8 * reference->elastic_energy());
    EXPECT_EQ(lb.contact_fraction(), reference->contact_fraction());
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, LbfgsbAgrees,
    ::testing::Values(Case{"light", 2, 64, 64, 0.02, "pressure"},
                      Case{"light", 2, 64, 64, 0.02, "gap"},
                      Case{"heavy", 2, 48, 40, 0.5, "pressure"},
                      Case{"heavy", 2, 48, 40, 0.5, "gap"},
                      Case{"odd sizes", 2, 31, 17, 0.1, "pressure"},
                      Case{"1D", 1, 257, 1, 0.1, "gap"}),
    [](const ::testing::TestParamInfo<Case> &info) {
      std::string name = std::string(info.param.name) + "_" + info.param.variable;
      std::replace(name.begin(), name.end(), ' ', '_');
      return name;
    });

}  // namespace
