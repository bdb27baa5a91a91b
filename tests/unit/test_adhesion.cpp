// SPDX-License-Identifier: GPL-2.0-or-later
// The hard wall with exponential adhesion, phi(g) = -w exp(-g/rho): the primal formulation
// against finite differences, the plain hard wall recovered bit for bit with w = 0, the
// registry's refusals, the safeguarded Bugnicourt step on strong adhesion, and the closed
// forms: Johnson's adhesive sinusoid, the JKR sphere (contact radius against load, pull-off)
// and the trend towards the DMT pull-off at small Tabor parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/random.hpp"
#include "physics/topography.hpp"
#include "scene.hpp"
#include "formulations/primal_formulation.hpp"

namespace {

using asp::Control;
using asp_test::pi;
using Vector = std::vector<double>;

using asp_test::dot;
using asp_test::max_abs;
Vector random_vector(std::size_t n, std::uint64_t seed, double low) {
  asp::Random random(seed);
  Vector v(n);
  for (double &x : v) x = low + (1.0 - low) * random.uniform();
  return v;
}

asp::SolveReport solve_on_gap(asp::System &system, Control control, double value,
                              double tolerance, std::int64_t max_iterations = 20000) {
  asp::Solver solver("bugnicourt");
  solver.set_option("variable", std::string("gap"));
  solver.set_option("tolerance", tolerance);
  solver.set_option("max_iterations", static_cast<double>(max_iterations));
  solver.solve(system, control, value);
  return solver.report();
}

// ---- the primal formulation with adhesion against finite differences ------------------------
// The reference pressure P is set, so that the scaled units are known here: gaps in
// l = P/k (k the pixel stiffness), the potential -W exp(-x/r) with W = w/(P l), r = rho/l.
// Central differences have the truncation error (h^2/6) f''' along the step: for the value
// sum_i (W/r^3) e^(h/r) |d_i|^3 (the elastic part is quadratic, exact), for a gradient entry
// (h^2/6) (W/r^4) e^(h/r) |d_i|^3; rounding adds 1e-12 of the rounded terms over h, as in
// test_primal_formulation.
class AdhesivePrimal
    : public ::testing::TestWithParam<std::tuple<std::int64_t, std::int64_t, Control>> {};

TEST_P(AdhesivePrimal, GradientAndHessianMatchCentralDifferences) {
  const auto [nx, ny, control] = GetParam();
  auto grid = ny == 1 ? asp_test::grid_1d(nx, 1.0) : asp_test::grid_2d(nx, ny, 1.0, 0.8);
  const auto heights = asp_test::rough_surface(*grid, 3, 0.1);
  asp::System system(grid, 1.0);
  system.set_topography(heights.data());
  const double P = 0.05, l = P / system.substrate().pixel_stiffness();
  system.set_reference_pressure(P);
  const double rho = 0.5 * l, w = 2.0 * rho * P;  // r = 0.5, W = 1: phi'' up to 4 k
  system.set_adhesion(w, rho);
  const double W = w / (P * l), r = rho / l;

  asp::PrimalFormulation f(system, control, control == Control::mean_gap ? 0.4 * l : 0.003);
  ASSERT_FALSE(f.quadratic());
  const auto n = static_cast<std::size_t>(f.size());
  const Vector x = random_vector(n, 11, 0.0);  // scaled gaps in [0, 1]: adhesion matters
  std::copy(x.begin(), x.end(), f.variable().begin());  // the Hessian is taken at the iterate
  Vector g(n), gp(n), gm(n), hd(n);
  const double value = f.value_and_gradient(x.data(), g.data());
  for (std::uint64_t seed : {21, 22}) {
    const Vector d = random_vector(n, seed, -1.0);
    f.hessian_product(d.data(), hd.data());
    for (double h : {1e-2, 1e-3}) {
      Vector xp(x), xm(x);
      for (std::size_t i = 0; i < n; ++i) xp[i] += h * d[i], xm[i] -= h * d[i];
      const double fp = f.value_and_gradient(xp.data(), gp.data());
      const double fm = f.value_and_gradient(xm.data(), gm.data());
      const double third = W / (r * r * r) * std::exp(h / r);  // |phi'''| at x - h|d|
      const double fourth = third / r;                            // |phi''''|
      double cubes = 0.0;
      for (double v : d) cubes += std::fabs(v * v * v);
      const double rounding =
          1e-12 * (std::fabs(value) + max_abs(g) * max_abs(x) * n + std::fabs(fp) + std::fabs(fm)) /
          h;
      EXPECT_NEAR((fp - fm) / (2 * h), dot(g, d), h * h / 6 * third * cubes + rounding)
          << "h " << h;
      const double gsize = 1e-12 * (max_abs(gp) + max_abs(gm)) / h;
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_NEAR((gp[i] - gm[i]) / (2 * h), hd[i],
                    h * h / 6 * fourth * std::fabs(d[i] * d[i] * d[i]) + gsize)
            << "pixel " << i << ", h " << h;
    }
    // The Hessian is the quadratic (elastic) part's plus the interaction's phi'' < 0: the
    // quadratic part's curvature d.K d lies above d.H d by exactly the interaction's part.
    // 1e-12: rounding of sums of a few thousand terms of either sign.
    Vector kd(n);
    const double elastic = f.quadratic_part_product(d.data(), kd.data());
    double interaction = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      interaction += -W / (r * r) * std::exp(-x[i] / r) * d[i] * d[i];
    EXPECT_GT(elastic, dot(d, hd));
    EXPECT_NEAR(elastic, dot(d, hd) - interaction,
                1e-12 * (std::fabs(elastic) + std::fabs(interaction)));
  }
}

INSTANTIATE_TEST_SUITE_P(Grids, AdhesivePrimal,
                         ::testing::Values(std::make_tuple(32, 32, Control::penetration),
                                           std::make_tuple(31, 17, Control::mean_gap),
                                           std::make_tuple(45, 1, Control::mean_gap)));

// ---- w = 0 is the plain hard wall, bit for bit ----------------------------------------------
// Setting adhesion and then work 0 must leave no trace: the same arithmetic as a system that
// never had adhesion, so equal fields, reports and observables, exactly.
TEST(Adhesion, ZeroWorkIsThePlainHardWallBitForBit) {
  auto grid = asp_test::grid_2d(48, 40, 1.0, 40.0 / 48.0);
  const auto heights = asp_test::rough_surface(*grid, 5, 0.1);
  asp::System plain(grid, 1.0), reset(grid, 1.0);
  plain.set_topography(heights.data());
  reset.set_topography(heights.data());
  reset.set_adhesion(1e-3, 1e-3);
  reset.set_adhesion(0.0, 1e-3);
  EXPECT_EQ(reset.interaction().kind(), asp::InteractionKind::hard_wall);
  for (Control control : {Control::penetration, Control::mean_gap}) {
    const double value = control == Control::penetration ? 0.01 : 0.02;
    const auto a = solve_on_gap(plain, control, value, 1e-10);
    const auto b = solve_on_gap(reset, control, value, 1e-10);
    ASSERT_TRUE(a.converged());
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.error, b.error);
    for (std::size_t i = 0; i < plain.state().pressure.size(); ++i) {
      ASSERT_EQ(plain.state().pressure[i], reset.state().pressure[i]) << i;
      ASSERT_EQ(plain.state().gap[i], reset.state().gap[i]) << i;
    }
    EXPECT_EQ(plain.state().penetration, reset.state().penetration);
    EXPECT_EQ(reset.interaction_energy(), 0.0);
    EXPECT_EQ(reset.attractive_fraction(), 0.0);
  }
}

