// SPDX-License-Identifier: GPL-2.0-or-later
// The free (non-periodic) half-space: its padded compliance against Love's coefficients summed
// directly, Hertz and the flat punch against their closed forms, agreement with the periodic
// half-space for a small contact in a large box, and what it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "physics/free_halfspace.hpp"
#include "physics/topography.hpp"
#include "scene.hpp"

namespace {
using asp_test::pi;
using Vector = std::vector<double>;

// ---- Love's coefficients, summed directly ----------------------------------------------------

// Johnson, Contact Mechanics, eq. 3.25, as printed: the displacement at (x, y) of a pressure p
// uniform over the rectangle |x'| <= a, |y'| <= b, times pi E*/p.
double johnson_3_25(double x, double y, double a, double b) {
  const auto r = [](double u, double v) { return std::sqrt(u * u + v * v); };
  return (x + a) * std::log(((y + b) + r(y + b, x + a)) / ((y - b) + r(y - b, x + a))) +
         (y + b) * std::log(((x + a) + r(y + b, x + a)) / ((x - a) + r(y + b, x - a))) +
         (x - a) * std::log(((y - b) + r(y - b, x - a)) / ((y + b) + r(y + b, x - a))) +
         (y - b) * std::log(((x - a) + r(y - b, x - a)) / ((x + a) + r(y - b, x + a)));
}

// u_i = sum_j C(x_i - x_j) p_j over the box, O(N^2).
Vector love_displacement(const asp::Grid &grid, double modulus, const Vector &p) {
  const std::int64_t nx = grid.nx(), ny = grid.ny();
  const double dx = grid.lx() / nx, dy = grid.ly() / ny;
  Vector u(p.size(), 0.0);
  for (std::int64_t iy = 0; iy < ny; ++iy)
    for (std::int64_t ix = 0; ix < nx; ++ix) {
      double sum = 0.0;
      for (std::int64_t jy = 0; jy < ny; ++jy)
        for (std::int64_t jx = 0; jx < nx; ++jx)
          sum += p[jx + nx * jy] *
                 johnson_3_25((ix - jx) * dx, (iy - jy) * dy, 0.5 * dx, 0.5 * dy);
      u[ix + nx * iy] = sum / (pi * modulus);
    }
  return u;
}

double largest_magnitude(const Vector &v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// The FFT of the padded grid with the compliance spectrum is the aperiodic convolution with
// Love's coefficients: both sides are the same sums, so they agree to round-off (1e-12 of the
// largest displacement; measured below 1e-15). Odd and even sizes, rectangular pixels.
TEST(FreeHalfSpace, PaddedComplianceIsLoveSummedDirectly) {
  struct Shape {
    std::int64_t nx, ny;
    double lx, ly;
  };
  for (const Shape &shape : {Shape{7, 5, 1.3, 0.7}, Shape{8, 6, 1.0, 1.0}, Shape{1, 9, 0.2, 2.0},
                             Shape{12, 1, 3.0, 0.5}}) {
    auto grid = asp_test::grid_2d(shape.nx, shape.ny, shape.lx, shape.ly);
    const double modulus = 2.5;
    asp::FreeHalfSpace substrate(*grid, modulus);
    Vector p(static_cast<std::size_t>(grid->n_pixels()));
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::cos(1.7 * i * i + 0.3) + 0.5;
    asp::Field u = grid->make_field();
    substrate.displacement_from_pressure(p.data(), u.data());
    const Vector direct = love_displacement(*grid, modulus, p);
    const double scale = largest_magnitude(direct);
    for (std::size_t i = 0; i < p.size(); ++i)
      ASSERT_NEAR(u[i], direct[i], 1e-12 * scale) << shape.nx << "x" << shape.ny << " " << i;

    // The energy is (a/2) p.u, by Parseval on the padded grid.
    double pu = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) pu += p[i] * direct[i];
    const double energy = 0.5 * grid->pixel_area() * pu;
    EXPECT_NEAR(substrate.elastic_energy_of_pressure(p.data()), energy, 1e-12 * energy);

    // The stiffness under uniform pressure: pbar over the mean displacement it makes.
    const Vector uniform = love_displacement(*grid, modulus, Vector(p.size(), 1.0));
    double mean = 0.0;
    for (double v : uniform) mean += v / static_cast<double>(uniform.size());
    EXPECT_NEAR(substrate.uniform_pressure_stiffness(), 1.0 / mean, 1e-12 / mean);
  }
}

// The elastic-operator helper of the substrate on a free half-space: apply_compliance is
// Love's sum (1e-12 of the largest displacement, as above); compliance_onto_surface holds the
// same displacement on the box, to the bit (the same transforms and pass), and the stiffness
// of the padded surface undoes it: K applied to that surface displacement gives back the
// pressure on the box and 0 outside it. The last holds to rounding times the condition of
// the padded compliance (the ratio of its largest to smallest spectral entry, below 100 on
// these grids), hence 1e-12 of the largest pressure. A caller's work spectrum gives the same
// bits as one made for the call.
TEST(FreeHalfSpace, ElasticOperatorHelperIsLoveSummedDirectly) {
  for (const auto &shape : {std::make_pair(7, 5), std::make_pair(8, 6), std::make_pair(1, 9)}) {
    auto grid = asp_test::grid_2d(shape.first, shape.second, 1.3, 0.7);
    const double modulus = 2.5;
    asp::FreeHalfSpace substrate(*grid, modulus);
    const auto n = static_cast<std::size_t>(grid->n_pixels());
    Vector p(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = std::cos(1.7 * i * i + 0.3) + 0.5;
    asp::Field u = grid->make_field();
    substrate.apply_compliance(p.data(), u.data());
    const Vector direct = love_displacement(*grid, modulus, p);
    const double scale = largest_magnitude(direct);
    for (std::size_t i = 0; i < n; ++i) ASSERT_NEAR(u[i], direct[i], 1e-12 * scale) << i;

    const auto m = static_cast<std::size_t>(substrate.surface_size());
    ASSERT_EQ(m, 4 * n);
    Vector surface(m), back(m);
    asp::Spectrum work = substrate.make_spectrum();
    substrate.compliance_onto_surface(p.data(), surface.data(), work.data());
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(surface[i], u[i]) << i;
    substrate.apply_stiffness(surface.data(), back.data());
    const double largest = largest_magnitude(p);
    for (std::size_t i = 0; i < m; ++i)
      ASSERT_NEAR(back[i], i < n ? p[i] : 0.0, 1e-12 * largest) << i;
    Vector again(m);
    substrate.apply_stiffness(surface.data(), again.data(), work.data());
    for (std::size_t i = 0; i < m; ++i) ASSERT_EQ(again[i], back[i]) << i;
  }
}

// The coefficients themselves: a square pixel on itself, 4 ln(1 + sqrt 2) dx/(pi E*)
// (Johnson's 2.24 p a/E* for a square of side 2a), to round-off; far from the load, the
// point-load solution A/(pi E* r) with its second-order pixel correction
// (dx^2 (2x^2 - y^2) + dy^2 (2y^2 - x^2))/(24 r^4), whose neglected fourth-order terms are
// below 0.05 (d/r)^4 (Taylor expansion of 1/r over the pixel; the tolerance 0.1 (d/r)^4 is
// twice that).
TEST(FreeHalfSpace, CoefficientsAreLovesSolution) {
  const std::int64_t n = 64;
  const double l = 2.0, modulus = 1.5, dx = l / n;
  auto grid = asp_test::grid_2d(n, n, l, l);
  asp::FreeHalfSpace substrate(*grid, modulus);
  const double self = 4.0 * std::log(1.0 + std::sqrt(2.0)) * dx / (pi * modulus);
  EXPECT_NEAR(substrate.pixel_stiffness(), 1.0 / self, 1e-14 / self);

  asp::Field p = grid->make_field(), u = grid->make_field();
  p[0] = 1.0;  // a unit pressure on the corner pixel
  substrate.displacement_from_pressure(p.data(), u.data());
  EXPECT_NEAR(u[0], self, 1e-13 * self);
  EXPECT_NEAR(substrate.self_compliance(), self, 1e-14 * self);
  for (const auto offset : {std::make_pair(20, 0), std::make_pair(0, 40), std::make_pair(30, 30),
                            std::make_pair(63, 17)}) {
    const double x = offset.first * dx, y = offset.second * dx, r = std::hypot(x, y);
    const double correction =
        (dx * dx * (2 * x * x - y * y) + dx * dx * (2 * y * y - x * x)) / (24 * r * r * r * r);
    const double expected = dx * dx / (pi * modulus * r) * (1.0 + correction);
    const double d_over_r = dx / r;
    EXPECT_NEAR(u[offset.first + n * offset.second], expected,
                0.1 * std::pow(d_over_r, 4) * expected)
        << offset.first << "," << offset.second;
  }
}

// ---- Hertz ----------------------------------------------------------------------------------

struct HertzErrors {
  double force, radius, peak, energy;  // relative errors against the closed forms
};

// A paraboloid h = -r^2/(2R) pressed to delta = a^2/R on a box of 2.5 a, so that the contact
// (diameter 2a) fits with room; a_pixels = a/dx.
HertzErrors hertz(const char *algorithm, int a_pixels) {
  const double radius = 1.0, modulus = 1.0, a = 0.05;
  const std::int64_t n = static_cast<std::int64_t>(std::lround(2.5 * a_pixels));
  const double dx = a / a_pixels, l = n * dx;
  auto grid = asp_test::grid_2d(n, n, l, l);
  Vector h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, radius, h.data());
  asp::System system(grid, modulus, asp::SubstrateKind::free);
  system.set_topography(h.data());
  const double delta = a * a / radius;
  asp::Solver solver(algorithm);
  solver.set_option("tolerance", 1e-10);
  if (std::string(algorithm) == "bugnicourt")
    solver.set_option("variable", std::string("pressure"));
  solver.solve(system, asp::Control::penetration, delta);
  EXPECT_TRUE(solver.report().converged()) << algorithm << " a/dx = " << a_pixels;

  const double force = 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(delta, 1.5);
  const double p0 = 2.0 * modulus / pi * std::sqrt(delta / radius);
  const double energy = 8.0 / 15.0 * modulus * std::sqrt(radius) * std::pow(delta, 2.5);
  const auto &p = system.state().pressure;
  HertzErrors e;
  e.force = system.total_force() / force - 1.0;
  e.radius = std::sqrt(system.contact_fraction() * l * l / pi) / a - 1.0;
  e.peak = *std::max_element(p.begin(), p.end()) / p0 - 1.0;
  e.energy = system.elastic_energy() / energy - 1.0;
  std::printf("%s a/dx = %d (%lld^2): force %+.2e, radius %+.2e, peak %+.2e, energy %+.2e, "
              "%lld iterations\n",
              algorithm, a_pixels, static_cast<long long>(n), e.force, e.radius, e.peak,
              e.energy, static_cast<long long>(solver.report().iterations));
  return e;
}

// Collocation with pressures uniform over pixels converges at second order for the smooth
// Hertz pressure (measured constants: force 0.03-0.05, peak 0.07, energy 0.09-0.10 times
// (dx/a)^2): each is held to 0.2 (dx/a)^2, twice the largest, so 1.2e-4 of the force at
// a/dx = 64 (the target there was 1e-3; measured 1.3e-5), and each doubling of the resolution
// must divide the error by at least 2 (measured 2.49 to 4.4). The radius comes from the pixel
// count, decided pixel by pixel along the edge: within half a pixel, 0.5 dx/a.
TEST(FreeHalfSpace, HertzConvergesWithResolution) {
  for (const char *algorithm : {"pk", "bugnicourt"}) {
    std::vector<HertzErrors> errors;
    const int resolutions[] = {16, 32, 64};
    for (int a_pixels : resolutions) {
      errors.push_back(hertz(algorithm, a_pixels));
      const HertzErrors &e = errors.back();
      const double second_order = 0.2 / (a_pixels * a_pixels);
      EXPECT_LE(std::fabs(e.force), second_order) << algorithm << " a/dx = " << a_pixels;
      EXPECT_LE(std::fabs(e.peak), second_order) << algorithm << " a/dx = " << a_pixels;
      EXPECT_LE(std::fabs(e.energy), second_order) << algorithm << " a/dx = " << a_pixels;
      EXPECT_LE(std::fabs(e.radius), 0.5 / a_pixels) << algorithm << " a/dx = " << a_pixels;
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
      EXPECT_LE(std::fabs(errors[k].force), std::fabs(errors[k - 1].force) / 2) << algorithm;
      EXPECT_LE(std::fabs(errors[k].peak), std::fabs(errors[k - 1].peak) / 2) << algorithm;
      EXPECT_LE(std::fabs(errors[k].energy), std::fabs(errors[k - 1].energy) / 2) << algorithm;
    }
  }
}

// ---- flat punch -----------------------------------------------------------------------------

// A flat circular face of radius r (pixels whose centre lies within r) with the surface a
// depth r below it elsewhere, pressed in by delta = 1e-3 r: F/delta = 2 r E* (Boussinesq).
// Returns F/delta/(2 r E*) - 1.
double punch_stiffness_error(int r_pixels) {
  const double modulus = 1.0, r = 0.1;
  const std::int64_t n = static_cast<std::int64_t>(std::lround(2.5 * r_pixels));
  const double dx = r / r_pixels, l = n * dx;
  auto grid = asp_test::grid_2d(n, n, l, l);
  Vector h(static_cast<std::size_t>(n * n));
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t i = 0; i < n; ++i)
      h[i + n * j] = std::hypot((i - n / 2) * dx, (j - n / 2) * dx) <= r ? 0.0 : -r;
  asp::System system(grid, modulus, asp::SubstrateKind::free);
  system.set_topography(h.data());
  const double delta = 1e-3 * r;
  const auto report = asp_test::solve_pk(system, asp::Control::penetration, delta, 1e-10);
  EXPECT_TRUE(report.converged()) << "r/dx = " << r_pixels;
  const double error = system.total_force() / delta / (2.0 * r * modulus) - 1.0;
  std::printf("flat punch r/dx = %d: stiffness %+.3e (%.3f dx/r), %lld iterations\n", r_pixels,
              error, error * r_pixels, static_cast<long long>(report.iterations));
  return error;
}

