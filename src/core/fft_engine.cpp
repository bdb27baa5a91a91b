// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/fft_engine.hpp"

#include <fftw3.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <system_error>

#include "core/error.hpp"
#include "core/transform_clock.hpp"
#include "core/fft_planner.hpp"

namespace asp {
namespace {
// FFTW's row-major dimensions of a field of nx x ny pixels, x fastest.
int dimensions(std::int64_t nx, std::int64_t ny, int dims[2]) {
  if (ny > 1) {
    dims[0] = static_cast<int>(ny);
    dims[1] = static_cast<int>(nx);
    return 2;
  }
  dims[0] = static_cast<int>(nx);
  return 1;
}

void destroy(void *plan) {
  if (plan != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(plan));
}

// Makes both plans or neither: if one fails, the other is destroyed and Error(fft) thrown.
void require_plans(fftw_plan a, fftw_plan b) {
  if (a != nullptr && b != nullptr) return;
  destroy(a);
  destroy(b);
  throw Error(Status::fft, "FFTW could not plan a transform of this grid size");
}
}  // namespace

RealFft::RealFft(std::int64_t nx, std::int64_t ny, FftPlanning planning, int threads) {
  int dims[2];
  const int rank = dimensions(nx, ny, dims);
  // Plan on scratch arrays: FFTW_MEASURE overwrites what it is given.
  Field real(static_cast<std::size_t>(nx * ny));
  Spectrum spectrum(static_cast<std::size_t>((nx / 2 + 1) * ny));
  auto *c = reinterpret_cast<fftw_complex *>(spectrum.data());

  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  const fft_planner::PlannerThreads planner_threads(threads, nx * ny);
  const fft_planner::PlanningTimeLimit time_limit(planning);
  const unsigned flags = fft_planner::flags_of(planning);
  fftw_plan r2c = fft_planner::plan(
      flags, [&](unsigned f) { return fftw_plan_dft_r2c(rank, dims, real.data(), c, f); });
  fftw_plan c2r = fft_planner::plan(flags | FFTW_DESTROY_INPUT, [&](unsigned f) {
    return fftw_plan_dft_c2r(rank, dims, c, real.data(), f);
  });
  require_plans(r2c, c2r);
  r2c_ = r2c;
  c2r_ = c2r;
}

RealFft::~RealFft() {
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  destroy(r2c_);
  destroy(c2r_);
}

void RealFft::forward(const double *real, Complex *spectrum) const {
  const transform_clock::Scope timed;
  // FFTW's r2c does not write its input when out of place; the cast only satisfies its API.
  fftw_execute_dft_r2c(static_cast<fftw_plan>(r2c_), const_cast<double *>(real),
                       reinterpret_cast<fftw_complex *>(spectrum));
}

void RealFft::backward(Complex *spectrum, double *real) const {
  const transform_clock::Scope timed;
  fftw_execute_dft_c2r(static_cast<fftw_plan>(c2r_), reinterpret_cast<fftw_complex *>(spectrum),
                       real);
}

PaddedRealFft::PaddedRealFft(std::int64_t nx, std::int64_t ny, FftPlanning planning,
                             int threads)
    : nx_(nx), ny_(ny) {
  const int width = static_cast<int>(2 * nx), height = static_cast<int>(2 * ny);
  const int columns = static_cast<int>(nx + 1), rows = static_cast<int>(ny);
  // Plan on scratch arrays: FFTW_MEASURE overwrites what it is given.
  Field real(static_cast<std::size_t>(2 * nx * ny));
  Spectrum spectrum(static_cast<std::size_t>((nx + 1) * 2 * ny));
  auto *c = reinterpret_cast<fftw_complex *>(spectrum.data());
  const unsigned flags = fft_planner::flags_of(planning);

  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  const fft_planner::PlannerThreads planner_threads(threads, 4 * nx * ny);
  const fft_planner::PlanningTimeLimit time_limit(planning);
  // Rows along x: ny of them, 2nx reals each, contiguous; out nx+1 complex each, contiguous.
  fftw_plan r2c = fft_planner::plan(flags, [&](unsigned f) {
    return fftw_plan_many_dft_r2c(1, &width, rows, real.data(), nullptr, 1, width, c, nullptr, 1,
                                  columns, f);
  });
  fftw_plan c2r = fft_planner::plan(flags | FFTW_DESTROY_INPUT, [&](unsigned f) {
    return fftw_plan_many_dft_c2r(1, &width, rows, c, nullptr, 1, columns, real.data(), nullptr,
                                  1, width, f);
  });
  // Columns along y: nx+1 of them, 2ny complex each, strided by nx+1, in place.
  fftw_plan forward = fft_planner::plan(flags, [&](unsigned f) {
    return fftw_plan_many_dft(1, &height, columns, c, nullptr, columns, 1, c, nullptr, columns, 1,
                              FFTW_FORWARD, f);
  });
  fftw_plan backward = fft_planner::plan(flags, [&](unsigned f) {
    return fftw_plan_many_dft(1, &height, columns, c, nullptr, columns, 1, c, nullptr, columns, 1,
                              FFTW_BACKWARD, f);
  });
  if (r2c == nullptr || c2r == nullptr || forward == nullptr || backward == nullptr) {
    destroy(r2c);
    destroy(c2r);
    destroy(forward);
    destroy(backward);
    throw Error(Status::fft, "FFTW could not plan a transform of this grid size");
  }
  rows_r2c_ = r2c;
  rows_c2r_ = c2r;
  columns_forward_ = forward;
  columns_backward_ = backward;
}

PaddedRealFft::~PaddedRealFft() {
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  destroy(rows_r2c_);
  destroy(rows_c2r_);
  destroy(columns_forward_);
  destroy(columns_backward_);
}

void PaddedRealFft::forward(const double *box, Complex *spectrum, double *rows) const {
  const transform_clock::Scope timed;
  const std::int64_t width = 2 * nx_, columns = nx_ + 1;
  // The box's rows, each followed by nx zeros.
  for (std::int64_t j = 0; j < ny_; ++j) {
    std::copy(box + nx_ * j, box + nx_ * (j + 1), rows + width * j);
    std::fill(rows + width * j + nx_, rows + width * (j + 1), 0.0);
  }
  auto *s = reinterpret_cast<fftw_complex *>(spectrum);
  fftw_execute_dft_r2c(static_cast<fftw_plan>(rows_r2c_), rows, s);
  // The rows beyond the box are zero, and so are their transforms along x.
  std::fill(spectrum + columns * ny_, spectrum + columns * 2 * ny_, Complex(0.0, 0.0));
  fftw_execute_dft(static_cast<fftw_plan>(columns_forward_), s, s);
}

void PaddedRealFft::backward(Complex *spectrum, double *box, double *rows) const {
  const transform_clock::Scope timed;
  const std::int64_t width = 2 * nx_;
  auto *s = reinterpret_cast<fftw_complex *>(spectrum);
  fftw_execute_dft(static_cast<fftw_plan>(columns_backward_), s, s);
  // Along x only the rows of the box, whose first nx values are kept.
  fftw_execute_dft_c2r(static_cast<fftw_plan>(rows_c2r_), s, rows);
  for (std::int64_t j = 0; j < ny_; ++j)
    std::copy(rows + width * j, rows + width * j + nx_, box + nx_ * j);
}

void PaddedRealFft::surface_forward(const double *surface, Complex *spectrum) const {
  const transform_clock::Scope timed;
  // All 2ny rows along x: the plan's ny rows twice (at offsets that keep the alignment it was
  // made for), then the columns.
  const std::int64_t width = 2 * nx_, columns = nx_ + 1;
  auto *s = reinterpret_cast<fftw_complex *>(spectrum);
  auto *rows = const_cast<double *>(surface);  // an out-of-place r2c preserves its input
  fftw_execute_dft_r2c(static_cast<fftw_plan>(rows_r2c_), rows, s);
  fftw_execute_dft_r2c(static_cast<fftw_plan>(rows_r2c_), rows + width * ny_, s + columns * ny_);
  fftw_execute_dft(static_cast<fftw_plan>(columns_forward_), s, s);
}

void PaddedRealFft::surface_backward(Complex *spectrum, double *surface) const {
  const transform_clock::Scope timed;
  const std::int64_t width = 2 * nx_, columns = nx_ + 1;
  auto *s = reinterpret_cast<fftw_complex *>(spectrum);
  fftw_execute_dft(static_cast<fftw_plan>(columns_backward_), s, s);
  fftw_execute_dft_c2r(static_cast<fftw_plan>(rows_c2r_), s, surface);
  fftw_execute_dft_c2r(static_cast<fftw_plan>(rows_c2r_), s + columns * ny_, surface + width * ny_);
}

namespace {
// The process's FFTW wisdom, set aside while it lives (under the planner lock) and put back
// afterwards. FFTW lets the wisdom of more rigorous planning (the grids' FFTW_MEASURE plans)
// choose the algorithm of an FFTW_ESTIMATE plan of the same transform, and another algorithm
// rounds differently: plans that must not depend on what the process planned before are made
// without it.
class WithoutWisdom {
 public:
  WithoutWisdom() : saved_(fftw_export_wisdom_to_string()) { fftw_forget_wisdom(); }
  ~WithoutWisdom() {
    fftw_forget_wisdom();
    if (saved_ != nullptr) {
      fftw_import_wisdom_from_string(saved_);
      fftw_free(saved_);
    }
  }
  WithoutWisdom(const WithoutWisdom &) = delete;
  WithoutWisdom &operator=(const WithoutWisdom &) = delete;

