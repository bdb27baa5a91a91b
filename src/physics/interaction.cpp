// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/interaction.hpp"

#include "core/loops.hpp"
#include "physics/system.hpp"

namespace asp {

const char *interaction_name(InteractionKind kind) {
  switch (kind) {
    case InteractionKind::hard_wall: return "non-adhesive hard wall";
    case InteractionKind::adhesive_hard_wall: return "adhesive hard wall";
    case InteractionKind::soft_wall: return "soft wall";
    case InteractionKind::lennard_jones: return "Lennard-Jones wall";
    case InteractionKind::user_potential: return "user potential";
    case InteractionKind::user_potential_hard_wall: return "user potential with hard wall";
  }
  return "unknown";
}

const char *family_name(InteractionFamily family) {
  switch (family) {
    case InteractionFamily::hard_wall: return "non-adhesive hard wall";
    case InteractionFamily::hard_wall_with_potential: return "hard wall with a potential";
    case InteractionFamily::soft_potential: return "soft potential";
  }
  return "unknown";
}

void Interaction::contact_map(const Grid &grid, const ContactState &state, double *out) const {
  const double *g = state.gap.data();
  loops::for_each(grid.local_pixels(), [&](std::int64_t i) { out[i] = g[i] <= 0.0 ? 1.0 : 0.0; });
}

namespace {
// The number of local pixels i for which counted(i, in_contact) holds, in_contact saying
// whether pixel i is in contact: from the gap with the wall, from the contact map without it
// (a temporary field only then).
template <class Count>
double count_in_contact(const Interaction &interaction, const Grid &grid,
                        const ContactState &state, Count &&counted) {
  const double *g = state.gap.data();
  if (interaction.has_hard_wall())
    return loops::sum(grid.reductions(), grid.local_pixels(),
                      [&](std::int64_t i) { return counted(i, g[i] <= 0.0) ? 1.0 : 0.0; });
  Field map = grid.make_field();
  interaction.contact_map(grid, state, map.data());
  const double *c = map.data();
  return loops::sum(grid.reductions(), grid.local_pixels(),
                    [&](std::int64_t i) { return counted(i, c[i] > 0.0) ? 1.0 : 0.0; });
}
}  // namespace

double Interaction::contact_fraction(const Grid &grid, const ContactState &state) const {
  const double count = count_in_contact(*this, grid, state,
                                        [](std::int64_t, bool in_contact) { return in_contact; });
  return count / static_cast<double>(grid.n_pixels());
}

double Interaction::compressive_fraction(const Grid &grid, const ContactState &state) const {
  const double *p = state.pressure.data();
  const double count =
      count_in_contact(*this, grid, state, [&](std::int64_t i, bool in_contact) {
        return in_contact && p[i] > 0.0;
      });
  return count / static_cast<double>(grid.n_pixels());
}

double ExponentialAdhesion::energy(const Grid &grid, const ContactState &state) const {
  // The gap of a consistent state is >= 0 up to rounding; phi is defined on the wall's side.
  const double *g = state.gap.data();
  const ExponentialPotential phi = potential_;
  const double total = loops::sum(grid.reductions(), grid.local_pixels(), [&](std::int64_t i) {
    return phi.phi(g[i] > 0.0 ? g[i] : 0.0);
  });
  return grid.pixel_area() * total;
}

void PotentialInteraction::evaluate_on(const Grid &grid, const ContactState &state, Field &phi,
                                       Field &slope) const {
  const std::int64_t n = grid.local_pixels();
  phi = grid.make_field();
  slope = grid.make_field();
  // With the hard wall, phi is defined on the wall's side (g >= 0 up to rounding).
  const double *gap = state.gap.data();
  Field clipped;
  if (has_hard_wall()) {
    clipped = grid.make_field();
    double *c = clipped.data();
    loops::for_each(n, [&](std::int64_t i) { c[i] = gap[i] > 0.0 ? gap[i] : 0.0; });
    gap = c;
  }
  potential_->evaluate(n, gap, phi.data(), slope.data(), nullptr);
}

double PotentialInteraction::energy(const Grid &grid, const ContactState &state) const {
  Field phi, slope;
  evaluate_on(grid, state, phi, slope);
  const double *f = phi.data();
  return grid.pixel_area() *
         loops::sum(grid.reductions(), grid.local_pixels(), [&](std::int64_t i) { return f[i]; });
}

void PotentialInteraction::contact_map(const Grid &grid, const ContactState &state,
                                       double *out) const {
  if (has_hard_wall()) {
    Interaction::contact_map(grid, state, out);
    return;
  }
  // Without a wall, the pixels the potential pushes apart, phi'(g) < 0: the sign of the
  // pressure would do as well at equilibrium, but far from contact that pressure is an
  // attraction below rounding, and its sign is noise. phi' < 0 is a property of the gap
  // alone, which a soft wall's range resolves: it changes sign once, at the potential's
  // minimum, where the gap is of the order of the range, not of rounding.
  Field phi, slope;
  evaluate_on(grid, state, phi, slope);
  const double *d = slope.data();
  loops::for_each(grid.local_pixels(), [&](std::int64_t i) { out[i] = d[i] < 0.0 ? 1.0 : 0.0; });
}

}  // namespace asp
