// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/scene_units.hpp"

#include <cfloat>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {
namespace {
// Scaled numbers beyond this would leave too little room for sums of squares over a grid.
constexpr double largest_scaled = 1e100;

bool representable(double v) { return std::isfinite(v) && std::fabs(v) <= DBL_MAX / 16; }
bool normal(double v) { return std::isfinite(v) && v >= DBL_MIN; }
}  // namespace

SceneUnits scene_units(const System &system, Control control, double value) {
  const Substrate &substrate = system.substrate();
  const bool load = control == Control::mean_pressure;
  const double k = substrate.pixel_stiffness();
  const ExponentialAdhesion *adhesion = exponential_adhesion(system.interaction());
  // The stiffness of the mean displacement: K~(0) on a periodic substrate.
  const double k_mean = substrate.uniform_pressure_stiffness();
  double control_scale = load ? std::fabs(value) : k_mean * std::fabs(value);
  if (!std::isfinite(control_scale)) control_scale = 0.0;
  const PotentialInteraction *soft = potential_interaction(system.interaction());
  const double tensile_stress = adhesion != nullptr ? adhesion->work() / adhesion->range()
                                : soft != nullptr   ? soft->potential().pressure_scale()
                                                    : 0.0;
  if (tensile_stress > control_scale) control_scale = tensile_stress;
  SceneUnits units;
  units.pressure = system.reference_pressure(control_scale);
  units.length = units.pressure / k;
  units.energy = system.grid().pixel_area() * units.pressure * units.length;
  units.target = load ? value / units.pressure : value / units.length;
  const double n = static_cast<double>(system.grid().n_pixels());

  // The scene in these units, and what its results will need in physical units.
  const double range = system.height_range() / units.length;
  // Under load control the mean displacement pbar/K~(0) joins the penetration; a soft mean
  // mode (small K~(0)) makes it much larger than the pressure scale.
  const double mean_displacement = load ? std::fabs(units.target) * (k / k_mean) : 0.0;
  if (!normal(units.pressure) || !normal(units.length))
    throw Error(Status::invalid_argument,
                "the scene's pressure scale " + format_number(units.pressure) +
                    " or length scale " + format_number(units.length) +
                    " is not a normal double; rescale the modulus or the heights");
  double stress = 0.0;  // w/rho in units of P
  if (adhesion != nullptr) {
    // phi' at most w/rho, phi'' at most w/rho^2: both must stay well inside doubles in these
    // units (the latter is the adhesive stiffness per pixel stiffness), and so must the work.
    stress = tensile_stress / units.pressure;
    units.adhesion_range = adhesion->range() / units.length;
    units.adhesion_work = stress * units.adhesion_range;
    const double stiffness = stress / units.adhesion_range;
    if (!(stress <= largest_scaled) || !(stiffness <= largest_scaled) ||
        !(units.adhesion_work <= largest_scaled) || !normal(units.adhesion_range))
      throw Error(Status::invalid_argument,
                  "the adhesion (work " + format_number(adhesion->work()) + ", range " +
                      format_number(adhesion->range()) + ") is out of proportion with the " +
                      "scene's pressure scale " + format_number(units.pressure) +
                      " and length scale " + format_number(units.length) +
                      ": w/rho, w/rho^2 or the work would not be representable in the solve; "
                      "rescale the adhesion or set a reference pressure");
  }
  if (soft != nullptr) {
    // Its pressures and range must be representable in these units, with room to spare. A
    // user's potential has no range known beforehand (length scale 0): its values are
    // checked as they come instead.
    stress = tensile_stress / units.pressure;
    const double length_scale = soft->potential().length_scale();
    const double range_scaled = length_scale / units.length;
    const bool range_fits = length_scale == 0.0 || (range_scaled <= largest_scaled &&
                                                    range_scaled >= 1.0 / largest_scaled);
    if (!(stress <= largest_scaled) || !range_fits)
      throw Error(Status::invalid_argument,
                  "the " + soft->potential().description() +
                      " is out of proportion with the scene's pressure scale " +
                      format_number(units.pressure) + " and length scale " +
                      format_number(units.length) +
                      ": its pressures or its range would not be representable in the solve; "
                      "rescale the potential or set a reference pressure");
  }
  // Pressures reach the adhesion's tensile stress besides the scales of the load and heights.
  const double extent = 1.0 + std::fabs(units.target) + range + mean_displacement + stress;
  if (!(std::fabs(units.target) <= largest_scaled))
    throw Error(Status::invalid_argument,
                "argument 'value' is " + format_number(value) + ", " +
                    format_number(std::fabs(units.target)) + " times the scene's " +
                    (load ? "pressure" : "length") + " scale " +
                    format_number(load ? units.pressure : units.length) +
                    "; such a solve cannot be represented in doubles");
  if (!(range <= largest_scaled) || !(mean_displacement <= largest_scaled) ||
      !representable(units.pressure * n * extent) || !representable(units.length * n * extent) ||
      !representable(units.energy * n * extent * extent) ||
      !representable(units.energy * n * units.adhesion_work))
    throw Error(Status::invalid_argument,
                "argument 'value' is " + format_number(value) + ": with heights spanning " +
                    format_number(system.height_range()) +
                    " and a stiffness under uniform pressure (K~(0) if periodic) of " +
                    format_number(k_mean) +
                    " the pressures, gaps, displacements or energies of this solve would "
                    "overflow a double; rescale the units");
  return units;
}

}  // namespace asp
