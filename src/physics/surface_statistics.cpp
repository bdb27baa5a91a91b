// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/surface_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {
namespace {

// The exponent e of the power of two 2^e just above value > 0 (0 for 0), at least the
// smallest normal exponent so that 2^-e stays finite. Dividing by a power of two is exact, so
// scaling by it changes no bits of the results; it only keeps squares and fourth powers from
// overflowing.
int exponent_above(double value) {
  return value > 0.0 ? std::max(std::ilogb(value) + 1, std::numeric_limits<double>::min_exponent)
                     : 0;
}

// The half spectrum of the heights divided by 2^exponent: every scaled height is below 1 in
// magnitude, so every |h^_q| and every power |h^_q|^2 is at most 1 (h^ the DFT divided by N)
// and no square overflows, for any finite heights.
struct ScaledSpectrum {
  Spectrum spectrum;
  int exponent = 0;
};

ScaledSpectrum scaled_spectrum(const Grid &grid, const double *heights) {
  const std::int64_t n = grid.local_pixels();
  ScaledSpectrum out;
  out.exponent = exponent_above(
      loops::maximum(grid.reductions(), n, [&](std::int64_t i) { return std::fabs(heights[i]); }));
  const double factor = std::ldexp(1.0, -out.exponent);
  // FFTW plans run only on the library's own aligned fields: the caller's array may start
  // anywhere (a NumPy slice, a Fortran section), so it is copied first, scaled on the way.
  Field h = grid.make_field();
  loops::for_each(n, [&](std::int64_t i) { h[i] = heights[i] * factor; });
  out.spectrum = grid.make_spectrum();
  grid.fft().forward(h.data(), out.spectrum.data());
  return out;
}

// Calls visit(|q|, |h^_q|^2, modes) for every entry of the half spectrum but the mean, h^ the
// scaled spectrum divided by N, modes the number of full-spectrum modes the entry stands for.
template <class Visit>
void for_each_mode(const Grid &grid, const ScaledSpectrum &h, Visit visit) {
  const double n = static_cast<double>(grid.n_pixels());
  const SpectralLayout layout = grid.half_spectrum();
  layout.for_each([&](std::int64_t k, double q, double weight) {
    if (layout.is_mean(k)) return;  // the mean, stored first
    visit(q, std::norm(h.spectrum[static_cast<std::size_t>(k)]) / (n * n), weight);
  });
}

// The largest |q| of the grid's half spectrum (0 for a single pixel).
double largest_wavevector(const Grid &grid) {
  double q_max = 0.0;
  grid.half_spectrum().for_each(
      [&](std::int64_t, double q, double) { q_max = std::fmax(q_max, q); });
  grid.reductions().combine_maxima(&q_max, 1);
  return q_max;
}

void require_bin_count(const Grid &grid, std::int64_t n_bins) {
  if (n_bins < 1 || n_bins > grid.n_pixels())
    throw Error(Status::invalid_argument,
                "argument 'n_bins' must lie between 1 and the number of pixels, " +
                    std::to_string(grid.n_pixels()) + " (more bins than modes stay empty), got " +
                    std::to_string(n_bins));
}

// The bin of a mode of magnitude q in [0, q_max]. q/q_max lies in [0, 1], so the position is
// finite and at most n_bins on any grid and its conversion to an integer is defined; q_max
// itself lands on the upper edge and goes into the last bin.
std::int64_t bin_of(double q, double q_max, std::int64_t n_bins) {
  const double position = q_max > 0.0 ? q / q_max * static_cast<double>(n_bins) : 0.0;
  if (!(position < static_cast<double>(n_bins))) return n_bins - 1;
  return std::min(static_cast<std::int64_t>(position), n_bins - 1);
}

// Reductions take an int count: any number of bins is combined in pieces.
void combine_sums(const Reductions &reductions, std::vector<double> &values) {
  const std::size_t piece = static_cast<std::size_t>(std::numeric_limits<int>::max());
  for (std::size_t start = 0; start < values.size(); start += piece)
    reductions.combine_sums(values.data() + start,
                            static_cast<int>(std::min(piece, values.size() - start)));
}

void require_representable(double value, const char *what) {
  if (!std::isfinite(value))
    throw Error(Status::invalid_argument,
                std::string("array 'heights': the ") + what +
                    " of these heights on this grid overflows a double; rescale the heights or "
                    "the lengths");
}

}  // namespace

SurfaceStatistics surface_statistics(const Grid &grid, const double *heights) {
  // Heights scaled by 2^-e_h and wavevectors by 2^-e_q: the sums below stay finite (q^4 alone
  // reaches 1e600 on the finest grids), and the scales come back exactly in ldexp.
  const ScaledSpectrum h = scaled_spectrum(grid, heights);
  const int q_exponent = exponent_above(largest_wavevector(grid));
  const double q_factor = std::ldexp(1.0, -q_exponent);
  double sums[3] = {0.0, 0.0, 0.0};
  for_each_mode(grid, h, [&](double q, double power, double modes) {
    const double qs = q * q_factor;
    const double q2 = qs * qs;
    sums[0] += modes * power;
    sums[1] += modes * q2 * power;
    sums[2] += modes * q2 * q2 * power;
  });
  grid.reductions().combine_sums(sums, 3);
  SurfaceStatistics s;
  s.rms_height = std::ldexp(std::sqrt(sums[0]), h.exponent);
  s.rms_slope = std::ldexp(std::sqrt(sums[1]), h.exponent + q_exponent);
  s.rms_curvature = std::ldexp(std::sqrt(grid.dimension() == 2 ? sums[2] / 4.0 : sums[2]),
                               h.exponent + 2 * q_exponent);
  return s;
}

