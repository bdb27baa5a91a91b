// The interaction between the rigid surface and the substrate: an energy per unit area phi(g)
// of the gap, with or without a hard wall g >= 0. Observables that depend on it (which pixels
// count as in contact, the interaction energy) are asked of it.
//
// Two interactions exist: the non-adhesive hard wall, which evaluates no potential at all, and
// the hard wall with exponential adhesion. The adhesive potential is offered element-wise as
// inline functions of a small value type (ExponentialPotential), so that a formulation fuses it
// into its own passes without a virtual call per pixel.
#pragma once

#include <cmath>

#include "core/grid.hpp"

namespace asp {

struct ContactState;

enum class InteractionKind { hard_wall, adhesive_hard_wall };
const char *interaction_name(InteractionKind kind);

class Interaction {
 public:
  virtual ~Interaction() = default;
  virtual InteractionKind kind() const = 0;
  // Fraction of pixels in repulsive contact (positive pressure).
  virtual double contact_fraction(const Grid &grid, const ContactState &state) const;
  // a sum_i phi(g_i) (per unit length in 1D).
  virtual double energy(const Grid &grid, const ContactState &state) const = 0;
};

// g >= 0 and phi = 0: a pixel is in contact when it carries positive pressure.
class HardWall final : public Interaction {
 public:
  InteractionKind kind() const override { return InteractionKind::hard_wall; }
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

// The hard wall with exponential adhesion. A pixel is in repulsive contact when it carries
// positive pressure, as for the plain hard wall: pixels on the wall near the edge of a contact
// may be under tension.
class ExponentialAdhesion final : public Interaction {
 public:
  // work > 0 and range > 0 (System::set_adhesion checks them).
  ExponentialAdhesion(double work, double range) : potential_{work, range} {}
  InteractionKind kind() const override { return InteractionKind::adhesive_hard_wall; }
  double energy(const Grid &grid, const ContactState &state) const override;

  const ExponentialPotential &potential() const { return potential_; }
  double work() const { return potential_.work; }
  double range() const { return potential_.range; }

 private:
  ExponentialPotential potential_;
};

// The exponential adhesion of an interaction, or null if it has none.
inline const ExponentialAdhesion *exponential_adhesion(const Interaction &interaction) {
  return interaction.kind() == InteractionKind::adhesive_hard_wall
             ? static_cast<const ExponentialAdhesion *>(&interaction)
             : nullptr;
}

}  // namespace asp
