// SPDX-License-Identifier: GPL-2.0-or-later
// A contact problem on a grid: the substrate, the interaction, the rigid topography and the
// current state. The state is kept between solves so that a load sweep warm-starts.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include "core/aligned_field.hpp"
#include "core/grid.hpp"
#include "core/loops.hpp"
#include "physics/interaction.hpp"
#include "physics/stiffness_law.hpp"
#include "physics/substrate.hpp"

namespace asp {

// The state every solver leaves behind. With the hard wall the gap is exactly 0 on the
// solver's active set (the pixels in contact) and >= 0 elsewhere, however the solve ended;
// it differs from the gap the pressure makes, K^-1 pressure - (h - max h) - penetration, by
// the residual of the solver's last iterate (see asp_system_get_field in asperity.h):
// a pressure solve stores its pressure iterate and the projection of that gap (0 where
// p > 0, > 0 elsewhere), a gap solve its gap iterate and the hard wall's reading
// of the pressure. Without the wall (soft walls) they are consistent to rounding.
struct ContactState {
  Field pressure;
  Field gap;
  double penetration = 0.0;
};

// One pixel of a solved state, in physical units, as a formulation reads it from its
// iterate: the pressure, the gap, and (with the hard wall) whether the pixel is on the wall,
// in the solver's active set.
struct SolvedPixel {
  double pressure;
  double gap;
  bool on_wall;
};

class System {
 public:
  // A half-space of the given kind (periodic, or free on a 2D grid: see free_halfspace.hpp)
  // with a non-adhesive hard wall and a flat topography. The system holds a reference to the
  // grid, which therefore outlives every system made on it.
  System(std::shared_ptr<const Grid> grid, double contact_modulus,
         SubstrateKind substrate = SubstrateKind::periodic);
  // A periodic substrate with the given stiffness law (a layer on a rigid base, ...), not
  // null; otherwise as above.
  System(std::shared_ptr<const Grid> grid, std::unique_ptr<const StiffnessLaw> law);

  const Grid &grid() const { return *grid_; }
  const Substrate &substrate() const { return *substrate_; }
  const Interaction &interaction() const { return *interaction_; }
  // The interaction: the hard wall with exponential adhesion phi(g) = -w exp(-g/rho), or the
  // plain hard wall for work 0. Refuses (Error(invalid_argument), naming the argument) a work
  // that is negative or not finite, a range that is not positive and finite, and a largest
  // tensile stress w/rho that is not a finite, normal double. Nothing else changes: the state
  // is kept as it is (an equilibrium of the old interaction, no longer of the new one), so
  // that the next solve starts from it.
  void set_adhesion(double work, double range);
  // The plain, non-adhesive hard wall (the default).
  void set_hard_wall();
  // The soft wall phi(g) = gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a) (SoftWallPotential):
  // gamma_r, rho_r, rho_a > 0, gamma_a >= 0, finite, and 4 gamma_r/rho_r^2 > gamma_a/rho_a^2
  // (the repulsion outgrows the attraction inside the wall); refuses others with
  // Error(invalid_argument) naming the arguments.
  void set_soft_wall(double gamma_r, double rho_r, double gamma_a, double rho_a);
  // The Lennard-Jones 9-3 wall phi(g) = (w/2) [(z0/g)^9 - 3 (z0/g)^3]
  // (LennardJonesPotential): w and z0 positive and finite, and its largest tensile stress
  // (about 1.466 w/z0) and its curvature at the continuation threshold z0/2 (91584 w/z0^2)
  // finite, normal doubles; refuses others with Error(invalid_argument) naming the arguments.
  void set_lennard_jones(double work_of_adhesion, double equilibrium_distance);
  // A user's potential (CallbackPotential), with the hard wall g >= 0 or without it. Refuses
  // a null function with Error(null_pointer) naming 'fn'.
  void set_user_potential(PotentialFunction function, void *user_data, bool hard_wall);
  // Any potential, as an interaction of the given kind (soft_wall, lennard_jones,
  // user_potential or user_potential_hard_wall). As for set_adhesion, the state is kept.
  void set_potential(InteractionKind kind, std::unique_ptr<Potential> potential);

  // Changes K~(0) keeping the pressure and the gap: only the rigid-body penetration moves, by
  // pbar (1/K~(0)new - 1/K~(0)old), so that the state stays an equilibrium. Throws
  // Error(unsupported) on a substrate whose K~(0) is no convention: the free half-space has
  // none, a layer on a rigid base has its own.
  void set_k0(double k0);

  // Copies the heights (finite, with a finite range max - min) and resets the state.
  void set_topography(const double *heights);
  const Field &heights() const { return heights_; }
  double max_height() const { return max_height_; }
  double height_range() const { return height_range_; }

  // 0 selects the default; see asp_system_set_reference_pressure.
  void set_reference_pressure(double p) {
    changed();
    reference_pressure_override_ = p;
    last_reference_pressure_ = reference_pressure(0.0);
  }
  // The reference pressure for a solve whose own natural scale is `control_scale`
  // (|mean pressure| or K~(0)|penetration|), used only when the surface has no slope.
  double reference_pressure(double control_scale) const;
  double last_reference_pressure() const { return last_reference_pressure_; }
  void remember_reference_pressure(double p) { last_reference_pressure_ = p; }