// The face made of pixels lies between the discs of radius r - dx/sqrt 2 and r + dx/sqrt 2,
// and the stiffness of a flat punch grows with its face, so the staircase alone moves it by
// up to dx/(sqrt 2 r); the collocation error of the square-root edge singularity is of the
// same first order. The tolerance is that bound, 0.71 dx/r (measured -0.15 to -0.17 dx/r),
// and doubling the resolution must divide the error by at least 1.5 (measured 1.9 to 2.4).
TEST(FreeHalfSpace, FlatPunchStiffnessIsTwoRadiusModulus) {
  double previous = 0.0;
  for (int r_pixels : {16, 32, 64}) {
    const double error = punch_stiffness_error(r_pixels);
    EXPECT_LE(std::fabs(error), 1.0 / (std::sqrt(2.0) * r_pixels)) << "r/dx = " << r_pixels;
    if (previous != 0.0) EXPECT_LE(std::fabs(error), std::fabs(previous) / 1.5);
    previous = error;
  }
}

// ---- periodic and free agree for a small contact in a large box -----------------------------

// Hertz at equal mean pressure (equal force: same box) on both substrates. The periodic one
// also feels the images of the contact, at the sites R of the square lattice of spacing L:
// near the contact their displacement is a constant (taken up by the penetration, which
// therefore differs and is not compared) plus F S x^2/(4 pi E* L^3), S = sum over R != 0 of
// (L/|R|)^3 = 9.0336. That flattens the sphere's effective curvature and raises the peak
// pressure by (4 S/(9 pi)) (a/L)^3 p0 = 1.278 (a/L)^3 p0, the leading difference of the
// pressure fields inside the contact. Checked within r < a/2, away from the edge pixels: the
// largest difference there is that prediction to 25% (the next image terms are
// (a/L)^2 smaller; the two kernels' discretisations differ by O((dx/a)^2) p0 inside the
// contact, 1.7e-5 p0 at a/dx = 16, 6% of the prediction at L/a = 16; measured: the prediction
// to 0.2% at L/a = 8 and 5.3% at L/a = 16). The contact
// areas, decided pixel by pixel where the two edges lie within a small fraction of a pixel
// (each discretisation puts a within 0.1 px), differ by at most a tenth of the edge ring of
// 2 pi a/dx pixels (measured: identical).
TEST(FreeHalfSpace, SmallContactAgreesWithPeriodicUpToImages) {
  const int a_pixels = 16;
  const double lattice_sum = 9.0336;
  for (std::int64_t n : {128, 256}) {
    const double l = 1.0, radius = 1.0, modulus = 1.0, a = l * a_pixels / n, dx = l / n;
    auto grid = asp_test::grid_2d(n, n, l, l);
    Vector h(static_cast<std::size_t>(n * n));
    asp::paraboloid_topography(*grid, radius, h.data());
    asp::System periodic(grid, modulus), free(grid, modulus, asp::SubstrateKind::free);
    periodic.set_topography(h.data());
    free.set_topography(h.data());
    const double mean = 4 * modulus * a * a * a / (3 * radius) / (l * l);
    ASSERT_TRUE(asp_test::solve_pk(periodic, asp::Control::mean_pressure, mean).converged());
    ASSERT_TRUE(asp_test::solve_pk(free, asp::Control::mean_pressure, mean).converged());

    const double p0 = 2 * modulus * a / (pi * radius);
    double inner = 0.0, periodic_contacts = 0.0, free_contacts = 0.0;
    for (std::int64_t j = 0; j < n; ++j)
      for (std::int64_t i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(i + n * j);
        const double pp = periodic.state().pressure[k], pf = free.state().pressure[k];
        if (std::hypot((i - n / 2) * dx, (j - n / 2) * dx) < 0.5 * a)
          inner = std::max(inner, std::fabs(pp - pf));
        periodic_contacts += pp > 0.0 ? 1.0 : 0.0;
        free_contacts += pf > 0.0 ? 1.0 : 0.0;
      }
    const double images = 4 * lattice_sum / (9 * pi) * std::pow(a / l, 3) * p0;
    std::printf("L/a = %.0f: inner |dp| = %.3e p0, images predict %.3e p0; contact pixels "
                "%.0f (periodic) and %.0f (free)\n",
                l / a, inner / p0, images / p0, periodic_contacts, free_contacts);
    EXPECT_NEAR(inner, images, 0.25 * images) << "L/a = " << l / a;
    EXPECT_LE(std::fabs(free_contacts - periodic_contacts), 0.1 * 2 * pi * a_pixels);
  }
}

