// SPDX-License-Identifier: GPL-2.0-or-later
// The periodic elastic half-space: normalisation against a single Fourier mode, inverse pair,
// and energy and gradient against finite differences.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.hpp"
#include "physics/periodic_halfspace.hpp"
#include "scene.hpp"

namespace {
using asp_test::pi;

// A single mode cos(2 pi (kx x/lx + ky y/ly)) of displacement u0 must give pressure
// E*|q| u0/2 exactly: checks the 1/N and 2 pi conventions on any grid.
void expect_single_mode(const asp::Grid &grid, std::int64_t kx, std::int64_t ky) {
  const double modulus = 3.7, u0 = 0.25;
  asp::PeriodicHalfSpace substrate(grid, modulus);
  asp::Field u = grid.make_field(), p = grid.make_field();
  const double qx = 2 * pi * kx / grid.lx(), qy = 2 * pi * ky / grid.ly();
  for (std::int64_t j = 0; j < grid.ny(); ++j)
    for (std::int64_t i = 0; i < grid.nx(); ++i)
      u[i + grid.nx() * j] =
          u0 * std::cos(qx * i * grid.lx() / grid.nx() + qy * j * grid.ly() / grid.ny());
  substrate.pressure_from_displacement(u.data(), p.data());
  const double amplitude = 0.5 * modulus * std::sqrt(qx * qx + qy * qy) * u0;
  for (std::size_t i = 0; i < u.size(); ++i)
    ASSERT_NEAR(p[i], amplitude / u0 * u[i], 1e-12 * amplitude) << "pixel " << i;
}

TEST(PeriodicHalfSpace, SingleModeHasPressureAmplitudeEStarQHOverTwo) {
  expect_single_mode(*asp_test::grid_1d(64, 1.0), 3, 0);
  expect_single_mode(*asp_test::grid_1d(97, 2.5), 5, 0);
  expect_single_mode(*asp_test::grid_2d(32, 24, 1.0, 0.75), 2, 3);
  expect_single_mode(*asp_test::grid_2d(31, 17, 1.0, 2.0), 4, 1);
  expect_single_mode(*asp_test::grid_2d(1, 29, 1.0, 2.0), 0, 5);
}

TEST(PeriodicHalfSpace, ComplianceInvertsStiffness) {
  auto grid = asp_test::grid_2d(23, 18, 1.3, 0.9);
  asp::PeriodicHalfSpace substrate(*grid, 2.0);
  asp::Field p = grid->make_field(), u = grid->make_field(), back = grid->make_field();
  asp::Random random(3);
  for (auto &v : p) v = random.gaussian();
  substrate.displacement_from_pressure(p.data(), u.data());
  substrate.pressure_from_displacement(u.data(), back.data());
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(back[i], p[i], 1e-12);
}

TEST(PeriodicHalfSpace, DefaultK0IsMeanStiffnessOfTheLowestModes) {
  auto grid = asp_test::grid_2d(16, 8, 2.0, 4.0);
  asp::PeriodicHalfSpace substrate(*grid, 2.0);
  EXPECT_DOUBLE_EQ(substrate.k0(), 0.5 * (2 * pi / 2.0 + 2 * pi / 4.0));
  auto line = asp_test::grid_1d(16, 2.0);
  EXPECT_DOUBLE_EQ(asp::PeriodicHalfSpace(*line, 2.0).k0(), 2 * pi / 2.0);
}

// E_el(u), the energy of the q != 0 modes, is quadratic, so a central difference is exact up
// to rounding: the gradient a (K u - K~(0) mean u)_i must match it to ~1e-7 relative (rounding
// of E divided by the step).
TEST(PeriodicHalfSpace, EnergyGradientMatchesFiniteDifferences) {
  std::shared_ptr<asp::Grid> grids[] = {asp_test::grid_2d(12, 9, 1.0, 0.8),
                                        asp_test::grid_1d(15, 2.0)};
  for (const auto &grid : grids) {
    asp::PeriodicHalfSpace substrate(*grid, 1.5);
    asp::Field u = grid->make_field(), p = grid->make_field();
    asp::Random random(11);
    for (auto &v : u) v = random.gaussian();
    substrate.pressure_from_displacement(u.data(), p.data());
    double mean_u = 0.0;
    for (double v : u) mean_u += v / grid->n_pixels();
    const double step = 1e-4;
    for (std::int64_t i = 0; i < grid->n_pixels(); i += 5) {
      asp::Field plus = u, minus = u;
      plus[i] += step;
      minus[i] -= step;
      const double fd = (substrate.elastic_energy(plus.data()) -
                         substrate.elastic_energy(minus.data())) /
                        (2 * step);
      const double gradient = grid->pixel_area() * (p[i] - substrate.k0() * mean_u);
      EXPECT_NEAR(fd, gradient, 1e-7 * (std::fabs(gradient) + 1.0)) << "pixel " << i;
    }
    // And the energy itself: (A/2) sum_{q != 0} K|u^|^2 = (a/2) sum p u - (A/2) K~(0) mean(u)^2.
    double pu = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) pu += p[i] * u[i];
    const double mean_mode = 0.5 * grid->area() * substrate.k0() * mean_u * mean_u;
    EXPECT_NEAR(substrate.elastic_energy(u.data()), 0.5 * grid->pixel_area() * pu - mean_mode,
                1e-12 * std::fabs(pu));
  }
}

// The pixel stiffness is the diagonal of K and the self compliance that of K^-1: the pressure
// on a pixel displaced alone by one unit, and the displacement of a pixel under a unit
// pressure on it alone, through K~(0) too (the default and a set one). On a half-space the
// inverse of the self compliance lies below the pixel stiffness (the surface around the
// pixel gives way), 1/1.35 of it on a large square grid (the means of |q| and 1/|q| over the
// square Brillouin zone).
TEST(PeriodicHalfSpace, PixelStiffnessAndSelfComplianceAreTheDiagonalsOfKAndItsInverse) {
  auto grid = asp_test::grid_2d(10, 7, 1.0, 1.0);
  asp::PeriodicHalfSpace substrate(*grid, 1.0);
  asp::Field unit = grid->make_field(), out = grid->make_field();
  unit[13] = 1.0;
  for (const bool set_k0 : {false, true}) {
    if (set_k0) substrate.set_k0(5.0);
    substrate.pressure_from_displacement(unit.data(), out.data());
    EXPECT_NEAR(out[13], substrate.pixel_stiffness(), 1e-12 * out[13]) << set_k0;
    substrate.displacement_from_pressure(unit.data(), out.data());
    EXPECT_NEAR(out[13], substrate.self_compliance(), 1e-12 * out[13]) << set_k0;
  }

  auto large = asp_test::grid_2d(512, 512, 1.0, 1.0);
  asp::PeriodicHalfSpace square(*large, 1.0);
  EXPECT_NEAR(1.0 / (square.pixel_stiffness() * square.self_compliance()), 1.0 / 1.35, 0.01);
}

}  // namespace
