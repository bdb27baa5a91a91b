// A periodic 1D or 2D grid: sizes, box, wavevectors and the FFT plans of that size.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>

#include "core/aligned_field.hpp"
#include "core/fft_engine.hpp"
#include "core/reductions.hpp"

namespace asp {

class Grid {
 public:
  // Checks its arguments (throws Error naming the bad one). 1D grids have ny = 1 and ly = 1,
  // so that the pixel "area" lx/nx is the pixel length.
  static std::unique_ptr<Grid> create(int dimension, std::int64_t nx, std::int64_t ny, double lx,
                                      double ly);
  Grid(const Grid &) = delete;
  Grid &operator=(const Grid &) = delete;

  int dimension() const { return dimension_; }
  std::int64_t nx() const { return nx_; }
  std::int64_t ny() const { return ny_; }
  double lx() const { return lx_; }
  double ly() const { return ly_; }
  std::int64_t n_pixels() const { return nx_ * ny_; }
  double area() const { return lx_ * ly_; }
  double pixel_area() const { return area() / static_cast<double>(n_pixels()); }

  // Half spectrum: kx in [0, nx/2], ky in [0, ny).
  std::int64_t spectral_nx() const { return nx_ / 2 + 1; }
  std::int64_t n_spectral() const { return spectral_nx() * ny_; }
  double qx(std::int64_t kx) const;  // 2 pi kx/lx
  double qy(std::int64_t ky) const;  // 2 pi k/ly, k = ky or ky - ny (nearest to zero)
  // How many full-spectrum modes a half-spectrum entry stands for (1 or 2): the weight of
  // that entry in Parseval sums.
  double hermitian_weight(std::int64_t kx) const;

  Field make_field() const { return Field(static_cast<std::size_t>(n_pixels()), 0.0); }
  Spectrum make_spectrum() const { return Spectrum(static_cast<std::size_t>(n_spectral())); }

  const FftEngine &fft() const;  // plans on first use
  void set_fft_planning(FftPlanning planning);
  bool has_fft_plans() const;

  const Reductions &reductions() const { return reductions_; }

 private:
  Grid(int dimension, std::int64_t nx, std::int64_t ny, double lx, double ly);

  int dimension_;
  std::int64_t nx_, ny_;
  double lx_, ly_;
  FftPlanning planning_ = FftPlanning::estimate;
  mutable std::mutex fft_mutex_;
  mutable std::unique_ptr<FftEngine> fft_;
  LocalReductions reductions_;
};

}  // namespace asp
