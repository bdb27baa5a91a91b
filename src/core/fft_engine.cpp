#include "core/fft_engine.hpp"

#include <fftw3.h>

#include <mutex>

#include "core/error.hpp"

namespace asp {
namespace {
// FFTW's planner is not thread-safe; every plan creation and destruction and every wisdom
// operation in the library goes through this lock. Executing existing plans is thread-safe.
std::mutex &planner_mutex() {
  static std::mutex m;
  return m;
}

unsigned flags_of(FftPlanning planning) {
  return planning == FftPlanning::measure ? FFTW_MEASURE : FFTW_ESTIMATE;
}

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

RealFft::RealFft(std::int64_t nx, std::int64_t ny, FftPlanning planning) {
  int dims[2];
  const int rank = dimensions(nx, ny, dims);
  // Plan on scratch arrays: FFTW_MEASURE overwrites what it is given.
  Field real(static_cast<std::size_t>(nx * ny));
  Spectrum spectrum(static_cast<std::size_t>((nx / 2 + 1) * ny));
  auto *c = reinterpret_cast<fftw_complex *>(spectrum.data());

  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_plan r2c = fftw_plan_dft_r2c(rank, dims, real.data(), c, flags_of(planning));
  fftw_plan c2r =
      fftw_plan_dft_c2r(rank, dims, c, real.data(), flags_of(planning) | FFTW_DESTROY_INPUT);
  require_plans(r2c, c2r);
  r2c_ = r2c;
  c2r_ = c2r;
}

RealFft::~RealFft() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  destroy(r2c_);
  destroy(c2r_);
}

void RealFft::forward(const double *real, Complex *spectrum) const {
  // FFTW's r2c does not write its input when out of place; the cast only satisfies its API.
  fftw_execute_dft_r2c(static_cast<fftw_plan>(r2c_), const_cast<double *>(real),
                       reinterpret_cast<fftw_complex *>(spectrum));
}

void RealFft::backward(Complex *spectrum, double *real) const {
  fftw_execute_dft_c2r(static_cast<fftw_plan>(c2r_), reinterpret_cast<fftw_complex *>(spectrum),
                       real);
}

HalfComplexFft::HalfComplexFft(std::int64_t nx, std::int64_t ny, FftPlanning planning) {
  int dims[2];
  const int rank = dimensions(nx, ny, dims);
  const fftw_r2r_kind forward_kinds[2] = {FFTW_R2HC, FFTW_R2HC};
  const fftw_r2r_kind backward_kinds[2] = {FFTW_HC2R, FFTW_HC2R};
  Field in(static_cast<std::size_t>(nx * ny)), out(static_cast<std::size_t>(nx * ny));

  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_plan r2hc =
      fftw_plan_r2r(rank, dims, in.data(), out.data(), forward_kinds, flags_of(planning));
  fftw_plan hc2r = fftw_plan_r2r(rank, dims, out.data(), in.data(), backward_kinds,
                                 flags_of(planning) | FFTW_DESTROY_INPUT);
  require_plans(r2hc, hc2r);
  r2hc_ = r2hc;
  hc2r_ = hc2r;
}

HalfComplexFft::~HalfComplexFft() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  destroy(r2hc_);
  destroy(hc2r_);
}

void HalfComplexFft::forward(const double *real, double *coefficients) const {
  fftw_execute_r2r(static_cast<fftw_plan>(r2hc_), const_cast<double *>(real), coefficients);
}

void HalfComplexFft::backward(double *coefficients, double *real) const {
  fftw_execute_r2r(static_cast<fftw_plan>(hc2r_), coefficients, real);
}

void export_fft_wisdom(const std::string &path) {
  std::lock_guard<std::mutex> lock(planner_mutex());
  if (fftw_export_wisdom_to_filename(path.c_str()) == 0)
    throw Error(Status::io, "argument 'path': cannot write FFTW wisdom to '" + path + "'");
}

void import_fft_wisdom(const std::string &path) {
  std::lock_guard<std::mutex> lock(planner_mutex());
  if (fftw_import_wisdom_from_filename(path.c_str()) == 0)
    throw Error(Status::io,
                "argument 'path': cannot read FFTW wisdom from '" + path +
                    "' (missing, unreadable, or not wisdom of this FFTW)");
}

}  // namespace asp
