// SPDX-License-Identifier: GPL-2.0-or-later
// The fused passes of Bugnicourt's algorithm (solvers/bugnicourt_passes.hpp) against what
// they replace: the error they gather is the formulation's error(); the curvature that the
// Hessian product sums by Parseval is d.H d; the gradient of the adhesive primal's quadratic
// part followed along a step, and the change of the objective to the trial point computed
// without a transform, are those evaluations give; the trial's jumps put on the wall exactly
// the pixels that adhesion makes unstable and pulls in, and where they come to rest exactly
// the unstable ones that the elastic field pulls off; the preconditioned direction adds the
// caller's correction of M's diagonal; the local term's exponential is skipped only where its
// slope is below 2^-60, and its rest beyond the instability is the root of the one-pixel
// model's slope.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "core/random.hpp"
#include "scene.hpp"
#include "physics/resolution.hpp"
#include "solvers/bugnicourt_passes.hpp"
#include "formulations/dual_formulation.hpp"
#include "formulations/primal_formulation.hpp"

namespace {

using asp::Control;
using Vector = std::vector<double>;

constexpr double epsilon = std::numeric_limits<double>::epsilon();

double max_abs(const Vector &a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}

// Uniform in [low, 1), then entries below 0 set to 0: a share of the unknowns on the bound.
Vector random_iterate(std::size_t n, std::uint64_t seed, double low) {
  asp::Random random(seed);
  Vector v(n);
  for (double &x : v) x = std::max(0.0, low + (1.0 - low) * random.uniform());
  return v;
}

Vector random_vector(std::size_t n, std::uint64_t seed, double low, double high) {
  asp::Random random(seed);
  Vector v(n);
  for (double &x : v) x = low + (high - low) * random.uniform();
  return v;
}

// A 48 x 40 rough scene (odd enough to have both single-weight columns), optionally adhesive.
struct Scene {
  std::shared_ptr<asp::Grid> grid = asp_test::grid_2d(48, 40, 1.0, 40.0 / 48.0);
  asp::System system{grid, 1.0};
  explicit Scene(bool adhesive) {
    const auto heights = asp_test::rough_surface(*grid, 5, 0.1);
    system.set_topography(heights.data());
    const double P = 0.05, l = P / system.substrate().pixel_stiffness();
    system.set_reference_pressure(P);
    // Scaled range 0.5 and work 1: psi'' up to 4 pixel stiffnesses, strong adhesion.
    if (adhesive) system.set_adhesion(P * l, 0.5 * l);
  }
};

// The error the gather measures is the formulation's error() of the same iterate and
// gradient. Without a mean constraint the multiplier is 0 and both take the same extremes, so
// they agree bit for bit. With one, the multipliers are the same mean summed relative to
// different pivots and in different orders: they differ by at most n eps max|g - pivot|
// (1920 * 2^-52 * 3 < 1.3e-12 here), and so do the errors.
class GatheredError : public ::testing::TestWithParam<std::tuple<bool, Control>> {};

TEST_P(GatheredError, IsTheFormulationsError) {
  const auto [primal, control] = GetParam();
  Scene scene(false);
  std::unique_ptr<asp::Formulation> f;
  if (primal)
    f = std::make_unique<asp::PrimalFormulation>(scene.system, control, 0.3);
  else
    f = std::make_unique<asp::DualFormulation>(scene.system, control, 0.01);
  const auto n = static_cast<std::size_t>(f->size());
  const asp::BugnicourtPasses passes(*f);
  const Vector zero(n, 0.0);
  for (std::uint64_t seed : {1, 2, 3}) {
    const Vector x = random_iterate(n, seed, -0.5);
    const Vector g = random_vector(n, seed + 10, -1.0, 2.0);
    const double expected = f->error(x.data(), g.data());
    for (double pivot : {0.0, 0.7}) {
      const asp::Projection p = passes.gather(
          x.data(), [&](std::int64_t i) { return g[i]; },
          [&](std::int64_t i) { return zero[i]; }, 0.0, f->constrains_mean() ? pivot : 0.0);
      if (f->constrains_mean())
        EXPECT_NEAR(p.error, expected, static_cast<double>(n) * epsilon * 3.0);
      else
        EXPECT_EQ(p.error, expected);
    }
  }
  // A gradient that is not finite gives an error that is not finite, with or without a mean.
  const Vector x = random_iterate(n, 4, -0.5);
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    Vector g = random_vector(n, 5, -1.0, 1.0);
    g[n / 3] = bad;
    const asp::Projection p = passes.gather(
        x.data(), [&](std::int64_t i) { return g[i]; }, [](std::int64_t) { return 0.0; }, 0.0,
        0.0);
    EXPECT_FALSE(std::isfinite(p.error)) << bad;
    EXPECT_FALSE(std::isfinite(f->error(x.data(), g.data()))) << bad;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Formulations, GatheredError,
    ::testing::Values(std::make_tuple(true, Control::penetration),
                      std::make_tuple(true, Control::mean_gap),
                      std::make_tuple(false, Control::penetration),
                      std::make_tuple(false, Control::mean_pressure)),
    [](const ::testing::TestParamInfo<std::tuple<bool, Control>> &info) {
      return std::string(std::get<0>(info.param) ? "gap_" : "pressure_") +
             (std::get<1>(info.param) == Control::penetration ? "penetration" : "mean");
    });

// The curvature that quadratic_part_product sums over the spectrum is d.(Q d) summed over the
// pixels: both are sums of the same energy, in different orders and after a transform pair,
// so they agree to the transform's rounding, a few eps log N of the sum of |d_i (Qd)_i|
// (1e-13 of it leaves a factor of 50).
TEST(QuadraticPartProduct, CurvatureIsTheSumOverPixels) {
  for (bool primal : {true, false}) {
    for (Control control : {Control::penetration, Control::mean_gap, Control::mean_pressure}) {
      if (primal == (control == Control::mean_pressure)) continue;
      Scene scene(primal);
      std::unique_ptr<asp::Formulation> f;
      if (primal)
        f = std::make_unique<asp::PrimalFormulation>(scene.system, control, 0.3);
      else
        f = std::make_unique<asp::DualFormulation>(scene.system, control, 0.01);
      const auto n = static_cast<std::size_t>(f->size());
      const Vector d = random_vector(n, 7, -1.0, 1.0);
      Vector product(n);
      const double curvature = f->quadratic_part_product(d.data(), product.data());
      double sum = 0.0, size = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        sum += d[i] * product[i];
        size += std::fabs(d[i] * product[i]);
      }
      EXPECT_NEAR(curvature, sum, 1e-13 * size) << primal << " " << static_cast<int>(control);
      EXPECT_GT(curvature, 0.0);
    }
  }
}

