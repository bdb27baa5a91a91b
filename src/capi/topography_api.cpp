// SPDX-License-Identifier: GPL-2.0-or-later
// asp_topography_*: surface generators and statistics, filling the caller's arrays.
#include <cmath>
#include <string>

#include "capi/constants.hpp"
#include "capi/firewall.hpp"
#include "capi/handles.hpp"
#include "core/checks.hpp"
#include "physics/detrend.hpp"
#include "physics/surface_statistics.hpp"
#include "physics/topography.hpp"

using asp::capi::Agreement;
using asp::capi::guarded_on;

namespace {
const asp::Grid *grid_of(const asp_grid *grid) {
  return grid != nullptr ? grid->grid.get() : nullptr;
}

// The grid of an array of n heights (this process's rows), after checking both.
const asp::Grid &grid_for(const asp_grid *grid, const void *heights, int64_t n) {
  asp::require_not_null(grid, "grid");
  asp::require_array(heights, n, grid->grid->local_pixels(), "heights");
  return *grid->grid;
}
}  // namespace

namespace asp::capi {

void require_topography(const asp_system *system) {
  if (!system->has_topography)
    throw Error(Status::invalid_state,
                "argument 'system' has no topography: set its heights with "
                "asp_system_set_topography before solving (an array of zeros, such as "
                "asp_topography_flat makes, is a flat surface)");
}

void require_finite_heights(const Grid &grid, const double *heights, std::int64_t n) {
  for (std::int64_t i = 0; i < n; ++i) {
    if (std::isfinite(heights[i])) continue;
    const std::int64_t x = i % grid.nx(), y = grid.row_offset() + i / grid.nx();
    const std::string pixel = grid.dimension() == 1
                                  ? "x = " + std::to_string(x)
                                  : "x = " + std::to_string(x) + ", y = " + std::to_string(y);
    throw Error(Status::invalid_argument,
                "array 'heights' has " + format_number(heights[i]) + " at pixel (" + pixel +
                    "), index " + std::to_string(i) +
                    (grid.partition() != nullptr ? " of this process's rows" : "") +
                    "; heights must be finite");
  }
}

}  // namespace asp::capi

extern "C" {

int asp_topography_detrend(const asp_grid *grid, int mode, double *heights, int64_t n) {
  return guarded_on("asp_topography_detrend", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    asp::capi::require_member(mode, asp::capi::Family::detrend, "mode");
    const asp::Detrend detrend = mode == ASP_DETREND_MEAN    ? asp::Detrend::mean
                                 : mode == ASP_DETREND_PLANE ? asp::Detrend::plane
                                                             : asp::Detrend::curvature;
    asp::capi::require_finite_heights(g, heights, n);
    agreement.checks_passed({Agreement::bits(mode)}, "argument 'mode'");
    asp::detrend_topography(g, detrend, heights);
  });
}

int asp_topography_flat(const asp_grid *grid, double *heights, int64_t n) {
  return guarded_on("asp_topography_flat", grid_of(grid), [&](Agreement &) {
    asp::flat_topography(grid_for(grid, heights, n), heights);
  });
}

int asp_topography_sphere(const asp_grid *grid, double radius, double *heights, int64_t n) {
  return guarded_on("asp_topography_sphere", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    agreement.checks_passed({radius}, "argument 'radius'");
    asp::sphere_topography(g, radius, heights);
  });
}

int asp_topography_paraboloid(const asp_grid *grid, double radius, double *heights, int64_t n) {
  return guarded_on("asp_topography_paraboloid", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    agreement.checks_passed({radius}, "argument 'radius'");
    asp::paraboloid_topography(g, radius, heights);
  });
}

int asp_topography_sinusoid(const asp_grid *grid, double amplitude, int64_t periods_x,
                            int64_t periods_y, double *heights, int64_t n) {
  return guarded_on("asp_topography_sinusoid", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    agreement.checks_passed({amplitude, Agreement::bits(periods_x), Agreement::bits(periods_y)},
                            "arguments 'amplitude', 'periods_x' and 'periods_y'");
    asp::sinusoid_topography(g, amplitude, periods_x, periods_y, heights);
  });
}

int asp_topography_double_sinewave(const asp_grid *grid, double amplitude, double ripple_amplitude,
                                   int64_t ripple_periods, double *heights, int64_t n) {
  return guarded_on("asp_topography_double_sinewave", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    agreement.checks_passed({amplitude, ripple_amplitude, Agreement::bits(ripple_periods)},
                            "arguments 'amplitude', 'ripple_amplitude' and 'ripple_periods'");
    asp::double_sinewave_topography(g, amplitude, ripple_amplitude, ripple_periods, heights);
  });
}

int asp_topography_self_affine(const asp_grid *grid, double hurst, double long_cutoff,
                               double rolloff, double short_cutoff, int normalise, double target,
                               int64_t seed, double *heights, int64_t n) {
  return guarded_on("asp_topography_self_affine", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    asp::capi::require_member(normalise, asp::capi::Family::normalisation, "normalise");
    asp::SelfAffineParameters p;
    p.hurst = hurst;
    p.long_cutoff = long_cutoff;
    p.rolloff = rolloff;
    p.short_cutoff = short_cutoff;
    p.norm = normalise == ASP_RMS_HEIGHT ? asp::RoughnessNorm::rms_height
                                         : asp::RoughnessNorm::rms_slope;
    p.target = target;
    p.seed = static_cast<std::uint64_t>(seed);
    agreement.checks_passed({hurst, long_cutoff, rolloff, short_cutoff, Agreement::bits(normalise),
                             target, Agreement::bits(seed)},
                            "the generator's parameters (hurst, cutoffs, normalise, target, seed)");
    asp::self_affine_topography(g, p, heights);
  });
}

int asp_topography_statistics(const asp_grid *grid, const double *heights, int64_t n,
                              double *rms_height, double *rms_slope, double *rms_curvature) {
  return guarded_on("asp_topography_statistics", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    asp::capi::require_finite_heights(g, heights, n);
    agreement.checks_passed();
    asp::surface_statistics(g, heights, rms_height, rms_slope, rms_curvature);
  });
}

int asp_topography_power_spectrum(const asp_grid *grid, const double *heights, int64_t n,
                                  int64_t n_bins, double *q, double *c) {
  return guarded_on("asp_topography_power_spectrum", grid_of(grid), [&](Agreement &agreement) {
    const asp::Grid &g = grid_for(grid, heights, n);
    asp::capi::require_finite_heights(g, heights, n);
    asp::require_not_null(q, "q");
    asp::require_not_null(c, "c");
    agreement.checks_passed({Agreement::bits(n_bins)}, "argument 'n_bins'");
    asp::radial_power_spectrum(g, heights, n_bins, q, c);
  });
}

}  // extern "C"
