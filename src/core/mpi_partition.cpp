// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/mpi_partition.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "core/fft_planner.hpp"

namespace asp {
namespace {

// FFTW-MPI's own set-up, once, after FFTW's threads (fftw_mpi_init must follow
// fftw_init_threads). Call under the planner lock.
void fftw_mpi_ready() {
  static const bool ready = [] {
    fft_planner::threads_ready();
    fftw_mpi_init();
    return true;
  }();
  (void)ready;
}

// Row-major FFTW-MPI sizes of a grid of nx x ny: ny rows (distributed) of nx.
struct Sizes {
  ptrdiff_t rows, columns, complex_columns;
};
Sizes sizes_of(std::int64_t nx, std::int64_t ny) {
  return {static_cast<ptrdiff_t>(ny), static_cast<ptrdiff_t>(nx),
          static_cast<ptrdiff_t>(nx / 2 + 1)};
}

// FFTW-MPI's r2c and c2r of a distributed grid, from this process's rows to its columns of
// the transposed half spectrum (FFTW_MPI_TRANSPOSED_OUT) and back (_IN): a 2D transform then
// needs one global transpose each way instead of two. FFTW-MPI wants the real rows padded to
// 2 (nx/2 + 1) and room of its own choosing (alloc_local complex numbers) for the transpose;
// the library's fields are unpadded, so each transform copies through one buffer of the
// plan's and runs in place there. Executed by one thread per process at a time, as every
// collective call of the library.
class MpiRealFft final : public RealTransform {
 public:
  MpiRealFft(std::int64_t nx, std::int64_t ny, MPI_Comm communicator, FftPlanning planning,
             int threads)
      : nx_(nx) {
    const Sizes s = sizes_of(nx, ny);
    std::lock_guard<std::mutex> lock(fft_planner::mutex());
    fftw_mpi_ready();
    ptrdiff_t local_rows = 0, offset = 0, local_columns = 0, column_offset = 0;
    const ptrdiff_t alloc =
        fftw_mpi_local_size_2d_transposed(s.rows, s.complex_columns, communicator, &local_rows,
                                          &offset, &local_columns, &column_offset);
    rows_ = local_rows;
    spectral_ = static_cast<std::int64_t>(local_columns) * ny;
    buffer_ = Spectrum(static_cast<std::size_t>(std::max<ptrdiff_t>(alloc, 1)));
    auto *c = reinterpret_cast<fftw_complex *>(buffer_.data());
    auto *r = reinterpret_cast<double *>(buffer_.data());
    const fft_planner::PlannerThreads planner_threads(threads, nx * local_rows);
    const unsigned flags = fft_planner::flags_of(planning);
    r2c_ = fftw_mpi_plan_dft_r2c_2d(s.rows, s.columns, r, c, communicator,
                                    flags | FFTW_MPI_TRANSPOSED_OUT);
    c2r_ = fftw_mpi_plan_dft_c2r_2d(s.rows, s.columns, c, r, communicator,
                                    flags | FFTW_MPI_TRANSPOSED_IN);
    if (r2c_ == nullptr || c2r_ == nullptr) {
      if (r2c_ != nullptr) fftw_destroy_plan(r2c_);
      if (c2r_ != nullptr) fftw_destroy_plan(c2r_);
      throw Error(Status::fft, "FFTW-MPI could not plan a transform of this grid size");
    }
  }
  ~MpiRealFft() override {
    // After MPI_Finalize (a handle released late, at a program's or interpreter's exit) the
    // plans' communicators are gone: they are left to the process's end.
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (finalized) return;
    std::lock_guard<std::mutex> lock(fft_planner::mutex());
    fftw_destroy_plan(r2c_);
    fftw_destroy_plan(c2r_);
  }

  void forward(const double *real, Complex *spectrum) const override {
    const std::int64_t padded = 2 * (nx_ / 2 + 1);
    auto *r = reinterpret_cast<double *>(buffer_.data());
    for (std::int64_t j = 0; j < rows_; ++j)
      std::copy(real + nx_ * j, real + nx_ * (j + 1), r + padded * j);
    fftw_execute(r2c_);
    std::copy(buffer_.begin(), buffer_.begin() + spectral_, spectrum);
  }

  void backward(Complex *spectrum, double *real) const override {
    const std::int64_t padded = 2 * (nx_ / 2 + 1);
    std::copy(spectrum, spectrum + spectral_, buffer_.begin());
    fftw_execute(c2r_);
    const auto *r = reinterpret_cast<const double *>(buffer_.data());
    for (std::int64_t j = 0; j < rows_; ++j)
      std::copy(r + padded * j, r + padded * j + nx_, real + nx_ * j);
  }

 private:
  std::int64_t nx_, rows_ = 0, spectral_ = 0;  // rows, and entries of the spectral columns
  mutable Spectrum buffer_;
  fftw_plan r2c_ = nullptr, c2r_ = nullptr;
};

class MpiPartition final : public Partition {
 public:
  explicit MpiPartition(MPI_Comm communicator) {
    MPI_Comm_dup(communicator, &communicator_);
    MPI_Comm_rank(communicator_, &rank_);
    MPI_Comm_size(communicator_, &ranks_);
  }
  ~MpiPartition() override {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Comm_free(&communicator_);
  }