// The adhesive primal f = Q + sum psi: after a step that the bound does not cut, the trial
// pass's followed gradient of Q, s (q + alpha Q d) + (1 - s) c, is Q's gradient evaluated at
// the trial point, and the change of the objective it sums without a transform,
// (y - x).(q + qy)/2 + sum (psi(y) - psi(x)), is the difference of the evaluated values.
// Both differ only by rounding: the gradient by that of the transforms, a few eps log N of
// its largest entry (1e-13 of it); the change by that of the evaluated values, whose
// difference loses their size: n eps (|f(x)| + |f(y)|).
class FollowedSeparable : public ::testing::TestWithParam<Control> {};

// What the trial pass reads, at an iterate with every unknown off the bound (random in
// [low, 1.5) from `seed`, then projected: under a mean constraint the mean on target, as the
// solver keeps it): Q's gradient there (q, and its value) and at 0 (c), the local term's
// states, a random direction d (from seed + 1) and k = Q d.
struct TrialInputs {
  Vector x, q, c, k, states, d;
  double quadratic_x = 0.0;

  TrialInputs(asp::PrimalFormulation &f, const asp::BugnicourtPasses &passes,
              const asp::LocalTerm &psi, std::uint64_t seed, double low) {
    const auto n = static_cast<std::size_t>(f.size());
    x = random_vector(n, seed, low, 1.5);
    f.project(x.data());
    q.resize(n);
    c.resize(n);
    k.resize(n);
    states.resize(n);
    f.quadratic_part_at_zero(c.data());
    quadratic_x = f.quadratic_part(x.data(), q.data());
    passes.local_states(x.data(), psi, states.data());
    d = random_vector(n, seed + 1, -1.0, 1.0);
    f.quadratic_part_product(d.data(), k.data());
  }