// ---- what the registry refuses ---------------------------------------------------------------
TEST(Adhesion, SolversWithoutAdhesionRefuseItNamingInteractionAndCondition) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  const auto heights = asp_test::rough_surface(*grid, 1, 0.1);
  asp::System system(grid, 1.0);
  system.set_topography(heights.data());
  system.set_adhesion(1e-3, 1e-3);
  const std::vector<double> before(system.state().gap.begin(), system.state().gap.end());
  struct Refused {
    const char *algorithm, *variable, *condition;
    Control control;
  };
  const Refused cases[] = {
      {"pk", nullptr, "solver 'pk' does not handle", Control::penetration},
      {"bugnicourt", "pressure", "with variable = pressure", Control::penetration},
      {"bugnicourt", "pressure", "with variable = pressure", Control::mean_pressure}};
  for (const Refused &c : cases) {
    asp::Solver solver(c.algorithm);
    if (c.variable != nullptr) solver.set_option("variable", std::string(c.variable));
    try {
      solver.solve(system, c.control, 0.01);
      ADD_FAILURE() << c.algorithm << " solved with adhesion";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported);
      const std::string message = e.what();
      EXPECT_NE(message.find("an adhesive hard wall"), std::string::npos) << message;
      EXPECT_NE(message.find(c.condition), std::string::npos) << message;
      EXPECT_NE(message.find("non-adhesive hard wall"), std::string::npos) << message;
    }
    EXPECT_FALSE(solver.report().available);
  }
  EXPECT_TRUE(std::equal(before.begin(), before.end(), system.state().gap.begin()));
}