double rms_slope_within_box(const Grid &grid, const double *heights) {
  // Differences divided by 2^e (e above the largest height) are at most 2 in magnitude, so
  // their squares cannot overflow; the scale comes back exactly in ldexp.
  const std::int64_t nx = grid.nx(), ny = grid.ny(), n = grid.local_pixels();
  const std::int64_t rows = grid.local_rows();
  const int exponent = exponent_above(
      loops::maximum(grid.reductions(), n, [&](std::int64_t i) { return std::fabs(heights[i]); }));
  const double factor = std::ldexp(1.0, -exponent);
  // The row after this process's last one, where another process holds it.
  std::vector<double> next;
  const bool has_next = rows > 0 && grid.row_offset() + rows < ny;
  if (grid.partition() != nullptr) {
    next.resize(static_cast<std::size_t>(nx));
    grid.partition()->next_row(heights, nx, ny, next.data());
  }
  const double *below_last = has_next && !next.empty() ? next.data() : heights + n;
  // Sums of squared differences along x and along y, each over the pairs inside the box.
  const auto sums = loops::sums<2>(grid.reductions(), n, [&](std::int64_t k, double *sum) {
    const std::int64_t i = k % nx, j = k / nx;
    const double here = heights[k] * factor;
    const double along_x = i + 1 < nx ? heights[k + 1] * factor - here : 0.0;
    const double below = j + 1 < rows ? heights[k + nx] : (has_next ? below_last[i] : 0.0);
    const double along_y = j + 1 < rows || has_next ? below * factor - here : 0.0;
    sum[0] += along_x * along_x;
    sum[1] += along_y * along_y;
  });
  const double dx = grid.lx() / static_cast<double>(nx), dy = grid.ly() / static_cast<double>(ny);
  const double pairs_x = static_cast<double>((nx - 1) * ny);
  const double pairs_y = static_cast<double>(nx * (ny - 1));
  const double slope_x = pairs_x > 0.0 ? std::sqrt(sums[0] / pairs_x) / dx : 0.0;
  const double slope_y = pairs_y > 0.0 ? std::sqrt(sums[1] / pairs_y) / dy : 0.0;
  return std::ldexp(std::hypot(slope_x, slope_y), exponent);
}

void surface_statistics(const Grid &grid, const double *heights, double *rms_height,
                        double *rms_slope, double *rms_curvature) {
  const SurfaceStatistics s = surface_statistics(grid, heights);
  // On a distributed grid every process checks all three, whichever it asked for, so that
  // the processes fail together.
  const bool all = grid.partition() != nullptr;
  if (rms_height || all) require_representable(s.rms_height, "rms height");
  if (rms_slope || all) require_representable(s.rms_slope, "rms slope");
  if (rms_curvature || all) require_representable(s.rms_curvature, "rms curvature");
  if (rms_height) *rms_height = s.rms_height;
  if (rms_slope) *rms_slope = s.rms_slope;
  if (rms_curvature) *rms_curvature = s.rms_curvature;
}

void radial_power_spectrum(const Grid &grid, const double *heights, std::int64_t n_bins,
                           double *q, double *c) {
  require_bin_count(grid, n_bins);
  const double q_max = largest_wavevector(grid);
  const double width = q_max > 0.0 ? q_max / static_cast<double>(n_bins) : 1.0;
  // C(q) = A/(2 pi)^2 |h^_q|^2 in 2D and L/(2 pi) |h^_q|^2 in 1D: then the sum of C over the
  // modes times the area of one mode in q-space, (2 pi)^2/A or 2 pi/L, is the mean square.
  const double two_pi = 6.283185307179586476925286766559;
  const double density =
      grid.dimension() == 2 ? grid.area() / (two_pi * two_pi) : grid.lx() / two_pi;
  const ScaledSpectrum h = scaled_spectrum(grid, heights);
  const std::size_t bins = static_cast<std::size_t>(n_bins);
  std::vector<double> sum_q(bins, 0.0), sum_power(bins, 0.0), count(bins, 0.0);
  for_each_mode(grid, h, [&](double qn, double power, double modes) {
    const std::size_t k = static_cast<std::size_t>(bin_of(qn, q_max, n_bins));
    sum_q[k] += modes * qn;
    sum_power[k] += modes * power;
    count[k] += modes;
  });
  combine_sums(grid.reductions(), sum_q);
  combine_sums(grid.reductions(), sum_power);
  combine_sums(grid.reductions(), count);

  // Each bin's mean C, with the height scale 2^(2 e_h) put back, replaces its power sum. All
  // are checked before anything is written, so that a refusal leaves q and c as they were.
  for (std::size_t b = 0; b < bins; ++b) {
    sum_power[b] = count[b] > 0.0
                       ? std::ldexp(density * (sum_power[b] / count[b]), 2 * h.exponent)
                       : 0.0;
    require_representable(sum_power[b], "power spectrum C(q)");
  }
  for (std::size_t b = 0; b < bins; ++b) {
    q[b] = count[b] > 0.0 ? sum_q[b] / count[b] : (static_cast<double>(b) + 0.5) * width;
    c[b] = sum_power[b];
  }
}

}  // namespace asp
