// SPDX-License-Identifier: GPL-2.0-or-later
// The unconstrained formulations of a soft potential: the Fourier variable describes the same
// objective as the displacement (energies equal to 1e-10 relative: only the rounding of the
// transforms separates them), their gradients match central finite differences, and the
// Fourier formulation's error measure is the real-space residual.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "scene.hpp"
#include "formulations/displacement_formulation.hpp"
#include "formulations/fourier_formulation.hpp"

using namespace asp;
using asp_test::grid_1d;
using asp_test::grid_2d;

namespace {

struct Shape {
  int dimension;
  std::int64_t nx, ny;
};

std::shared_ptr<Grid> make_grid(const Shape &s) {
  return s.dimension == 1 ? grid_1d(s.nx, 1.0 * s.nx) : grid_2d(s.nx, s.ny, 1.0 * s.nx, 0.8 * s.ny);
}

std::vector<double> random_vector(std::size_t n, std::uint64_t seed, double scale) {
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(0.0, scale);
  std::vector<double> v(n);
  for (double &x : v) x = normal(engine);
  return v;
}

// A rough surface with a soft wall whose range is a few pixels' elastic length, so that both
// the elastic and the interaction parts of the objective matter, in a random state (gaps
// drawn from the seed): the formulations start from the displacement it makes.
std::unique_ptr<System> soft_scene(const std::shared_ptr<Grid> &grid, std::uint64_t seed) {
  auto system = std::make_unique<System>(grid, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 3, 0.1, 0.5, 2.0);
  system->set_topography(h.data());
  system->set_soft_wall(1.0, 0.2, 0.3, 0.2);
  const std::vector<double> g =
      random_vector(static_cast<std::size_t>(grid->n_pixels()), seed, 0.5);
  std::copy(g.begin(), g.end(), system->state().gap.data());
  system->state().penetration = 0.1;
  return system;
}

class SoftFormulations : public ::testing::TestWithParam<std::tuple<Shape, Control>> {};

// Both formulations start from the displacement of the same state: the Fourier variable's
// displacement is the real one, and the energies, gradients' errors agree there.
TEST_P(SoftFormulations, FourierAndDisplacementObjectivesAreTheSame) {
  const auto [shape, control] = GetParam();
  auto grid = make_grid(shape);
  auto system = soft_scene(grid, 7);
  const double value = control == Control::penetration ? 0.3 : 0.02;
  const auto n = static_cast<std::size_t>(grid->n_pixels());

  DisplacementFormulation real(*system, control, value);
  FourierFormulation fourier(*system, control, value);
  std::vector<double> u(n), gradient_real(n), u_of_v(n);
  std::vector<double> gradient_fourier(static_cast<std::size_t>(fourier.size()));
  std::copy(real.variable().begin(), real.variable().end(), u.begin());
  fourier.displacement_of(fourier.variable().data(), u_of_v.data());
  for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(u_of_v[i], u[i], 1e-12 * (1.0 + std::fabs(u[i])));

  const double e_real = real.value_and_gradient(u.data(), gradient_real.data());
  std::vector<double> v(fourier.variable().begin(), fourier.variable().end());
  const double e_fourier = fourier.value_and_gradient(v.data(), gradient_fourier.data());
  EXPECT_NEAR(e_fourier, e_real, 1e-10 * std::fabs(e_real));
  // The error measures agree: both are the largest real-space residual.
  const double error_real = real.error(u.data(), gradient_real.data());
  EXPECT_NEAR(fourier.error(v.data(), gradient_fourier.data()), error_real, 1e-10 * error_real);
}

// Central differences with step h: truncation h^2 f'''/6 and rounding eps f/h; h = 1e-5 on
// unknowns of order 1 leaves about 1e-7 relative.
template <class F>
void check_gradient(F &f, std::uint64_t seed) {
  const auto n = static_cast<std::size_t>(f.size());
  std::vector<double> x(f.variable().begin(), f.variable().end());
  std::vector<double> gradient(n), scratch(n);
  f.value_and_gradient(x.data(), gradient.data());
  const double scale = asp_test::max_abs(gradient);
  std::mt19937_64 engine(seed);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  const double h = 1e-5;
  for (int trial = 0; trial < 12; ++trial) {
    const std::size_t i = trial == 0 ? 0 : pick(engine);  // the q = 0 mode first
    std::vector<double> xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    const double fp = f.value_and_gradient(xp.data(), scratch.data());
    const double fm = f.value_and_gradient(xm.data(), scratch.data());
    EXPECT_NEAR((fp - fm) / (2 * h), gradient[i], 1e-6 * scale) << "unknown " << i;
  }
}

TEST_P(SoftFormulations, GradientsMatchFiniteDifferences) {
  const auto [shape, control] = GetParam();
  auto grid = make_grid(shape);
  auto system = soft_scene(grid, 11);
  const double value = control == Control::penetration ? 0.3 : 0.02;
  DisplacementFormulation real(*system, control, value);
  check_gradient(real, 1);
  FourierFormulation fourier(*system, control, value);
  check_gradient(fourier, 2);
}

INSTANTIATE_TEST_SUITE_P(
    OddAndEven, SoftFormulations,
    ::testing::Combine(::testing::Values(Shape{1, 16, 1}, Shape{1, 15, 1}, Shape{2, 8, 6},
                                         Shape{2, 7, 9}, Shape{2, 6, 5}),
                       ::testing::Values(Control::penetration, Control::mean_pressure)));

}  // namespace