// ---- the reference pressure of a surface that is not periodic -------------------------------

// A tilted plane h = s x + t y: its slope is sqrt(s^2 + t^2) everywhere, and a free system's
// reference pressure E* h'_rms/2 says so to round-off (differences of a plane are exact up to
// rounding, 1e-12). Read as periodic, the step between its opposite edges would count too: the
// spectral slope of the same heights is many times larger.
TEST(FreeHalfSpace, ReferencePressureIgnoresTheStepAcrossTheEdges) {
  const std::int64_t nx = 48, ny = 20;
  const double lx = 1.5, ly = 0.5, s = 0.03, t = -0.02, modulus = 3.0;
  auto grid = asp_test::grid_2d(nx, ny, lx, ly);
  Vector h(static_cast<std::size_t>(nx * ny));
  for (std::int64_t j = 0; j < ny; ++j)
    for (std::int64_t i = 0; i < nx; ++i) h[i + nx * j] = s * i * lx / nx + t * j * ly / ny;
  asp::System free(grid, modulus, asp::SubstrateKind::free), periodic(grid, modulus);
  free.set_topography(h.data());
  periodic.set_topography(h.data());
  const double expected = 0.5 * modulus * std::hypot(s, t);
  EXPECT_NEAR(free.last_reference_pressure(), expected, 1e-12 * expected);
  EXPECT_GT(periodic.last_reference_pressure(), 3.0 * expected);
}

