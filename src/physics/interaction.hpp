// SPDX-License-Identifier: GPL-2.0-or-later
// The interaction between the rigid surface and the substrate: an energy per unit area phi(g)
// of the gap, with or without a hard wall g >= 0. Observables that depend on it (which pixels
// count as in contact, the interaction energy) are asked of it.
//
// The non-adhesive hard wall evaluates no potential at all. The hard wall with exponential
// adhesion offers its potential element-wise as inline functions of a small value type
// (ExponentialPotential), so that a formulation fuses it into its own passes without a
// virtual call per pixel. Every other interaction is a Potential (potential.hpp), evaluated
// over many gaps at once: a soft wall, which the gap may cross, or a user's potential with or
// without the hard wall.
#pragma once

#include <cmath>
#include <memory>

#include "core/grid.hpp"
#include "physics/potential.hpp"

namespace asp {

struct ContactState;

enum class InteractionKind {
  hard_wall,
  adhesive_hard_wall,
  soft_wall,                 // SoftWallPotential, no hard wall
  lennard_jones,             // the 9-3 wall potential, no hard wall
  user_potential,            // a user's callback, no hard wall
  user_potential_hard_wall,  // a user's callback with the hard wall g >= 0
};
const char *interaction_name(InteractionKind kind);

// What an interaction is to a solver: the hard wall alone (no potential to evaluate), the
// hard wall with a potential on the open gap, or a soft potential that the gap may cross.
enum class InteractionFamily { hard_wall, hard_wall_with_potential, soft_potential };
const char *family_name(InteractionFamily family);

// Solvers ask an interaction what it can do (family(), whether its potential is a user's
// callback, known only by its values); kind() names it in reports and messages.
class Interaction {
 public:
  virtual ~Interaction() = default;
  virtual InteractionKind kind() const = 0;
  virtual InteractionFamily family() const = 0;
  // Whether the potential is a user's callback: the library knows its values, not its
  // range, its largest tension or a bound on its curvature.
  virtual bool potential_from_callback() const { return false; }
  // The contact map of a state: 1.0 on the pixels in contact, 0.0 elsewhere, into out (the
  // grid's local pixels). With the hard wall, the pixels on the wall, g <= 0: every solve
  // leaves g exactly 0 on its active set and >= 0 elsewhere, so that the rule is never a
  // decision on the sign of rounding (a state kept from a soft wall may have g < 0, and
  // those pixels touch too). Without it (soft walls), where the potential repels:
  // PotentialInteraction.
  virtual void contact_map(const Grid &grid, const ContactState &state, double *out) const;
  // Whether the hard wall g >= 0 bounds the gap (every interaction but the soft walls).
  bool has_hard_wall() const { return family() != InteractionFamily::soft_potential; }
  // The mean of the contact map (a count of pixels over their number, exact in doubles, so
  // that the mean of contact_map() taken anywhere gives the same number).
  double contact_fraction(const Grid &grid, const ContactState &state) const;
  // The fraction of pixels in contact that carry compressive (positive) pressure: the
  // contact's repulsive core. With adhesion, pixels on the wall near a contact's edge are
  // under tension and do not count; off contact the sign of a pressure of rounding size
  // decides nothing, because only contact pixels are asked.
  double compressive_fraction(const Grid &grid, const ContactState &state) const;
  // a sum_i phi(g_i) (per unit length in 1D).
  virtual double energy(const Grid &grid, const ContactState &state) const = 0;
};

// g >= 0 and phi = 0: a pixel is in contact when it is on the wall (g = 0).
class HardWall final : public Interaction {
 public:
  InteractionKind kind() const override { return InteractionKind::hard_wall; }
  InteractionFamily family() const override { return InteractionFamily::hard_wall; }
  double energy(const Grid &, const ContactState &) const override { return 0.0; }
};

// phi(g) = -w exp(-g/rho) for g >= 0 (thesis eq. 11) and its derivatives, in whatever units
// work and range are given in. The equilibrium pressure away from the wall is
// -phi'(g) = -(w/rho) exp(-g/rho): tensile, at most w/rho in magnitude (at g = 0). phi is
// concave (phi'' < 0): the adhesive energy softens the elastic Hessian.
struct ExponentialPotential {
  double work;   // w
  double range;  // rho

  struct Terms {
    double phi, dphi, d2phi;
  };
  // phi, phi' and phi'' from one exponential.
  Terms at(double g) const {
    const double e = std::exp(-g / range);
    const double phi = -work * e;
    return {phi, -phi / range, phi / (range * range)};
  }
  double phi(double g) const { return -work * std::exp(-g / range); }
  double dphi(double g) const { return work / range * std::exp(-g / range); }
  double d2phi(double g) const { return -work / (range * range) * std::exp(-g / range); }
};

// The hard wall with exponential adhesion. A pixel is in contact when it is on the wall
// (g = 0), as for the plain hard wall: that is the JKR/Maugis contact area, whose pixels near
// the edge are under tension (compressive_fraction counts the compressive core only).
class ExponentialAdhesion final : public Interaction {
 public:
  // work > 0 and range > 0 (System::set_adhesion checks them).
  ExponentialAdhesion(double work, double range) : potential_{work, range} {}
  InteractionKind kind() const override { return InteractionKind::adhesive_hard_wall; }
  InteractionFamily family() const override {
    return InteractionFamily::hard_wall_with_potential;
  }
  double energy(const Grid &grid, const ContactState &state) const override;

  const ExponentialPotential &potential() const { return potential_; }
  double work() const { return potential_.work; }
  double range() const { return potential_.range; }

 private:
  ExponentialPotential potential_;
};

// A Potential, with or without the hard wall g >= 0. With the wall a pixel is in contact when
// it is on the wall (g = 0), as for the other hard walls; without it, where the potential
// repels (phi'(g) < 0).
class PotentialInteraction final : public Interaction {
 public:
  // kind: soft_wall, lennard_jones, user_potential (without the wall) or
  // user_potential_hard_wall (with it).
  PotentialInteraction(InteractionKind kind, std::unique_ptr<Potential> potential)
      : kind_(kind), potential_(std::move(potential)) {}
  InteractionKind kind() const override { return kind_; }
  InteractionFamily family() const override {
    return kind_ == InteractionKind::user_potential_hard_wall
               ? InteractionFamily::hard_wall_with_potential
               : InteractionFamily::soft_potential;
  }
  bool potential_from_callback() const override {
    return kind_ == InteractionKind::user_potential ||
           kind_ == InteractionKind::user_potential_hard_wall;
  }
  // Both evaluate the potential (a user's callback may throw Error(callback)); contact_map,
  // and the fractions that use it, only without the hard wall.
  void contact_map(const Grid &grid, const ContactState &state, double *out) const override;
  double energy(const Grid &grid, const ContactState &state) const override;

  const Potential &potential() const { return *potential_; }

 private:
  // phi and phi' at the state's gaps (clipped at the wall if there is one).
  void evaluate_on(const Grid &grid, const ContactState &state, Field &phi, Field &slope) const;

  InteractionKind kind_;
  std::unique_ptr<Potential> potential_;
};

// The potential of an interaction, or null if it has none of this kind.
inline const PotentialInteraction *potential_interaction(const Interaction &interaction) {
  return dynamic_cast<const PotentialInteraction *>(&interaction);
}

// The exponential adhesion of an interaction, or null if it has none.
inline const ExponentialAdhesion *exponential_adhesion(const Interaction &interaction) {
  return dynamic_cast<const ExponentialAdhesion *>(&interaction);
}

}  // namespace asp
