// Real-to-complex and complex-to-real transforms of one grid, planned once and executed on
// any pair of fields (FFTW's new-array interface; all fields share FFTW's alignment).
//
// Layout: real fields are x fastest, f[i + nx*j]; FFTW sees them as row-major arrays of shape
// (ny, nx), so the half spectrum is halved along x: S[kx + (nx/2+1)*ky].
// Neither transform is normalised: backward(forward(f)) = nx*ny*f.
#pragma once

#include <cstdint>

#include "core/aligned_field.hpp"

namespace asp {

enum class FftPlanning { estimate = 0, measure = 1 };

class FftEngine {
 public:
  FftEngine(std::int64_t nx, std::int64_t ny, FftPlanning planning);
  ~FftEngine();
  FftEngine(const FftEngine &) = delete;
  FftEngine &operator=(const FftEngine &) = delete;

  void forward(const double *real, Complex *spectrum) const;
  // Destroys the spectrum it reads (FFTW's multi-dimensional c2r does).
  void backward(Complex *spectrum, double *real) const;

 private:
  void *r2c_ = nullptr;  // fftw_plan, kept opaque so that fftw3.h stays out of the headers
  void *c2r_ = nullptr;
};

}  // namespace asp
