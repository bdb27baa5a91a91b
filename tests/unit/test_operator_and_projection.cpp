// SPDX-License-Identifier: GPL-2.0-or-later
// Two helpers every formulation shares: the substrate's elastic operator on a periodic
// half-space (apply_compliance and apply_stiffness against the operator evaluated directly,
// a discrete Fourier sum written out here; the free half-space's is in
// test_free_halfspace.cpp, against Love's coefficients), and Formulation::project() against
// its rule written out (bound, then the mean by scaling).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include "formulations/dual_formulation.hpp"
#include "formulations/primal_formulation.hpp"
#include "physics/periodic_halfspace.hpp"
#include "scene.hpp"

namespace {

using asp::Control;
using asp_test::max_abs;
using asp_test::pi;
using Vector = std::vector<double>;

// The signed wavenumber of index m of an axis of n points.
double wavenumber(std::int64_t m, std::int64_t n, double length) {
  const std::int64_t signed_m = 2 * m <= n ? m : m - n;
  return 2 * pi * static_cast<double>(signed_m) / length;
}

using Complexes = std::vector<std::complex<double>>;

// The discrete Fourier transform written out, O(N^2): out_m = sum_j f_j exp(sign i q_m.x_j).
Complexes dft(const asp::Grid &grid, const Complexes &f, double sign) {
  const std::int64_t nx = grid.nx(), ny = grid.ny();
  Complexes out(f.size());
  for (std::int64_t my = 0; my < ny; ++my)
    for (std::int64_t mx = 0; mx < nx; ++mx) {
      std::complex<double> sum = 0.0;
      for (std::int64_t jy = 0; jy < ny; ++jy)
        for (std::int64_t jx = 0; jx < nx; ++jx) {
          const double phase = 2 * pi * (static_cast<double>(mx * jx) / nx +
                                         static_cast<double>(my * jy) / ny);
          sum += f[jx + nx * jy] * std::polar(1.0, sign * phase);
        }
      out[mx + nx * my] = sum;
    }
  return out;
}

// out = (1/N) sum_q multiplier(|q|) f^_q exp(i q.x), f^ the transform of f: a Fourier
// multiplier applied directly.
template <class Multiplier>
Vector apply_directly(const asp::Grid &grid, const Vector &f, Multiplier &&multiplier) {
  const std::int64_t nx = grid.nx(), ny = grid.ny();
  Complexes spectrum = dft(grid, Complexes(f.begin(), f.end()), -1.0);
  for (std::int64_t my = 0; my < ny; ++my)
    for (std::int64_t mx = 0; mx < nx; ++mx) {
      const double qx = wavenumber(mx, nx, grid.lx()), qy = wavenumber(my, ny, grid.ly());
      spectrum[mx + nx * my] *= multiplier(std::sqrt(qx * qx + qy * qy));
    }
  const Complexes back = dft(grid, spectrum, 1.0);
  Vector out(f.size());
  for (std::size_t i = 0; i < f.size(); ++i)
    out[i] = back[i].real() / static_cast<double>(f.size());
  return out;
}

// Values without structure about `offset`, between offset - 1 and offset + 1.
Vector some_field(std::size_t n, double offset = 0.5) {
  Vector f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = std::cos(1.7 * i * i + 0.3) + offset;
  return f;
}

// K~(q) = E*|q|/2, K~(0) the substrate's convention. The direct sums and the FFT round
// differently, by about N eps times the largest term: 1e-12 of the largest value on these
// grids (N <= 117). Odd and even sizes, 1D and 2D.
TEST(ElasticOperator, PeriodicComplianceAndStiffnessAreTheFourierMultipliers) {
  for (const auto &grid : {asp_test::grid_1d(16, 2.0), asp_test::grid_1d(17, 1.0),
                           asp_test::grid_2d(12, 9, 1.0, 0.75), asp_test::grid_2d(13, 9, 1.3, 2.0)}) {
    const double modulus = 3.7;
    asp::PeriodicHalfSpace substrate(*grid, modulus);
    const double k0 = substrate.k0();
    const auto stiffness = [&](double q) { return q > 0.0 ? 0.5 * modulus * q : k0; };
    const auto n = static_cast<std::size_t>(grid->n_pixels());
    const Vector f = some_field(n);

    Vector u(n), p(n);
    substrate.apply_compliance(f.data(), u.data());
    const Vector u_direct = apply_directly(*grid, f, [&](double q) { return 1.0 / stiffness(q); });
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_NEAR(u[i], u_direct[i], 1e-12 * max_abs(u_direct)) << grid->nx() << " " << i;

    substrate.apply_stiffness(f.data(), p.data());
    const Vector p_direct = apply_directly(*grid, f, stiffness);
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_NEAR(p[i], p_direct[i], 1e-12 * max_abs(p_direct)) << grid->nx() << " " << i;

    // A factor and the mean mode left out (the mean-pressure controls' stiffness): 2.5 K
    // without the q = 0 term.
    Vector scaled(n);
    asp::Spectrum work = substrate.make_spectrum();
    substrate.apply_stiffness(f.data(), scaled.data(), work.data(),
                              asp::Substrate::KernelTimes{2.5, true});
    const Vector scaled_direct =
        apply_directly(*grid, f, [&](double q) { return q > 0.0 ? 2.5 * stiffness(q) : 0.0; });
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_NEAR(scaled[i], scaled_direct[i], 1e-12 * max_abs(scaled_direct)) << i;

    // A caller's work spectrum gives the same bits as one made for the call, and the
    // substrate's own u = K^-1 p and p = K u are the helper.
    Vector again(n);
    substrate.apply_compliance(f.data(), again.data(), work.data());
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(again[i], u[i]) << i;
    substrate.displacement_from_pressure(f.data(), again.data());
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(again[i], u[i]) << i;
    substrate.pressure_from_displacement(f.data(), again.data());
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(again[i], p[i]) << i;
  }
}

// A pass of the caller's own sees the spectrum and the kernel: kernel_times_summing returns
// f.K f, which the direct evaluation gives as f.p (1e-12 relative: rounding of the sums).
TEST(ElasticOperator, FusedPassSumsTheQuadraticForm) {
  auto grid = asp_test::grid_2d(12, 9, 1.0, 0.75);
  asp::PeriodicHalfSpace substrate(*grid, 1.3);
  const auto n = static_cast<std::size_t>(grid->n_pixels());
  const Vector f = some_field(n);
  Vector p(n);
  double energy = 0.0;
  substrate.apply_stiffness(f.data(), p.data(), nullptr,
                            [&](asp::Complex *s, const double *k, const asp::SpectralLayout &l) {
                              energy = asp::kernel_times_summing(grid->reductions(), l, s, k, 1.0);
                            });
  double fp = 0.0;
  for (std::size_t i = 0; i < n; ++i) fp += f[i] * p[i];
  EXPECT_NEAR(energy, fp, 1e-12 * std::fabs(fp));
  Vector plain(n);
  substrate.apply_stiffness(f.data(), plain.data());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(p[i], plain[i]) << i;
}

// ---- Formulation::project ------------------------------------------------------------------

struct Scene {
  std::shared_ptr<asp::Grid> grid;
  std::unique_ptr<asp::System> system;
};

Scene make(asp::SubstrateKind kind = asp::SubstrateKind::periodic) {
  Scene s;
  s.grid = asp_test::grid_2d(32, 24, 1.0, 0.8);
  const std::vector<double> heights = asp_test::rough_surface(*s.grid, 3, 0.1);
  s.system.reset(new asp::System(s.grid, 1.0, kind));
  s.system->set_topography(heights.data());
  return s;
}

// Values of either sign, some far below the bound.
Vector mixed(std::size_t n) { return some_field(n, 0.3); }

// Under a mean constraint (the dual formulation under load control: x >= 0, mean of x =
// target): x <- max(x, 0) scaled by target N / sum max(x, 0), the rule written out here; the
// sums may be added in another order (the loop helper's), so each entry and the mean meet
// theirs to rounding (1e-14 relative: a sum of 768 positive terms).
TEST(Project, RestoresTheBoundThenTheMeanByScaling) {
  Scene s = make();
  asp::DualFormulation f(*s.system, Control::mean_pressure, 0.02);
  ASSERT_TRUE(f.constrains_mean());
  const auto n = static_cast<std::size_t>(f.size());
  Vector x = mixed(n);
  Vector expected(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    expected[i] = std::max(x[i], 0.0);
    sum += expected[i];
  }
  const double scale = f.mean_target() * static_cast<double>(n) / sum;
  for (double &e : expected) e *= scale;
  f.project(x.data());
  double mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_NEAR(x[i], expected[i], 1e-14 * expected[i]) << i;
    ASSERT_GE(x[i], 0.0) << i;
    mean += x[i] / static_cast<double>(n);
  }
  EXPECT_NEAR(mean, f.mean_target(), 1e-14 * f.mean_target());