 private:
  char *saved_;
};
}  // namespace

LineFft::LineFft(std::int64_t n) {
  Spectrum line(static_cast<std::size_t>(n));
  auto *c = reinterpret_cast<fftw_complex *>(line.data());
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  fft_planner::threads_ready();  // so that the wisdom of threaded plans is read back
  const WithoutWisdom own_choice;
  const fft_planner::PlannerThreads one_thread(1, 0);
  plan_ = fftw_plan_dft_1d(static_cast<int>(n), c, c, FFTW_BACKWARD, FFTW_ESTIMATE);
  if (plan_ == nullptr) throw Error(Status::fft, "FFTW could not plan a transform of this length");
}

LineFft::~LineFft() {
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  destroy(plan_);
}

void LineFft::backward(Complex *line) const {
  auto *c = reinterpret_cast<fftw_complex *>(line);
  fftw_execute_dft(static_cast<fftw_plan>(plan_), c, c);
}

RealLineFft::RealLineFft(std::int64_t n) {
  Spectrum half(static_cast<std::size_t>(n / 2 + 1));
  Field real(static_cast<std::size_t>(n));
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  fft_planner::threads_ready();
  const WithoutWisdom own_choice;
  const fft_planner::PlannerThreads one_thread(1, 0);
  plan_ = fftw_plan_dft_c2r_1d(static_cast<int>(n), reinterpret_cast<fftw_complex *>(half.data()),
                               real.data(), FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
  if (plan_ == nullptr) throw Error(Status::fft, "FFTW could not plan a transform of this length");
}

RealLineFft::~RealLineFft() {
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  destroy(plan_);
}

void RealLineFft::backward(Complex *half, double *real) const {
  fftw_execute_dft_c2r(static_cast<fftw_plan>(plan_), reinterpret_cast<fftw_complex *>(half),
                       real);
}

void export_fft_wisdom(const std::string &path) {
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  fft_planner::threads_ready();
  if (fftw_export_wisdom_to_filename(path.c_str()) == 0)
    throw Error(Status::io, "argument 'path': cannot write FFTW wisdom to '" + path + "'");
}

void import_fft_wisdom(const std::string &path) {
  // Read here, not by FFTW, so that what is not a plain file of a sensible size (a device, a
  // pipe, a file grown without bound) is refused before it is read.
  const std::string where = "argument 'path': FFTW wisdom '" + path + "' ";
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status))
    throw Error(Status::io, where + "cannot be read (missing or unreadable)");
  if (!std::filesystem::is_regular_file(status))
    throw Error(Status::io, where + "is not a regular file");
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(largest_wisdom_bytes) + 1, '\0');
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  if (in.bad() || (!in.eof() && in.gcount() == 0))
    throw Error(Status::io, where + "cannot be read");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (static_cast<std::int64_t>(text.size()) > largest_wisdom_bytes)
    throw Error(Status::io, where + "is larger than " + std::to_string(largest_wisdom_bytes) +
                                " bytes, more than wisdom of any number of plans holds");
  std::lock_guard<std::mutex> lock(fft_planner::mutex());
  fft_planner::threads_ready();
  // FFTW refuses text that does not parse, or that another version of FFTW wrote, as a
  // whole: what the process knew before is kept.
  if (fftw_import_wisdom_from_string(text.c_str()) == 0)
    throw Error(Status::io, where + "is not wisdom of this FFTW (" + fftw_version +
                                "): damaged, or written by another version");
}

}  // namespace asp
