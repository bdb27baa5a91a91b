// SPDX-License-Identifier: GPL-2.0-or-later
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
#include "physics/topography.hpp"
#include "solvers/compact_bfgs.hpp"
#include "formulations/dual_formulation.hpp"
#include "solvers/lbfgsb.hpp"
#include "formulations/primal_formulation.hpp"
#include "scene.hpp"

namespace {

using asp::Control;

using asp_test::max_abs;
using asp_test::max_abs_difference;

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

// The bound holds bitwise: L-BFGS-B's iterate (the formulation's variable before it is written
// back) has no entry below 0, and the pressure written back none below 0, on either variable.
TEST(Lbfgsb, KeepsTheBoundExactly) {
  auto grid = asp_test::grid_2d(48, 40, 1.0, 40.0 / 48.0);
  const auto h = asp_test::rough_surface(*grid, 3, 0.1);
  for (bool gap : {false, true}) {
    asp::System system(grid, 1.0);
    system.set_topography(h.data());
    asp::MonitorSettings settings;
    settings.tolerance = 1e-10;
    asp::Monitor monitor(settings);
    double smallest = 0.0;
    if (gap) {
      asp::PrimalFormulation f(system, Control::penetration, 0.01);
      asp::lbfgsb(f, monitor, 5);
      smallest = *std::min_element(f.variable().begin(), f.variable().end());
      ASSERT_TRUE(f.finish());
    } else {
      asp::DualFormulation f(system, Control::penetration, 0.01);
      asp::lbfgsb(f, monitor, 5);
      smallest = *std::min_element(f.variable().begin(), f.variable().end());
      ASSERT_TRUE(f.finish());
    }
    EXPECT_EQ(monitor.termination(), asp::Termination::converged) << (gap ? "gap" : "pressure");
    EXPECT_GE(smallest, 0.0) << (gap ? "gap" : "pressure");
    const auto &p = system.state().pressure;
    EXPECT_GE(*std::min_element(p.begin(), p.end()), 0.0) << (gap ? "gap" : "pressure");
    EXPECT_GT(system.contact_fraction(), 0.0);
    EXPECT_LT(system.contact_fraction(), 0.5);
  }
}

// A warm start from the converged state converges at iteration 0, with one evaluation, on
// the pressure. On the gap the state written back is the hard wall's reading of the iterate
// (the gap recomputed from the clipped pressure), which leaves contact pixels with gaps of
// rounding size that the primal formulation loads as open, with their pressure as residual
// (error about 4e-2 here): one iteration closes them again.
TEST(Lbfgsb, WarmStartStopsAtOnce) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  std::vector<double> h(64 * 64);
  asp::sphere_topography(*grid, 0.5, h.data());
  for (const char *variable : {"pressure", "gap"}) {
    asp::System system(grid, 1.0);
    system.set_topography(h.data());
    asp::Solver solver("lbfgsb");
    solver.set_option("variable", std::string(variable));
    solver.solve(system, Control::penetration, 2e-3);
    ASSERT_TRUE(solver.report().converged()) << variable;
    EXPECT_GT(solver.report().iterations, 5);
    solver.set_history(true);
    solver.solve(system, Control::penetration, 2e-3);
    EXPECT_TRUE(solver.report().converged()) << variable;
    // On the gap too: the stored state has its contact pixels exactly on the wall (they
    // used to come back with rounding-size gaps, read as open pixels: one more iteration).
    EXPECT_EQ(solver.report().iterations, 0) << variable;
    EXPECT_EQ(solver.history().back()[static_cast<int>(asp::HistoryColumn::evaluations)], 1.0);
  }
}