  // The trial pass from these inputs, into y, qy and states_y.
  asp::Trial trial(const asp::BugnicourtPasses &passes, const asp::LocalTerm &psi, double alpha,
                   Vector &y, Vector &qy, Vector &states_y, bool jumps) const {
    return passes.trial(x.data(), d.data(), alpha, q.data(), k.data(), c.data(), states.data(),
                        psi, y.data(), qy.data(), states_y.data(), jumps);
  }
};

TEST_P(FollowedSeparable, GradientAndChangeAreTheEvaluatedOnes) {
  const Control control = GetParam();
  Scene scene(true);
  asp::PrimalFormulation f(scene.system, control, control == Control::mean_gap ? 0.6 : 0.003);
  ASSERT_FALSE(f.quadratic());
  const asp::LocalTerm *psi = f.local_term();
  ASSERT_NE(psi, nullptr);
  const auto n = static_cast<std::size_t>(f.size());
  const asp::BugnicourtPasses passes(f);

  // Every unknown off the bound, so that a short step cuts nothing.
  const TrialInputs in(f, passes, *psi, 31, 0.1);
  const Vector &x = in.x, &q = in.q;
  const double quadratic_x = in.quadratic_x;
  Vector y(n), qy(n), states_y(n), evaluated(n), full(n);
  // Short enough that nothing reaches the bound: the smallest x is above 0.07.
  const double alpha = 0.05;
  const asp::Trial t = in.trial(passes, *psi, alpha, y, qy, states_y, false);
  ASSERT_FALSE(t.cut);
  const double quadratic_y = f.quadratic_part(y.data(), evaluated.data());
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_NEAR(qy[i], evaluated[i], 1e-13 * max_abs(evaluated)) << "pixel " << i;
  const double rounding = static_cast<double>(n) * epsilon;
  EXPECT_NEAR(t.quadratic_change, quadratic_y - quadratic_x,
              rounding * (std::fabs(quadratic_x) + std::fabs(quadratic_y)));
  EXPECT_NEAR(passes.quadratic_change(x.data(), y.data(), q.data(), evaluated.data()),
              quadratic_y - quadratic_x,
              rounding * (std::fabs(quadratic_x) + std::fabs(quadratic_y)));

  const double value_y = f.value_and_gradient(y.data(), full.data());
  const double value_x = f.value_and_gradient(x.data(), evaluated.data());
  EXPECT_NEAR(t.quadratic_change + psi->value_per_state() * t.state_change, value_y - value_x,
              rounding * (std::fabs(value_x) + std::fabs(value_y)));
  // The full gradient is Q's plus the local slopes the states give.
  f.quadratic_part(y.data(), evaluated.data());
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_NEAR(evaluated[i] + psi->slope_per_state() * states_y[i], full[i],
                1e-13 * max_abs(full))
        << "pixel " << i;
}

INSTANTIATE_TEST_SUITE_P(Controls, FollowedSeparable,
                         ::testing::Values(Control::penetration, Control::mean_gap),
                         [](const ::testing::TestParamInfo<Control> &info) {
                           return info.param == Control::penetration ? "penetration"
                                                                     : "mean_gap";
                         });

