#include "core/grid.hpp"

#include <cmath>
#include <limits>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {

namespace {
constexpr double two_pi = 6.283185307179586476925286766559;
// FFTW takes int dimensions; larger grids would not fit in memory anyway.
constexpr std::int64_t largest_axis = std::numeric_limits<int>::max();
}  // namespace

std::unique_ptr<Grid> Grid::create(int dimension, std::int64_t nx, std::int64_t ny, double lx,
                                   double ly) {
  require_at_least(nx, 1, "nx");
  if (nx > largest_axis)
    throw Error(Status::invalid_argument, "argument 'nx' is larger than FFTW can transform");
  require_positive(lx, "lx");
  if (dimension == 2) {
    require_at_least(ny, 1, "ny");
    if (ny > largest_axis)
      throw Error(Status::invalid_argument, "argument 'ny' is larger than FFTW can transform");
    if (nx > std::numeric_limits<std::int64_t>::max() / ny)
      throw Error(Status::invalid_argument, "arguments 'nx' and 'ny': nx*ny overflows int64");
    require_positive(ly, "ly");
  } else {
    ny = 1;
    ly = 1.0;
  }
  return std::unique_ptr<Grid>(new Grid(dimension, nx, ny, lx, ly));
}

Grid::Grid(int dimension, std::int64_t nx, std::int64_t ny, double lx, double ly)
    : dimension_(dimension), nx_(nx), ny_(ny), lx_(lx), ly_(ly) {}

double Grid::qx(std::int64_t kx) const { return two_pi * static_cast<double>(kx) / lx_; }

double Grid::qy(std::int64_t ky) const {
  const std::int64_t k = ky <= ny_ / 2 ? ky : ky - ny_;
  return two_pi * static_cast<double>(k) / ly_;
}

double Grid::hermitian_weight(std::int64_t kx) const {
  // Entry kx of the half spectrum also stands for -kx, except kx = 0 and, for even nx, the
  // Nyquist column kx = nx/2, which are their own partners.
  const bool self_partner = kx == 0 || (nx_ % 2 == 0 && kx == nx_ / 2);
  return self_partner ? 1.0 : 2.0;
}

const FftEngine &Grid::fft() const {
  std::lock_guard<std::mutex> lock(fft_mutex_);
  if (!fft_) fft_.reset(new FftEngine(nx_, ny_, planning_));
  return *fft_;
}

void Grid::set_fft_planning(FftPlanning planning) {
  std::lock_guard<std::mutex> lock(fft_mutex_);
  if (fft_)
    throw Error(Status::invalid_state,
                "the grid's FFT plans already exist; set the planning right after creating it");
  planning_ = planning;
}

bool Grid::has_fft_plans() const {
  std::lock_guard<std::mutex> lock(fft_mutex_);
  return fft_ != nullptr;
}

}  // namespace asp
