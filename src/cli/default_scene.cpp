// SPDX-License-Identifier: GPL-2.0-or-later
// The built-in scene: what `asperity` solves with no arguments.
#include "scene.hpp"

namespace cli {

const char *const default_scene_text = R"scene(# The built-in scene of the asperity command: a 2D adhesive rough contact.
# Save it with `asperity --print-scene > my.toml`, change it, and run `asperity run my.toml`.
title = "adhesive rough contact (built-in)"

[grid]
nx = 512              # pixels along x
ny = 512              # pixels along y (1: a one-dimensional, line contact)
lx = 1.0              # box size; ly defaults to lx * ny / nx
unit = ""             # length unit of the scene (m, mm, um, nm, ...); "" dimensionless

[substrate]
type = "periodic"     # periodic, free (non-periodic) for measured surfaces, or layer
                      # (an elastic layer on a rigid base: thickness, poisson_ratio)
contact_modulus = 1.0 # E*: pressures are in its unit

[topography]
type = "self_affine"  # self-affine Gaussian random surface
hurst = 0.8
rolloff = 0.25        # roll-off wavelength: a quarter of the box
short_cutoff = 0.015625  # short cutoff wavelength: 8 pixels
rms_slope = 0.1
seed = 1

[interaction]
type = "soft_wall"    # the exponential soft wall of the thesis (eqs. 12-13)
gamma_r = 3.2e-4      # repulsion strength (energy per area, E* times length)
gamma_a = 8.0e-5      # attraction strength: work of adhesion gamma_a^2/(4 gamma_r) = 5e-6,
                      # largest tensile stress gamma_a/(32 range) = 0.025 E*
range = 1.0e-4        # range of both exponentials, about 1/40 of the rms height

[control]
quantity = "mean_pressure"
value = 0.002         # in units of E*

[solver]
algorithm = "lbfgs_fourier"
tolerance = 1e-8

[output]
fields = ["pressure", "gap", "contact"]
)scene";

}  // namespace cli