TEST(Lbfgsb, RefusesWhatItCannotServe) {
  asp::Solver solver("lbfgsb");
  EXPECT_THROW(solver.set_option("memory", 0.0), asp::Error);
  EXPECT_THROW(solver.set_option("memory", 101.0), asp::Error);
  EXPECT_THROW(solver.set_option("memory", 2.5), asp::Error);
  EXPECT_THROW(solver.set_option("variable", std::string("displacement")), asp::Error);
  EXPECT_EQ(solver.option("memory"), 5.0);
  EXPECT_EQ(solver.option_text("variable"), "pressure");
  auto grid = asp_test::grid_2d(8, 8, 1.0, 1.0);
  asp::System system(grid, 1.0);
  // A mean-value constraint it cannot keep: mean-gap control on either variable, and load
  // control on the pressure (on the gap the load is a work term, no constraint).
  for (const char *variable : {"pressure", "gap"}) {
    solver.set_option("variable", std::string(variable));
    const bool gap = std::string(variable) == "gap";
    for (Control control : {Control::mean_pressure, Control::mean_gap}) {
      if (gap && control == Control::mean_pressure) continue;
      try {
        solver.solve(system, control, 0.1);
        ADD_FAILURE() << variable << ": a mean-value control was accepted";
      } catch (const asp::Error &e) {
        EXPECT_EQ(e.status(), asp::Status::unsupported);
        EXPECT_NE(std::string(e.what()).find(std::string("variable = ") + variable),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find(gap ? "it offers: penetration, mean_pressure"
                                                 : "it offers: penetration"),
                  std::string::npos)
            << e.what();
      }
    }
  }
}

// ---- small quadratics with known answers ---------------------------------------------------

// f(x) = x.A x/2 + b.x over x >= 0, A symmetric positive definite, on a handful of unknowns.
class SmallQuadratic final : public asp::Formulation {
 public:
  SmallQuadratic(std::vector<double> a, std::vector<double> b, std::vector<double> start)
      : a_(std::move(a)), b_(std::move(b)), x_(start.begin(), start.end()) {}
  std::int64_t size() const override { return static_cast<std::int64_t>(b_.size()); }
  asp::Field &variable() override { return x_; }
  double value_and_gradient(const double *x, double *gradient) override {
    ++counters_.evaluations;
    double value = 0.0;
    for (std::size_t i = 0; i < b_.size(); ++i) {
      double ax = 0.0;
      for (std::size_t j = 0; j < b_.size(); ++j) ax += a_[i * b_.size() + j] * x[j];
      gradient[i] = ax + b_[i];
      value += x[i] * (0.5 * ax + b_[i]);
    }
    return value;
  }
  void hessian_product(const double *, double *) override {}
  double gradient_at_zero(double *) override { return 0.0; }
  double dot(const double *a, const double *b) const override {
    double sum = 0.0;
    for (std::size_t i = 0; i < b_.size(); ++i) sum += a[i] * b[i];
    return sum;
  }
  double lower_bound() const override { return 0.0; }
  bool constrains_mean() const override { return false; }
  double mean_target() const override { return 0.0; }
  double error(const double *x, const double *gradient) const override {
    double e = 0.0;
    for (std::size_t i = 0; i < b_.size(); ++i)
      e = std::max(e, x[i] > 0.0 ? std::fabs(gradient[i]) : std::max(-gradient[i], 0.0));
    return e;
  }
  double contact_fraction(const double *, const double *) const override { return 0.0; }
  double reported_objective(const double *, const double *, double value) const override {
    return value;
  }
  double energy_unit() const override { return 1.0; }
  const asp::Reductions &reductions() const override { return reductions_; }
  bool finish() override { return true; }

 private:
  std::vector<double> a_, b_;
  asp::Field x_;
  asp::LocalReductions reductions_;
};

// On 2 unknowns, A = [[2, 1], [1, 2]], b = (-1, 3): the unconstrained minimiser (5/3, -7/3)
// is infeasible, and the solution is (1/2, 0) with gradient (0, 7/2) (x_1 held by the bound).
// From (1, 1) the whole solve reaches it to rounding: 1e-15.
TEST(Lbfgsb, SolvesASmallQuadraticExactly) {
  for (int memory : {1, 5}) {
    SmallQuadratic f({2.0, 1.0, 1.0, 2.0}, {-1.0, 3.0}, {1.0, 1.0});
    asp::MonitorSettings settings;
    settings.tolerance = 1e-15;
    asp::Monitor monitor(settings);
    asp::lbfgsb(f, monitor, memory);
    EXPECT_EQ(monitor.termination(), asp::Termination::converged) << memory;
    EXPECT_NEAR(f.variable()[0], 0.5, 1e-15) << memory;
    EXPECT_EQ(f.variable()[1], 0.0) << memory;
    EXPECT_LE(monitor.iterations(), 10) << memory;
  }
}

