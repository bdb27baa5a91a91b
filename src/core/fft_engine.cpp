#include "core/fft_engine.hpp"

#include <fftw3.h>

#include <mutex>

#include "core/error.hpp"

namespace asp {
namespace {
// FFTW's planner is not thread-safe; every plan creation and destruction in the library goes
// through this lock. Execution of existing plans is thread-safe and needs no lock.
std::mutex &planner_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

FftEngine::FftEngine(std::int64_t nx, std::int64_t ny, FftPlanning planning) {
  const std::int64_t n_real = nx * ny;
  const std::int64_t n_complex = (nx / 2 + 1) * ny;
  const int rank = ny > 1 ? 2 : 1;
  int dims[2];
  if (rank == 2) {
    dims[0] = static_cast<int>(ny);
    dims[1] = static_cast<int>(nx);
  } else {
    dims[0] = static_cast<int>(nx);
  }
  const unsigned flags = planning == FftPlanning::measure ? FFTW_MEASURE : FFTW_ESTIMATE;

  // Plan on scratch arrays: FFTW_MEASURE overwrites what it is given.
  Field real(static_cast<std::size_t>(n_real));
  Spectrum spectrum(static_cast<std::size_t>(n_complex));
  auto *c = reinterpret_cast<fftw_complex *>(spectrum.data());

  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_plan r2c = fftw_plan_dft_r2c(rank, dims, real.data(), c, flags);
  fftw_plan c2r = fftw_plan_dft_c2r(rank, dims, c, real.data(), flags | FFTW_DESTROY_INPUT);
  if (r2c == nullptr || c2r == nullptr) {
    if (r2c) fftw_destroy_plan(r2c);
    if (c2r) fftw_destroy_plan(c2r);
    throw Error(Status::fft, "FFTW could not plan a transform of this grid size");
  }
  r2c_ = r2c;
  c2r_ = c2r;
}

FftEngine::~FftEngine() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(static_cast<fftw_plan>(r2c_));
  fftw_destroy_plan(static_cast<fftw_plan>(c2r_));
}

void FftEngine::forward(const double *real, Complex *spectrum) const {
  // FFTW's r2c does not write its input when out of place; the cast only satisfies its API.
  fftw_execute_dft_r2c(static_cast<fftw_plan>(r2c_), const_cast<double *>(real),
                       reinterpret_cast<fftw_complex *>(spectrum));
}

void FftEngine::backward(Complex *spectrum, double *real) const {
  fftw_execute_dft_c2r(static_cast<fftw_plan>(c2r_), reinterpret_cast<fftw_complex *>(spectrum),
                       real);
}

}  // namespace asp
