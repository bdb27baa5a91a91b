// SPDX-License-Identifier: GPL-2.0-or-later
// The primal (gap) formulation against its own definition: the gradient against central
// finite differences of the value, the Hessian product against differences of the gradient,
// its symmetry and positivity, and the error against the optimality conditions written out
// here. The objective is quadratic, so central differences are exact up to rounding: the
// tolerances are 1e-12 of the size of the rounded terms (divided by the step where a quotient
// is taken).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/random.hpp"
#include "scene.hpp"
#include "formulations/primal_formulation.hpp"

namespace {

using asp::Control;
using Vector = std::vector<double>;

using asp_test::dot;
using asp_test::max_abs;

struct Scene {
  std::shared_ptr<asp::Grid> grid;
  std::vector<double> heights;
  std::unique_ptr<asp::System> system;
};

Scene make(std::int64_t nx, std::int64_t ny) {
  Scene s;
  s.grid = ny == 1 ? asp_test::grid_1d(nx, 1.0) : asp_test::grid_2d(nx, ny, 1.0, 0.8);
  s.heights = asp_test::rough_surface(*s.grid, 3, 0.1);
  s.system.reset(new asp::System(s.grid, 1.0));
  s.system->set_topography(s.heights.data());
  return s;
}

Vector random_vector(std::size_t n, std::uint64_t seed, double low) {
  asp::Random random(seed);
  Vector v(n);
  for (double &x : v) x = low + (1.0 - low) * random.uniform();
  return v;
}

class PrimalFormulationTest
    : public ::testing::TestWithParam<std::tuple<std::int64_t, std::int64_t, Control>> {};

TEST_P(PrimalFormulationTest, GradientAndHessianMatchDifferences) {
  const auto [nx, ny, control] = GetParam();
  Scene s = make(nx, ny);
  asp::PrimalFormulation f(*s.system, control, control == Control::mean_gap ? 0.002 : 0.003);
  const auto n = static_cast<std::size_t>(f.size());
  const Vector x = random_vector(n, 11, 0.0);
  Vector g(n), gp(n), gm(n), hd(n);
  const double value = f.value_and_gradient(x.data(), g.data());
  for (std::uint64_t seed : {21, 22, 23}) {
    const Vector d = random_vector(n, seed, -1.0);
    for (double h : {1.0, 1e-3}) {
      Vector xp(x), xm(x);
      for (std::size_t i = 0; i < n; ++i) xp[i] += h * d[i], xm[i] -= h * d[i];
      const double fp = f.value_and_gradient(xp.data(), gp.data());
      const double fm = f.value_and_gradient(xm.data(), gm.data());
      // Sizes of the rounded terms: the value's terms u p/2 and a gradient entry's max.
      const double size = (std::fabs(value) + max_abs(g) * max_abs(x) * n + fp + fm) / h;
      EXPECT_NEAR((fp - fm) / (2 * h), dot(g, d), 1e-12 * size) << "h " << h;
      f.hessian_product(d.data(), hd.data());
      const double gsize = (max_abs(gp) + max_abs(gm)) / h;
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_NEAR((gp[i] - gm[i]) / (2 * h), hd[i], 1e-12 * gsize) << "pixel " << i;
    }
  }
  // Symmetric and positive: a.Hb = b.Ha, d.Hd > 0 for a direction with a q != 0 part.
  const Vector a = random_vector(n, 31, -1.0), b = random_vector(n, 32, -1.0);
  Vector ha(n), hb(n);
  f.hessian_product(a.data(), ha.data());
  f.hessian_product(b.data(), hb.data());
  EXPECT_NEAR(dot(a, hb), dot(b, ha), 1e-12 * (max_abs(ha) + max_abs(hb)) * n);
  EXPECT_GT(dot(a, ha), 0.0);
}

TEST_P(PrimalFormulationTest, ErrorIsTheOptimalityResidual) {
  const auto [nx, ny, control] = GetParam();
  Scene s = make(nx, ny);
  asp::PrimalFormulation f(*s.system, control, control == Control::mean_gap ? 0.002 : 0.003);
  const auto n = static_cast<std::size_t>(f.size());
  Vector x = random_vector(n, 41, -0.5);
  for (double &v : x) v = std::max(v, 0.0);  // about a third on the bound
  const Vector r = random_vector(n, 42, -1.0);
  // The multiplier under mean-gap control: the mean of r over the free unknowns.
  double shift = 0.0, free = 0.0;
  if (f.constrains_mean()) {
    for (std::size_t i = 0; i < n; ++i)
      if (x[i] > 0.0) shift += r[i], free += 1.0;
    shift /= free;
  }
  double expected = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double p = r[i] - shift;
    expected = std::max(expected, x[i] > 0.0 ? std::fabs(p) : std::max(-p, 0.0));
  }
  EXPECT_NEAR(f.error(x.data(), r.data()), expected, 1e-15);
  EXPECT_EQ(f.lower_bound(), 0.0);
  EXPECT_EQ(f.constrains_mean(), control == Control::mean_gap);
}

INSTANTIATE_TEST_SUITE_P(Grids, PrimalFormulationTest,
                         ::testing::Values(std::make_tuple(32, 32, Control::penetration),
                                           std::make_tuple(31, 17, Control::mean_gap),
                                           std::make_tuple(64, 1, Control::penetration),
                                           std::make_tuple(45, 1, Control::mean_gap)));

}  // namespace