  int rank() const override { return rank_; }
  int ranks() const override { return ranks_; }

  Slab slab(std::int64_t nx, std::int64_t ny) const override {
    const Sizes s = sizes_of(nx, ny);
    ptrdiff_t rows = 0, offset = 0, columns = 0, column_offset = 0;
    {
      std::lock_guard<std::mutex> lock(fft_planner::mutex());
      fftw_mpi_ready();
      fftw_mpi_local_size_2d_transposed(s.rows, s.complex_columns, communicator_, &rows, &offset,
                                        &columns, &column_offset);
    }
    // FFTW gives a process without rows (columns) an offset of its own choosing; they end at
    // ny (nx/2 + 1).
    if (rows == 0) offset = s.rows;
    if (columns == 0) column_offset = s.complex_columns;
    return {static_cast<std::int64_t>(rows), static_cast<std::int64_t>(offset),
            static_cast<std::int64_t>(columns), static_cast<std::int64_t>(column_offset)};
  }

  std::unique_ptr<RealTransform> real_transform(std::int64_t nx, std::int64_t ny,
                                                FftPlanning planning, int threads) const override {
    return std::make_unique<MpiRealFft>(nx, ny, communicator_, planning, threads);
  }

  // Every process's values, then the totals in rank order: the same bits on every process
  // whatever the collective algorithm of the MPI library.
  void combine_sums(double *values, int count) const override {
    combine(values, count, [](double &total, double v) { total += v; });
  }
  void combine_maxima(double *values, int count) const override {
    // A NaN anywhere stays NaN (v > NaN is false, so NaN is kept; NaN > total is false, so
    // it is taken explicitly).
    combine(values, count, [](double &total, double v) {
      if (v > total || v != v) total = v;
    });
  }

  bool select_smallest(double &key, double *payload, int count) const override {
    const std::size_t width = static_cast<std::size_t>(count) + 1;
    std::vector<double> mine(width), all(width * static_cast<std::size_t>(ranks_));
    mine[0] = key;
    std::copy(payload, payload + count, mine.begin() + 1);
    MPI_Allgather(mine.data(), count + 1, MPI_DOUBLE, all.data(), count + 1, MPI_DOUBLE,
                  communicator_);
    int winner = 0;
    for (int r = 1; r < ranks_; ++r)
      if (all[width * static_cast<std::size_t>(r)] < all[width * static_cast<std::size_t>(winner)])
        winner = r;
    const double *chosen = all.data() + width * static_cast<std::size_t>(winner);
    key = chosen[0];
    std::copy(chosen + 1, chosen + width, payload);
    return winner == rank_;
  }

  void agree(const Error *failure) const override {
    const int status = failure != nullptr ? static_cast<int>(failure->status()) : 0;
    std::vector<int> statuses(static_cast<std::size_t>(ranks_));
    MPI_Allgather(&status, 1, MPI_INT, statuses.data(), 1, MPI_INT, communicator_);
    const auto first = std::find_if(statuses.begin(), statuses.end(), [](int s) { return s != 0; });
    if (first == statuses.end()) return;
    const int root = static_cast<int>(first - statuses.begin());
    std::string message = rank_ == root ? failure->what() : std::string();
    int length = static_cast<int>(message.size());
    MPI_Bcast(&length, 1, MPI_INT, root, communicator_);
    message.resize(static_cast<std::size_t>(length));
    MPI_Bcast(&message[0], length, MPI_CHAR, root, communicator_);
    throw Error(static_cast<Status>(*first), "on process " + std::to_string(root) + " of " +
                                                 std::to_string(ranks_) + ": " + message);
  }

  int first_differing(const double *values, int count, double *theirs) const override {
    const auto width = static_cast<std::size_t>(count);
    std::vector<double> all(width * static_cast<std::size_t>(ranks_));
    MPI_Allgather(values, count, MPI_DOUBLE, all.data(), count, MPI_DOUBLE, communicator_);
    for (int r = 1; r < ranks_; ++r) {
      const double *other = all.data() + width * static_cast<std::size_t>(r);
      if (std::memcmp(other, all.data(), sizeof(double) * width) != 0) {
        std::copy(other, other + width, theirs);
        return r;
      }
    }
    return -1;
  }

 private:
  template <class Fold>
  void combine(double *values, int count, Fold fold) const {
    if (count <= 0) return;
    std::vector<double> all(static_cast<std::size_t>(count) * static_cast<std::size_t>(ranks_));
    MPI_Allgather(values, count, MPI_DOUBLE, all.data(), count, MPI_DOUBLE, communicator_);
    for (int k = 0; k < count; ++k) {
      double total = all[static_cast<std::size_t>(k)];
      for (int r = 1; r < ranks_; ++r) fold(total, all[static_cast<std::size_t>(r) * count + k]);
      values[k] = total;
    }
  }

  MPI_Comm communicator_ = MPI_COMM_NULL;
  int rank_ = 0, ranks_ = 1;
};

}  // namespace

std::shared_ptr<const Partition> make_mpi_partition(MPI_Comm communicator) {
  return std::make_shared<MpiPartition>(communicator);
}

}  // namespace asp