// The monitor's error after iteration 0 is gathered in the line search's pass for the slope;
// it must be the formulation's own error at the accepted point, to the bit. Checked at the
// last iterate of solves that stop short of convergence, mid-way.
TEST(Lbfgsb, ItsErrorIsTheFormulationsAtTheAcceptedPoint) {
  for (int iterations : {1, 2, 3}) {
    SmallQuadratic f({4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0}, {-1.0, 0.5, -2.0},
                     {1.0, 1.0, 1.0});
    asp::MonitorSettings settings;
    settings.tolerance = 1e-15;
    settings.max_iterations = iterations;
    asp::Monitor monitor(settings);
    asp::lbfgsb(f, monitor, 5);
    ASSERT_EQ(monitor.iterations(), iterations);
    std::vector<double> g(3);
    f.value_and_gradient(f.variable().data(), g.data());
    EXPECT_EQ(monitor.error(), f.error(f.variable().data(), g.data())) << iterations;
    EXPECT_GT(monitor.error(), 0.0) << iterations;
  }
}

// The generalized Cauchy point against a direct computation: B built by the BFGS recursion
// from theta I with the same pairs (not the compact form), the model minimised exactly on
// each segment of the projected path in turn. The first local minimiser t must agree to
// rounding (1e-12 relative; the two compute it by different sums).
std::vector<double> bfgs_matrix(int n, const std::vector<std::vector<double>> &s,
                                const std::vector<std::vector<double>> &y) {
  const auto dot = [](const std::vector<double> &a, const std::vector<double> &b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
    return sum;
  };
  const double theta = dot(y.back(), y.back()) / dot(s.back(), y.back());
  std::vector<double> b(static_cast<std::size_t>(n * n), 0.0);
  for (int i = 0; i < n; ++i) b[i * n + i] = theta;
  for (std::size_t k = 0; k < s.size(); ++k) {
    std::vector<double> bs(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) bs[i] += b[i * n + j] * s[k][j];
    const double sbs = dot(s[k], bs), sy = dot(s[k], y[k]);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) b[i * n + j] += -bs[i] * bs[j] / sbs + y[k][i] * y[k][j] / sy;
  }
  return b;
}

double direct_cauchy_t(const std::vector<double> &x, const std::vector<double> &g,
                       const std::vector<double> &b) {
  const int n = static_cast<int>(x.size());
  std::vector<double> breaks;
  for (int i = 0; i < n; ++i)
    if (g[i] > 0.0) breaks.push_back(x[i] / g[i]);
  breaks.push_back(std::numeric_limits<double>::infinity());
  std::sort(breaks.begin(), breaks.end());
  double t = 0.0;
  for (double next : breaks) {
    // On [t, next]: z = x(t) - x and the direction d.
    std::vector<double> z(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const bool held = g[i] > 0.0 && x[i] / g[i] <= t;
      z[i] = held ? -x[i] : -t * g[i];
      d[i] = held ? 0.0 : -g[i];
    }
    double slope = 0.0, curvature = 0.0;
    for (int i = 0; i < n; ++i) {
      double bd = 0.0;
      for (int j = 0; j < n; ++j) bd += b[i * n + j] * d[j];
      slope += g[i] * d[i] + z[i] * bd;
      curvature += d[i] * bd;
    }
    if (slope >= 0.0) return t;
    if (curvature > 0.0 && t - slope / curvature < next) return t - slope / curvature;
    if (!std::isfinite(next)) return t;
    t = next;
  }
  return t;
}

