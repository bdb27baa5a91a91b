// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/mpi_partition.hpp"

#include <fftw3-mpi.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "core/fft_planner.hpp"
#include "core/transform_clock.hpp"

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
    const transform_clock::Scope timed;
    const std::int64_t padded = 2 * (nx_ / 2 + 1);
    auto *r = reinterpret_cast<double *>(buffer_.data());
    for (std::int64_t j = 0; j < rows_; ++j)
      std::copy(real + nx_ * j, real + nx_ * (j + 1), r + padded * j);
    fftw_execute(r2c_);
    std::copy(buffer_.begin(), buffer_.begin() + spectral_, spectrum);
  }

  void backward(Complex *spectrum, double *real) const override {
    const transform_clock::Scope timed;
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

// The transform of a distributed grid's box zero-padded to 2nx x 2ny (a free substrate's):
// FFTW's serial plans along x on this process's rows and along y on its spectral columns, with
// one global transpose between them each way (MPI_Alltoallv). A process holds the padded rows
// of its box rows and the rows ny further down, so that its part of the padded surface lies
// with its part of the box; FFTW-MPI's contiguous slabs of the padded grid cannot say that.
// The spectrum is transposed like the grid's: this process's columns kx, those of
// slab(2nx, 2ny), each with its 2ny entries ky. Forward, only the box's rows are transformed
// along x and sent (the rest is zero); backward, only they are received and transformed.
// Executed by one thread per process at a time, as every collective call of the library.
class MpiPaddedFft final : public PaddedTransform {
 public:
  MpiPaddedFft(std::int64_t nx, std::int64_t ny, MPI_Comm communicator, const Slab &box,
               const Slab &padded, FftPlanning planning, int threads)
      : nx_(nx), ny_(ny), rows_(box.rows), columns_(padded.columns), communicator_(communicator) {
    int ranks = 1;
    MPI_Comm_size(communicator, &ranks);
    // Every process's rows and spectral columns.
    const std::int64_t mine[4] = {box.rows, box.offset, padded.columns, padded.column_offset};
    std::vector<std::int64_t> all(4 * static_cast<std::size_t>(ranks));
    MPI_Allgather(mine, 4, MPI_INT64_T, all.data(), 4, MPI_INT64_T, communicator);
    for (int r = 0; r < ranks; ++r) {
      const std::int64_t *theirs = all.data() + 4 * r;
      row_counts_.push_back(theirs[0]);
      row_offsets_.push_back(theirs[1]);
      column_counts_.push_back(theirs[2]);
      column_offsets_.push_back(theirs[3]);
    }
    // MPI counts are ints (of complex numbers here): the most one process sends or receives.
    const std::int64_t largest =
        std::max(2 * rows_ * (nx + 1), 2 * ny * columns_);
    if (largest > std::numeric_limits<int>::max())
      throw Error(Status::unsupported,
                  "argument 'grid': the padded transform of a free substrate would exchange " +
                      std::to_string(largest) + " complex numbers between two processes at "
                      "once, more than MPI counts; use more processes");
    row_spectra_ = Spectrum(static_cast<std::size_t>(std::max<std::int64_t>(2 * rows_ * (nx + 1), 1)));
    send_ = Spectrum(static_cast<std::size_t>(std::max<std::int64_t>(largest, 1)));
    receive_ = Spectrum(static_cast<std::size_t>(std::max<std::int64_t>(largest, 1)));

    // Plans on scratch arrays (FFTW_MEASURE overwrites what it is given), one process's own:
    // nothing here is planned together.
    const int width = static_cast<int>(2 * nx), height = static_cast<int>(2 * ny);
    const int half = static_cast<int>(nx + 1);
    const unsigned flags = fft_planner::flags_of(planning);
    std::lock_guard<std::mutex> lock(fft_planner::mutex());
    const fft_planner::PlannerThreads planner_threads(threads, 4 * nx * std::max(rows_, columns_));
    if (rows_ > 0) {
      Field real(static_cast<std::size_t>(2 * nx * rows_));
      auto *c = reinterpret_cast<fftw_complex *>(row_spectra_.data());
      const int count = static_cast<int>(rows_);
      rows_r2c_ = fftw_plan_many_dft_r2c(1, &width, count, real.data(), nullptr, 1, width, c,
                                         nullptr, 1, half, flags);
      rows_c2r_ = fftw_plan_many_dft_c2r(1, &width, count, c, nullptr, 1, half, real.data(),
                                         nullptr, 1, width, flags | FFTW_DESTROY_INPUT);
    }
    if (columns_ > 0) {
      auto *c = reinterpret_cast<fftw_complex *>(send_.data());
      const int count = static_cast<int>(columns_);
      columns_forward_ = fftw_plan_many_dft(1, &height, count, c, nullptr, 1, height, c, nullptr,
                                            1, height, FFTW_FORWARD, flags);
      columns_backward_ = fftw_plan_many_dft(1, &height, count, c, nullptr, 1, height, c, nullptr,
                                             1, height, FFTW_BACKWARD, flags);
    }
    if ((rows_ > 0 && (rows_r2c_ == nullptr || rows_c2r_ == nullptr)) ||
        (columns_ > 0 && (columns_forward_ == nullptr || columns_backward_ == nullptr))) {
      destroy_plans();
      throw Error(Status::fft, "FFTW could not plan a transform of this grid size");
    }
  }
  ~MpiPaddedFft() override {
    std::lock_guard<std::mutex> lock(fft_planner::mutex());
    destroy_plans();
  }

  void forward(const double *box, Complex *spectrum, double *rows) const override {
    const transform_clock::Scope timed;
    const std::int64_t width = 2 * nx_;
    for (std::int64_t j = 0; j < rows_; ++j) {
      std::copy(box + nx_ * j, box + nx_ * (j + 1), rows + width * j);
      std::fill(rows + width * j + nx_, rows + width * (j + 1), 0.0);
    }
    rows_along_x(rows, 1);
    to_columns(spectrum, 1);
    columns_along_y(spectrum, columns_forward_);
  }

  void backward(Complex *spectrum, double *box, double *rows) const override {
    const transform_clock::Scope timed;
    const std::int64_t width = 2 * nx_;
    columns_along_y(spectrum, columns_backward_);
    to_rows(spectrum, 1);
    rows_back_along_x(rows, 1);
    for (std::int64_t j = 0; j < rows_; ++j)
      std::copy(rows + width * j, rows + width * j + nx_, box + nx_ * j);
  }

  void surface_forward(const double *surface, Complex *spectrum) const override {
    const transform_clock::Scope timed;
    rows_along_x(surface, 2);
    to_columns(spectrum, 2);
    columns_along_y(spectrum, columns_forward_);
  }

  void surface_backward(Complex *spectrum, double *surface) const override {
    const transform_clock::Scope timed;
    columns_along_y(spectrum, columns_backward_);
    to_rows(spectrum, 2);
    rows_back_along_x(surface, 2);
  }

 private:
  // The x transforms of `sets` sets of this process's rows (1: the box's; 2: and those ny
  // further down), into row_spectra_ and back, each set at offsets that keep the alignment
  // the plans were made for.
  void rows_along_x(const double *rows, int sets) const {
    if (rows_ == 0) return;
    auto *in = const_cast<double *>(rows);  // an out-of-place r2c preserves its input
    for (int set = 0; set < sets; ++set)
      fftw_execute_dft_r2c(rows_r2c_, in + 2 * nx_ * rows_ * set,
                           reinterpret_cast<fftw_complex *>(row_spectra_.data()) +
                               (nx_ + 1) * rows_ * set);
  }
  void rows_back_along_x(double *rows, int sets) const {
    if (rows_ == 0) return;
    for (int set = 0; set < sets; ++set)
      fftw_execute_dft_c2r(rows_c2r_,
                           reinterpret_cast<fftw_complex *>(row_spectra_.data()) +
                               (nx_ + 1) * rows_ * set,
                           rows + 2 * nx_ * rows_ * set);
  }
  void columns_along_y(Complex *spectrum, fftw_plan plan) const {
    if (columns_ == 0) return;
    auto *s = reinterpret_cast<fftw_complex *>(spectrum);
    fftw_execute_dft(plan, s, s);
  }

  // The global transposes. Row spectra (set, row j, kx) of every process to this process's
  // columns of the spectrum, S[ky + 2ny (kx - first column)], padded row ky = set ny + the
  // owner's offset + j; rows beyond the box, when only the box is sent, zero. And back.
  void to_columns(Complex *spectrum, int sets) const {
    const int ranks = static_cast<int>(row_counts_.size());
    std::vector<int> send_counts(ranks), send_offsets(ranks), receive_counts(ranks),
        receive_offsets(ranks);
    Complex *send = send_.data();
    std::int64_t at = 0;
    for (int d = 0; d < ranks; ++d) {
      send_offsets[d] = static_cast<int>(at);
      for (int set = 0; set < sets; ++set)
        for (std::int64_t j = 0; j < rows_; ++j) {
          const Complex *row =
              row_spectra_.data() + (nx_ + 1) * (rows_ * set + j) + column_offsets_[d];
          std::copy(row, row + column_counts_[d], send + at);
          at += column_counts_[d];
        }
      send_counts[d] = static_cast<int>(at - send_offsets[d]);
    }
    at = 0;
    for (int s = 0; s < ranks; ++s) {
      receive_offsets[s] = static_cast<int>(at);
      receive_counts[s] = static_cast<int>(sets * row_counts_[s] * columns_);
      at += receive_counts[s];
    }
    MPI_Alltoallv(send, send_counts.data(), send_offsets.data(), MPI_C_DOUBLE_COMPLEX,
                  receive_.data(), receive_counts.data(), receive_offsets.data(),
                  MPI_C_DOUBLE_COMPLEX, communicator_);
    const std::int64_t height = 2 * ny_;
    if (sets == 1)
      for (std::int64_t c = 0; c < columns_; ++c)
        std::fill(spectrum + height * c + ny_, spectrum + height * (c + 1), Complex(0.0, 0.0));
    const Complex *received = receive_.data();
    for (int s = 0; s < ranks; ++s)
      for (int set = 0; set < sets; ++set)
        for (std::int64_t j = 0; j < row_counts_[s]; ++j) {
          const std::int64_t ky = ny_ * set + row_offsets_[s] + j;
          for (std::int64_t c = 0; c < columns_; ++c) spectrum[height * c + ky] = *received++;
        }
  }

  void to_rows(const Complex *spectrum, int sets) const {
    const int ranks = static_cast<int>(row_counts_.size());
    std::vector<int> send_counts(ranks), send_offsets(ranks), receive_counts(ranks),
        receive_offsets(ranks);
    const std::int64_t height = 2 * ny_;
    Complex *send = send_.data();
    std::int64_t at = 0;
    for (int d = 0; d < ranks; ++d) {
      send_offsets[d] = static_cast<int>(at);
      for (int set = 0; set < sets; ++set)
        for (std::int64_t j = 0; j < row_counts_[d]; ++j) {
          const std::int64_t ky = ny_ * set + row_offsets_[d] + j;
          for (std::int64_t c = 0; c < columns_; ++c) send[at++] = spectrum[height * c + ky];
        }
      send_counts[d] = static_cast<int>(at - send_offsets[d]);
    }
    at = 0;
    for (int s = 0; s < ranks; ++s) {
      receive_offsets[s] = static_cast<int>(at);
      receive_counts[s] = static_cast<int>(sets * rows_ * column_counts_[s]);
      at += receive_counts[s];
    }
    MPI_Alltoallv(send, send_counts.data(), send_offsets.data(), MPI_C_DOUBLE_COMPLEX,
                  receive_.data(), receive_counts.data(), receive_offsets.data(),
                  MPI_C_DOUBLE_COMPLEX, communicator_);
    const Complex *received = receive_.data();
    for (int s = 0; s < ranks; ++s)
      for (int set = 0; set < sets; ++set)
        for (std::int64_t j = 0; j < rows_; ++j) {
          Complex *row = row_spectra_.data() + (nx_ + 1) * (rows_ * set + j) + column_offsets_[s];
          std::copy(received, received + column_counts_[s], row);
          received += column_counts_[s];
        }
  }

  void destroy_plans() {
    for (fftw_plan *plan : {&rows_r2c_, &rows_c2r_, &columns_forward_, &columns_backward_})
      if (*plan != nullptr) {
        fftw_destroy_plan(*plan);
        *plan = nullptr;
      }
  }

  std::int64_t nx_, ny_, rows_, columns_;
  MPI_Comm communicator_;
  std::vector<std::int64_t> row_counts_, row_offsets_, column_counts_, column_offsets_;
  mutable Spectrum row_spectra_, send_, receive_;
  fftw_plan rows_r2c_ = nullptr, rows_c2r_ = nullptr;
  fftw_plan columns_forward_ = nullptr, columns_backward_ = nullptr;
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

  std::unique_ptr<PaddedTransform> padded_transform(std::int64_t nx, std::int64_t ny,
                                                    FftPlanning planning,
                                                    int threads) const override {
    return std::make_unique<MpiPaddedFft>(nx, ny, communicator_, slab(nx, ny),
                                          slab(2 * nx, 2 * ny), planning, threads);
  }

  void next_row(const double *field, std::int64_t nx, std::int64_t ny,
                double *row) const override {
    // Every process's slab, then the first row of each slab to the process whose slab ends
    // just above it.
    const Slab mine = slab(nx, ny);
    const std::int64_t sent[2] = {mine.rows, mine.offset};
    std::vector<std::int64_t> all(2 * static_cast<std::size_t>(ranks_));
    MPI_Allgather(sent, 2, MPI_INT64_T, all.data(), 2, MPI_INT64_T, communicator_);
    MPI_Request requests[2];
    int pending = 0;
    for (int r = 0; r < ranks_; ++r) {
      const std::int64_t rows = all[2 * r], offset = all[2 * r + 1];
      if (rows == 0 || r == rank_) continue;
      if (mine.rows > 0 && offset == mine.offset + mine.rows)
        MPI_Irecv(row, static_cast<int>(nx), MPI_DOUBLE, r, 0, communicator_,
                  &requests[pending++]);
      if (mine.rows > 0 && offset + rows == mine.offset)
        MPI_Isend(field, static_cast<int>(nx), MPI_DOUBLE, r, 0, communicator_,
                  &requests[pending++]);
    }
    MPI_Waitall(pending, requests, MPI_STATUSES_IGNORE);
  }

  void gather_rows(const double *mine, std::int64_t offset, std::int64_t rows,
                   std::int64_t width, std::int64_t first, std::int64_t count,
                   double *out) const override {
    // Every process's rows and the rows it asks for, then one exchange: to each process the
    // rows of this one it asks for, from each the rows of it this one asks for.
    const std::int64_t sent[4] = {offset, rows, first, count};
    const std::size_t n = static_cast<std::size_t>(ranks_);
    std::vector<std::int64_t> all(4 * n);
    MPI_Allgather(sent, 4, MPI_INT64_T, all.data(), 4, MPI_INT64_T, communicator_);
    // MPI counts are ints. Every process sees the same sizes, so all refuse alike.
    for (std::size_t r = 0; r < n; ++r)
      if (std::max(all[4 * r + 1], all[4 * r + 3]) * width > std::numeric_limits<int>::max())
        throw Error(Status::unsupported,
                    "a distributed field moves between slabs in pieces of at most " +
                        std::to_string(std::numeric_limits<int>::max()) +
                        " values per process; this one has more");
    std::vector<int> send_counts(n, 0), send_displacements(n, 0), receive_counts(n, 0),
        receive_displacements(n, 0);
    for (std::size_t r = 0; r < n; ++r) {
      const std::int64_t held = all[4 * r], held_end = held + all[4 * r + 1];
      const std::int64_t asked = all[4 * r + 2], asked_end = asked + all[4 * r + 3];
      const std::int64_t to_send = std::min(offset + rows, asked_end) - std::max(offset, asked);
      if (to_send > 0) {
        send_counts[r] = static_cast<int>(to_send * width);
        send_displacements[r] = static_cast<int>((std::max(offset, asked) - offset) * width);
      }
      const std::int64_t to_receive = std::min(held_end, first + count) - std::max(held, first);
      if (to_receive > 0) {
        receive_counts[r] = static_cast<int>(to_receive * width);
        receive_displacements[r] = static_cast<int>((std::max(held, first) - first) * width);
      }
    }
    MPI_Alltoallv(mine, send_counts.data(), send_displacements.data(), MPI_DOUBLE, out,
                  receive_counts.data(), receive_displacements.data(), MPI_DOUBLE,
                  communicator_);
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
