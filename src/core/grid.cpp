// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/grid.hpp"

#include <algorithm>
#include <string>

#include <cfloat>
#include <cmath>
#include <limits>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {

namespace {
constexpr double two_pi = 6.283185307179586476925286766559;
// FFTW takes int dimensions, and the padded shape of a non-periodic substrate doubles them.
constexpr std::int64_t largest_axis = std::numeric_limits<int>::max() / 2;

void check_axis(std::int64_t n, double length, const char *size_name, const char *length_name) {
  require_at_least(n, 1, size_name);
  if (n > largest_axis)
    throw Error(Status::invalid_argument, std::string("argument '") + size_name + "' is " +
                                              std::to_string(n) + ", more than FFTW can transform (" +
                                              std::to_string(largest_axis) + ")");
  require_positive(length, length_name);
  // Pixel size and the wavevectors from 2 pi/length to 2 pi (n/2)/length must be normal
  // doubles, and so must their squares (|q| = sqrt(qx^2 + qy^2), slopes, curvatures), hence
  // the margins of 1e150 either way.
  const double pixel = length / static_cast<double>(n);
  const double q_min = two_pi / length;
  const double q_max = two_pi * static_cast<double>(n) / length;
  if (!(pixel >= DBL_MIN) || !(q_max < 1e150) || !(q_min > 1e-150))
    throw Error(Status::invalid_argument,
                std::string("argument '") + length_name + "' is " + format_number(length) +
                    ": with " + std::to_string(n) + " pixels the pixel size " +
                    format_number(pixel) + " or the wavevectors from " + format_number(q_min) +
                    " to " + format_number(q_max) +
                    " (and their squares) are not representable; rescale the lengths");
}
}  // namespace

std::shared_ptr<Grid> Grid::create(int dimension, std::int64_t nx, std::int64_t ny, double lx,
                                   double ly) {
  check_axis(nx, lx, "nx", "lx");
  if (dimension == 2) {
    check_axis(ny, ly, "ny", "ly");
    if (nx > std::numeric_limits<std::int64_t>::max() / ny)
      throw Error(Status::invalid_argument, "arguments 'nx' and 'ny': nx*ny overflows int64");
    const double area = lx * ly;
    const double pixel_area = (lx / static_cast<double>(nx)) * (ly / static_cast<double>(ny));
    if (!std::isfinite(area) || !(pixel_area >= DBL_MIN))
      throw Error(Status::invalid_argument,
                  "arguments 'lx' and 'ly': the box area " + format_number(area) +
                      " or the pixel area " + format_number(pixel_area) +
                      " is not representable; rescale the lengths");
  } else {
    ny = 1;
    ly = 1.0;
  }
  return std::shared_ptr<Grid>(new Grid(dimension, nx, ny, lx, ly));
}

std::shared_ptr<Grid> Grid::create_distributed(std::shared_ptr<const Partition> partition,
                                               std::int64_t nx, std::int64_t ny, double lx,
                                               double ly) {
  // Every process checks its own arguments, then all agree, so that a bad argument on one
  // of them is reported on each, and then that they were given the same grid.
  std::shared_ptr<Grid> grid;
  try {
    grid = create(2, nx, ny, lx, ly);
  } catch (const Error &e) {
    partition->agree(&e);
  }
  partition->agree(nullptr);
  const double shape[4] = {static_cast<double>(nx), static_cast<double>(ny), lx, ly};
  double theirs[4];  // the first differing process's, the same on every process
  const int differing = partition->first_differing(shape, 4, theirs);
  if (differing >= 0) {
    const auto grid_text = [](const double *s) {
      return format_number(s[0]) + " x " + format_number(s[1]) + " pixels on a box " +
             format_number(s[2]) + " x " + format_number(s[3]);
    };
    throw Error(Status::invalid_argument,
                "on process " + std::to_string(differing) + " of " +
                    std::to_string(partition->ranks()) + ": arguments 'nx', 'ny', 'lx' and 'ly' "
                    "give " + grid_text(theirs) + ", other than process 0's: a distributed "
                    "grid is one grid, created with the same sizes and box on every process");
  }
  const Slab slab = partition->slab(nx, ny);
  grid->threads_ = default_distributed_threads();
  grid->local_rows_ = slab.rows;
  grid->row_offset_ = slab.offset;
  grid->spectral_columns_ = slab.columns;
  grid->column_offset_ = slab.column_offset;
  const Slab padded = partition->slab(2 * nx, 2 * ny);
  grid->padded_columns_ = padded.columns;
  grid->padded_column_offset_ = padded.column_offset;
  grid->partition_ = std::move(partition);
  return grid;
}

Grid::Grid(int dimension, std::int64_t nx, std::int64_t ny, double lx, double ly)
    : dimension_(dimension),
      nx_(nx),
      ny_(ny),
      lx_(lx),
      ly_(ly),
      threads_(default_threads()),
      local_rows_(ny) {}

SpectralLayout Grid::half_spectrum() const {
  if (partition_)
    return SpectralLayout(Packing::transposed_half_spectrum, nx_, ny_, lx_, ly_,
                          spectral_columns_, column_offset_);
  return SpectralLayout(Packing::half_spectrum, nx_, ny_, lx_, ly_);
}

