// SPDX-License-Identifier: GPL-2.0-or-later
// The surface of the contact-mechanics challenge (Müser et al., Tribol. Lett. 65, 118 (2017))
// as asperity_challenge and asperity_iteration_scaling --challenge solve it: a periodic
// self-affine surface on a 100 um box, Hurst 0.8, flat spectrum from the box down to the
// roll-off at 20 um, short cutoff 0.1 um, rms slope 1, seed 1.
//
// One surface at every size. The generator draws each mode's noise from a stream keyed by the
// mode's index on its grid, so one seed gives another surface on a grid of another size. The
// surface is therefore drawn once, on the smallest grid that holds all of its modes (2048^2:
// the short cutoff is the 1000th harmonic of the box, and 1000 < 2048/2), and resampled onto
// the grid asked for by its spectrum: on a finer grid that is the same surface sampled finer,
// exactly (it is band-limited); on a coarser one, its modes below that grid's Nyquist
// wavevector, the surface that a nested solve's coarse level sees (rms slope 0.88 at 1024^2).
// A study of the iterations against the grid then compares one problem at several
// resolutions, not several surfaces.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/grid.hpp"
#include "physics/coarse_system.hpp"
#include "physics/topography.hpp"

namespace bench {

constexpr double challenge_box = 100e-6;

// The smallest power of two whose grid holds every mode of the surface below its Nyquist
// wavevector.
inline std::int64_t challenge_source_size(const asp::SelfAffineParameters &p) {
  const double harmonics = challenge_box / p.short_cutoff;
  std::int64_t n = 2;
  while (!(static_cast<double>(n / 2) > harmonics)) n *= 2;
  return n;
}

inline asp::SelfAffineParameters challenge_surface_parameters() {
  asp::SelfAffineParameters p;
  p.hurst = 0.8;
  p.long_cutoff = challenge_box;
  p.rolloff = 20e-6;
  p.short_cutoff = 0.1e-6;
  p.norm = asp::RoughnessNorm::rms_slope;
  p.target = 1.0;
  p.seed = 1;
  return p;
}

// The challenge's heights on `grid` (a serial 2D grid on the challenge's box), into heights.
inline void challenge_heights(const asp::Grid &grid, double *heights) {
  const asp::SelfAffineParameters p = challenge_surface_parameters();
  const std::int64_t n = challenge_source_size(p);
  if (grid.nx() == n && grid.ny() == n) {
    asp::self_affine_topography(grid, p, heights);
    return;
  }
  auto source = asp::Grid::create(2, n, n, challenge_box, challenge_box);
  source->set_threads(grid.threads());
  source->set_fft_planning(asp::FftPlanning::estimate);
  std::vector<double> drawn(static_cast<std::size_t>(source->n_pixels()));
  asp::self_affine_topography(*source, p, drawn.data());
  asp::resample_field(*source, grid, drawn.data(), heights);
}

}  // namespace bench
