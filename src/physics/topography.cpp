// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/topography.hpp"

#include <algorithm>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"
#include "core/random.hpp"
#include "core/fft_engine.hpp"

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

// heights[i + nx (j - row_offset)] = height(i, j) for the pixels (i, j) of this process's
// rows (all of them unless the grid is distributed).
template <class Height>
void fill_rows(const Grid &g, double *heights, Height height) {
  for (std::int64_t local = 0; local < g.local_rows(); ++local) {
    const std::int64_t j = g.row_offset() + local;
    for (std::int64_t i = 0; i < g.nx(); ++i) heights[i + g.nx() * local] = height(i, j);
  }
}

// heights of pixel (i, j) = shape(dx, dy), its offsets from the centre of the box (from the
// axis in 1D).
template <class Shape>
void fill_radial(const Grid &g, double *heights, Shape shape) {
  const double cx = 0.5 * g.lx();
  const double cy = g.dimension() == 2 ? 0.5 * g.ly() : 0.0;
  fill_rows(g, heights, [&](std::int64_t i, std::int64_t j) {
    return shape(x_of(g, i) - cx, y_of(g, j) - cy);
  });
}
}  // namespace

void flat_topography(const Grid &grid, double *heights) {
  for (std::int64_t k = 0; k < grid.local_pixels(); ++k) heights[k] = 0.0;
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
  fill_rows(grid, heights, [&](std::int64_t i, std::int64_t j) {
    return amplitude * std::cos(kx * x_of(grid, i)) * std::cos(ky * y_of(grid, j));
  });
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
  fill_rows(grid, heights, [&](std::int64_t i, std::int64_t) {
    const double x = x_of(grid, i);
    return amplitude * std::cos(k * x) + ripple_amplitude * std::cos(kr * x);
  });
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

  // Gaussian white noise in Fourier space, one complex number per wavevector from a stream
  // keyed by the seed and the wavevector (Random::keyed), filtered by sqrt(C(q)), then
  // transformed back along y for each column kx and along x for each row, with the same
  // one-dimensional transforms (LineFft) on every process. Each process makes every column
  // (it needs all ky of a column for its rows) and keeps its rows: a seed gives the same
  // surface, to the bit, on any number of processes, and the statistics that set the scale
  // are summed over all modes in one order on each. The spectrum is Hermitian by
  // construction: the columns kx = 0 and, for even nx, kx = nx/2 hold conjugate pairs
  // (ky, ny - ky) drawn once, real where ky is its own partner.
  const std::int64_t nx = grid.nx(), ny = grid.ny(), columns = nx / 2 + 1;
  const std::int64_t rows = grid.local_rows(), first_row = grid.row_offset();
  const double q_l = two_pi / p.long_cutoff, q_r = two_pi / p.rolloff;
  const double q_s = two_pi / p.short_cutoff;
  // C(q) ~ q^(-2-2H) on a surface, q^(-1-2H) on a profile (the field's convention, so that a
  // Hurst exponent means the same roughness in 1D and 2D); the amplitude goes as sqrt(C).
  const double spectral_exponent = grid.dimension() == 2 ? -2.0 - 2.0 * p.hurst
                                                         : -1.0 - 2.0 * p.hurst;
  const double exponent = 0.5 * spectral_exponent;
  const auto frequency = [](std::int64_t k, std::int64_t n) { return k <= n / 2 ? k : n - k; };
  const double per_x = two_pi / grid.lx(), per_y = two_pi / grid.ly();
  // Sums of |S|^2, (q/q_s)^2 |S|^2 over the full spectrum: the mean square height and slope
  // of the surface (Parseval, with the unnormalised backward transform).
  double square_sum = 0.0, slope_sum = 0.0;
  bool any_mode = false;

  Spectrum line(static_cast<std::size_t>(ny));
  Spectrum kept(static_cast<std::size_t>(columns * rows));
  const LineFft along_y(ny);
  for (std::int64_t kx = 0; kx < columns; ++kx) {
    const bool self_paired = kx == 0 || (nx % 2 == 0 && 2 * kx == nx);
    const double qx = per_x * static_cast<double>(kx);
    double column_square = 0.0, column_slope = 0.0;
    for (std::int64_t ky = 0; ky < ny; ++ky) {
      const std::int64_t partner = (ny - ky) % ny;
      const std::int64_t drawn = self_paired ? std::min(ky, partner) : ky;
      Random noise = Random::keyed(p.seed, static_cast<std::uint64_t>(kx + columns * drawn));
      const double a = noise.gaussian(), b = noise.gaussian();
      Complex z = self_paired && drawn == ky && ky == partner
                      ? Complex(a, 0.0)
                      : Complex(a, b) * 0.70710678118654752440;
      if (self_paired && drawn != ky) z = std::conj(z);
      const double qy = per_y * static_cast<double>(frequency(ky, ny));
      const double q = std::sqrt(qx * qx + qy * qy);
      double amplitude = 0.0;
      // Small relative slack so that a cutoff placed exactly on a grid wavevector keeps it.
      if (q > 0.0 && q >= q_l * (1 - 1e-12) && q <= q_s * (1 + 1e-12)) {
        amplitude = q < q_r ? 1.0 : std::pow(q / q_r, exponent);
        any_mode = true;
      }
      z *= amplitude;
      line[static_cast<std::size_t>(ky)] = z;
      const double qs = q / q_s;
      column_square += std::norm(z);
      column_slope += qs * qs * std::norm(z);
    }
    const double modes = self_paired ? 1.0 : 2.0;
    square_sum += modes * column_square;
    slope_sum += modes * column_slope;
    along_y.backward(line.data());
    for (std::int64_t local = 0; local < rows; ++local)
      kept[static_cast<std::size_t>(kx + columns * local)] =
          line[static_cast<std::size_t>(first_row + local)];
  }
  if (!any_mode)
    throw Error(Status::invalid_argument,
                "arguments 'long_cutoff' and 'short_cutoff': no wavevector of the grid lies "
                "between 2 pi/long_cutoff and 2 pi/short_cutoff");
  Field surface = grid.make_field();
  {
    const RealLineFft along_x(nx);
    Spectrum half(static_cast<std::size_t>(columns));
    Field row(static_cast<std::size_t>(nx));
    for (std::int64_t local = 0; local < rows; ++local) {
      std::copy(kept.begin() + columns * local, kept.begin() + columns * (local + 1), half.begin());
      along_x.backward(half.data(), row.data());
      std::copy(row.begin(), row.end(), surface.begin() + nx * local);
    }
  }
  const std::int64_t n = grid.local_pixels();
  const double rms_height = std::sqrt(square_sum), rms_slope = std::sqrt(slope_sum) * q_s;

  // Scaled to the target. A Gaussian surface's peaks reach several times its rms height,
  // so a target near the largest double can need heights beyond it: refused, naming the
  // target, before the caller's array is touched. Rounding is monotone, so if the largest
  // height scales to a finite value every height does.
  const bool by_height = p.norm == RoughnessNorm::rms_height;
  const double measured = by_height ? rms_height : rms_slope;
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
