// SPDX-License-Identifier: GPL-2.0-or-later
// FFTW plans for one transform shape, executed on any pair of the library's own fields
// (FFTW's new-array interface; every field is allocated by fftw_malloc, so all share the
// alignment the plans were made for). Plans are never run on caller memory.
//
// Layout: real fields are x fastest, f[i + nx*j]; FFTW sees them as row-major arrays of shape
// (ny, nx). No transform is normalised: backward(forward(f)) = nx*ny*f.
#pragma once

#include <cstdint>
#include <string>

#include "core/aligned_field.hpp"

namespace asp {

enum class FftPlanning { estimate, measure, patient };

// The real-to-complex transform of a grid and back, on this process's rows of it: the half
// spectrum is halved along x, S[kx + (nx/2+1)*ky]. Serial (RealFft) or distributed over
// processes (core/mpi_partition.cpp), the formulations do not tell which.
class RealTransform {
 public:
  virtual ~RealTransform() = default;
  virtual void forward(const double *real, Complex *spectrum) const = 0;
  // Destroys the spectrum it reads.
  virtual void backward(Complex *spectrum, double *real) const = 0;
};

// The whole grid in this process.
class RealFft final : public RealTransform {
 public:
  RealFft(std::int64_t nx, std::int64_t ny, FftPlanning planning, int threads = 1);
  ~RealFft();
  RealFft(const RealFft &) = delete;
  RealFft &operator=(const RealFft &) = delete;

  void forward(const double *real, Complex *spectrum) const override;
  // Destroys the spectrum it reads (FFTW's multi-dimensional c2r does).
  void backward(Complex *spectrum, double *real) const override;

 private:
  void *r2c_ = nullptr;  // fftw_plan, kept opaque so that fftw3.h stays out of the headers
  void *c2r_ = nullptr;
};

// The transform of a 2D field of nx x ny, taken as zero outside its box, on the grid
// zero-padded to 2nx x 2ny, and back, keeping only the box (a free substrate's transforms);
// and the transform of a field over the whole padded grid (its surface) and back. On this
// process's rows: `box` holds its rows of the box, nx values each; the padded surface its
// padded rows, 2nx values each, first those of its box rows, then the rows ny further down.
// Serial (PaddedRealFft) or distributed over processes (core/mpi_partition.cpp). The spectrum
// is laid out as Grid::padded_spectrum() says. No transform is normalised: backward(forward(f))
// = 4 nx ny f.
class PaddedTransform {
 public:
  virtual ~PaddedTransform() = default;
  // rows: work for 2nx values per padded row of this process (4 nx local_rows), from the
  // library's allocator.
  virtual void forward(const double *box, Complex *spectrum, double *rows) const = 0;
  // Destroys the spectrum it reads.
  virtual void backward(Complex *spectrum, double *box, double *rows) const = 0;
  virtual void surface_forward(const double *surface, Complex *spectrum) const = 0;
  // Destroys the spectrum it reads.
  virtual void surface_backward(Complex *spectrum, double *surface) const = 0;
};

// The whole padded grid in this process: RealFft(2nx, 2ny) without the work its zero rows
// need. Forward: the ny rows of the box along x, then every column along y (the rows beyond
// the box, zero, need no transform along x); backward the reverse, and along x only the rows
// of the box. The surface's transforms take all 2ny rows along x. The spectrum is laid out as
// RealFft(2nx, 2ny)'s, S[kx + (nx+1)*ky].
class PaddedRealFft final : public PaddedTransform {
 public:
  PaddedRealFft(std::int64_t nx, std::int64_t ny, FftPlanning planning, int threads = 1);
  ~PaddedRealFft() override;
  PaddedRealFft(const PaddedRealFft &) = delete;
  PaddedRealFft &operator=(const PaddedRealFft &) = delete;

  void forward(const double *box, Complex *spectrum, double *rows) const override;
  void backward(Complex *spectrum, double *box, double *rows) const override;
  void surface_forward(const double *surface, Complex *spectrum) const override;
  void surface_backward(Complex *spectrum, double *surface) const override;

 private:
  std::int64_t nx_, ny_;
  void *rows_r2c_ = nullptr;     // ny transforms of 2nx along x
  void *columns_forward_ = nullptr;   // nx+1 transforms of 2ny along y, in place
  void *columns_backward_ = nullptr;
  void *rows_c2r_ = nullptr;
};

// One-dimensional backward transforms along one axis at a time, complex in place (LineFft)
// and half-complex to real (RealLineFft), planned with FFTW_ESTIMATE and without the
// process's wisdom: the plan, and so the rounding, depends only on the length, the same on
// every process, in every run and whatever was planned before. Arrays
// come from the library's allocator. Unnormalised, as all transforms here.
class LineFft {
 public:
  explicit LineFft(std::int64_t n);
  ~LineFft();
  LineFft(const LineFft &) = delete;
  LineFft &operator=(const LineFft &) = delete;
  void backward(Complex *line) const;

 private:
  void *plan_ = nullptr;
};

class RealLineFft {
 public:
  explicit RealLineFft(std::int64_t n);
  ~RealLineFft();
  RealLineFft(const RealLineFft &) = delete;
  RealLineFft &operator=(const RealLineFft &) = delete;
  // n/2 + 1 complex numbers in (destroyed), n reals out.
  void backward(Complex *half, double *real) const;

 private:
  void *plan_ = nullptr;
};

// FFTW's accumulated planning knowledge, to and from a file (throws Error(io) naming it).
// Importing refuses, before reading, what is not a regular file or holds more than
// largest_wisdom_bytes (the wisdom of hundreds of grid shapes is tens of kilobytes), and,
// after, what FFTW does not read as its own wisdom; the process's wisdom is then unchanged.
constexpr std::int64_t largest_wisdom_bytes = std::int64_t{16} << 20;
void export_fft_wisdom(const std::string &path);
void import_fft_wisdom(const std::string &path);

}  // namespace asp