std::shared_ptr<Grid> Grid::halved() const {
  const bool two_d = dimension_ == 2;
  if (nx_ % 2 != 0 || (two_d && ny_ % 2 != 0))
    throw Error(Status::invalid_argument,
                "a grid of " + std::to_string(nx_) + " x " + std::to_string(ny_) +
                    " pixels cannot be halved per axis (odd size)");
  const std::int64_t nx = nx_ / 2, ny = two_d ? ny_ / 2 : 1;
  std::shared_ptr<Grid> half = partition_ ? create_distributed(partition_, nx, ny, lx_, ly_)
                                          : create(dimension_, nx, ny, lx_, ly_);
  half->set_threads(threads());
  half->set_fft_planning(fft_planning());
  return half;
}

void Grid::gather_rows(const double *local, std::int64_t first, std::int64_t count,
                       double *out) const {
  if (partition_) {
    partition_->gather_rows(local, row_offset_, local_rows_, nx_, first, count, out);
    return;
  }
  std::copy(local + first * nx_, local + (first + count) * nx_, out);
}

void Grid::gather_spectral_columns(const Complex *local, std::int64_t first, std::int64_t count,
                                   Complex *out) const {
  if (!partition_)
    throw Error(Status::unsupported,
                "a serial grid's spectrum is stored by rows, not by columns, and all of it is "
                "local");
  // A complex entry is two doubles (std::complex's layout), so a column of ny entries is a
  // row of 2 ny doubles.
  partition_->gather_rows(reinterpret_cast<const double *>(local), column_offset_,
                          spectral_columns_, 2 * ny_, first, count,
                          reinterpret_cast<double *>(out));
}

void Grid::require_serial(const char *what) const {
  if (partition_)
    throw Error(Status::unsupported,
                std::string("argument 'grid' is distributed over processes, and ") + what +
                    " is not: use a grid of one process");
}

const RealTransform &Grid::fft() const {
  if (!partition_) return real_fft(nx_, ny_);
  std::lock_guard<std::mutex> lock(plans_mutex_);
  if (!distributed_plan_) {
    // FFTW-MPI plans together: a process that measures while another estimates would wait
    // for it forever. Refused on every process instead.
    const double planning = static_cast<double>(planning_);
    double theirs = 0.0;
    const int differing = partition_->first_differing(&planning, 1, &theirs);
    if (differing >= 0)
      throw Error(Status::invalid_state,
                  "on process " + std::to_string(differing) + " of " +
                      std::to_string(partition_->ranks()) +
                      ": the grid's FFT planning (asp_grid_set_fft_planning) differs from "
                      "process 0's; set the same planning on every process");
    distributed_plan_ = partition_->real_transform(nx_, ny_, planning_, threads_);
  }
  return *distributed_plan_;
}

const RealFft &Grid::real_fft(std::int64_t nx, std::int64_t ny) const {
  require_serial("the transform of another shape");
  std::lock_guard<std::mutex> lock(plans_mutex_);
  const auto key = std::make_tuple(nx, ny);
  auto found = real_plans_.find(key);
  if (found == real_plans_.end())
    found = real_plans_.emplace(key, std::make_unique<RealFft>(nx, ny, planning_, threads_)).first;
  return *found->second;
}

const PaddedTransform &Grid::padded_fft() const {
  std::lock_guard<std::mutex> lock(plans_mutex_);
  if (!padded_plan_) {
    if (partition_)
      padded_plan_ = partition_->padded_transform(nx_, ny_, planning_, threads_);
    else
      padded_plan_.reset(new PaddedRealFft(nx_, ny_, planning_, threads_));
  }
  return *padded_plan_;
}

SpectralLayout Grid::padded_spectrum() const {
  if (partition_)
    return SpectralLayout(Packing::transposed_half_spectrum, 2 * nx_, 2 * ny_, 2.0 * lx_,
                          2.0 * ly_, padded_columns_, padded_column_offset_);
  return SpectralLayout(Packing::half_spectrum, 2 * nx_, 2 * ny_, 2.0 * lx_, 2.0 * ly_);
}

void Grid::set_fft_planning(FftPlanning planning) {
  std::lock_guard<std::mutex> lock(plans_mutex_);
  if (!real_plans_.empty() || padded_plan_ || distributed_plan_)
    throw Error(Status::invalid_state,
                "the grid's FFT plans already exist; set the planning right after creating it");
  planning_ = planning;
}

void Grid::set_threads(int threads) {
  if (threads < 1)
    throw Error(Status::invalid_argument,
                "argument 'threads' is " + std::to_string(threads) + ": must be at least 1");
  std::lock_guard<std::mutex> lock(plans_mutex_);
  if (!real_plans_.empty() || padded_plan_ || distributed_plan_)
    throw Error(Status::invalid_state,
                "the grid's FFT plans already exist; set the threads right after creating it");
  threads_ = threads;
}

int Grid::threads() const {
  std::lock_guard<std::mutex> lock(plans_mutex_);
  return threads_;
}

FftPlanning Grid::fft_planning() const {
  std::lock_guard<std::mutex> lock(plans_mutex_);
  return planning_;
}

bool Grid::has_fft_plans() const {
  std::lock_guard<std::mutex> lock(plans_mutex_);
  return !real_plans_.empty() || padded_plan_ != nullptr || distributed_plan_ != nullptr;
}

}  // namespace asp