// The trial's jumps, on the adhesive scene (psi'' down to -4 pixel stiffnesses, so that a
// pixel alone is unstable below 0.5 ln 4 = 0.69 in scaled units), from an iterate with every
// seventh pixel on the bound (d >= 0 there, so that the step along d cuts nothing): every
// free unknown that has no rest off the bound when the surface around it relaxes
// (LocalTerm::falls_to_wall; some of them still stable on their own) goes onto it (a snap);
// every unknown with 1 + psi'' < 0, on the bound or free, where the objective falls away
// from the bound goes where LocalTerm::rest_beyond_instability puts it (a peel); every
// other one, those on the bound with a positive gradient included, moves as the trial
// without the jumps moves it, to the bit; and the trial counts as cut. Under a mean
// constraint nothing jumps (the rescaling to the mean would move the pixels again).
TEST(JumpingTrial, SnapsAndPeelsThePixelsThatAdhesionMakesUnstable) {
  for (const Control control : {Control::penetration, Control::mean_gap}) {
    Scene scene(true);
    asp::PrimalFormulation f(scene.system, control, control == Control::mean_gap ? 0.6 : 0.003);
    const asp::LocalTerm *psi = f.local_term();
    ASSERT_NE(psi, nullptr);
    const auto n = static_cast<std::size_t>(f.size());
    const asp::BugnicourtPasses passes(f);
    TrialInputs in(f, passes, *psi, 41, 0.05);
    for (std::size_t i = 0; i < n; i += 7) {
      in.x[i] = f.lower_bound();
      in.d[i] = std::fabs(in.d[i]);
    }
    in.quadratic_x = f.quadratic_part(in.x.data(), in.q.data());
    passes.local_states(in.x.data(), *psi, in.states.data());
    f.quadratic_part_product(in.d.data(), in.k.data());
    const Vector &x = in.x, &q = in.q, &states = in.states;
    Vector plain(n), jumped(n), qy(n), states_y(n);
    // Short enough that nothing reaches the bound along d.
    const double alpha = 0.01;
    const asp::Trial without = in.trial(passes, *psi, alpha, plain, qy, states_y, false);
    ASSERT_FALSE(without.cut);
    const asp::Trial with = in.trial(passes, *psi, alpha, jumped, qy, states_y, true);
    std::size_t snapped = 0, snapped_while_stable = 0, peeled = 0, peeled_off_the_bound = 0,
                held_on_the_bound = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool unstable = 1.0 + psi->curvature_per_state() * states[i] < 0.0;
      const double gradient = q[i] + psi->slope_per_state() * states[i];
      const bool on_the_bound = x[i] == f.lower_bound();
      if (control == Control::penetration && !on_the_bound &&
          psi->falls_to_wall(x[i], q[i], states[i], f.lower_bound())) {
        ASSERT_EQ(jumped[i], f.lower_bound()) << "pixel " << i;
        ++snapped;
        if (!unstable) ++snapped_while_stable;
      } else if (control == Control::penetration && unstable && gradient < 0.0) {
        ASSERT_EQ(jumped[i], psi->rest_beyond_instability(x[i], q[i])) << "pixel " << i;
        ASSERT_GT(jumped[i], x[i]) << "pixel " << i;
        ++peeled;
        if (on_the_bound) ++peeled_off_the_bound;
      } else {
        ASSERT_EQ(jumped[i], plain[i]) << "pixel " << i;
        if (on_the_bound && gradient > 0.0) ++held_on_the_bound;
      }
    }
    if (control == Control::penetration) {
      EXPECT_GT(snapped, 0u);
      EXPECT_GT(snapped_while_stable, 0u);
      EXPECT_GT(peeled_off_the_bound, 0u);
      EXPECT_GT(peeled, peeled_off_the_bound);
      EXPECT_GT(held_on_the_bound, 0u);
      EXPECT_LT(snapped + peeled, n);
      EXPECT_TRUE(with.cut);
    } else {
      EXPECT_FALSE(with.cut);
    }
  }
}