TEST(Adhesion, SetAdhesionRefusesBadArgumentsNamingThem) {
  auto grid = asp_test::grid_1d(8, 1.0);
  asp::System system(grid, 1.0);
  const double inf = HUGE_VAL, nan = std::nan("");
  struct Bad {
    double work, range;
    const char *named;
  };
  for (const Bad &b : {Bad{-1.0, 1.0, "work_of_adhesion"}, Bad{nan, 1.0, "work_of_adhesion"},
                       Bad{inf, 1.0, "work_of_adhesion"}, Bad{1.0, 0.0, "range"},
                       Bad{1.0, -1.0, "range"}, Bad{1.0, inf, "range"}, Bad{0.0, nan, "range"},
                       Bad{1e300, 1e-300, "w/rho"}, Bad{1e-300, 1e300, "w/rho"}}) {
    try {
      system.set_adhesion(b.work, b.range);
      ADD_FAILURE() << "accepted " << b.work << ", " << b.range;
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::invalid_argument);
      EXPECT_NE(std::string(e.what()).find(b.named), std::string::npos) << e.what();
    }
    EXPECT_EQ(system.interaction().kind(), asp::InteractionKind::hard_wall);
  }
}

// ---- strong adhesion on a rough surface: converged, or a clear reason, never NaN ----------
// Interaction ranges down to a tenth of a pixel's compliance length make phi'' up to 1e3
// times the pixel stiffness: the Hessian is far from positive (on the hardest scene OUT-LIN's
// curvature was negative in about a third of the steps, and its step rejected or halved in a
// few). Each step must lower the objective, and each solve end converged with a finite state
// that meets the tolerance, or say why it stopped, with a finite, consistent state either way.
TEST(Adhesion, StrongAdhesionOnRoughSurfacesEndsFiniteAndHonest) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const auto heights = asp_test::rough_surface(*grid, 9, 0.1);
  // Without the continuation in the range (one objective, whose every step descends), and
  // with it (the default: two objectives, a longer range's first; its descent is checked in
  // test_range_continuation.cpp).
  for (const bool continued : {false, true}) {
    for (double range_over_l : {10.0, 1.0, 0.1}) {
      for (double stress_over_p : {1.0, 100.0}) {
        asp::System system(grid, 1.0);
        system.set_topography(heights.data());
        const double P = 0.05, l = P / system.substrate().pixel_stiffness();
        const double rho = range_over_l * l;
        system.set_adhesion(stress_over_p * P * rho, rho);
        const double delta = 0.3 * system.height_range();
        asp::Solver solver("bugnicourt");
        solver.set_option("variable", std::string("gap"));
        solver.set_option("tolerance", 1e-8);
        solver.set_option("max_iterations", 3000);
        if (!continued) solver.set_option("range_continuation", 0.0);
        solver.set_history(true);
        solver.solve(system, Control::penetration, delta);
        const asp::SolveReport report = solver.report();
        // Every step descends: the objective never rises by more than rounding (1e-12 of it).
        const auto &history = solver.history();
        const int objective = static_cast<int>(asp::HistoryColumn::objective);
        int rises = 0;
        for (std::size_t k = 1; k < history.size(); ++k)
          rises += history[k][objective] >
                   history[k - 1][objective] + 1e-12 * std::fabs(history[k - 1][objective]);
        if (!continued) EXPECT_EQ(rises, 0);
        std::printf("%s, rho = %g l, w/rho = %g P: %s after %lld iterations, error %.1e\n",
                    continued ? "continued" : "plain", range_over_l, stress_over_p,
                    asp::termination_name(report.termination),
                    static_cast<long long>(report.iterations), report.error);
        EXPECT_NE(report.termination, asp::Termination::breakdown);
        if (report.converged()) EXPECT_LE(report.error, 1e-8);
        for (std::size_t i = 0; i < system.state().pressure.size(); ++i) {
          ASSERT_TRUE(std::isfinite(system.state().pressure[i]));
          ASSERT_TRUE(std::isfinite(system.state().gap[i]));
          // The wall pulls no harder than adhesion can: p >= -w/rho.
          ASSERT_GE(system.state().pressure[i], -stress_over_p * P * (1 + 1e-12));
        }
        EXPECT_TRUE(std::isfinite(system.interaction_energy()));
        EXPECT_NEAR(system.repulsive_force() + system.attractive_force(), system.total_force(),
                    1e-12 * (system.repulsive_force() - system.attractive_force()));
      }
    }
  }
}