// ---- what it refuses ------------------------------------------------------------------------

TEST(FreeHalfSpace, RefusesA1DGridNamingIt) {
  auto line = asp_test::grid_1d(64, 1.0);
  try {
    asp::System system(line, 1.0, asp::SubstrateKind::free);
    FAIL() << "a free substrate on a 1D grid was made";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::unsupported);
    EXPECT_NE(std::string(e.what()).find("'grid'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reference point"), std::string::npos) << e.what();
  }
}

// No K~(0) to set, no stiffness on the spectral space, no gap formulation; after each refusal
// the system is as it was and solves.
TEST(FreeHalfSpace, RefusesK0AndMeanGapControl) {
  const std::int64_t n = 32;
  auto grid = asp_test::grid_2d(n, n, 1.0, 1.0);
  Vector h(static_cast<std::size_t>(n * n));
  asp::paraboloid_topography(*grid, 1.0, h.data());
  asp::System system(grid, 1.0, asp::SubstrateKind::free);
  system.set_topography(h.data());
  ASSERT_TRUE(asp_test::solve_pk(system, asp::Control::mean_pressure, 1e-4).converged());
  const Vector pressure = asp_test::field_vector(system.state().pressure);
  const double penetration = system.state().penetration;
  EXPECT_FALSE(system.substrate().has_k0());
  EXPECT_EQ(system.mean_mode_energy(), 0.0);

  const auto expect_refusal = [&](const auto &call, const char *named) {
    try {
      call();
      ADD_FAILURE() << "not refused: " << named;
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported) << e.what();
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    }
    EXPECT_EQ(asp_test::field_vector(system.state().pressure), pressure);
    EXPECT_EQ(system.state().penetration, penetration);
  };
  expect_refusal([&] { system.set_k0(2.0); }, "'system'");
  expect_refusal([&] { system.set_k0(-1.0); }, "'system'");
  asp::Solver gap("bugnicourt");
  gap.set_option("variable", std::string("gap"));
  expect_refusal([&] { gap.solve(system, asp::Control::mean_gap, 1e-3); },
                 "periodic substrate only");

  // Still usable: a warm solve at another load.
  EXPECT_TRUE(asp_test::solve_pk(system, asp::Control::mean_pressure, 2e-4).converged());
  EXPECT_NEAR(system.mean_pressure(), 2e-4, 1e-16);
}

}  // namespace