// `pairs` pairs from a convex quadratic entered into bfgs (so that s.y > 0), with g the
// gradient whose products with them the Cauchy point uses; the pairs also go to s and y.
// Returns whether every pair entered.
bool add_quadratic_pairs(asp::CompactBfgs &bfgs, const std::vector<double> &g, int pairs,
                         std::vector<std::vector<double>> &s,
                         std::vector<std::vector<double>> &y) {
  const int n = static_cast<int>(g.size());
  for (int k = 0; k < pairs; ++k) {
    std::vector<double> sk(n), yk(n);
    for (int i = 0; i < n; ++i) {
      sk[i] = std::sin(1.0 + i + 3.0 * k);
      // y = H s with H = diag(1 + i) plus a coupling of neighbours: positive definite.
      yk[i] = (1.0 + i) * sk[i] + 0.3 * ((i > 0 ? sk[i - 1] : 0.0) + (i < n - 1 ? sk[i + 1] : 0.0));
    }
    // add_pair takes x, x_old, g, g_old: the differences are the pair.
    asp::Field x_old(n, 0.0), g_old(n);
    for (int i = 0; i < n; ++i) g_old[i] = g[i] - yk[i];
    if (!bfgs.add_pair(sk.data(), x_old, g.data(), g_old)) return false;
    s.push_back(sk);
    y.push_back(yk);
  }
  return true;
}

TEST(Lbfgsb, GeneralizedCauchyPointIsTheFirstMinimiserAlongThePath) {
  const int n = 6;
  const asp::LocalReductions reductions;
  // Pairs from a convex quadratic, so that s.y > 0; x and g chosen so that the path crosses
  // several breakpoints before the minimum (some unknowns on the bound, some not).
  const std::vector<double> x = {0.0, 0.03, 0.1, 0.05, 0.2, 0.06};
  const std::vector<double> g = {1.0, 0.9, 0.8, -0.4, 1.5, 0.2};
  for (int pairs : {0, 1, 3}) {
    asp::CompactBfgs bfgs(n, 3, reductions);
    std::vector<std::vector<double>> s, y;
    ASSERT_TRUE(add_quadratic_pairs(bfgs, g, pairs, s, y));
    asp::CauchyWork work;
    const asp::CauchyPoint cauchy =
        asp::generalized_cauchy_point(x.data(), g.data(), n, n, 0.0, bfgs, reductions, work);
    const std::vector<double> b =
        pairs == 0 ? std::vector<double>{} : bfgs_matrix(n, s, y);
    std::vector<double> identity(static_cast<std::size_t>(n * n), 0.0);
    for (int i = 0; i < n; ++i) identity[i * n + i] = 1.0;
    const double expected = direct_cauchy_t(x, g, pairs == 0 ? identity : b);
    std::printf("%d pairs: t = %.15g (direct %.15g), %lld at the bound\n", pairs, cauchy.t,
                expected, static_cast<long long>(cauchy.at_bound));
    EXPECT_NEAR(cauchy.t, expected, 1e-12 * expected) << pairs << " pairs";
    EXPECT_GT(cauchy.t, 0.0);
    // The path crossed breakpoints before its minimum: more than the one unknown held at
    // t = 0 is on the bound.
    EXPECT_GE(cauchy.at_bound, 3) << pairs << " pairs";
    // The sums over the free set at x(t), which the subspace step takes from the Cauchy
    // point (formed over the free set at t = 0, or as the totals less the bound set, and
    // then less the breakpoints passed), against the same sums formed directly over the
    // unknowns off the bound at x(t). Allowed: rounding, 1e-14 of the sum of the terms'
    // sizes over all unknowns, since totals may be formed and then reduced.
    const int k2 = bfgs.columns();
    ASSERT_EQ(cauchy.free_gradient.size(), static_cast<std::size_t>(k2));
    ASSERT_EQ(cauchy.free_gram.size(), static_cast<std::size_t>(k2 * k2));
    for (int r = 0; r < k2; ++r) {
      double gradient = 0.0, gradient_size = 0.0;
      std::vector<double> gram(static_cast<std::size_t>(k2), 0.0), gram_size(gram);
      for (int i = 0; i < n; ++i) {
        const bool free = !(g[i] > 0.0 && x[i] <= cauchy.t * g[i]);
        gradient += free ? g[i] * bfgs.entry(r, i) : 0.0;
        gradient_size += std::fabs(g[i] * bfgs.entry(r, i));
        for (int c = 0; c < k2; ++c) {
          gram[c] += free ? bfgs.entry(r, i) * bfgs.entry(c, i) : 0.0;
          gram_size[c] += std::fabs(bfgs.entry(r, i) * bfgs.entry(c, i));
        }
      }
      EXPECT_NEAR(cauchy.free_gradient[r], gradient, 1e-14 * gradient_size)
          << pairs << " pairs, column " << r;
      for (int c = 0; c < k2; ++c)
        EXPECT_NEAR(cauchy.free_gram[r * k2 + c], gram[c], 1e-14 * gram_size[c])
            << pairs << " pairs, entry " << r << ", " << c;
    }
  }
}

