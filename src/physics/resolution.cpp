// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/resolution.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "physics/interaction.hpp"
#include "physics/potential.hpp"
#include "physics/system.hpp"

namespace asp {
namespace {

// log(pi/4)
const double log_quarter_pi = std::log(0.78539816339744830962);

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// The smaller side of a pixel: lx/nx, and ly/ny in 2D.
double pixel_size(const Grid &grid) {
  const double dx = grid.lx() / static_cast<double>(grid.nx());
  if (grid.dimension() == 1) return dx;
  return std::min(dx, grid.ly() / static_cast<double>(grid.ny()));
}

// A cohesive zone of logarithm log_length compared with the pixel dx. The lengths are
// formed as logarithms so that no product of extreme parameters overflows on the way.
// `zone` says what the zone is of, `remedy` what lengthens it.
Resolution compared(double log_length, double dx, const std::string &zone,
                    const std::string &remedy) {
  Resolution r;
  const double log_ratio = log_length - std::log(dx);
  r.ratio = log_ratio >= std::log(DBL_MAX)   ? DBL_MAX
            : log_ratio <= std::log(DBL_MIN) ? DBL_MIN
                                             : std::exp(log_ratio);
  r.resolved = r.ratio >= resolution_threshold;
  const double length = std::exp(log_length);
  const std::string lengths =
      std::isfinite(length) ? " (" + number(length) + " against a pixel of " + number(dx) + ")"
                            : "";
  r.sentence = zone + " is " + number(r.ratio) + " pixels" + lengths;
  if (r.resolved)
    r.sentence = "resolved: " + r.sentence + ", at least about one pixel";
  else
    r.sentence = "not resolved: " + r.sentence +
                 ", below about one pixel: the discrete problem has many metastable states "
                 "(lattice trapping), and a solver may stall or end in one of them; " + remedy;
  return r;
}

Resolution nothing_to_resolve(const std::string &why) {
  Resolution r;
  r.sentence = "resolved: " + why;
  return r;
}

// The exponential soft wall phi = c_r exp(-g/r_r) - c_a exp(-g/r_a) (r_r = rho_r/2). With
// m = r_a/r_r > 1 its well lies at u* = exp(-g*/r_a) = (m c_r/c_a)^(-1/(m-1)), of depth
// w = c_a u* (1 - 1/m), and its largest tensile stress at the inflection,
// u_i = (m^2 c_r/c_a)^(-1/(m-1)), is s = (c_a/r_a) u_i (1 - 1/m); so
//   w/s^2 = r_a^2 (m^3 c_r/c_a)^(1/(m-1)) / (c_a (1 - 1/m)),
// 16 c_r rho^2/c_a^2 with one range (m = 2).
Resolution soft_wall(const SoftWallPotential &wall, double e_star, double dx) {
  const double c_r = wall.repulsion().coefficient, r_r = wall.repulsion().range;
  const double c_a = -wall.attraction().coefficient, r_a = wall.attraction().range;
  if (!(c_a > 0.0))
    return nothing_to_resolve(
        "the soft wall has no attraction (gamma_a = 0): the problem is convex, with one "
        "equilibrium, and there is no cohesive zone to resolve");
  const double m = r_a / r_r;
  if (!(m > 1.0))
    return nothing_to_resolve(
        "the soft wall's attraction fades no slower than its repulsion (rho_a <= rho_r/2), "
        "so it has no adhesive well and no cohesive zone to resolve");
  const double log_ratio_of_strengths = std::log(c_r) - std::log(c_a);
  const double log_work = std::log(c_a) - (std::log(m) + log_ratio_of_strengths) / (m - 1.0) +
                          std::log1p(-1.0 / m);
  const double log_stress = std::log(c_a / r_a) -
                            (2.0 * std::log(m) + log_ratio_of_strengths) / (m - 1.0) +
                            std::log1p(-1.0 / m);
  const double log_length = log_quarter_pi + std::log(e_star) + log_work - 2.0 * log_stress;
  const double work = std::exp(log_work), stress = std::exp(log_stress);
  const bool shown = std::isfinite(work) && work > 0.0 && std::isfinite(stress) && stress > 0.0;
  return compared(log_length, dx,
                  "the cohesive zone (pi/4) E* w/s^2 of the soft wall" +
                      (shown ? " (w = " + number(work) + " the depth of its well, s = " +
                                   number(stress) + " its largest tensile stress)"
                             : std::string()),
                  "use a finer grid or longer ranges");
}

}  // namespace

Resolution resolution(const System &system) {
  const Interaction &interaction = system.interaction();
  const double e_star = system.substrate().contact_modulus();
  const double dx = pixel_size(system.grid());
  switch (interaction.kind()) {
    case InteractionKind::hard_wall:
      return nothing_to_resolve(
          "the plain hard wall has no interaction length, so there is nothing for the grid "
          "to resolve");
    case InteractionKind::adhesive_hard_wall: {
      const ExponentialAdhesion &a = *exponential_adhesion(interaction);
      const double log_length = log_quarter_pi + std::log(e_star) +
                                2.0 * std::log(a.range()) - std::log(a.work());
      return compared(log_length, dx,
                      "the cohesive zone (pi/4) E* rho^2/w of the exponential adhesion",
                      "use a finer grid or a longer range");
    }
    case InteractionKind::soft_wall:
      return soft_wall(
          static_cast<const SoftWallPotential &>(potential_interaction(interaction)->potential()),
          e_star, dx);
    case InteractionKind::lennard_jones: {
      const auto &lj = static_cast<const LennardJonesPotential &>(
          potential_interaction(interaction)->potential());
      // s = (27/10) (2/5)^(2/3) w/z0, its largest tensile stress.
      const double log_stress = std::log(lj.pressure_scale());
      const double log_length = log_quarter_pi + std::log(e_star) +
                                std::log(lj.work_of_adhesion()) - 2.0 * log_stress;
      return compared(log_length, dx,
                      "the cohesive zone (pi/4) E* w/s^2 of the Lennard-Jones wall (s = "
                      "1.466 w/z0 its largest tensile stress)",
                      "use a finer grid or a larger equilibrium distance");
    }
    case InteractionKind::user_potential:
    case InteractionKind::user_potential_hard_wall: {
      Resolution r;
      r.resolved = false;
      r.sentence =
          "unknown: a user's potential has no length the library knows, so it cannot tell "
          "whether the grid resolves it; compare its cohesive zone (pi/4) E* w/s^2 (w the "
          "depth of its well, s its largest tensile stress) with the pixel, " +
          number(dx) +
          ": below about one pixel the discrete problem has many metastable states (lattice "
          "trapping)";
      return r;
    }
  }
  throw Error(Status::internal, "an interaction without a resolution rule");
}

}  // namespace asp
