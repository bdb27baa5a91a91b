// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/topography.hpp"

#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"
#include "core/random.hpp"
#include "physics/surface_statistics.hpp"

namespace asp {
namespace {
constexpr double two_pi = 6.283185307179586476925286766559;

// Position of pixel i along x (j along y; 0 in 1D): i lx/nx, computed as lx (i/nx) so that
// it stays finite on boxes near the largest double, where lx i would overflow.
double x_of(const Grid &g, std::int64_t i) {
  return g.lx() * (static_cast<double>(i) / static_cast<double>(g.nx()));
}
double y_of(const Grid &g, std::int64_t j) {
  return g.dimension() == 2 ? g.ly() * (static_cast<double>(j) / static_cast<double>(g.ny()))
                            : 0.0;
}

// heights[i + nx j] = shape(dx, dy), the offsets of pixel (i, j) from the centre of the box
// (from the axis in 1D).
template <class Shape>
void fill_radial(const Grid &g, double *heights, Shape shape) {
  const double cx = 0.5 * g.lx();
  const double cy = g.dimension() == 2 ? 0.5 * g.ly() : 0.0;
  for (std::int64_t j = 0; j < g.ny(); ++j)
    for (std::int64_t i = 0; i < g.nx(); ++i)
      heights[i + g.nx() * j] = shape(x_of(g, i) - cx, y_of(g, j) - cy);
}
}  // namespace

void flat_topography(const Grid &grid, double *heights) {
  for (std::int64_t k = 0; k < grid.n_pixels(); ++k) heights[k] = 0.0;
}

void sphere_topography(const Grid &grid, double radius, double *heights) {
  require_positive(radius, "radius");
  // sqrt(R^2 - r^2) - R rewritten as -r t/(1 + sqrt(1 - t^2)), t = r/R: it squares neither R
  // nor r (R = 1e200 would overflow) and does not cancel near the apex. Finite for any R.
  fill_radial(grid, heights, [&](double dx, double dy) {
    const double r = std::hypot(dx, dy);
    if (!(r < radius)) return -radius;
    const double t = r / radius;
    return -r * t / (1.0 + std::sqrt((1.0 - t) * (1.0 + t)));
  });
}

void paraboloid_topography(const Grid &grid, double radius, double *heights) {
  require_positive(radius, "radius");
  const auto depth = [&](double dx, double dy) { return -(dx * dx + dy * dy) / (2.0 * radius); };
  // Pixel (0, 0), a corner of the box, is the farthest from the centre; rounding is monotone,
  // so if its depth is finite every height is. Checked before anything is written.
  const double dx = -0.5 * grid.lx(), dy = grid.dimension() == 2 ? -0.5 * grid.ly() : 0.0;
  const double r2 = dx * dx + dy * dy;
  const double deepest = depth(dx, dy);
  if (!std::isfinite(deepest))
    throw Error(Status::invalid_argument,
                "argument 'radius' is " + format_number(radius) +
                    ": the depth r^2/(2 radius) at the corner of the box (r^2 = " +
                    format_number(r2) +
                    ") overflows a double; use a larger radius or rescale the lengths");
  fill_radial(grid, heights, depth);
}

void sinusoid_topography(const Grid &grid, double amplitude, std::int64_t periods_x,
                         std::int64_t periods_y, double *heights) {
  require_finite(amplitude, "amplitude");
  require_at_least(periods_x, 1, "periods_x");
  require_at_least(periods_y, 0, "periods_y");
  if (grid.dimension() == 1 && periods_y != 0)
    throw Error(Status::invalid_argument,
                "argument 'periods_y' must be 0 on a 1D grid, got " + std::to_string(periods_y));
  // |h| <= |amplitude|. The phases are finite on every grid: Grid keeps 2 pi nx/lx below
  // 1e150, so kx < 1e150 periods_x, and x_of stays below lx.
  const double kx = two_pi * static_cast<double>(periods_x) / grid.lx();
  const double ky = two_pi * static_cast<double>(periods_y) / grid.ly();
  for (std::int64_t j = 0; j < grid.ny(); ++j) {
    const double cy = std::cos(ky * y_of(grid, j));
    for (std::int64_t i = 0; i < grid.nx(); ++i)
      heights[i + grid.nx() * j] = amplitude * std::cos(kx * x_of(grid, i)) * cy;
  }
}

void double_sinewave_topography(const Grid &grid, double amplitude, double ripple_amplitude,
                                std::int64_t ripple_periods, double *heights) {
  require_finite(amplitude, "amplitude");
  require_finite(ripple_amplitude, "ripple_amplitude");
  require_at_least(ripple_periods, 1, "ripple_periods");
  // |h| <= |amplitude| + |ripple_amplitude| (reached at x = 0 when both are positive):
  // refused before anything is written if that bound overflows.
  if (!std::isfinite(std::fabs(amplitude) + std::fabs(ripple_amplitude)))
    throw Error(Status::invalid_argument,
                "arguments 'amplitude' (" + format_number(amplitude) + ") and 'ripple_amplitude' (" +
                    format_number(ripple_amplitude) +
                    "): the heights reach |amplitude| + |ripple_amplitude|, which overflows a "
                    "double");
  const double k = two_pi / grid.lx();
  const double kr = k * static_cast<double>(ripple_periods);
  for (std::int64_t i = 0; i < grid.nx(); ++i) {
    const double x = x_of(grid, i);
    const double h = amplitude * std::cos(k * x) + ripple_amplitude * std::cos(kr * x);
    for (std::int64_t j = 0; j < grid.ny(); ++j) heights[i + grid.nx() * j] = h;
  }
}

void self_affine_topography(const Grid &grid, const SelfAffineParameters &p, double *heights) {
  if (!(std::isfinite(p.hurst) && p.hurst >= 0.0 && p.hurst <= 1.0))
    throw Error(Status::invalid_argument,
                "argument 'hurst' must lie in [0, 1], got " + format_number(p.hurst));
  require_positive(p.long_cutoff, "long_cutoff");
  require_positive(p.rolloff, "rolloff");
  require_positive(p.short_cutoff, "short_cutoff");
  if (p.rolloff > p.long_cutoff)
    throw Error(Status::invalid_argument, "argument 'rolloff' (" + format_number(p.rolloff) +
                                              ") must not exceed 'long_cutoff' (" +
                                              format_number(p.long_cutoff) + ")");
  if (!(p.short_cutoff < p.rolloff))
    throw Error(Status::invalid_argument, "argument 'short_cutoff' (" +
                                              format_number(p.short_cutoff) +
                                              ") must be below 'rolloff' (" +
                                              format_number(p.rolloff) + ")");
  require_positive(p.target, "target");

  // White noise in a fixed order, then filtered by sqrt(C(q)) in Fourier space: the spectrum
  // is Hermitian by construction, for odd and even sizes alike. The surface is made in the
  // library's own aligned field, where FFTW plans may run, and copied out at the end: the
  // caller's array may start anywhere (a NumPy slice, a Fortran section).
  const std::int64_t n = grid.n_pixels();
  Random random(p.seed);
  Field surface = grid.make_field();
  for (std::int64_t k = 0; k < n; ++k) surface[static_cast<std::size_t>(k)] = random.gaussian();

  const double q_l = two_pi / p.long_cutoff, q_r = two_pi / p.rolloff;
  const double q_s = two_pi / p.short_cutoff;
  // C(q) ~ q^(-2-2H) on a surface, q^(-1-2H) on a profile (the field's convention, so that a
  // Hurst exponent means the same roughness in 1D and 2D); the amplitude goes as sqrt(C).
  const double spectral_exponent = grid.dimension() == 2 ? -2.0 - 2.0 * p.hurst
                                                         : -1.0 - 2.0 * p.hurst;
  const double exponent = 0.5 * spectral_exponent;
  Spectrum s = grid.make_spectrum();
  grid.fft().forward(surface.data(), s.data());
  bool any_mode = false;
  grid.half_spectrum().for_each([&](std::int64_t k, double q, double) {
    double amplitude = 0.0;
    // Small relative slack so that a cutoff placed exactly on a grid wavevector keeps it.
    if (q > 0.0 && q >= q_l * (1 - 1e-12) && q <= q_s * (1 + 1e-12)) {
      amplitude = q < q_r ? 1.0 : std::pow(q / q_r, exponent);
      any_mode = true;
    }
    s[static_cast<std::size_t>(k)] *= amplitude;
  });
  if (!any_mode)
    throw Error(Status::invalid_argument,
                "arguments 'long_cutoff' and 'short_cutoff': no wavevector of the grid lies "
                "between 2 pi/long_cutoff and 2 pi/short_cutoff");
  grid.fft().backward(s.data(), surface.data());

  // Scaled to the target. A Gaussian surface's peaks reach several times its rms height,
  // so a target near the largest double can need heights beyond it: refused, naming the
  // target, before the caller's array is touched. Rounding is monotone, so if the largest
  // height scales to a finite value every height does.
  const SurfaceStatistics stats = surface_statistics(grid, surface.data());
  const bool by_height = p.norm == RoughnessNorm::rms_height;
  const double measured = by_height ? stats.rms_height : stats.rms_slope;
  const double scale = p.target / measured;
  const double largest =
      loops::maximum(grid.reductions(), n, [&](std::int64_t k) { return std::fabs(surface[k]); });
  if (!std::isfinite(scale) || !std::isfinite(largest * scale))
    throw Error(Status::invalid_argument,
                "argument 'target' is " + format_number(p.target) + ": the surface with this rms " +
                    (by_height ? "height" : "slope") + " would have heights up to " +
                    format_number(largest * scale) + " (unscaled rms " +
                    (by_height ? "height " : "slope ") + format_number(measured) +
                    "), which doubles cannot hold; lower the target or rescale the lengths");
  loops::for_each(n, [&](std::int64_t k) { heights[k] = surface[k] * scale; });
}

}  // namespace asp
