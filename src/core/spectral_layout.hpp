// SPDX-License-Identifier: GPL-2.0-or-later
// One description of a stored spectrum: for every stored entry, its wavevector magnitude |q|
// and its Parseval weight (how many modes of the full spectrum it stands for). Every loop over
// Fourier modes in the library goes through for_each, so that odd and even sizes, the
// packings and distributed spectra are handled in one place.
//
// Packings:
//  - half_spectrum: FFTW's r2c output, complex entries S[kx + (nx/2+1)*ky], kx in [0, nx/2].
//    An entry stands for itself and its mirror (weight 2), except kx = 0 and, for even nx,
//    kx = nx/2 (weight 1).
//  - transposed_half_spectrum: the same entries stored column by column, S[ky + ny*kx], as
//    FFTW-MPI's transposed r2c output leaves them (a distributed grid's spectrum: each
//    process holds columns kx of it).
// In both, sum over entries of weight * |entry|^2 equals N times the sum of squares of the
// field (Parseval), and K~(|q|) is diagonal.
//
// A layout stores lines: rows (ky) of the row packings, columns (kx) of the transposed one. On
// a distributed grid it describes this process's lines [first_line, first_line + lines)
// (stored from index 0); its sums are over those, and the caller combines them across
// processes (Grid::reductions()).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/loops.hpp"

namespace asp {

enum class Packing { half_spectrum, transposed_half_spectrum };

class SpectralLayout {
 public:
  // A field of nx x ny pixels (ny = 1 in 1D) on a box lx x ly; of its spectrum, `lines`
  // lines from first_line on (all of them by default).
  SpectralLayout(Packing packing, std::int64_t nx, std::int64_t ny, double lx, double ly,
                 std::int64_t lines = -1, std::int64_t first_line = 0);

  Packing packing() const { return packing_; }
  // Number of stored (complex) entries.
  std::int64_t size() const { return line_length_ * lines_; }
  // Whether stored entry k is the q = 0 mode (the mean), which only one process holds.
  bool is_mean(std::int64_t k) const { return k == 0 && first_line_ == 0; }

  // sum over the stored entries of weight_k * value(k): Parseval sums, line by line so that
  // the inner loop vectorises.
  template <class Value>
  double weighted_sum(Value &&value) const {
    // Whole lines per chunk, about loops::chunk_entries entries each (core/loops.hpp): on
    // several threads when the spectrum is large, with a sum that does not depend on them.
    const std::int64_t per_chunk = std::max<std::int64_t>(1, loops::chunk_entries / line_length_);
    return loops::reduce_in_chunks(
        lines_, per_chunk, loops::threads_for(size()), 0.0,
        [&](std::int64_t first, std::int64_t end, double &part) {
          double total = 0.0;
          for (std::int64_t local = first; local < end; ++local) {
            const std::int64_t start = line_length_ * local, line = first_line_ + local;
            double sum = 0.0;
#pragma omp simd reduction(+ : sum)
            for (std::int64_t k = 0; k < line_length_; ++k) sum += value(start + k);
            if (packing_ == Packing::transposed_half_spectrum) {
              // A column's entries all share its kx, and so its weight.
              total += axis_weight(line, nx_) * sum;
              continue;
            }
            // Every entry of a row counts twice, minus the edge entries.
            sum = 2.0 * sum - value(start);
            if (second_single_ > 0) sum -= value(start + second_single_);
            total += sum;
          }
          part = total;
        },
        [](double &total, double part) { total += part; });
  }

  // For the half spectra, weighted_sum(value) = 2 * (sum of value over all entries)
  // - single_entries_sum(value). A loop that computes its entries as it goes, and so cannot
  // evaluate one twice, sums over all entries itself and subtracts this afterwards.
  template <class Value>
  double single_entries_sum(Value &&value) const {
    double total = 0.0;
    if (packing_ == Packing::transposed_half_spectrum) {
      // The columns kx = 0 and, for even nx, kx = nx/2, where this process holds them.
      for (std::int64_t local = 0; local < lines_; ++local) {
        if (axis_weight(first_line_ + local, nx_) != 1.0) continue;
        for (std::int64_t k = 0; k < line_length_; ++k) total += value(line_length_ * local + k);
      }
      return total;
    }
    for (std::int64_t local = 0; local < lines_; ++local) {
      const std::int64_t start = line_length_ * local;
      total += value(start);
      if (second_single_ > 0) total += value(start + second_single_);
    }
    return total;
  }

