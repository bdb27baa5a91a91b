// SPDX-License-Identifier: GPL-2.0-or-later
// A periodic 1D or 2D grid: sizes, box, spectral layouts and the FFT plans of its shapes.
//
// A 2D grid may be distributed over processes (create_distributed): each then holds a slab
// of rows, and every field and spectrum of the library on it is that slab (local_pixels(),
// local_spectral()); sizes, box and n_pixels() stay those of the whole grid.
//
// Grids are shared: every system made on a grid holds a reference, so that the handles of the
// C API may be destroyed in any order.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "core/aligned_field.hpp"
#include "core/fft_engine.hpp"
#include "core/partition.hpp"
#include "core/reductions.hpp"
#include "core/spectral_layout.hpp"
#include "core/threads.hpp"

namespace asp {

class Grid {
 public:
  // Checks its arguments (throws Error naming the bad one), including that the box can be
  // represented: area, pixel size and largest wavevector are finite, normal doubles. 1D grids
  // have ny = 1 and ly = 1, so that the pixel "area" lx/nx is the pixel length.
  static std::shared_ptr<Grid> create(int dimension, std::int64_t nx, std::int64_t ny,
                                      double lx, double ly);
  // A 2D grid whose rows are shared among the processes of `partition` (collective). Throws
  // Error naming the bad argument, on every process, also when the processes disagree on
  // the sizes or the box.
  static std::shared_ptr<Grid> create_distributed(std::shared_ptr<const Partition> partition,
                                                  std::int64_t nx, std::int64_t ny, double lx,
                                                  double ly);
  Grid(const Grid &) = delete;
  Grid &operator=(const Grid &) = delete;

  int dimension() const { return dimension_; }
  std::int64_t nx() const { return nx_; }
  std::int64_t ny() const { return ny_; }
  double lx() const { return lx_; }
  double ly() const { return ly_; }
  std::int64_t n_pixels() const { return nx_ * ny_; }
  double area() const { return lx_ * ly_; }
  double pixel_area() const {
    return (lx_ / static_cast<double>(nx_)) * (ly_ / static_cast<double>(ny_));
  }

  // This process's rows: all of them unless the grid is distributed.
  std::int64_t local_rows() const { return local_rows_; }
  std::int64_t row_offset() const { return row_offset_; }
  std::int64_t local_pixels() const { return nx_ * local_rows_; }
  // The partition of a distributed grid, null otherwise.
  const Partition *partition() const { return partition_.get(); }
  // A grid of half the pixels per axis (along x only in 1D) on the same box, distributed over
  // the same processes as this one, with its threads and FFT planning. Collective on a
  // distributed grid. The sizes must be even (Error(invalid_argument) otherwise).
  std::shared_ptr<Grid> halved() const;
  // Rows [first, first + count) of a field of the grid, of which `local` holds this process's
  // rows, into out[0..count * nx). Collective on a distributed grid, where each process asks
  // for the rows it needs; a copy on a serial one.
  void gather_rows(const double *local, std::int64_t first, std::int64_t count,
                   double *out) const;

  // The r2c half spectrum of the grid, kx in [0, nx/2]: all of it by rows on a serial grid;
  // on a distributed one this process's columns kx of it, transposed (core/partition.hpp).
  SpectralLayout half_spectrum() const;
  // A distributed grid's columns of the half spectrum that this process holds: kx in
  // [column_offset, column_offset + spectral_columns). 0 and 0 on a serial grid.
  std::int64_t column_offset() const { return column_offset_; }
  std::int64_t spectral_columns() const { return spectral_columns_; }
  // Columns kx in [first, first + count) of a distributed grid's half spectrum, ny entries
  // each, of which `local` holds this process's columns, into out[0..count * ny). Collective;
  // Error(unsupported) on a serial grid, whose spectrum is stored by rows, all of it local.
  void gather_spectral_columns(const Complex *local, std::int64_t first, std::int64_t count,
                               Complex *out) const;
  std::int64_t local_spectral() const {
    return partition_ ? spectral_columns_ * ny_ : (nx_ / 2 + 1) * local_rows_;
  }

  // Fields and spectra of this process's rows.
  Field make_field() const { return Field(static_cast<std::size_t>(local_pixels()), 0.0); }
  Spectrum make_spectrum() const { return Spectrum(static_cast<std::size_t>(local_spectral())); }

  // Plans, made on first use under the planner lock and kept for the grid's life, one per
  // (shape, kind): the grid's own shape and the padded one below (distributed with the
  // grid), or another one (serial grids only: those throw Error(unsupported) on a
  // distributed grid).
  const RealTransform &fft() const;
  const RealFft &real_fft(std::int64_t nx, std::int64_t ny) const;
  // The grid's box on the grid zero-padded to 2nx x 2ny (2D grids; distributed with the
  // grid), and the layout of its spectrum: the half spectrum of the padded grid, by rows on a
  // serial grid, on a distributed one this process's columns kx of it, transposed.
  const PaddedTransform &padded_fft() const;
  SpectralLayout padded_spectrum() const;
  void set_fft_planning(FftPlanning planning);
  FftPlanning fft_planning() const;
  // The threads of the grid's FFTs and of the loops of solves on it (default_threads() at
  // creation). Set before the plans exist (Error(invalid_state) after), >= 1.
  void set_threads(int threads);
  int threads() const;
  bool has_fft_plans() const;

  // Sums and maxima over the processes (the identity on a serial grid).
  const Reductions &reductions() const {
    return partition_ ? static_cast<const Reductions &>(*partition_) : reductions_;
  }

 private:
  Grid(int dimension, std::int64_t nx, std::int64_t ny, double lx, double ly);
  void require_serial(const char *what) const;

  int dimension_;
  std::int64_t nx_, ny_;
  double lx_, ly_;
  FftPlanning planning_ = FftPlanning::measure;
  int threads_;
  std::int64_t local_rows_, row_offset_ = 0;
  std::int64_t spectral_columns_ = 0, column_offset_ = 0;  // of a distributed grid
  std::int64_t padded_columns_ = 0, padded_column_offset_ = 0;
  std::shared_ptr<const Partition> partition_;
  mutable std::mutex plans_mutex_;
  mutable std::unique_ptr<RealTransform> distributed_plan_;
  mutable std::map<std::tuple<std::int64_t, std::int64_t>, std::unique_ptr<RealFft>> real_plans_;
  mutable std::unique_ptr<PaddedTransform> padded_plan_;
  LocalReductions reductions_;
};

}  // namespace asp
