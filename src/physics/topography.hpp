// SPDX-License-Identifier: GPL-2.0-or-later
// Generators of rigid-surface heights on a grid. Each checks its parameters and writes
// grid.n_pixels() heights, x fastest. Pixel (i, j) sits at (i lx/nx, j ly/ny).
#pragma once

#include <cstdint>

#include "core/grid.hpp"

namespace asp {

void flat_topography(const Grid &grid, double *heights);
void sphere_topography(const Grid &grid, double radius, double *heights);
void paraboloid_topography(const Grid &grid, double radius, double *heights);
void sinusoid_topography(const Grid &grid, double amplitude, std::int64_t periods_x,
                         std::int64_t periods_y, double *heights);
void double_sinewave_topography(const Grid &grid, double amplitude, double ripple_amplitude,
                                std::int64_t ripple_periods, double *heights);

enum class RoughnessNorm { rms_height = 1, rms_slope = 2 };

struct SelfAffineParameters {
  double hurst = 0.8;
  double long_cutoff = 0.0;   // wavelength; no roughness above it
  double rolloff = 0.0;       // wavelength; flat spectrum between it and long_cutoff
  double short_cutoff = 0.0;  // wavelength; no roughness below it
  RoughnessNorm norm = RoughnessNorm::rms_slope;
  double target = 1.0;
  std::uint64_t seed = 0;
};

void self_affine_topography(const Grid &grid, const SelfAffineParameters &parameters,
                            double *heights);

}  // namespace asp