  // Nothing left above the bound: the uniform iterate at the target.
  Vector below(n, -1.0);
  f.project(below.data());
  for (double v : below) ASSERT_EQ(v, f.mean_target());
}

// Without a mean constraint only the bound: a feasible entry keeps its bits, an infeasible
// one goes onto the bound (the primal formulation under penetration control).
TEST(Project, WithoutAMeanConstraintClipsOnly) {
  Scene s = make();
  asp::PrimalFormulation f(*s.system, Control::penetration, 0.01);
  ASSERT_FALSE(f.constrains_mean());
  const auto n = static_cast<std::size_t>(f.size());
  const Vector start = mixed(n);
  Vector x = start;
  f.project(x.data());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(x[i], start[i] > 0.0 ? start[i] : 0.0) << i;
}

// The unknowns past bounded_size() (a free substrate's surface outside the box) are free of
// the bound: they keep their values, negative ones included.
TEST(Project, LeavesTheUnknownsBeyondTheBoundedOnes) {
  Scene s = make(asp::SubstrateKind::free);
  asp::PrimalFormulation f(*s.system, Control::penetration, 0.01);
  const auto n = static_cast<std::size_t>(f.size());
  const auto bounded = static_cast<std::size_t>(f.bounded_size());
  ASSERT_LT(bounded, n);
  const Vector start = mixed(n);
  Vector x = start;
  f.project(x.data());
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(x[i], i < bounded && !(start[i] > 0.0) ? 0.0 : start[i]) << i;
}

}  // namespace