  ContactState &state() { return state_; }
  const ContactState &state() const { return state_; }
  // Zero pressure: the undeformed body touching the highest point.
  void reset_state();
  // Whether a solve holds the state in its own units, from the moment a formulation begins to
  // work on it in place until the solve ends: an error in between (memory running out) leaves
  // the state reset rather than half-scaled.
  void set_state_held_by_solve(bool held) { state_held_by_solve_ = held; }
  bool state_held_by_solve() const { return state_held_by_solve_; }
  // Whether the state carries pressure anywhere: a solved or prolonged state, not a cold one
  // (a new system, after a reset or a new topography). Collective on a distributed grid.
  bool carries_pressure() const;
  // Exchanges the system's interaction with `other`, which must not be null, without counting
  // it as a change (revision() stays): for a solve that solves a variant of its scene on the
  // way and puts the system's own interaction back (solvers/range_continuation.hpp). Cannot
  // fail.
  void exchange_interaction(std::unique_ptr<Interaction> &other) noexcept {
    interaction_.swap(other);
  }

  // Stores a solved state, the one way every formulation writes its result back:
  // pixel(i) gives pixel i's SolvedPixel (it may read the state's arrays at i, which are
  // written after it), then penetration(mean_gap) the penetration from the mean of the gap as
  // stored; the reference pressure of the solve is remembered. With the hard wall the gap is
  // stored exactly 0 on the wall and > 0 elsewhere, so that the contact set (g = 0) is the
  // solver's active set and never the sign of a rounding residue: off the wall a gap <= 0 (a
  // pixel that touches with no pressure, to rounding, or that the iterate leaves
  // interpenetrating, by at most its error) is stored as the smallest positive double, the
  // marker of a pixel just off the wall; NaN is kept, for the check. Without the wall (soft
  // potentials) the gap is stored as it is. Returns false if a pressure, a gap as the solve
  // gave it or the penetration is not finite (the caller then resets the state).
  template <class Pixel, class Penetration>
  bool store_solved_state(Pixel &&pixel, Penetration &&penetration, double reference_pressure) {
    constexpr double off_the_wall = std::numeric_limits<double>::denorm_min();
    double *p = state_.pressure.data();
    double *g = state_.gap.data();
    const bool wall = interaction_->has_hard_wall();
    const double n = static_cast<double>(grid_->n_pixels());
    const auto store = [&](std::int64_t i, double *sum) {
      const SolvedPixel s = pixel(i);
      const double gi = s.gap;
      const double open = gi > 0.0 || std::isnan(gi) ? gi : off_the_wall;
      p[i] = s.pressure;
      g[i] = !wall ? gi : (s.on_wall ? 0.0 : open);
      sum[0] += g[i] / n;
      sum[1] += 0.0 * (p[i] + gi);  // NaN if anything overflowed
    };
    const auto sums = loops::sums<2>(grid_->reductions(), grid_->local_pixels(), store);
    const double delta = penetration(sums[0]);
    state_.penetration = delta;
    remember_reference_pressure(reference_pressure);
    return sums[1] == 0.0 && std::isfinite(delta);
  }

  // Observables of the current state. Contact as Interaction::contact_map defines it: with
  // the hard wall the pixels on the wall, without it where the potential repels.
  double contact_fraction() const { return interaction_->contact_fraction(*grid_, state_); }
  void contact_map(double *out) const { interaction_->contact_map(*grid_, state_, out); }
  // Pixels in contact with positive pressure.
  double compressive_fraction() const {
    return interaction_->compressive_fraction(*grid_, state_);
  }
  double attractive_fraction() const;  // pixels with negative pressure
  // a times the sum of the positive pressures, and of the negative ones (<= 0).
  double repulsive_force() const;
  double attractive_force() const;
  double interaction_energy() const { return interaction_->energy(*grid_, state_); }
  double mean_pressure() const;
  double mean_gap() const;
  double total_force() const;
  // See Substrate::elastic_energy_of_pressure: without the q = 0 term on a periodic
  // substrate, all of it on a free one.
  double elastic_energy() const;
  // A pbar^2/(2 K~(0)) on a periodic substrate; 0 on a free one, whose elastic energy is
  // whole.
  double mean_mode_energy() const;
  // The displacement u = K^-1 p of the state's pressure (two transforms), into out.
  void displacement(double *out) const;

  // A number that changes whenever the system is changed through its methods (topography,
  // interaction, K~(0), reference pressure, a reset), unique among all systems of the process:
  // whoever keeps it along with a solve's result can tell later whether the system is still
  // the one that solve left. A solve's own changes to the state do not change it.
  std::uint64_t revision() const { return revision_; }

 private:
  // The fields come first: members are made in this order, and a grid too large for memory
  // must fail at its first allocation, before the substrate walks its spectrum.
  std::shared_ptr<const Grid> grid_;
  Field heights_;
  ContactState state_;
  std::unique_ptr<Substrate> substrate_;
  std::unique_ptr<Interaction> interaction_;
  double max_height_ = 0.0;
  double height_range_ = 0.0;
  double slope_pressure_ = 0.0;  // E* h'_rms/2
  double reference_pressure_override_ = 0.0;
  double last_reference_pressure_ = 0.0;
  bool state_held_by_solve_ = false;
  std::uint64_t revision_ = 0;
  void changed();
};

}  // namespace asp