// ---- Johnson's adhesive sinusoid (Johnson, Int. J. Solids Struct. 32, 1995) ---------------
// h = h0 cos(2 pi x/l): in the JKR limit the mean pressure at contact half-width a is
//     pbar/p* = sin^2(pi a/l) - alpha sqrt(tan(pi a/l)),
// p* = pi E* h0/l, alpha^2 = 2 l w/(pi^2 E* h0^2). Check of the conventions: for a << l the
// crest is a cylinder of radius l^2/(4 pi^2 h0), and pbar l becomes the JKR cylinder's force
// per length pi E* a^2/(4R) - sqrt(2 pi E* w a) (Barquins 1988), as it must.
// The JKR limit needs a range rho small against everything but the pixel: the cohesive zone
// beyond the contact edge, of length ~ E* rho^2/w, is set to 2 pixels (smaller, the edge is
// trapped by the lattice; larger, the zone shifts the edge). Its shift of the edge makes the
// error fall as the square root of that length, so as sqrt(dx): 8 times finer, about 2.8
// times smaller (measured: 7.6e-3 p* at 512 pixels, 2.3e-3 p* at 4096, over contact
// half-widths from 0.03 l to 0.25 l along a loading sweep in penetration).
double johnson_worst_error(std::int64_t n) {
  const double l = 1.0, modulus = 1.0, h0 = 0.01, alpha = 0.2;
  const double w = alpha * alpha * pi * pi * modulus * h0 * h0 / (2 * l);
  const double dx = l / n, rho = std::sqrt(2.0 * dx * w / modulus);
  auto grid = asp_test::grid_1d(n, l);
  std::vector<double> h(static_cast<std::size_t>(n));
  asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
  asp::System system(grid, modulus);
  system.set_topography(h.data());
  system.set_adhesion(w, rho);
  const double p_star = pi * modulus * h0 / l;
  double worst = 0.0;
  int points = 0;
  // Loading from below contact to about half contact, each solve warm-started.
  for (double delta = -0.3 * h0; delta <= 1.0 * h0 + 1e-12; delta += 0.1 * h0) {
    const auto report = solve_on_gap(system, Control::penetration, delta, 1e-10);
    EXPECT_TRUE(report.converged()) << "delta " << delta;
    // The contact: pixels on the wall (their gap is the residual's, far below rho).
    const auto &g = system.state().gap;
    const double on_wall = static_cast<double>(
        std::count_if(g.begin(), g.end(), [&](double v) { return v <= 1e-3 * rho; }));
    const double a = 0.5 * on_wall * dx, s = pi * a / l;
    EXPECT_GT(a, 0.02 * l);
    EXPECT_LT(a, 0.3 * l);
    const double johnson = std::sin(s) * std::sin(s) - alpha * std::sqrt(std::tan(s));
    worst = std::max(worst, std::fabs(system.mean_pressure() / p_star - johnson));
    ++points;
  }
  EXPECT_EQ(points, 14);
  return worst;
}

TEST(JohnsonSinusoid, MeanPressureAgainstContactWidthConvergesToTheJKRLimit) {
  const double coarse = johnson_worst_error(512);
  const double fine = johnson_worst_error(4096);
  std::printf("Johnson's sinusoid: worst |pbar - pbar_Johnson| = %.2e p* (512), %.2e p* (4096)\n",
              coarse, fine);
  EXPECT_LT(coarse, 1e-2);
  EXPECT_LT(fine, 1e-2);
  EXPECT_LT(fine, coarse / 2.0);
}

// ---- JKR and DMT spheres ---------------------------------------------------------------------
// A paraboloid on the free half-space, whose box need only hold the contact, or on a periodic
// box large enough that its images matter less than a test's tolerance.
std::unique_ptr<asp::System> sphere_system(std::int64_t n, double box, double radius,
                                           double modulus, asp::SubstrateKind substrate) {
  auto grid = asp_test::grid_2d(n, n, box, box);
  std::vector<double> h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, radius, h.data());
  std::unique_ptr<asp::System> system(new asp::System(grid, modulus, substrate));
  system->set_topography(h.data());
  return system;
}

