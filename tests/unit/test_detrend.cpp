// SPDX-License-Identifier: GPL-2.0-or-later
// Detrending: a plane or a quadratic form added to a rough surface is removed to rounding
// (1e-12 of the form's amplitude: the fit's normal equations are well conditioned in the
// scaled coordinates, and only rounding separates the fit from the form); the mean mode
// leaves a zero mean and the shape; terms a small grid cannot determine are left out;
// refusals leave the heights as they were.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "physics/detrend.hpp"
#include "scene.hpp"

using namespace asp;

namespace {

std::vector<double> with_form(const Grid &grid, const std::vector<double> &rough, double a,
                              double bx, double by, double cxx, double cxy, double cyy) {
  std::vector<double> h = rough;
  for (std::int64_t j = 0; j < grid.ny(); ++j)
    for (std::int64_t i = 0; i < grid.nx(); ++i) {
      const double x = (i + 0.5) * grid.lx() / grid.nx(), y = (j + 0.5) * grid.ly() / grid.ny();
      h[static_cast<std::size_t>(i + grid.nx() * j)] +=
          a + bx * x + by * y + cxx * x * x + cxy * x * y + cyy * y * y;
    }
  return h;
}

TEST(Detrend, RemovesAPlaneAndAQuadraticFormToRounding) {
  auto grid = asp_test::grid_2d(64, 48, 2.0, 1.5);
  const std::vector<double> rough = asp_test::rough_surface(*grid, 4, 0.1, 0.5, 2.0);
  // The rough surface's own fit, removed first, so that what remains to compare is the form.
  std::vector<double> reference = rough;
  detrend_topography(*grid, Detrend::curvature, reference.data());
  std::vector<double> h = with_form(*grid, reference, 3.0, 0.5, -0.2, 0.7, 0.3, -0.4);
  detrend_topography(*grid, Detrend::curvature, h.data());
  EXPECT_LT(asp_test::max_abs_difference(h, reference), 1e-12 * 5.0);

  std::vector<double> planar = rough;
  detrend_topography(*grid, Detrend::plane, planar.data());
  h = with_form(*grid, planar, -1.0, 0.03, 0.02, 0.0, 0.0, 0.0);
  detrend_topography(*grid, Detrend::plane, h.data());
  EXPECT_LT(asp_test::max_abs_difference(h, planar), 1e-12 * 1.0);
}

TEST(Detrend, MeanModeLeavesAZeroMeanAndTheShape) {
  auto grid = asp_test::grid_1d(100, 3.0);
  std::vector<double> h(100);
  for (int i = 0; i < 100; ++i) h[static_cast<std::size_t>(i)] = 5.0 + std::sin(0.3 * i);
  const std::vector<double> before = h;
  detrend_topography(*grid, Detrend::mean, h.data());
  double mean = 0.0;
  for (double v : h) mean += v / 100.0;
  EXPECT_LT(std::fabs(mean), 1e-14 * 6.0);
  for (std::size_t i = 1; i < h.size(); ++i)
    EXPECT_NEAR(h[i] - h[0], before[i] - before[0], 1e-14 * 6.0);
}

TEST(Detrend, OneDimensionalLineAndParabola) {
  auto grid = asp_test::grid_1d(257, 10.0);
  std::vector<double> h(257), expected(257);
  for (int i = 0; i < 257; ++i) {
    const double x = (i + 0.5) * 10.0 / 257.0;
    expected[static_cast<std::size_t>(i)] = 0.0;
    h[static_cast<std::size_t>(i)] = 2.0 - 0.1 * x + 0.05 * x * x;
  }
  detrend_topography(*grid, Detrend::curvature, h.data());
  EXPECT_LT(asp_test::max_abs_difference(h, expected), 1e-12 * 5.0);
}

TEST(Detrend, TermsTheGridCannotDetermineAreLeftOut) {
  // Two pixels along x: x^2 is a multiple of 1 there; the fit keeps the plane.
  auto grid = asp_test::grid_2d(2, 8, 1.0, 1.0);
  std::vector<double> h(16);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 2; ++i) h[static_cast<std::size_t>(i + 2 * j)] = 1.0 + 0.5 * i - 0.25 * j;
  detrend_topography(*grid, Detrend::curvature, h.data());
  for (double v : h) EXPECT_NEAR(v, 0.0, 1e-12);
}

TEST(Detrend, RefusesHeightsThatAreNotFiniteAndLeavesThem) {
  auto grid = asp_test::grid_1d(8, 1.0);
  std::vector<double> h = {1, 2, 3, NAN, 5, 6, 7, 8};
  try {
    detrend_topography(*grid, Detrend::plane, h.data());
    ADD_FAILURE() << "accepted a NaN";
  } catch (const Error &e) {
    EXPECT_EQ(e.status(), Status::invalid_argument);
    EXPECT_NE(std::string(e.what()).find("heights"), std::string::npos) << e.what();
  }
  EXPECT_EQ(h[0], 1.0);
  // A tilt from -DBL_MAX to DBL_MAX: the detrended heights are representable.
  std::vector<double> extreme(8);
  for (int i = 0; i < 8; ++i) extreme[static_cast<std::size_t>(i)] = (i - 3.5) / 3.5 * 1e308;
  detrend_topography(*grid, Detrend::plane, extreme.data());
  for (double v : extreme) EXPECT_LT(std::fabs(v), 1e293);
}

}  // namespace
