// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/coarse_system.hpp"

#include <algorithm>
#include <cstdlib>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "physics/periodic_halfspace.hpp"

namespace asp {

std::string coarsening_obstacle(const Grid &grid, std::int64_t smallest) {
  if (grid.partition() != nullptr)
    return "the grid is distributed over processes, and nested grids need a serial grid";
  const bool two_d = grid.dimension() == 2;
  if (grid.nx() % 2 != 0 || (two_d && grid.ny() % 2 != 0))
    return "the grid's " + std::to_string(grid.nx()) +
           (two_d ? " x " + std::to_string(grid.ny()) : std::string()) +
           " pixels cannot be halved per axis (odd size)";
  if (grid.nx() / 2 < smallest || (two_d && grid.ny() / 2 < smallest))
    return "halving the grid's " + std::to_string(grid.nx()) +
           (two_d ? " x " + std::to_string(grid.ny()) : std::string()) +
           " pixels would leave fewer than " + std::to_string(smallest) + " a side";
  return "";
}

void resample_field(const Grid &from, const Grid &to, const double *in, double *out) {
  Field source = from.make_field();
  std::copy(in, in + from.local_pixels(), source.begin());
  Spectrum a = from.make_spectrum();
  from.fft().forward(source.data(), a.data());
  // The modes both grids hold, strictly below the smaller one's Nyquist wavevector per axis
  // (2|k| < n: on a 1D grid, ny = 1, that leaves ky = 0 only).
  const std::int64_t sx = std::min(from.nx(), to.nx()), sy = std::min(from.ny(), to.ny());
  const std::int64_t to_row = to.nx() / 2 + 1, from_row = from.nx() / 2 + 1;
  const std::int64_t to_ny = to.ny(), from_ny = from.ny();
  Spectrum b = to.make_spectrum();
  const Complex *sa = a.data();
  Complex *sb = b.data();
  // Both transforms are unnormalised: backward(forward(f)) = N_from f on `from`, and the
  // same coefficients transformed back on `to` make N_from times the resampled field.
  const double scale = 1.0 / static_cast<double>(from.n_pixels());
  loops::for_each(to.local_spectral(), [&](std::int64_t q) {
    const std::int64_t kx = q % to_row, ky = q / to_row;
    const std::int64_t signed_ky = 2 * ky <= to_ny ? ky : ky - to_ny;
    const bool kept = 2 * kx < sx && 2 * std::llabs(signed_ky) < sy;
    const std::int64_t from_ky = signed_ky < 0 ? signed_ky + from_ny : signed_ky;
    sb[q] = kept ? scale * sa[kx + from_row * from_ky] : Complex(0.0, 0.0);
  });
  Field target = to.make_field();
  to.fft().backward(b.data(), target.data());
  std::copy(target.begin(), target.end(), out);
}

std::unique_ptr<System> coarse_system(const System &fine) {
  const Grid &grid = fine.grid();
  const std::string obstacle = coarsening_obstacle(grid, 2);
  if (!obstacle.empty()) throw Error(Status::unsupported, "nested grids: " + obstacle);
  const bool two_d = grid.dimension() == 2;
  std::shared_ptr<Grid> coarse_grid = Grid::create(
      grid.dimension(), grid.nx() / 2, two_d ? grid.ny() / 2 : 1, grid.lx(), grid.ly());
  coarse_grid->set_threads(grid.threads());
  coarse_grid->set_fft_planning(grid.fft_planning());

  const Substrate &substrate = fine.substrate();
  // A periodic substrate's law (the half-space's, a layer's) goes with the body; the free
  // half-space has none.
  const auto *periodic = dynamic_cast<const PeriodicHalfSpace *>(&substrate);
  auto coarse = periodic != nullptr
                    ? std::make_unique<System>(coarse_grid, periodic->law().copy())
                    : std::make_unique<System>(coarse_grid, substrate.contact_modulus(),
                                               substrate.kind());
  // The same box has the same lowest wavevectors, so the default K~(0) is the same; a K~(0)
  // the user chose is carried over.
  if (substrate.mean_stiffness() == MeanStiffness::convention &&
      coarse->substrate().k0() != substrate.k0())
    coarse->set_k0(substrate.k0());

  const Interaction &interaction = fine.interaction();
  if (const ExponentialAdhesion *adhesion = exponential_adhesion(interaction)) {
    coarse->set_adhesion(adhesion->work(), adhesion->range());
  } else if (const PotentialInteraction *soft = potential_interaction(interaction)) {
    coarse->set_potential(soft->kind(), soft->potential().in_units(1.0, 1.0));
  }

  Field heights = coarse_grid->make_field();
  resample_field(grid, *coarse_grid, fine.heights().data(), heights.data());
  coarse->set_topography(heights.data());
  return coarse;
}

void prolong_pressure(const Grid &coarse, const Grid &fine, bool periodic, const double *in,
                      double *out) {
  const std::int64_t cnx = coarse.nx(), cny = coarse.ny(), nx = fine.nx();
  const bool two_d = fine.dimension() == 2;
  // The neighbour beyond the last coarse pixel: the first one on a periodic substrate, the
  // last one itself on a free one (whose pressure does not wrap around).
  const auto next = [periodic](std::int64_t k, std::int64_t n) {
    return k + 1 < n ? k + 1 : periodic ? 0 : k;
  };
  loops::for_each(fine.local_pixels(), [&](std::int64_t f) {
    const std::int64_t i = f % nx, j = two_d ? f / nx : 0;
    const std::int64_t ci = i / 2, cj = j / 2;
    const std::int64_t ci1 = next(ci, cnx), cj1 = two_d ? next(cj, cny) : cj;
    const double wx = i % 2 == 0 ? 0.0 : 0.5, wy = j % 2 == 0 ? 0.0 : 0.5;
    out[f] = (1.0 - wy) * ((1.0 - wx) * in[ci + cnx * cj] + wx * in[ci1 + cnx * cj]) +
             wy * ((1.0 - wx) * in[ci + cnx * cj1] + wx * in[ci1 + cnx * cj1]);
  });
}

void prolong_state(const System &coarse, System &fine) {
  const Grid &grid = fine.grid();
  ContactState &state = fine.state();
  prolong_pressure(coarse.grid(), grid, fine.substrate().periodic(),
                   coarse.state().pressure.data(), state.pressure.data());
  const Interaction &interaction = fine.interaction();
  const bool wall = interaction.has_hard_wall();
  const double *p = state.pressure.data();

  // The rigid body stays where the coarse solve left it: the penetration is counted from
  // the highest height, which the truncation of the spectrum lowered.
  const double penetration =
      coarse.state().penetration + (fine.max_height() - coarse.max_height());
  state.penetration = penetration;
  fine.displacement(state.gap.data());  // u = K^-1 p
  double *g = state.gap.data();
  const double *h = fine.heights().data();
  const double top = fine.max_height();
  loops::for_each(grid.local_pixels(), [&](std::int64_t i) {
    const double gap = g[i] - (h[i] - top) - penetration;
    g[i] = !wall ? gap : p[i] > 0.0 ? 0.0 : std::max(gap, 0.0);
  });
}

}  // namespace asp
