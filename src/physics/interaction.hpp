// The interaction between the rigid surface and the substrate: an energy per unit area phi(g)
// of the gap, with or without a hard wall g >= 0. Observables that depend on it (which pixels
// count as in contact, the interaction energy) are asked of it.
//
// Only the non-adhesive hard wall exists so far; it evaluates no potential at all.
#pragma once

#include "core/grid.hpp"

namespace asp {

struct ContactState;

enum class InteractionKind { hard_wall };
const char *interaction_name(InteractionKind kind);

class Interaction {
 public:
  virtual ~Interaction() = default;
  virtual InteractionKind kind() const = 0;
  // Fraction of pixels in repulsive contact.
  virtual double contact_fraction(const Grid &grid, const ContactState &state) const = 0;
  // a sum_i phi(g_i) (per unit length in 1D).
  virtual double energy(const Grid &grid, const ContactState &state) const = 0;
};

// g >= 0 and phi = 0: a pixel is in contact when it carries positive pressure.
class HardWall final : public Interaction {
 public:
  InteractionKind kind() const override { return InteractionKind::hard_wall; }
  double contact_fraction(const Grid &grid, const ContactState &state) const override;
  double energy(const Grid &, const ContactState &) const override { return 0.0; }
};

}  // namespace asp
