// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/system.hpp"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"
#include "physics/free_halfspace.hpp"
#include "physics/periodic_halfspace.hpp"
#include "physics/surface_statistics.hpp"

namespace asp {

namespace {
std::unique_ptr<Substrate> make_substrate(SubstrateKind kind, const Grid &grid,
                                          double contact_modulus) {
  if (kind == SubstrateKind::free) return std::make_unique<FreeHalfSpace>(grid, contact_modulus);
  return std::make_unique<PeriodicHalfSpace>(grid, contact_modulus);
}
}  // namespace

void System::changed() {
  static std::atomic<std::uint64_t> revisions{0};
  revision_ = ++revisions;
}

System::System(std::shared_ptr<const Grid> grid, double contact_modulus, SubstrateKind substrate)
    : grid_(std::move(grid)),
      heights_(grid_->make_field()),
      state_{grid_->make_field(), grid_->make_field(), 0.0},
      substrate_(make_substrate(substrate, *grid_, contact_modulus)),
      interaction_(new HardWall()) {
  last_reference_pressure_ = reference_pressure(0.0);
  reset_state();
}

System::System(std::shared_ptr<const Grid> grid, std::unique_ptr<const StiffnessLaw> law)
    : grid_(std::move(grid)),
      heights_(grid_->make_field()),
      state_{grid_->make_field(), grid_->make_field(), 0.0},
      substrate_(std::make_unique<PeriodicHalfSpace>(*grid_, std::move(law))),
      interaction_(new HardWall()) {
  last_reference_pressure_ = reference_pressure(0.0);
  reset_state();
}

void System::set_topography(const double *heights) {
  const std::int64_t n = grid_->local_pixels();
  const Reductions &reduce = grid_->reductions();
  const double top = loops::maximum(reduce, n, [&](std::int64_t i) { return heights[i]; });
  const double bottom = -loops::maximum(reduce, n, [&](std::int64_t i) { return -heights[i]; });
  if (!std::isfinite(top - bottom))
    throw Error(Status::invalid_argument,
                "array 'heights' spans " + format_number(bottom) + " to " + format_number(top) +
                    "; the range max - min must be a finite double");
  // A free substrate's heights need not be periodic: their slope is taken inside the box.
  const double rms_slope = !substrate_->periodic() ? rms_slope_within_box(*grid_, heights)
                                                   : surface_statistics(*grid_, heights).rms_slope;
  const double slope_pressure = 0.5 * substrate_->contact_modulus() * rms_slope;
  if (!std::isfinite(slope_pressure))
    throw Error(Status::invalid_argument,
                "array 'heights': the pressure scale E* h'_rms/2 of this surface is not a "
                "finite double; rescale the heights or the modulus");

  std::copy(heights, heights + n, heights_.begin());
  max_height_ = top;
  height_range_ = top - bottom;
  slope_pressure_ = slope_pressure;
  last_reference_pressure_ = reference_pressure(0.0);
  reset_state();
}

double System::reference_pressure(double control_scale) const {
  if (reference_pressure_override_ > 0.0) return reference_pressure_override_;
  if (slope_pressure_ > 0.0) return slope_pressure_;
  if (control_scale > 0.0) return control_scale;
  return substrate_->contact_modulus();
}

void System::reset_state() {
  changed();
  double *p = state_.pressure.data();
  double *g = state_.gap.data();
  const double *h = heights_.data();
  loops::for_each(grid_->local_pixels(), [&](std::int64_t i) {
    p[i] = 0.0;
    g[i] = max_height_ - h[i];
  });
  state_.penetration = 0.0;
}

bool System::carries_pressure() const {
  const double *p = state_.pressure.data();
  const double count = loops::sum(grid_->reductions(), grid_->local_pixels(),
                                  [&](std::int64_t i) { return p[i] != 0.0 ? 1.0 : 0.0; });
  return count > 0.0;
}

double System::mean_pressure() const {
  const double *p = state_.pressure.data();
  // Each term divided by N first: the sum of finite pressures cannot overflow.
  const double n = static_cast<double>(grid_->n_pixels());
  return loops::sum(grid_->reductions(), grid_->local_pixels(),
                    [&](std::int64_t i) { return p[i] / n; });
}

double System::mean_gap() const {
  const double *g = state_.gap.data();
  const double n = static_cast<double>(grid_->n_pixels());
  return loops::sum(grid_->reductions(), grid_->local_pixels(),
                    [&](std::int64_t i) { return g[i] / n; });
}

double System::total_force() const { return mean_pressure() * grid_->area(); }

double System::attractive_fraction() const {
  const double *p = state_.pressure.data();
  const double count = loops::sum(grid_->reductions(), grid_->local_pixels(),
                                  [&](std::int64_t i) { return p[i] < 0.0 ? 1.0 : 0.0; });
  return count / static_cast<double>(grid_->n_pixels());
}

double System::repulsive_force() const {
  // As the mean pressure: each term divided by N first, then times the box area.
  const double *p = state_.pressure.data();
  const double n = static_cast<double>(grid_->n_pixels());
  return grid_->area() * loops::sum(grid_->reductions(), grid_->local_pixels(), [&](std::int64_t i) {
           return (p[i] > 0.0 ? p[i] : 0.0) / n;
         });
}

double System::attractive_force() const {
  const double *p = state_.pressure.data();
  const double n = static_cast<double>(grid_->n_pixels());
  return grid_->area() * loops::sum(grid_->reductions(), grid_->local_pixels(), [&](std::int64_t i) {
           return (p[i] < 0.0 ? p[i] : 0.0) / n;
         });
}

void System::displacement(double *out) const {
  // u = K^-1 p, the displacement the pressure makes (with the mean pbar/K~(0) on a periodic
  // substrate). Of a consistent state that is g + h - max h + delta as well, but taken from
  // the gap it would carry the rounding of the gap and the penetration, 1e-16 of their size,
  // which under a wall of long range can be 1e25 while the displacement is 1e-3: from the
  // pressure it keeps its own precision. The transforms run on the library's buffers.
  Field u = grid_->make_field();
  substrate_->apply_compliance(state_.pressure.data(), u.data());
  std::copy(u.begin(), u.end(), out);
}

void System::set_adhesion(double work, double range) {
  require_non_negative(work, "work_of_adhesion");
  require_positive(range, "range");
  changed();
  if (work == 0.0) {
    interaction_.reset(new HardWall());
    return;
  }
  const double stress = work / range;
  if (!std::isfinite(stress) || stress < DBL_MIN)
    throw Error(Status::invalid_argument,
                "arguments 'work_of_adhesion' " + format_number(work) + " and 'range' " +
                    format_number(range) + ": the largest tensile stress w/rho = " +
                    format_number(stress) + " is not a finite, normal double; rescale the units");
  interaction_.reset(new ExponentialAdhesion(work, range));
}

void System::set_hard_wall() {
  changed();
  interaction_.reset(new HardWall());
}

void System::set_soft_wall(double repulsion, double repulsion_range, double attraction,
                           double attraction_range) {
  require_positive(repulsion, "gamma_r");
  require_positive(repulsion_range, "rho_r");
  require_non_negative(attraction, "gamma_a");
  require_positive(attraction_range, "rho_a");
  // Far inside the wall both exponentials are continued by parabolas; the repulsion's must be
  // the steeper, or the energy would fall without bound as the surfaces interpenetrate.
  const double repulsive_curvature = 4.0 * repulsion / (repulsion_range * repulsion_range);
  const double attractive_curvature = attraction / (attraction_range * attraction_range);
  if (!(repulsive_curvature > attractive_curvature))
    throw Error(Status::invalid_argument,
                "arguments 'gamma_r' " + format_number(repulsion) + ", 'rho_r' " +
                    format_number(repulsion_range) + ", 'gamma_a' " + format_number(attraction) +
                    ", 'rho_a' " + format_number(attraction_range) +
                    ": the repulsion's curvature 4 gamma_r/rho_r^2 must exceed the attraction's "
                    "gamma_a/rho_a^2 (and both be finite), or the energy has no lower bound "
                    "when the surfaces interpenetrate");
  set_potential(InteractionKind::soft_wall,
                std::make_unique<SoftWallPotential>(repulsion, repulsion_range, attraction,
                                                    attraction_range));
}

void System::set_lennard_jones(double work_of_adhesion, double equilibrium_distance) {
  require_positive(work_of_adhesion, "work_of_adhesion");
  require_positive(equilibrium_distance, "equilibrium_distance");
  const LennardJonesPotential potential(work_of_adhesion, equilibrium_distance);
  // The stiffest the potential gets is at its continuation threshold; both scales must be
  // doubles that a solve can divide by and square.
  const double start = LennardJonesPotential::threshold * equilibrium_distance;
  double phi = 0.0, slope = 0.0, curvature = 0.0;
  potential.evaluate(1, &start, &phi, &slope, &curvature);
  const double stress = potential.pressure_scale();
  if (!std::isfinite(stress) || stress < DBL_MIN || !std::isfinite(curvature) ||
      !std::isfinite(phi) || !std::isfinite(slope))
    throw Error(Status::invalid_argument,
                "arguments 'work_of_adhesion' " + format_number(work_of_adhesion) +
                    " and 'equilibrium_distance' " + format_number(equilibrium_distance) +
                    ": the largest tensile stress (about 1.466 w/z0 = " + format_number(stress) +
                    ") or the curvature 91584 w/z0^2 at the continuation threshold z0/2 is not "
                    "a finite, normal double; rescale the units");
  set_potential(InteractionKind::lennard_jones,
                std::make_unique<LennardJonesPotential>(work_of_adhesion, equilibrium_distance));
}

void System::set_user_potential(PotentialFunction function, void *user_data, bool hard_wall) {
  if (function == nullptr) throw Error(Status::null_pointer, "argument 'fn' is NULL");
  set_potential(hard_wall ? InteractionKind::user_potential_hard_wall
                          : InteractionKind::user_potential,
                std::make_unique<CallbackPotential>(
                    function, user_data, grid_->partition() != nullptr ? &grid_->reductions() : nullptr));
}

void System::set_potential(InteractionKind kind, std::unique_ptr<Potential> potential) {
  changed();
  interaction_.reset(new PotentialInteraction(kind, std::move(potential)));
}

void System::set_k0(double k0) {
  // Refuses, naming the substrate, where K~(0) is no convention to set.
  if (substrate_->mean_stiffness() != MeanStiffness::convention) substrate_->set_k0(k0);
  require_positive(k0, "k0");
  const double p_mean = mean_pressure();
  const double shift = p_mean / k0 - p_mean / substrate_->k0();
  if (!std::isfinite(state_.penetration + shift))
    throw Error(Status::invalid_argument,
                "argument 'k0' is " + format_number(k0) + ": the mean displacement pbar/k0 of " +
                    "the current state would not be a finite double");
  changed();
  substrate_->set_k0(k0);
  state_.penetration += shift;
}

double System::elastic_energy() const {
  return substrate_->elastic_energy_of_pressure(state_.pressure.data());
}

double System::mean_mode_energy() const {
  if (!substrate_->has_k0()) return 0.0;
  const double p_mean = mean_pressure();
  return 0.5 * grid_->area() * p_mean * (p_mean / substrate_->k0());
}

}  // namespace asp
