// SPDX-License-Identifier: GPL-2.0-or-later
// The FFT engine: round trips on every kind of size and the half-spectrum bookkeeping.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "core/transform_clock.hpp"
#include "scene.hpp"

namespace {

struct Shape {
  int dimension;
  std::int64_t nx, ny;
};

// Readable parameters in test listings and failure messages (gtest would print raw bytes).
void PrintTo(const Shape &s, std::ostream *os) {
  *os << s.dimension << "D " << s.nx << "x" << s.ny;
}

class FftRoundTrip : public ::testing::TestWithParam<Shape> {};

TEST_P(FftRoundTrip, BackwardOfForwardIsNTimesTheField) {
  const Shape s = GetParam();
  auto grid = asp::Grid::create(s.dimension, s.nx, s.ny, 1.0, 2.0);
  asp::Field f = grid->make_field(), back = grid->make_field();
  asp::Random random(42);
  for (auto &v : f) v = random.gaussian();
  asp::Spectrum spectrum = grid->make_spectrum();
  grid->fft().forward(f.data(), spectrum.data());
  grid->fft().backward(spectrum.data(), back.data());
  const double n = static_cast<double>(grid->n_pixels());
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(back[i] / n, f[i], 1e-13) << i;
}

INSTANTIATE_TEST_SUITE_P(Sizes, FftRoundTrip,
                         ::testing::Values(Shape{1, 1, 1}, Shape{1, 2, 1}, Shape{1, 97, 1},
                                           Shape{1, 128, 1}, Shape{1, 135, 1},
                                           Shape{2, 16, 16}, Shape{2, 17, 13},
                                           Shape{2, 31, 64}, Shape{2, 1, 37},
                                           Shape{2, 37, 1}, Shape{2, 2, 2}),
                         [](const ::testing::TestParamInfo<Shape> &info) {
                           return std::to_string(info.param.dimension) + "d_" +
                                  std::to_string(info.param.nx) + "x" +
                                  std::to_string(info.param.ny);
                         });

TEST(Fft, ParsevalWeightsCountEveryModeOnce) {
  // sum |f|^2 = (1/N) sum over the full spectrum |F|^2, with the half-spectrum weights.
  for (auto shape : {Shape{2, 12, 10}, Shape{2, 11, 9}, Shape{1, 10, 1}, Shape{1, 9, 1}}) {
    auto grid = asp::Grid::create(shape.dimension, shape.nx, shape.ny, 1.0, 1.0);
    asp::Field f = grid->make_field();
    asp::Random random(7);
    double direct = 0.0;
    for (auto &v : f) {
      v = random.gaussian();
      direct += v * v;
    }
    asp::Spectrum s = grid->make_spectrum();
    grid->fft().forward(f.data(), s.data());
    double spectral = 0.0;
    grid->half_spectrum().for_each([&](std::int64_t k, double, double weight) {
      spectral += weight * std::norm(s[static_cast<std::size_t>(k)]);
    });
    EXPECT_NEAR(spectral / grid->n_pixels(), direct, 1e-10 * direct);
  }
}

TEST(Fft, WavevectorsWrapToTheNearestAlias) {
  // 8 x 7 on 2 x 3: the r2c rows hold kx = 0..4; rows ky = 4..6 stand for ky - 7 = -3..-1.
  auto grid = asp_test::grid_2d(8, 7, 2.0, 3.0);
  std::vector<double> q(static_cast<std::size_t>(grid->local_spectral()));
  grid->half_spectrum().for_each(
      [&](std::int64_t k, double magnitude, double) { q[static_cast<std::size_t>(k)] = magnitude; });
  const std::int64_t row = 8 / 2 + 1;
  EXPECT_DOUBLE_EQ(q[4], 2 * asp_test::pi * 4 / 2.0);
  EXPECT_DOUBLE_EQ(q[3 * row], 2 * asp_test::pi * 3 / 3.0);
  EXPECT_DOUBLE_EQ(q[4 * row], 2 * asp_test::pi * 3 / 3.0);
  EXPECT_DOUBLE_EQ(q[6 * row], 2 * asp_test::pi * 1 / 3.0);
  EXPECT_DOUBLE_EQ(q[1 + 6 * row], 2 * asp_test::pi * std::hypot(1 / 2.0, 1 / 3.0));
}

TEST(Fft, PaddedTransformIsTheFullTransformOfTheZeroPaddedField) {
  // The pruned transform skips the padding's zero rows; it must give RealFft(2nx, 2ny)'s
  // spectrum of the padded field, and back the box of its inverse, to round-off.
  for (auto shape : {Shape{2, 8, 6}, Shape{2, 9, 5}, Shape{2, 1, 4}, Shape{2, 7, 1}}) {
    const std::int64_t nx = shape.nx, ny = shape.ny;
    auto box_grid = asp::Grid::create(2, nx, ny, 1.0, 1.0);
    auto padded_grid = asp::Grid::create(2, 2 * nx, 2 * ny, 2.0, 2.0);
    asp::Field box = box_grid->make_field(), padded = padded_grid->make_field();
    asp::Random random(11);
    for (std::int64_t y = 0; y < ny; ++y)
      for (std::int64_t x = 0; x < nx; ++x)
        padded[static_cast<std::size_t>(x + 2 * nx * y)] =
            box[static_cast<std::size_t>(x + nx * y)] = random.gaussian();
    asp::Spectrum expected = padded_grid->make_spectrum(), pruned = padded_grid->make_spectrum();
    padded_grid->fft().forward(padded.data(), expected.data());
    asp::Field rows = padded_grid->make_field();
    box_grid->padded_fft().forward(box.data(), pruned.data(), rows.data());
    for (std::size_t k = 0; k < expected.size(); ++k)
      EXPECT_LT(std::abs(pruned[k] - expected[k]), 1e-12 * (1 + std::abs(expected[k]))) << k;

    asp::Field back = box_grid->make_field();
    box_grid->padded_fft().backward(pruned.data(), back.data(), rows.data());
    padded_grid->fft().backward(expected.data(), padded.data());
    for (std::int64_t y = 0; y < ny; ++y)
      for (std::int64_t x = 0; x < nx; ++x) {
        const std::size_t i = static_cast<std::size_t>(x + nx * y);
        EXPECT_NEAR(back[i], padded[static_cast<std::size_t>(x + 2 * nx * y)], 1e-12) << i;
        EXPECT_NEAR(back[i] / (4.0 * nx * ny), box[i], 1e-13) << i;
      }
  }
}

// The benchmarks' clock of the transforms: off, a transform adds nothing; on, every
// transform of a grid, serial or padded, adds its time, and a reset starts again from zero.
TEST(TransformClock, TimesTransformsOnlyWhileOn) {
  auto grid = asp::Grid::create(2, 64, 64, 1.0, 1.0);
  asp::Field f = grid->make_field(), rows = grid->make_field();
  asp::Spectrum spectrum = grid->make_spectrum();
  const auto pair = [&]() {
    grid->fft().forward(f.data(), spectrum.data());
    grid->fft().backward(spectrum.data(), f.data());
  };
  pair();  // plans made before the clock runs
  asp::transform_clock::reset();
  asp::transform_clock::enable(false);
  pair();
  EXPECT_EQ(asp::transform_clock::seconds(), 0.0);

  asp::transform_clock::enable(true);
  pair();
  const double after_pair = asp::transform_clock::seconds();
  EXPECT_GT(after_pair, 0.0);
  auto box_grid = asp::Grid::create(2, 32, 32, 1.0, 1.0);
  asp::Spectrum padded = grid->make_spectrum();
  asp::Field box = box_grid->make_field();
  box_grid->padded_fft().forward(box.data(), padded.data(), rows.data());
  EXPECT_GT(asp::transform_clock::seconds(), after_pair);

  asp::transform_clock::enable(false);
  asp::transform_clock::reset();
  EXPECT_EQ(asp::transform_clock::seconds(), 0.0);
}

}  // namespace
