// SPDX-License-Identifier: GPL-2.0-or-later
// The core layers every solver stands on: the spectral layout (|q| and Parseval weights of
// the half spectrum), the element-wise loop helper, and the plan cache of a grid.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "core/random.hpp"
#include "core/spectral_layout.hpp"
#include "scene.hpp"

namespace {
using asp_test::pi;

struct Shape {
  std::int64_t nx, ny;
};
void PrintTo(const Shape &s, std::ostream *out) { *out << s.nx << "x" << s.ny; }
std::string shape_name(const ::testing::TestParamInfo<Shape> &info) {
  return std::to_string(info.param.nx) + "x" + std::to_string(info.param.ny);
}

class Layout : public ::testing::TestWithParam<Shape> {};

// Parseval: sum_k weight_k |F_k|^2 = N sum_i f_i^2, for the r2c half spectrum, whatever the
// parity of each axis. Exact up to rounding.
TEST_P(Layout, WeightsSatisfyParseval) {
  const Shape s = GetParam();
  auto grid = asp_test::grid_2d(s.nx, s.ny, 1.3, 0.7);
  asp::Field f = grid->make_field();
  asp::Random random(3);
  double sum_squares = 0.0;
  for (auto &v : f) {
    v = random.gaussian();
    sum_squares += v * v;
  }
  const double n = static_cast<double>(grid->n_pixels());

  asp::Spectrum spectrum = grid->make_spectrum();
  grid->fft().forward(f.data(), spectrum.data());
  const asp::SpectralLayout half = grid->half_spectrum();
  ASSERT_EQ(half.size(), static_cast<std::int64_t>(spectrum.size()));
  double by_visit = 0.0;
  half.for_each([&](std::int64_t k, double, double w) { by_visit += w * std::norm(spectrum[k]); });
  const double by_rows = half.weighted_sum([&](std::int64_t k) { return std::norm(spectrum[k]); });
  EXPECT_NEAR(by_visit, n * sum_squares, 1e-12 * n * sum_squares);
  EXPECT_NEAR(by_rows, n * sum_squares, 1e-12 * n * sum_squares);
}

// A single mode cos(2 pi (a x/lx + b y/ly)) puts all its power on entries whose |q| is that
// of the mode: checks the wavevector each entry is given.
TEST_P(Layout, EntriesCarryTheWavevectorOfTheirMode) {
  const Shape s = GetParam();
  const double lx = 1.3, ly = 0.7;
  auto grid = asp_test::grid_2d(s.nx, s.ny, lx, ly);
  const std::int64_t a = s.nx / 3, b = s.ny / 2;
  asp::Field f = grid->make_field();
  for (std::int64_t j = 0; j < s.ny; ++j)
    for (std::int64_t i = 0; i < s.nx; ++i)
      f[i + s.nx * j] = std::cos(2 * pi * (double(a * i) / s.nx + double(b * j) / s.ny));
  const double q = 2 * pi * std::hypot(a / lx, b / ly);

  asp::Spectrum spectrum = grid->make_spectrum();
  grid->fft().forward(f.data(), spectrum.data());
  grid->half_spectrum().for_each([&](std::int64_t k, double qk, double) {
    if (std::abs(spectrum[k]) > 1e-8 * grid->n_pixels()) EXPECT_NEAR(qk, q, 1e-12 * q) << k;
  });
}

INSTANTIATE_TEST_SUITE_P(Shapes, Layout,
                         ::testing::Values(Shape{8, 6}, Shape{9, 7}, Shape{10, 5}, Shape{7, 12},
                                           Shape{1, 9}, Shape{12, 1}, Shape{2, 2}, Shape{1, 1}),
                         shape_name);

TEST(Loops, SumsMaximaAndForEachCoverEveryEntry) {
  const asp::LocalReductions local;
  std::vector<double> v(1003);
  asp::loops::for_each(1003, [&](std::int64_t i) { v[i] = static_cast<double>(i % 17) - 8; });
  const auto s = asp::loops::sums_and_max<2>(local, 1003, [&](std::int64_t i, double *sum,
                                                               double &max) {
    sum[0] += v[i];
    sum[1] += 1.0;
    max = v[i] > max ? v[i] : max;
  });
  double expected = 0.0;
  for (double x : v) expected += x;
  EXPECT_EQ(s[0], expected);
  EXPECT_EQ(s[1], 1003.0);
  EXPECT_EQ(s[2], 8.0);
  EXPECT_EQ(asp::loops::maximum(local, 0, [](std::int64_t) { return 1.0; }), -HUGE_VAL);
  EXPECT_EQ(asp::loops::sum(local, 1003, [&](std::int64_t i) { return v[i]; }), expected);
}

TEST(PlanCache, OnePlanPerShapeAndKindIncludingThePaddedShape) {
  auto grid = asp_test::grid_2d(12, 10, 1.0, 1.0);
  EXPECT_FALSE(grid->has_fft_plans());
  const asp::RealTransform &own = grid->fft();
  EXPECT_EQ(&own, &grid->real_fft(12, 10));
  const asp::RealFft &padded = grid->real_fft(24, 20);
  EXPECT_NE(&own, &padded);
  EXPECT_EQ(&padded, &grid->real_fft(24, 20));
  EXPECT_TRUE(grid->has_fft_plans());
  EXPECT_THROW(grid->set_fft_planning(asp::FftPlanning::measure), asp::Error);

  // The padded plan transforms a 24 x 20 field: a round trip gives N times the field back.
  asp::Field f(24 * 20), back(24 * 20);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = std::sin(0.1 * i);
  asp::Spectrum s((24 / 2 + 1) * 20);
  padded.forward(f.data(), s.data());
  padded.backward(s.data(), back.data());
  for (std::size_t i = 0; i < f.size(); ++i) ASSERT_NEAR(back[i], 480 * f[i], 1e-10);
}

TEST(Grid, MeasuredPlanningIsTheDefault) {
  auto grid = asp::Grid::create(2, 16, 16, 1.0, 1.0);
  EXPECT_EQ(grid->fft_planning(), asp::FftPlanning::measure);
}

TEST(Grid, RefusesBoxesDoublesCannotRepresent) {
  // A box of 1e160 has an area of 1e320; a length of 4.9e-324 has pixels of size 0.
  EXPECT_THROW(asp::Grid::create(2, 64, 64, 1e160, 1e160), asp::Error);
  EXPECT_THROW(asp::Grid::create(1, 64, 1, 4.9e-324, 1.0), asp::Error);
  EXPECT_THROW(asp::Grid::create(1, 64, 1, 1e-300, 1.0), asp::Error);  // |q| 4e302
  // The unit scene scaled by 1e+-100 is fine.
  EXPECT_NO_THROW(asp::Grid::create(2, 64, 64, 1e100, 1e100));
  EXPECT_NO_THROW(asp::Grid::create(2, 64, 64, 1e-100, 1e-100));
}

}  // namespace
