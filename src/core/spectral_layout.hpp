// SPDX-License-Identifier: GPL-2.0-or-later
// One description of a stored spectrum: for every stored entry, its wavevector magnitude |q|
// and its Parseval weight (how many modes of the full spectrum it stands for). Every loop over
// Fourier modes in the library goes through for_each, so that odd and even sizes, the two
// packings and (later) distributed spectra are handled in one place.
//
// Packings:
//  - half_spectrum: FFTW's r2c output, complex entries S[kx + (nx/2+1)*ky], kx in [0, nx/2].
//    An entry stands for itself and its mirror (weight 2), except kx = 0 and, for even nx,
//    kx = nx/2 (weight 1).
//  - half_complex: FFTW's R2HC along each axis, nx*ny real coefficients, x fastest. Along an
//    axis of n points, index k carries frequency k (k <= n/2) or n - k (above); indices 0 and,
//    for even n, n/2 have weight 1, the others 2; a 2D entry's weight is the product. Then
//    sum_i f_i^2 = (1/N) sum_k weight_k c_k^2, N = nx*ny.
// In both, sum over entries of weight * |entry|^2 equals N times the sum of squares of the
// field (Parseval), and K~(|q|) is diagonal.
//
// On a distributed grid a layout describes this process's rows ky in [row_offset,
// row_offset + rows) (stored from index 0); its sums are over those rows, and the caller
// combines them across processes (Grid::reductions()).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/loops.hpp"

namespace asp {

enum class Packing { half_spectrum, half_complex };

class SpectralLayout {
 public:
  // A field of nx x ny pixels (ny = 1 in 1D) on a box lx x ly; of it, local_rows rows from
  // row_offset on (all of them by default).
  SpectralLayout(Packing packing, std::int64_t nx, std::int64_t ny, double lx, double ly,
                 std::int64_t local_rows = -1, std::int64_t row_offset = 0);

  Packing packing() const { return packing_; }
  // Number of stored entries (complex for half_spectrum, real for half_complex).
  std::int64_t size() const { return row_length_ * rows_; }
  // Whether stored entry k is the q = 0 mode (the mean), which only one process holds.
  bool is_mean(std::int64_t k) const { return k == 0 && row_offset_ == 0; }

  // sum over the stored entries of weight_k * value(k): Parseval sums, row by row so that the
  // inner loop vectorises (every entry of a row counts twice, minus the edge entries).
  template <class Value>
  double weighted_sum(Value &&value) const {
    // Whole rows per chunk, about loops::chunk_entries entries each (core/loops.hpp): on
    // several threads when the spectrum is large, with a sum that does not depend on them.
    const std::int64_t rows = std::max<std::int64_t>(1, loops::chunk_entries / row_length_);
    return loops::reduce_in_chunks(
        rows_, rows, loops::threads_for(size()), 0.0,
        [&](std::int64_t first, std::int64_t end, double &part) {
          double total = 0.0;
          for (std::int64_t local = first; local < end; ++local) {
            const std::int64_t row = row_length_ * local, ky = row_offset_ + local;
            double sum = 0.0;
#pragma omp simd reduction(+ : sum)
            for (std::int64_t kx = 0; kx < row_length_; ++kx) sum += value(row + kx);
            sum = 2.0 * sum - value(row);
            if (second_single_ > 0) sum -= value(row + second_single_);
            total += (packing_ == Packing::half_complex ? axis_weight(ky, ny_) : 1.0) * sum;
          }
          part = total;
        },
        [](double &total, double part) { total += part; });
  }

  // For the half_spectrum packing, weighted_sum(value) = 2 * (sum of value over all entries)
  // - single_entries_sum(value). A loop that computes its entries as it goes, and so cannot
  // evaluate one twice, sums over all entries itself and subtracts this afterwards.
  template <class Value>
  double single_entries_sum(Value &&value) const {
    double total = 0.0;
    for (std::int64_t local = 0; local < rows_; ++local) {
      const std::int64_t row = row_length_ * local;
      total += value(row);
      if (second_single_ > 0) total += value(row + second_single_);
    }
    return total;
  }

  // visit(k, q, weight) for every stored entry k, in storage order.
  template <class Visit>
  void for_each(Visit &&visit) const {
    for (std::int64_t local = 0; local < rows_; ++local) {
      const std::int64_t ky = row_offset_ + local;
      const double qy = wavenumber(axis_frequency(ky, ny_), ly_);
      const double wy = packing_ == Packing::half_complex ? axis_weight(ky, ny_) : 1.0;
      const std::int64_t row = row_length_ * local;
      for (std::int64_t kx = 0; kx < row_length_; ++kx) {
        const double qx = wavenumber(packing_ == Packing::half_complex ? axis_frequency(kx, nx_)
                                                                        : kx,
                                     lx_);
        visit(row + kx, std::sqrt(qx * qx + qy * qy), wy * axis_weight(kx, nx_));
      }
    }
  }

 private:
  // Frequency (number of periods over the box) carried by index k of an axis of n points,
  // for the full complex and for the half-complex packing alike: k up to n/2, n - k above.
  static std::int64_t axis_frequency(std::int64_t k, std::int64_t n) {
    return k <= n / 2 ? k : n - k;
  }
  // Index 0 and an even axis's Nyquist index stand for one mode; the others for two (in
  // r2c only along x; in R2HC along each axis).
  static double axis_weight(std::int64_t k, std::int64_t n) {
    return k == 0 || (n % 2 == 0 && 2 * k == n) ? 1.0 : 2.0;
  }
  static double wavenumber(std::int64_t frequency, double length) {
    return 6.283185307179586476925286766559 * static_cast<double>(frequency) / length;
  }

  Packing packing_;
  std::int64_t nx_, ny_;
  double lx_, ly_;
  std::int64_t rows_, row_offset_;
  std::int64_t row_length_;
  // Index in a row of the entry besides 0 that stands for one mode along x (the Nyquist
  // frequency of an even nx: last of an r2c row, middle of an R2HC row), or 0 if none.
  std::int64_t second_single_;
};

}  // namespace asp