// The Cauchy point lists the set the last call listed, and lists again if that guess was
// wrong; when it lists the free set, the breakpoints come from the list. Whatever the guess,
// the point and its sums are the same bits as a first call's: with few free unknowns (the
// free set listed) and with many (the set on the bound listed).
TEST(Lbfgsb, CauchyPointIsTheSameWhicheverSetTheLastCallListed) {
  const int n = 6;
  const asp::LocalReductions reductions;
  const std::vector<double> g = {1.0, 0.9, 0.8, -0.4, 1.5, 0.2};
  for (const std::vector<double> &x : {std::vector<double>{0.0, 0.0, 0.0, 0.05, 0.2, 0.0},
                                       std::vector<double>{0.0, 0.03, 0.1, 0.05, 0.2, 0.06}}) {
    asp::CompactBfgs bfgs(n, 3, reductions);
    std::vector<std::vector<double>> s, y;
    ASSERT_TRUE(add_quadratic_pairs(bfgs, g, 3, s, y));
    asp::CauchyWork first;
    const asp::CauchyPoint expected =
        asp::generalized_cauchy_point(x.data(), g.data(), n, n, 0.0, bfgs, reductions, first);
    using Listed = asp::CauchyWork::Listed;
    for (const Listed guess : {Listed::free, Listed::on_bound}) {
      asp::CauchyWork work;
      work.last_listed = guess;
      const asp::CauchyPoint cauchy =
          asp::generalized_cauchy_point(x.data(), g.data(), n, n, 0.0, bfgs, reductions, work);
      EXPECT_EQ(cauchy.t, expected.t);
      EXPECT_EQ(cauchy.at_bound, expected.at_bound);
      EXPECT_EQ(cauchy.listed_free, expected.listed_free);
      EXPECT_EQ(cauchy.c, expected.c);
      EXPECT_EQ(cauchy.free_gradient, expected.free_gradient);
      EXPECT_EQ(cauchy.free_gram, expected.free_gram);
      EXPECT_EQ(work.last_listed, first.last_listed);
    }
    EXPECT_GT(expected.t, 0.0);
  }
}

// On the gap the search direction is the system's pressure array, which the gap formulation
// writes only when it finishes: 8 bytes per pixel fewer for the largest scenes. Counted by
// the allocator at 64^2 with adhesion and the default memory of 5 pairs: the gradient, the
// trial gradient and the previous iterate (24 B/pixel), the pairs (80), the formulation's
// half spectrum (33 x 64 complex, 8.25) and the substrate's stiffness on it (4.125), and the
// Cauchy point's index list and breakpoint heap (24 on this scene): 140.4 in all; with an
// array of its own the direction made it 148.4.
TEST(Lbfgsb, OnTheGapItsDirectionIsTheSystemsPressure) {
  const double per_pixel = asp_test::adhesive_gap_solve_bytes_per_pixel("lbfgsb");
  std::printf("lbfgsb on the gap: %.2f bytes per pixel\n", per_pixel);
  EXPECT_LE(per_pixel, 140.5);
}

}  // namespace
