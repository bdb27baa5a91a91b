#include "physics/surface_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {
namespace {

// Calls visit(|q|, |h^_q|^2, modes) for every non-zero entry of the half spectrum, h^ the DFT
// divided by N, modes the number of full-spectrum modes the entry stands for (1 or 2).
template <class Visit>
void for_each_mode(const Grid &grid, const double *heights, Visit visit) {
  // FFTW plans run only on the library's own aligned fields: the caller's array may start
  // anywhere (a NumPy slice, a Fortran section), so it is copied first.
  Field h = grid.make_field();
  loops::for_each(grid.n_pixels(), [&](std::int64_t i) { h[i] = heights[i]; });
  Spectrum s = grid.make_spectrum();
  grid.fft().forward(h.data(), s.data());
  const double n = static_cast<double>(grid.n_pixels());
  grid.half_spectrum().for_each([&](std::int64_t k, double q, double weight) {
    if (k == 0) return;  // the mean, stored first
    visit(q, std::norm(s[static_cast<std::size_t>(k)]) / (n * n), weight);
  });
}

// The largest |q| of the grid's half spectrum (0 for a single pixel).
double largest_wavevector(const Grid &grid) {
  double q_max = 0.0;
  grid.half_spectrum().for_each(
      [&](std::int64_t, double q, double) { q_max = std::fmax(q_max, q); });
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

}  // namespace

SurfaceStatistics surface_statistics(const Grid &grid, const double *heights) {
  double sums[3] = {0.0, 0.0, 0.0};
  for_each_mode(grid, heights, [&](double q, double power, double modes) {
    const double q2 = q * q;
    sums[0] += modes * power;
    sums[1] += modes * q2 * power;
    sums[2] += modes * q2 * q2 * power;
  });
  grid.reductions().combine_sums(sums, 3);
  SurfaceStatistics s;
  s.rms_height = std::sqrt(sums[0]);
  s.rms_slope = std::sqrt(sums[1]);
  s.rms_curvature = std::sqrt(grid.dimension() == 2 ? sums[2] / 4.0 : sums[2]);
  return s;
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
  const std::size_t bins = static_cast<std::size_t>(n_bins);
  std::vector<double> sum_q(bins, 0.0), sum_c(bins, 0.0), count(bins, 0.0);
  for_each_mode(grid, heights, [&](double qn, double power, double modes) {
    const std::size_t k = static_cast<std::size_t>(bin_of(qn, q_max, n_bins));
    sum_q[k] += modes * qn;
    sum_c[k] += modes * density * power;
    count[k] += modes;
  });
  combine_sums(grid.reductions(), sum_q);
  combine_sums(grid.reductions(), sum_c);
  combine_sums(grid.reductions(), count);
  for (std::size_t b = 0; b < bins; ++b) {
    if (count[b] > 0.0) {
      q[b] = sum_q[b] / count[b];
      c[b] = sum_c[b] / count[b];
    } else {
      q[b] = (static_cast<double>(b) + 0.5) * width;
      c[b] = 0.0;
    }
  }
}

}  // namespace asp