// The preconditioned direction with a correction own(i) of M's diagonal, from a restart
// (beta = 0) and conjugate to an old direction d_old with H d_old = h and d_old.H d_old = 2.5:
// on N, d = -(z - mean) + beta d_old with z = M r + own r, the mean over N under a mean
// constraint (0 without one) and beta = (z - mean).h / 2.5 over N; 0 off N; the descent is
// r.d. M r is the formulation's preconditioner applied to r (0 off N), as the pass applies
// it, bit for bit; the sums over N are taken in another order, so the two differ by their
// rounding, a few eps times the number of terms relative to the largest (1e-13 covers it at
// this size).
TEST(PreconditionedDirection, AddsTheCallersCorrectionOfTheDiagonal) {
  for (const Control control : {Control::penetration, Control::mean_gap}) {
    for (const double curvature : {0.0, 2.5}) {
      Scene scene(true);
      asp::PrimalFormulation f(scene.system, control,
                               control == Control::mean_gap ? 0.6 : 0.003);
      const asp::LocalTerm *psi = f.local_term();
      ASSERT_NE(psi, nullptr);
      const auto n = static_cast<std::size_t>(f.size());
      const asp::BugnicourtPasses passes(f);
      // A third of the unknowns on the bound, so that N is a proper subset.
      Vector x = random_vector(n, 51, -0.5, 1.0);
      for (double &xi : x) xi = std::max(xi, f.lower_bound());
      Vector q(n), states(n), g(n);
      f.quadratic_part(x.data(), q.data());
      passes.local_states(x.data(), *psi, states.data());
      for (std::size_t i = 0; i < n; ++i) g[i] = q[i] + psi->slope_per_state() * states[i];
      const auto gradient = [&](std::int64_t i) { return g[static_cast<std::size_t>(i)]; };
      const auto none = [](std::int64_t) { return 0.0; };
      const Vector own = random_vector(n, 52, 0.0, 3.0);
      const Vector h = random_vector(n, 53, -1.0, 1.0);
      const Vector d_old = random_vector(n, 54, -1.0, 1.0);
      const auto product = [&](std::int64_t i) { return h[static_cast<std::size_t>(i)]; };
      const asp::Projection p = passes.gather(x.data(), gradient, none, 0.0, 0.0);

      Vector z(n), d = d_old;
      const auto along = passes.direct_preconditioned(
          x.data(), gradient, p, product, curvature, z.data(), d.data(),
          [](std::int64_t, double) { return 0.0; },
          [&](std::int64_t i) { return own[static_cast<std::size_t>(i)]; });

      // The reference: r on N, M r, the correction, the mean over N, beta.
      Vector r(n), corrected(n), expected(n);
      std::vector<char> kept(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double ri = g[i] - p.shift;
        kept[i] = x[i] > f.lower_bound() || ri <= 0.0;
        r[i] = kept[i] ? ri - p.again : 0.0;
      }
      Vector mr = r;
      ASSERT_TRUE(f.precondition(mr.data()));
      double count = 0.0, sum = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!kept[i]) continue;
        corrected[i] = mr[i] + own[i] * r[i];
        count += 1.0;
        sum += corrected[i];
      }
      ASSERT_GT(count, 0.0);
      ASSERT_LT(count, static_cast<double>(n));
      const double mean = control == Control::mean_gap ? sum / count : 0.0;
      double zh = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (kept[i]) zh += (corrected[i] - mean) * h[i];
      const double beta = curvature > 0.0 ? zh / curvature : 0.0;
      if (curvature > 0.0) ASSERT_NE(beta, 0.0);
      double descent = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        expected[i] = kept[i] ? -(corrected[i] - mean) + beta * d_old[i] : 0.0;
        descent += r[i] * expected[i];
      }
      const double scale = max_abs(expected);
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_NEAR(d[i], expected[i], 1e-13 * scale) << "pixel " << i;
      EXPECT_NEAR(along[0], descent, 1e-12 * std::fabs(descent));
      if (curvature == 0.0) EXPECT_LT(along[0], 0.0);
    }
  }
}