// The range of the Tabor parameter mu = (R w^2/(E*^2 rho^3))^(1/3).
double range_for_tabor(double tabor, double radius, double work, double modulus) {
  return std::cbrt(radius * work * work / (modulus * modulus)) / tabor;
}

struct SweepPoint {
  double delta, force, radius;
};

// A retraction sweep in penetration, warm-started from the first point: the force and the
// contact radius (from the pixels on the wall) at each step.
std::vector<SweepPoint> retract(asp::System &system, double from, double to, double step,
                                double rho) {
  std::vector<SweepPoint> sweep;
  const double pixel_area = system.grid().pixel_area();
  for (double delta = from; delta >= to - 1e-12 * std::fabs(step); delta -= step) {
    const auto report = solve_on_gap(system, Control::penetration, delta, 1e-7);
    EXPECT_TRUE(report.converged()) << "delta " << delta << ": "
                                    << asp::termination_name(report.termination);
    const auto &g = system.state().gap;
    const double on_wall = static_cast<double>(
        std::count_if(g.begin(), g.end(), [&](double v) { return v <= 1e-3 * rho; }));
    sweep.push_back({delta, system.total_force(), std::sqrt(on_wall * pixel_area / pi)});
  }
  return sweep;
}

// The smallest force of a sweep: the parabola through the lowest sample and its neighbours
// (the force is smooth in the penetration there), or the lowest sample at an end.
double minimum_force(const std::vector<SweepPoint> &sweep) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < sweep.size(); ++i)
    if (sweep[i].force < sweep[k].force) k = i;
  if (k == 0 || k + 1 == sweep.size()) return sweep[k].force;
  const double f0 = sweep[k - 1].force, f1 = sweep[k].force, f2 = sweep[k + 1].force;
  const double curvature = f0 - 2 * f1 + f2;
  return curvature > 0.0 ? f1 - (f2 - f0) * (f2 - f0) / (8 * curvature) : f1;
}

// JKR: F = 4E* a^3/(3R) - sqrt(8 pi w E* a^3); on the branch a > a_c (dF/da > 0), a of F.
double jkr_force(double a, double radius, double work, double modulus) {
  return 4 * modulus * a * a * a / (3 * radius) - std::sqrt(8 * pi * work * modulus * a * a * a);
}
double jkr_radius_on_stable_branch(double force, double radius, double work, double modulus) {
  double low = std::cbrt(9 * pi * work * radius * radius / (8 * modulus)), high = 10 * low;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (jkr_force(mid, radius, work, modulus) < force ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

// Tabor parameter 5, E* = R = 1, w = 1e-3: rho = 2e-3, the load-controlled pull-off radius
// a_c = (9 pi w R^2/(8 E*))^(1/3) = 0.152 = 65 pixels of a free box of 0.6 = 256 pixels, and
// the cohesive zone E* rho^2/w of 1.7 pixels. The errors: the discretisation (a lattice of
// 2.3e-3 under a zone of 1.7 pixels) moves the pull-off by under 0.2% (256 and 512 pixels
// on a periodic box of 0.6 agree to 1e-3); the finite range at Tabor 5 makes it about 1% more
// tensile than JKR's limit (the Maugis-Dugdale curve at this strength). The free substrate
// has no images (on a periodic box of 0.9 they added 2.2%). Hence 2% (measured -1.514: the
// parabola through the lowest samples of a sweep in steps of 2e-3). Contact radius against
// load: on the stable branch (a > 1.1 a_c, where a(F) is well conditioned) within 3% of
// JKR's (the pixel count decides the edge ring to half a pixel of 70, and the finite range
// widens the ring on the wall); and at every point the force at the measured radius within
// 0.05 pi w R of JKR's (measured 0.005-0.04).
TEST(JKRSphere, ContactRadiusAgainstLoadAndPullOffAtTaborFive) {
  const double radius = 1.0, modulus = 1.0, work = 1e-3, box = 0.6;
  const std::int64_t n = 256;
  const double rho = range_for_tabor(5.0, radius, work, modulus);
  const double a_c = std::cbrt(9 * pi * work * radius * radius / (8 * modulus));
  auto system = sphere_system(n, box, radius, modulus, asp::SubstrateKind::free);
  system->set_adhesion(work, rho);
  const auto sweep = retract(*system, 0.004, -0.012, 0.002, rho);
  const double scale = pi * work * radius;
  int stable = 0;
  for (const SweepPoint &p : sweep) {
    const double force_at_radius = jkr_force(p.radius, radius, work, modulus);
    std::printf("JKR: delta %+.4f F/(pi w R) %+.4f a %.4f, JKR F(a) %+.4f\n", p.delta,
                p.force / scale, p.radius, force_at_radius / scale);
    EXPECT_NEAR(p.force / scale, force_at_radius / scale, 0.05) << "delta " << p.delta;
    if (p.radius > 1.1 * a_c) {
      ++stable;
      EXPECT_NEAR(p.radius / jkr_radius_on_stable_branch(p.force, radius, work, modulus), 1.0,
                  0.03)
          << "delta " << p.delta;
    }
  }
  EXPECT_GE(stable, 2);
  const double pull_off = minimum_force(sweep);
  std::printf("JKR: pull-off %.4f pi w R (JKR -1.5)\n", pull_off / scale);
  EXPECT_NEAR(pull_off / scale, -1.5, 0.02 * 1.5);
}

// The smallest force near the lowest sample of a sweep, by golden-section search between its
// neighbours, each solve warm-started from the last: for small Tabor parameters the force
// has a kink where contact starts (a parabola through samples would overshoot), and no
// hysteresis, so the force is one function of the penetration.
double refined_minimum_force(asp::System &system, const std::vector<SweepPoint> &sweep,
                             int evaluations) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < sweep.size(); ++i)
    if (sweep[i].force < sweep[k].force) k = i;
  if (k == 0 || k + 1 == sweep.size()) return sweep[k].force;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double low = sweep[k + 1].delta, high = sweep[k - 1].delta, best = sweep[k].force;
  const auto force_at = [&](double delta) {
    EXPECT_TRUE(solve_on_gap(system, Control::penetration, delta, 1e-7).converged());
    best = std::min(best, system.total_force());
    return system.total_force();
  };
  double a = high - golden * (high - low), b = low + golden * (high - low);
  double fa = force_at(a), fb = force_at(b);
  for (int i = 2; i < evaluations; ++i) {
    if (fa < fb) {
      high = b, b = a, fb = fa;
      a = high - golden * (high - low);
      fa = force_at(a);
    } else {
      low = a, a = b, fa = fb;
      b = low + golden * (high - low);
      fb = force_at(b);
    }
  }
  return best;
}

