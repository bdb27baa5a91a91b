#include "physics/interaction.hpp"

#include "core/loops.hpp"
#include "physics/system.hpp"

namespace asp {

const char *interaction_name(InteractionKind kind) {
  switch (kind) {
    case InteractionKind::hard_wall: return "non-adhesive hard wall";
  }
  return "unknown";
}

double HardWall::contact_fraction(const Grid &grid, const ContactState &state) const {
  const double *p = state.pressure.data();
  const double count = loops::sum(grid.reductions(), grid.n_pixels(),
                                  [&](std::int64_t i) { return p[i] > 0.0 ? 1.0 : 0.0; });
  return count / static_cast<double>(grid.n_pixels());
}

}  // namespace asp