// The exponential is skipped exactly where the slope it would give is below 2^-60 (in units
// of the reference pressure): at the threshold the slope is 2^-60 to rounding, and beyond it
// the state is 0, while just before it it is the exponential itself.
TEST(LocalTerm, SkipsTheExponentialOnlyWhereTheSlopeIsBelowTwoToTheMinusSixty) {
  for (double work : {1e-3, 1.0, 1e3}) {
    for (double range : {1e-2, 0.5, 20.0}) {
      const asp::ExponentialPotential potential{work, range};
      const asp::LocalTerm psi(potential, false, 1.0);
      const double cutoff = psi.negligible_beyond();
      EXPECT_NEAR(potential.dphi(cutoff), std::ldexp(1.0, -60), 1e-12 * std::ldexp(1.0, -60))
          << work << " " << range;
      EXPECT_EQ(psi.state(std::nextafter(cutoff, HUGE_VAL)), 0.0);
      EXPECT_EQ(psi.state(cutoff), std::exp(-cutoff / range));
      EXPECT_EQ(psi.state(0.0), 1.0);
      EXPECT_EQ(psi.slope_per_state(), potential.dphi(0.0));
      EXPECT_EQ(psi.curvature_per_state(), potential.d2phi(0.0));
      EXPECT_EQ(psi.value_per_state(), potential.phi(0.0));
    }
  }
}

// The rest beyond the instability is the root of the one-pixel model's slope
// m'(t) = q + (t - x) + psi'(t) on the side where m is convex (1 + psi''(t) > 0), above x: for
// strong adhesion (psi'' at the wall down to -100 pixel stiffnesses), starts on the wall and
// inside the unstable zone, and gradients from barely to far past what tears the pixel off
// (q + psi'(x) from -1e-3 to -1e3). m'(t) vanishes to the rounding of its three terms: each
// is rounded once and the sum twice, and the last Newton step leaves t within an ulp or two
// of the root, a few eps of the largest term in all (8 eps bounds it; measured at most 4 eps
// over many more cases).
TEST(LocalTerm, RestBeyondTheInstabilityIsTheRootOfTheModelsSlope) {
  int cases = 0;
  for (double work : {0.5, 1.0}) {
    for (double range : {0.1, 0.2}) {
      const asp::ExponentialPotential potential{work, range};
      const asp::LocalTerm psi(potential, false, 1.0);
      ASSERT_TRUE(psi.unstable_alone(1.0));
      for (double x : {0.0, 0.05, 0.2}) {
        const double e = psi.state(x);
        if (!psi.unstable_alone(e)) continue;
        for (double pull : {1e-3, 1.0, 1e3}) {
          // q + psi'(x) = -pull.
          const double q = -pull - psi.slope_per_state() * e;
          const double t = psi.rest_beyond_instability(x, q);
          const double et = psi.state(t);
          const double slope = q + (t - x) + psi.slope_per_state() * et;
          const double largest = std::max({std::fabs(q), std::fabs(t - x),
                                           psi.slope_per_state() * et});
          EXPECT_NEAR(slope, 0.0, 8.0 * epsilon * largest)
              << work << " " << range << " " << x << " " << pull;
          EXPECT_GT(psi.own_curvature(et), 0.0) << work << " " << range << " " << x;
          EXPECT_GT(t, x);
          ++cases;
        }
      }
    }
  }
  // Every start is unstable (the least, 0.2 from the wall with the weaker work and the
  // shorter range: 1 + psi'' = 1 - 50 e^-2 = -5.8): 12 starts, 3 pulls each.
  EXPECT_EQ(cases, 36);

  // Eager, the model's stiffness is the relaxed one, k: the root of q + k (t - x) + psi'(t),
  // where k + psi'' > 0, from which falls_to_wall does not send the pixel back (with q
  // followed to t in the same model).
  const double k = 0.74;
  const asp::LocalTerm eager(asp::ExponentialPotential{1.0, 0.2}, true, k);
  for (double x : {0.0, 0.05, 0.2, 0.6}) {
    for (double pull : {1e-6, 1e-3, 1.0, 1e3}) {
      const double e = eager.state(x);
      const double q = -pull - eager.slope_per_state() * e;
      const double t = eager.rest_beyond_instability(x, q);
      const double et = eager.state(t);
      const double slope = q + k * (t - x) + eager.slope_per_state() * et;
      const double largest =
          std::max({std::fabs(q), k * std::fabs(t - x), eager.slope_per_state() * et});
      EXPECT_NEAR(slope, 0.0, 8.0 * epsilon * largest) << x << " " << pull;
      EXPECT_GT(k + eager.curvature_per_state() * et, 0.0) << x << " " << pull;
      EXPECT_GT(t, x);
      EXPECT_FALSE(eager.falls_to_wall(t, q + k * (t - x), et, 0.0)) << x << " " << pull;
    }
  }
}