  // visit(k, q, weight) for every stored entry k, in storage order.
  template <class Visit>
  void for_each(Visit &&visit) const {
    if (packing_ == Packing::transposed_half_spectrum) {
      for (std::int64_t local = 0; local < lines_; ++local) {
        const std::int64_t kx = first_line_ + local, start = line_length_ * local;
        const double qx = wavenumber(kx, lx_), wx = axis_weight(kx, nx_);
        for (std::int64_t ky = 0; ky < ny_; ++ky) {
          const double qy = wavenumber(axis_frequency(ky, ny_), ly_);
          visit(start + ky, std::sqrt(qx * qx + qy * qy), wx);
        }
      }
      return;
    }
    for (std::int64_t local = 0; local < lines_; ++local) {
      const std::int64_t ky = first_line_ + local;
      const double qy = wavenumber(axis_frequency(ky, ny_), ly_);
      const std::int64_t start = line_length_ * local;
      for (std::int64_t kx = 0; kx < line_length_; ++kx) {
        const double qx = wavenumber(kx, lx_);
        visit(start + kx, std::sqrt(qx * qx + qy * qy), axis_weight(kx, nx_));
      }
    }
  }

  // visit(k, kx, ky) for every stored entry k, in storage order, with its integer wavevector
  // (periods over the box): kx in [0, nx/2], ky signed, in (-ny/2, ny/2].
  template <class Visit>
  void for_each_wavevector(Visit &&visit) const {
    for (std::int64_t local = 0; local < lines_; ++local) {
      const std::int64_t line = first_line_ + local, start = line_length_ * local;
      for (std::int64_t k = 0; k < line_length_; ++k) {
        const bool by_columns = packing_ == Packing::transposed_half_spectrum;
        visit(start + k, by_columns ? line : k, signed_frequency(by_columns ? k : line, ny_));
      }
    }
  }

  // The stored entry of the integer wavevector (kx, ky) (ky signed, as above), whose line
  // (its ky by rows, its kx by columns) this layout holds.
  std::int64_t entry(std::int64_t kx, std::int64_t ky) const {
    const std::int64_t row = ky < 0 ? ky + ny_ : ky;
    return packing_ == Packing::transposed_half_spectrum ? (kx - first_line_) * ny_ + row
                                                          : (row - first_line_) * line_length_ + kx;
  }

 private:
  // The signed frequency of index k of an axis of n points stored in full.
  static std::int64_t signed_frequency(std::int64_t k, std::int64_t n) {
    return 2 * k <= n ? k : k - n;
  }
  // Frequency (number of periods over the box) carried by index k of an axis of n points
  // stored in full (y of the row packings): k up to n/2, n - k above.
  static std::int64_t axis_frequency(std::int64_t k, std::int64_t n) {
    return k <= n / 2 ? k : n - k;
  }
  // Index 0 and an even axis's Nyquist index stand for one mode; the others for two (r2c
  // halves the spectrum along x only).
  static double axis_weight(std::int64_t k, std::int64_t n) {
    return k == 0 || (n % 2 == 0 && 2 * k == n) ? 1.0 : 2.0;
  }
  static double wavenumber(std::int64_t frequency, double length) {
    return 6.283185307179586476925286766559 * static_cast<double>(frequency) / length;
  }

  Packing packing_;
  std::int64_t nx_, ny_;
  double lx_, ly_;
  std::int64_t lines_, first_line_;
  std::int64_t line_length_;
  // Index in a row of the entry besides 0 that stands for one mode along x (the Nyquist
  // frequency of an even nx, the last of an r2c row), or 0 if none.
  std::int64_t second_single_;
};

}  // namespace asp
