#include "physics/interaction.hpp"

#include "core/loops.hpp"
#include "physics/system.hpp"

namespace asp {

const char *interaction_name(InteractionKind kind) {
  switch (kind) {
    case InteractionKind::hard_wall: return "non-adhesive hard wall";
    case InteractionKind::adhesive_hard_wall: return "adhesive hard wall";
  }
  return "unknown";
}

double Interaction::contact_fraction(const Grid &grid, const ContactState &state) const {
  const double *p = state.pressure.data();
  const double count = loops::sum(grid.reductions(), grid.n_pixels(),
                                  [&](std::int64_t i) { return p[i] > 0.0 ? 1.0 : 0.0; });
  return count / static_cast<double>(grid.n_pixels());
}

double ExponentialAdhesion::energy(const Grid &grid, const ContactState &state) const {
  // The gap of a consistent state is >= 0 up to rounding; phi is defined on the wall's side.
  const double *g = state.gap.data();
  const ExponentialPotential phi = potential_;
  const double total = loops::sum(grid.reductions(), grid.n_pixels(), [&](std::int64_t i) {
    return phi.phi(g[i] > 0.0 ? g[i] : 0.0);
  });
  return grid.pixel_area() * total;
}

}  // namespace asp