// The preconditioner's correction for an unknown's own curvature c = 1 + psi'': none out of
// the adhesion's reach (c = 1) or where the unknown is unstable on its own (c <= 0);
// 1/c - 1 between; and 1/0.05 - 1 = 19 where c is at most 0.05, the cap.
TEST(LocalTerm, PreconditionerCorrectionIsTheLongerOnePixelStepCapped) {
  const asp::ExponentialPotential potential{1.0, 0.2};  // psi'' = -25 at the wall
  const asp::LocalTerm psi(potential, false, 1.0);
  EXPECT_EQ(psi.preconditioner_correction(0.0), 0.0);
  EXPECT_EQ(psi.preconditioner_correction(1.0), 0.0);     // c = -24
  EXPECT_EQ(psi.preconditioner_correction(0.0401), 0.0);  // c = -0.0025
  const double cap = 1.0 / 0.05 - 1.0;
  EXPECT_EQ(psi.preconditioner_correction(0.0396), cap);  // c = 0.01
  EXPECT_EQ(psi.preconditioner_correction(0.0385), cap);  // c = 0.0375
  for (const double c : {0.1, 0.5, 0.9, 0.999}) {
    const double state = (1.0 - c) / 25.0;
    EXPECT_NEAR(psi.preconditioner_correction(state), 1.0 / psi.own_curvature(state) - 1.0,
                1e-15 / c)
        << c;
    EXPECT_NEAR(psi.own_curvature(state), c, 1e-15);
  }
}

// The pixels near the wall jump eagerly (the relaxed one-pixel model, in every step) on a
// cold solve of a scene whose cohesive zone is at most half a pixel: a state without
// pressure, or one an earlier stage of the same solve left (the solve holds the state when
// the formulation is made). A state with pressure is a warm start's, and nearer to resolved
// the jumps are as before, cold or warm. The relaxed stiffness is 1/(k c0), k the pixel
// stiffness and c0 the self-compliance: about 0.74 on a periodic half-space.
TEST(LocalTerm, JumpsEagerlyOnColdSolvesFarFromResolved) {
  Scene scene(true);
  const asp::Substrate &substrate = scene.system.substrate();
  const double relaxed = 1.0 / (substrate.pixel_stiffness() * substrate.self_compliance());
  EXPECT_GT(relaxed, 0.7);
  EXPECT_LT(relaxed, 0.8);
  // A formulation holds the state from its making on; a solve lets it go at its end.
  const auto eager = [&](bool held) {
    scene.system.set_state_held_by_solve(held);
    const asp::PrimalFormulation f(scene.system, Control::penetration, 0.003);
    scene.system.set_state_held_by_solve(false);
    EXPECT_EQ(f.local_term()->relaxed_stiffness(), relaxed);
    return f.local_term()->eager();
  };
  EXPECT_TRUE(eager(false));
  scene.system.state().pressure[7] = 1e-3;
  EXPECT_FALSE(eager(false));
  EXPECT_TRUE(eager(true));
  scene.system.reset_state();
  EXPECT_TRUE(eager(false));

  const double P = 0.05, l = P / substrate.pixel_stiffness();
  ASSERT_LE(asp::resolution(scene.system).ratio, asp::far_from_resolved);
  int resolved_more = 0;
  for (double range = 0.5 * l; range < 50.0 * l; range *= 1.25) {
    scene.system.set_adhesion(P * l, range);
    const bool far = asp::resolution(scene.system).ratio <= asp::far_from_resolved;
    EXPECT_EQ(eager(false), far) << "range " << range / l << " l";
    resolved_more += far ? 0 : 1;
  }
  EXPECT_GT(resolved_more, 0);
}