// Small Tabor parameter: the sphere hardly deforms and the pull-off tends to DMT's -2 pi w R
// (Derjaguin's approximation of a rigid sphere: 2 pi R times the work, exact for the
// exponential law on a paraboloid). w = 1e-6, E* = R = 1, rho = 1e-3 at mu = 0.1 and
// 3.3e-3 at mu = 0.03: the adhesive annulus, of width sqrt(R rho), spans 7-12 pixels of
// 128 on a box of 0.6, whose edge is 13 ranges or more away (images: below exp(-13)). The
// sweep steps by rho/5, then the minimum is searched between the neighbours of the lowest
// sample, to 3e-3 of that bracket. Measured: -1.963 pi w R at mu = 0.1, -1.992 at 0.03, and
// -1.514 at mu = 5 (above): the pull-off grows towards -2 as mu falls. Derjaguin's -2 is its
// limit, which the lattice sum over the smooth adhesive annulus meets to far below 1e-3. The
// test asks for that order, for mu = 0.03 within 1% of DMT and for mu = 0.1 within 3%.
double dmt_pull_off(double tabor) {
  const double radius = 1.0, modulus = 1.0, work = 1e-6;
  const double rho = range_for_tabor(tabor, radius, work, modulus);
  auto system = sphere_system(128, 0.6, radius, modulus, asp::SubstrateKind::periodic);
  system->set_adhesion(work, rho);
  const auto sweep = retract(*system, rho, -rho, 0.2 * rho, rho);
  return refined_minimum_force(*system, sweep, 14) / (pi * work * radius);
}

TEST(DMTSphere, PullOffTendsToTwoPiWRAsTaborFalls) {
  const double mu_01 = dmt_pull_off(0.1), mu_003 = dmt_pull_off(0.03);
  std::printf("DMT: pull-off %.4f pi w R at Tabor 0.1, %.4f at 0.03 (DMT -2)\n", mu_01, mu_003);
  EXPECT_LT(mu_003, mu_01);
  EXPECT_GT(mu_003, -2.0 * (1 + 1e-3));
  EXPECT_NEAR(mu_003, -2.0, 0.01 * 2.0);
  EXPECT_NEAR(mu_01, -2.0, 0.03 * 2.0);
}

}  // namespace
