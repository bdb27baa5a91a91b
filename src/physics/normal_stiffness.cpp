// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/normal_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"
#include "core/threads.hpp"
#include "physics/interaction.hpp"

namespace asp {

namespace {

// The conjugate gradients stop at a residual this small relative to the right-hand side: the
// stiffness is then exact to about this times the condition number of the restricted
// operator (at most about the grid's width for K or K^-1 alone), far below the 1e-5 at which
// finite differences of solves can check it.
constexpr double relative_tolerance = 1e-12;

// One application of a substrate's operator, K^-1 on the grid (compliance) or K on the
// surface (stiffness), through the substrate's helper with a work spectrum of its own;
// counts the transforms.
class Operator {
 public:
  Operator(const Substrate &substrate, bool on_surface)
      : substrate_(substrate), on_surface_(on_surface), spectrum_(substrate.make_spectrum()) {}

  void apply(const double *in, double *out) {
    if (on_surface_)
      substrate_.apply_stiffness(in, out, spectrum_.data());
    else
      substrate_.apply_compliance(in, out, spectrum_.data());
    transforms += 2;
  }

  std::int64_t transforms = 0;

 private:
  const Substrate &substrate_;
  bool on_surface_;
  Spectrum spectrum_;
};

Error unstable(const std::string &why) {
  return Error(Status::invalid_state,
               "the state is not a stable equilibrium: " + why +
                   " (the linearised problem about it is not positive definite, so it has "
                   "no stiffness; an adhesive state past an instability, a jump into or out "
                   "of contact, is one)");
}

// Preconditioned conjugate gradients for A x = b, x from 0, over the n local entries of the
// fields whose `free` is 1 (0 elsewhere; b, x and what apply(in, out) writes, out = A in, are
// 0 there). inverse_diagonal scales the residual (Jacobi), or is null for none. A is
// symmetric; meeting a direction of non-positive curvature means it is not positive definite.
// Returns the steps taken.
template <class Apply>
std::int64_t conjugate_gradients(const Reductions &reductions, std::int64_t n,
                                 double unknowns, const double *b, const double *inverse_diagonal,
                                 double *x, Apply &&apply) {
  Field r(b, b + n), z(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n)),
      ad(static_cast<std::size_t>(n));
  double *rp = r.data(), *zp = z.data(), *dp = d.data(), *adp = ad.data();
  const auto precondition = [&] {
    if (inverse_diagonal == nullptr) {
      std::copy(r.begin(), r.end(), z.begin());
      return loops::sum(reductions, n, [&](std::int64_t i) { return rp[i] * rp[i]; });
    }
    return loops::sum(reductions, n, [&](std::int64_t i) {
      zp[i] = inverse_diagonal[i] * rp[i];
      return rp[i] * zp[i];
    });
  };
  const double bb = loops::sum(reductions, n, [&](std::int64_t i) { return b[i] * b[i]; });
  std::fill(x, x + n, 0.0);
  if (!(bb > 0.0)) return 0;
  double rz = precondition();
  std::copy(z.begin(), z.end(), d.begin());
  // In exact arithmetic at most `unknowns` steps; rounding may cost some more.
  const double limit = 2.0 * unknowns + 1000.0;
  for (std::int64_t k = 1; k <= limit; ++k) {
    apply(dp, adp);
    const double curvature = loops::sum(reductions, n, [&](std::int64_t i) { return dp[i] * adp[i]; });
    if (!(curvature > 0.0)) {
      if (!std::isfinite(curvature))
        throw Error(Status::invalid_state,
                    "the linearised problem about the state produced a value that is not "
                    "finite; the state is not one the stiffness can be taken of");
      throw unstable("the Hessian restricted to the free points has a direction of "
                     "non-positive curvature");
    }
    const double alpha = rz / curvature;
    const double rr = loops::sum(reductions, n, [&](std::int64_t i) {
      x[i] += alpha * dp[i];
      rp[i] -= alpha * adp[i];
      return rp[i] * rp[i];
    });
    if (rr <= relative_tolerance * relative_tolerance * bb) return k;
    const double rz_next = precondition();
    const double beta = rz_next / rz;
    rz = rz_next;
    loops::for_each(n, [&](std::int64_t i) { dp[i] = zp[i] + beta * dp[i]; });
  }
  throw Error(Status::invalid_state,
              "the linearised problem about the state did not converge in " +
                  format_number(limit) +
                  " conjugate-gradient steps; the state may be close to an instability");
}

// The plain hard wall: (K^-1 dp)_C = 1, dp = 0 off C; the mean of dp.
NormalStiffness hard_wall_stiffness(const System &system) {
  const Grid &grid = system.grid();
  const Reductions &reductions = grid.reductions();
  const std::int64_t n = grid.local_pixels();
  const double *p = system.state().pressure.data();
  const double *g = system.state().gap.data();
  Field on_wall = grid.make_field(), rhs = grid.make_field(), dp = grid.make_field();
  double *c = on_wall.data(), *b = rhs.data();
  const double contacts = loops::sum(reductions, n, [&](std::int64_t i) {
    c[i] = g[i] <= 0.0 || p[i] > 0.0 ? 1.0 : 0.0;
    b[i] = c[i];
    return c[i];
  });
  NormalStiffness result;
  if (contacts == 0.0) return result;  // no contact: nothing resists the approach
  Operator compliance(system.substrate(), false);
  result.iterations = conjugate_gradients(
      reductions, n, contacts, b, nullptr, dp.data(), [&](const double *in, double *out) {
        compliance.apply(in, out);
        loops::for_each(n, [&](std::int64_t i) { out[i] *= c[i]; });
      });
  result.transforms = compliance.transforms;
  const double pixels = static_cast<double>(grid.n_pixels());
  const double *x = dp.data();
  result.value = loops::sum(reductions, n, [&](std::int64_t i) { return x[i] / pixels; });
  return result;
}

// phi''(g) of the state's gaps (at the wall, g <= 0, at 0: those pixels are held anyway).
Field curvatures(const System &system) {
  const Grid &grid = system.grid();
  const std::int64_t n = grid.local_pixels();
  const double *g = system.state().gap.data();
  Field d2phi = grid.make_field();
  double *out = d2phi.data();
  if (const ExponentialAdhesion *adhesion = exponential_adhesion(system.interaction())) {
    const ExponentialPotential potential = adhesion->potential();
    loops::for_each(n, [&](std::int64_t i) { out[i] = potential.d2phi(g[i] > 0.0 ? g[i] : 0.0); });
    return d2phi;
  }
  const PotentialInteraction *interaction = potential_interaction(system.interaction());
  if (interaction == nullptr)
    throw Error(Status::internal, "normal stiffness: an interaction without a potential");
  Field gap = grid.make_field(), phi = grid.make_field(), dphi = grid.make_field();
  double *gp = gap.data();
  const bool wall = interaction->has_hard_wall();
  loops::for_each(n, [&](std::int64_t i) { gp[i] = wall && !(g[i] > 0.0) ? 0.0 : g[i]; });
  interaction->potential().evaluate(n, gp, phi.data(), dphi.data(), out);
  return d2phi;
}

// With a potential: (K + phi'') du = phi'' on the free points, du = 1 on C; dp = K du on the
// box, and its mean.
NormalStiffness potential_stiffness(const System &system, bool hard_wall) {
  const Grid &grid = system.grid();
  const Substrate &substrate = system.substrate();
  const Reductions &reductions = grid.reductions();
  const std::int64_t box = grid.local_pixels();
  const std::int64_t m = substrate.surface_size();  // the box's pixels first
  const Field d2phi = curvatures(system);
  const double *curvature = d2phi.data();
  const double *g = system.state().gap.data();

  Operator stiffness(substrate, true);
  // K's diagonal: K is a convolution over the surface, so its diagonal is one number, the
  // response at the first pixel of the grid to a unit displacement there.
  double diagonal = 0.0;
  {
    Field unit(static_cast<std::size_t>(m)), response(static_cast<std::size_t>(m));
    const bool first = grid.row_offset() == 0 && box > 0;
    if (first) unit[0] = 1.0;
    stiffness.apply(unit.data(), response.data());
    diagonal = first ? response[0] : 0.0;
    reductions.combine_sums(&diagonal, 1);
  }

  // free: 1 off C; held: du = 1 there. The Jacobi preconditioner 1/(K_ii + phi''_i) needs a
  // positive diagonal, which a positive definite Hessian has.
  Field free(static_cast<std::size_t>(m)), held(static_cast<std::size_t>(m)),
      inverse_diagonal(static_cast<std::size_t>(m)), rhs(static_cast<std::size_t>(m)),
      du(static_cast<std::size_t>(m)), work(static_cast<std::size_t>(m));
  double *f = free.data(), *h = held.data(), *w = inverse_diagonal.data();
  const auto counts = loops::sums_and_max<1>(reductions, m, [&](std::int64_t i, double *sum,
                                                                double &largest) {
    const bool on_box = i < box;
    const bool on_wall = on_box && hard_wall && !(g[i] > 0.0);
    f[i] = on_wall ? 0.0 : 1.0;
    h[i] = on_wall ? 1.0 : 0.0;
    const double entry = diagonal + (on_box ? curvature[i] : 0.0);
    w[i] = on_wall ? 0.0 : 1.0 / entry;
    sum[0] += f[i];
    // A non-positive (or NaN) diagonal entry of a free point: its negative, or +infinity.
    const double bad = on_wall ? -1.0 : (entry > 0.0 ? -1.0 : 1.0);
    largest = bad > largest ? bad : largest;
  });
  if (counts[1] > 0.0)
    throw unstable("at some gap phi''(g) is below -K_ii, the elastic stiffness of one point");

  // The right-hand side phi'' - K 1_C on the free points; K 1_C is kept for dp.
  Field held_force(static_cast<std::size_t>(m));
  double *k_held = held_force.data(), *b = rhs.data();
  stiffness.apply(h, k_held);
  loops::for_each(m, [&](std::int64_t i) {
    b[i] = f[i] * ((i < box ? curvature[i] : 0.0) - k_held[i]);
  });

  NormalStiffness result;
  result.iterations = conjugate_gradients(
      reductions, m, counts[0], b, w, du.data(), [&](const double *in, double *out) {
        stiffness.apply(in, out);
        loops::for_each(m, [&](std::int64_t i) {
          out[i] = f[i] * (out[i] + (i < box ? curvature[i] : 0.0) * in[i]);
        });
      });
  // dp = K (du + 1_C) on the box.
  double *kdu = work.data();
  stiffness.apply(du.data(), kdu);
  result.transforms = stiffness.transforms;
  const double pixels = static_cast<double>(grid.n_pixels());
  result.value = loops::sum(reductions, box, [&](std::int64_t i) {
    return (kdu[i] + k_held[i]) / pixels;
  });
  return result;
}

}  // namespace

NormalStiffness normal_stiffness(const System &system) {
  // The loops run on the grid's threads, as a solve's do (its FFTs were planned with them).
  const ThreadScope threads(system.grid().threads());
  const Interaction &interaction = system.interaction();
  switch (interaction.family()) {
    case InteractionFamily::hard_wall: return hard_wall_stiffness(system);
    case InteractionFamily::hard_wall_with_potential: return potential_stiffness(system, true);
    case InteractionFamily::soft_potential: break;
  }
  return potential_stiffness(system, false);
}

}  // namespace asp
