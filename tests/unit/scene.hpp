// SPDX-License-Identifier: GPL-2.0-or-later
// Small helpers to set up scenes in the internal tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/aligned_field.hpp"

#include "core/error.hpp"
#include "core/grid.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

namespace asp_test {

constexpr double pi = 3.14159265358979323846;

// Grids plan with FFTW_ESTIMATE in the tests: they make many shapes once each, where
// measuring would cost more than it saves.
inline std::shared_ptr<asp::Grid> grid_1d(std::int64_t nx, double lx) {
  auto grid = asp::Grid::create(1, nx, 1, lx, 1.0);
  grid->set_fft_planning(asp::FftPlanning::estimate);
  return grid;
}
inline std::shared_ptr<asp::Grid> grid_2d(std::int64_t nx, std::int64_t ny, double lx,
                                          double ly) {
  auto grid = asp::Grid::create(2, nx, ny, lx, ly);
  grid->set_fft_planning(asp::FftPlanning::estimate);
  return grid;
}

inline std::vector<double> field_vector(const asp::Field &f) {
  return std::vector<double>(f.begin(), f.end());
}

// A self-affine surface (Hurst 0.8, no roughness longer than the box) with the given rms
// slope, roll-off wavelength (as a fraction of lx) and short cutoff (in pixels).
inline std::vector<double> rough_surface(const asp::Grid &grid, std::uint64_t seed,
                                         double slope = 0.1, double rolloff_fraction = 0.25,
                                         double short_cutoff_pixels = 4.0) {
  asp::SelfAffineParameters p;
  p.hurst = 0.8;
  p.long_cutoff = grid.lx();
  p.rolloff = rolloff_fraction * grid.lx();
  p.short_cutoff = short_cutoff_pixels * grid.lx() / grid.nx();
  p.norm = asp::RoughnessNorm::rms_slope;
  p.target = slope;
  p.seed = seed;
  std::vector<double> h(static_cast<std::size_t>(grid.n_pixels()));
  asp::self_affine_topography(grid, p, h.data());
  return h;
}

// Runs a solve with the named algorithm and returns the report.
inline asp::SolveReport solve_with(const char *algorithm, asp::System &system,
                                   asp::Control control, double value,
                                   double tolerance = 1e-10,
                                   std::int64_t max_iterations = 100000) {
  asp::Solver solver(algorithm);
  solver.set_option("tolerance", tolerance);
  solver.set_option("max_iterations", static_cast<double>(max_iterations));
  solver.solve(system, control, value);
  return solver.report();
}

inline asp::SolveReport solve_pk(asp::System &system, asp::Control control, double value,
                                 double tolerance = 1e-10,
                                 std::int64_t max_iterations = 100000) {
  return solve_with("pk", system, control, value, tolerance, max_iterations);
}

// Vector arithmetic of the tests, for any containers of doubles of one length.
template <class A, class B>
double dot(const A &a, const B &b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
template <class A>
double max_abs(const A &a) {
  double m = 0.0;
  for (double v : a) m = std::fmax(m, std::fabs(v));
  return m;
}
template <class A, class B>
double max_abs_difference(const A &a, const B &b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::fmax(m, std::fabs(a[i] - b[i]));
  return m;
}

// Runs `call`, which must throw asp::Error with `status`; returns the error's message (empty,
// and a failure recorded, where it threw nothing).
template <class Call>
std::string expect_error(asp::Status status, Call call, const std::string &what = "") {
  try {
    call();
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), status) << what << ": " << e.what();
    return e.what();
  }
  ADD_FAILURE() << what << ": no error";
  return std::string();
}

// A user's potential that is zero everywhere (asp_potential_fn's signature).
inline int zero_potential(std::int64_t n, const double *, double *phi, double *dphi,
                          double *d2phi, void *) {
  for (std::int64_t i = 0; i < n; ++i) {
    phi[i] = dphi[i] = 0.0;
    if (d2phi != nullptr) d2phi[i] = 0.0;
  }
  return 0;
}

// Distance of x from the origin on a periodic interval of length l, in [0, l/2].
inline double periodic_distance(double x, double l) {
  double d = std::fmod(std::fabs(x), l);
  return d > 0.5 * l ? l - d : d;
}

// A solve with `algorithm` on the gap of a 64^2 rough surface with adhesion, under
// penetration control: the bytes per pixel its fields held beyond the system's (the
// allocator's peak), after checking that it converged and that the pressure it may have held
// as work is the solution's (finite, tensile or zero wherever the gap is open). For the
// memory tests of the solvers that borrow the system's pressure array.
inline double adhesive_gap_solve_bytes_per_pixel(const char *algorithm) {
  auto grid = grid_2d(64, 64, 1.0, 1.0);
  const auto h = rough_surface(*grid, 5, 0.1);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  system.set_adhesion(1e-4, 0.01);
  asp::Solver solver(algorithm);
  solver.set_option("variable", std::string("gap"));
  asp::reset_field_bytes_peak();
  const std::int64_t before = asp::field_bytes_in_use();
  solver.solve(system, asp::Control::penetration, 0.004);
  const double per_pixel = static_cast<double>(asp::field_bytes_peak() - before) / (64.0 * 64.0);
  EXPECT_TRUE(solver.report().converged()) << algorithm << ": error " << solver.report().error;
  EXPECT_GT(system.contact_fraction(), 0.0) << algorithm;
  for (std::size_t i = 0; i < system.state().pressure.size(); ++i) {
    EXPECT_TRUE(std::isfinite(system.state().pressure[i])) << algorithm << " " << i;
    if (system.state().gap[i] > 0.0) EXPECT_LE(system.state().pressure[i], 0.0) << algorithm << " " << i;
  }
  return per_pixel;
}

}  // namespace asp_test
