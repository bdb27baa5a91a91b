// SPDX-License-Identifier: GPL-2.0-or-later
// How a 2D grid is shared among the processes of a distributed run: each owns a slab of
// whole rows (y), all nx pixels of each, and a slab of whole columns (kx) of the half
// spectrum, which FFTW-MPI leaves transposed (Packing::transposed_half_spectrum: a
// transposed transform skips one of the two global transposes of a 2D FFT each way). Sums and
// maxima over the slabs become totals through the partition (it is the grid's Reductions),
// its transforms are FFTW-MPI's, and calls that fail on some processes fail on all of them
// through agree(). The one implementation is over MPI (core/mpi_partition.hpp, built with
// ASPERITY_MPI); nothing else in the library knows about MPI.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "core/fft_engine.hpp"
#include "core/reductions.hpp"

namespace asp {

// Rows [offset, offset + rows) of the grid, and columns [column_offset, column_offset +
// columns) of its half spectrum.
struct Slab {
  std::int64_t rows = 0;
  std::int64_t offset = 0;
  std::int64_t columns = 0;
  std::int64_t column_offset = 0;
};

class Partition : public Reductions {
 public:
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // The slab this process owns of a grid of nx x ny: the rows and spectral columns its
  // transforms hold.
  virtual Slab slab(std::int64_t nx, std::int64_t ny) const = 0;
  // The grid's transform on the slabs, from rows to transposed columns and back. Collective.
  virtual std::unique_ptr<RealTransform> real_transform(std::int64_t nx, std::int64_t ny,
                                                        FftPlanning planning,
                                                        int threads) const = 0;
  // The transform of the grid's box zero-padded to 2nx x 2ny (a free substrate's), from this
  // process's rows of the box (or of the padded surface) to its columns of the padded half
  // spectrum, the columns of slab(2nx, 2ny), and back (PaddedTransform). Collective.
  virtual std::unique_ptr<PaddedTransform> padded_transform(std::int64_t nx, std::int64_t ny,
                                                            FftPlanning planning,
                                                            int threads) const = 0;
  // Collective: the row just below this process's slab of a grid of nx x ny, row offset +
  // rows, from the process that holds it, into row[0..nx); left alone when the slab is empty
  // or ends the grid. For differences between neighbouring rows across slabs.
  virtual void next_row(const double *field, std::int64_t nx, std::int64_t ny,
                        double *row) const = 0;
  // Collective: rows [first, first + count) of a field of `width` doubles a row, whose rows
  // are shared among the processes (this one holding rows [offset, offset + rows) of it, in
  // `mine`), into out[0..count * width). Each process asks for the rows it needs, which the
  // processes together hold. For fields that move between grids of other slabs (the
  // restriction and prolongation of nested grids).
  virtual void gather_rows(const double *mine, std::int64_t offset, std::int64_t rows,
                           std::int64_t width, std::int64_t first, std::int64_t count,
                           double *out) const = 0;
  // Collective: each process says whether its part of a call failed (failure is null if
  // not). If any did, every process throws the Error of the lowest failing rank, its
  // message prefixed with that rank; otherwise it returns.
  virtual void agree(const Error *failure) const = 0;
  // Collective: the first process whose values[0..count) differ from process 0's (not the
  // same bits), its values copied into theirs; -1 if all hold the same.
  virtual int first_differing(const double *values, int count, double *theirs) const = 0;
};

}  // namespace asp