// Eager, whether a pixel falls to the wall is whether the slope of the one-pixel model with
// the relaxed stiffness k, m'(t) = q + k (t - x) + psi'(t), stays positive from x down to the
// bound: checked against m' sampled at 20001 points of [lower, x] and at its minimum t*
// (psi''(t*) = -k) where that lies inside, for the relaxed stiffness of a periodic
// half-space (0.74) and of a free substrate (1), starts on both sides of t* and gradients
// that hold the pixel off, barely and firmly, or pull it in. Cases whose sampled minimum lies
// within 1e-9 of zero (relative to the terms of m') are too close to call and skipped; of
// the rest, both answers occur. Not eager, it is whether the pixel is unstable on its own
// with a positive gradient.
TEST(LocalTerm, FallsToTheWallWhereTheRelaxedModelsSlopeStaysPositive) {
  const asp::ExponentialPotential potential{1.0, 0.2};  // psi'' = -25 at the wall
  const double lower = 0.0;
  int falls = 0, stays = 0;
  for (const double k : {0.74, 1.0}) {
    const asp::LocalTerm psi(potential, true, k);
    const double instability = 0.2 * std::log(25.0 / k);
    for (const double x : {0.05, 0.3, instability, 0.7, 0.9, 1.5}) {
      for (const double q : {-3.0, -1.0, -0.3, -0.1, -0.01, 0.0, 0.5}) {
        const auto slope = [&](double t) {
          return q + k * (t - x) + psi.slope_per_state() * psi.state(t);
        };
        double least = slope(x);
        for (int j = 0; j <= 20000; ++j)
          least = std::min(least, slope(lower + (x - lower) * j / 20000.0));
        if (instability > lower && instability < x) least = std::min(least, slope(instability));
        const double scale = std::fabs(q) + k * x + psi.slope_per_state();
        if (std::fabs(least) < 1e-9 * scale) continue;
        const bool expected = least > 0.0;
        EXPECT_EQ(psi.falls_to_wall(x, q, psi.state(x), lower), expected)
            << "k " << k << " x " << x << " q " << q << " least slope " << least;
        (expected ? falls : stays) += 1;
      }
    }
  }
  EXPECT_GT(falls, 10);
  EXPECT_GT(stays, 10);
  // Where psi'' never reaches -k, no pixel falls on its own account.
  const asp::LocalTerm weak(asp::ExponentialPotential{0.01, 0.2}, true, 1.0);  // psi'' >= -0.25
  EXPECT_FALSE(weak.falls_to_wall(0.1, 0.5, weak.state(0.1), 0.0));
  // Not eager: exactly the pixels unstable on their own with a positive gradient.
  const asp::LocalTerm plain(potential, false, 0.74);
  for (const double x : {0.05, 0.3, 0.6, 0.7, 0.9})
    for (const double q : {-3.0, -0.3, 0.0, 0.5}) {
      const double e = plain.state(x);
      EXPECT_EQ(plain.falls_to_wall(x, q, e, lower),
                plain.unstable_alone(e) && q + plain.slope_per_state() * e > 0.0)
          << x << " " << q;
    }
}

}  // namespace
