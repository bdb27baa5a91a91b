// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/coarse_system.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "core/spectral_layout.hpp"
#include "physics/periodic_halfspace.hpp"

namespace asp {

std::string coarsening_obstacle(const Grid &grid, std::int64_t smallest) {
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
  // Where from's entries are: all of them here on a serial grid. On a distributed one both
  // spectra are stored by columns kx, each process holding a slab of them, and this process's
  // columns of `to` need the same columns of `from`, which other processes may hold (those
  // beyond from's last column, nx/2, are not kept).
  SpectralLayout held = from.half_spectrum();
  const Complex *sa = a.data();
  Spectrum gathered;
  if (from.partition() != nullptr) {
    const std::int64_t first = to.column_offset();
    const std::int64_t columns = std::max<std::int64_t>(
        0, std::min(first + to.spectral_columns(), from.nx() / 2 + 1) - first);
    gathered = Spectrum(static_cast<std::size_t>(columns * from.ny()));
    from.gather_spectral_columns(a.data(), columns > 0 ? first : 0, columns, gathered.data());
    held = SpectralLayout(Packing::transposed_half_spectrum, from.nx(), from.ny(), from.lx(),
                          from.ly(), columns, first);
    sa = gathered.data();
  }
  Spectrum b = to.make_spectrum();
  Complex *sb = b.data();
  // The modes both grids hold, strictly below the smaller one's Nyquist wavevector per axis
  // (2|k| < n: on a 1D grid, ny = 1, that leaves ky = 0 only). Both transforms are
  // unnormalised: backward(forward(f)) = N_from f on `from`, and the same coefficients
  // transformed back on `to` make N_from times the resampled field.
  const std::int64_t sx = std::min(from.nx(), to.nx()), sy = std::min(from.ny(), to.ny());
  const double scale = 1.0 / static_cast<double>(from.n_pixels());
  to.half_spectrum().for_each_wavevector([&](std::int64_t k, std::int64_t kx, std::int64_t ky) {
    const bool kept = 2 * kx < sx && 2 * std::llabs(ky) < sy;
    sb[k] = kept ? scale * sa[held.entry(kx, ky)] : Complex(0.0, 0.0);
  });
  Field target = to.make_field();
  to.fft().backward(b.data(), target.data());
  std::copy(target.begin(), target.end(), out);
}

std::unique_ptr<System> coarse_system(const System &fine) {
  const Grid &grid = fine.grid();
  const std::string obstacle = coarsening_obstacle(grid, 2);
  if (!obstacle.empty()) throw Error(Status::unsupported, "nested grids: " + obstacle);
  std::shared_ptr<Grid> coarse_grid = grid.halved();

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
  // The coarse rows this process's fine rows fall on, and the row after the last of them:
  // rows [first, first + count), and row 0 again where that row wraps around (on a
  // distributed grid other processes may hold them).
  const std::int64_t rows = fine.local_rows(), offset = fine.row_offset();
  const std::int64_t first = rows > 0 ? offset / 2 : 0;
  const std::int64_t last = rows > 0 ? (offset + rows - 1) / 2 : -1;
  const std::int64_t after = two_d && rows > 0 ? next(last, cny) : last;
  const std::int64_t count = std::max(last, after == 0 ? last : after) - first + 1;
  const std::int64_t wrapped = after == 0 && first > 0 ? 1 : 0;
  std::vector<double> near(static_cast<std::size_t>((count + wrapped) * cnx));
  coarse.gather_rows(in, first, count, near.data());
  coarse.gather_rows(in, 0, wrapped, near.data() + count * cnx);
  const auto row = [&](std::int64_t cj) {
    return near.data() + cnx * (cj >= first ? cj - first : count);
  };
  loops::for_each(fine.local_pixels(), [&](std::int64_t f) {
    const std::int64_t i = f % nx, j = two_d ? offset + f / nx : 0;
    const std::int64_t ci = i / 2, cj = j / 2;
    const std::int64_t ci1 = next(ci, cnx), cj1 = two_d ? next(cj, cny) : cj;
    const double wx = i % 2 == 0 ? 0.0 : 0.5, wy = j % 2 == 0 ? 0.0 : 0.5;
    const double *r0 = row(cj), *r1 = row(cj1);
    out[f] = (1.0 - wy) * ((1.0 - wx) * r0[ci] + wx * r0[ci1]) +
             wy * ((1.0 - wx) * r1[ci] + wx * r1[ci1]);
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
