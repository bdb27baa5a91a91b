// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/primal_formulation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "formulations/bound_residual.hpp"
#include "physics/resolution.hpp"

namespace asp {

namespace {

constexpr const char *mean_pressure_with_potential =
    "mean-pressure control of the gap formulation takes the hard wall with or without "
    "exponential adhesion, not a user's potential (whose separation under a tensile load "
    "cannot be told from its values); use penetration control";

}  // namespace

PrimalFormulation::PrimalFormulation(System &system, Control control, double value)
    : ScaledFormulation(system, control, value),
      local_term_(adhesion_, snaps_eagerly(),
                  1.0 / (substrate_.pixel_stiffness() * substrate_.self_compliance())) {
  // The stiffness, made now: on a free substrate its making checks that it exists, before
  // anything changes, and a solve then allocates nothing for it.
  substrate_.normalised_stiffness();
  unknowns_ = substrate_.surface_size();
  if (control == Control::mean_gap && substrate_.surface_beyond_grid())
    throw Error(Status::unsupported,
                "mean-gap control of the gap formulation is offered on a periodic substrate "
                "only: on a " + std::string(substrate_.name()) +
                    " the mean displacement is not a free mode whose energy can be left out; "
                    "use penetration control");
  penetration_ = control == Control::penetration ? target_ : 0.0;
  const PotentialInteraction *user = potential_interaction(system.interaction());
  if (user != nullptr && user->has_hard_wall())
    potential_ = user->potential().in_units(length_unit_, pressure_unit_);
  if (control == Control::mean_pressure && potential_ != nullptr)
    throw Error(Status::unsupported, mean_pressure_with_potential);
  // The load spread over the displacement's surface: the mean pressure on the grid, N/M of
  // it on each of the M points of a surface beyond the grid (N pixels).
  if (control == Control::mean_pressure) {
    double surface = static_cast<double>(unknowns_);
    grid_.reductions().combine_sums(&surface, 1);
    load_ = target_ * (pixels_ / surface);
  }

  // Work arrays before anything changes, so that running out of memory changes nothing.
  if (potential_ != nullptr) {
    phi_ = Field(static_cast<std::size_t>(n_));
    dphi_ = Field(static_cast<std::size_t>(n_));
    d2phi_ = Field(static_cast<std::size_t>(n_));
  }
  spectrum_ = substrate_.make_spectrum();
  if (substrate_.surface_beyond_grid()) {
    surface_unknowns_ = Field(static_cast<std::size_t>(unknowns_));
    surface_pressure_ = Field(static_cast<std::size_t>(unknowns_));
  }

  hold_state();
  // The stored gap as the starting iterate, in units of P/k; on a surface beyond the grid,
  // the displacement there that the stored pressure makes.
  if (substrate_.surface_beyond_grid()) {
    substrate_.compliance_onto_surface(state_.pressure.data(), surface_unknowns_.data(),
                                       spectrum_.data());
    counters_.transforms += 2;
    double *outside = surface_unknowns_.data();
    const double per_length = 1.0 / length_unit_;
    // Under load control the unknowns there are the displacement less the penetration.
    const double offset =
        control == Control::mean_pressure ? state_.penetration * per_length : 0.0;
    loops::for_each(unknowns_ - n_, [&](std::int64_t i) {
      outside[n_ + i] = outside[n_ + i] * per_length - offset;
    });
    std::copy(state_.gap.data(), state_.gap.data() + n_, surface_unknowns_.data());
  }
  // A pixel that carries compressive pressure is in contact, on the wall: its stored gap is
  // the residue of the solve that left the state (finish()), which read as an open pixel
  // would cost the next solve its first steps.
  double *g = variable().data();
  const double *pressure = state_.pressure.data();
  const double per_length = 1.0 / length_unit_;
  const double total = loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    g[i] = (g[i] > 0.0 && !(pressure[i] > 0.0) ? g[i] : 0.0) * per_length;
    return g[i];
  });
  if (control == Control::mean_gap) {
    const double n = pixels_;
    if (total > 0.0) {
      const double factor = target_ * n / total;
      loops::for_each(n_, [&](std::int64_t i) { g[i] *= factor; });
    } else {
      loops::for_each(n_, [&](std::int64_t i) { g[i] = target_; });
    }
  }
}

double PrimalFormulation::apply_stiffness(const double *field, double *out) {
  // K~/k with the transform's 1/N: the scaled stiffness, pixel stiffness 1. The q = 0 entry is
  // the first: without K~(0) under mean-gap and load control, also in u.K u, summed in the
  // same pass (Parseval).
  const bool without_mean = control_ != Control::penetration;
  const double factor = 1.0 / substrate_.pixel_stiffness();
  double energy = 0.0;
  substrate_.apply_stiffness(field, out, spectrum_.data(),
                             [&](Complex *s, const double *k, const SpectralLayout &layout) {
                               if (without_mean && layout.is_mean(0)) s[0] = 0.0;
                               energy = kernel_times_summing(grid_.reductions(), layout, s, k,
                                                             factor);
                             });
  counters_.transforms += 2;
  return energy;
}

double PrimalFormulation::elastic_pressure(const double *x, double *out) {
  // u = x + (h - max h)/l + delta on the grid, u = x beyond it, into out, then p = K u,
  // scaled, over it (the transform reads u before it writes p). Under load control the load
  // is added to p, and the sum of x, read before out (which may be x) is written, gives its
  // work.
  const double per_length = 1.0 / length_unit_, top = max_height_, delta = penetration_;
  const auto displacement = [&](std::int64_t i) {
    const double xi = x[i];
    out[i] = xi + (heights_[i] - top) * per_length + delta;
    return xi;
  };
  double sum = 0.0;
  if (control_ == Control::mean_pressure) {
    sum = loops::sum(grid_.reductions(), n_, displacement) +
          loops::sum(grid_.reductions(), unknowns_ - n_,
                     [&](std::int64_t i) { return x[n_ + i]; });
  } else {
    loops::for_each(n_, displacement);
  }
  if (out != x) std::copy(x + n_, x + unknowns_, out + n_);
  const double energy = apply_stiffness(out, out);
  if (control_ != Control::mean_pressure) return energy;
  const double load = load_;
  loops::for_each(unknowns_, [&](std::int64_t i) { out[i] += load; });
  return energy + 2.0 * load * sum;
}

double PrimalFormulation::value_and_gradient(const double *x, double *gradient) {
  // E = (1/2) u.p (+ sum_i phi(x_i) with adhesion), gradient p (+ phi'(x)), all scaled.
  if (potential_ != nullptr) return value_and_gradient_of_potential(x, gradient);
  if (!adhesive_) return quadratic_part(x, gradient);
  const double elastic = 0.5 * elastic_pressure(x, gradient);
  counters_.evaluations += 1;
  // One pass adds the interaction's pressure to the gradient and sums its energy.
  const ExponentialPotential phi = adhesion_;
  return elastic + loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    const ExponentialPotential::Terms t = phi.at(x[i]);
    gradient[i] += t.dphi;
    return t.phi;
  });
}

double PrimalFormulation::value_and_gradient_of_potential(const double *x, double *gradient) {
  // As with adhesion, with the potential evaluated over the grid's gaps at once (a user's
  // callback may throw Error(callback)).
  const double elastic = 0.5 * elastic_pressure(x, gradient);
  counters_.evaluations += 1;
  potential_->evaluate(n_, x, phi_.data(), dphi_.data(), nullptr);
  const double *phi = phi_.data(), *dphi = dphi_.data();
  return elastic + loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    gradient[i] += dphi[i];
    return phi[i];
  });
}

void PrimalFormulation::gradient(const double *x, double *gradient) {
  if (adhesive_ || potential_ != nullptr) {
    value_and_gradient(x, gradient);
    return;
  }
  elastic_pressure(x, gradient);
  counters_.evaluations += 1;
}

double PrimalFormulation::gradient_at_zero(double *out) {
  const Field zero(static_cast<std::size_t>(unknowns_), 0.0);
  return value_and_gradient(zero.data(), out);
}

double PrimalFormulation::quadratic_part(const double *x, double *gradient) {
  const double energy = elastic_pressure(x, gradient);
  counters_.evaluations += 1;
  return 0.5 * energy;
}

double PrimalFormulation::quadratic_part_at_zero(double *out) {
  // out doubles as the zero iterate: each of its values is read before it is written.
  loops::for_each(unknowns_, [&](std::int64_t i) { out[i] = 0.0; });
  return quadratic_part(out, out);
}

double PrimalFormulation::quadratic_part_product(const double *direction, double *product) {
  return apply_stiffness(direction, product);
}

void PrimalFormulation::hessian_product(const double *direction, double *product) {
  apply_stiffness(direction, product);
  if (potential_ != nullptr) {
    potential_->evaluate(n_, variable().data(), phi_.data(), dphi_.data(), d2phi_.data());
    const double *d2phi = d2phi_.data();
    loops::for_each(n_, [&](std::int64_t i) { product[i] += d2phi[i] * direction[i]; });
    return;
  }
  if (!adhesive_) return;
  // K d + phi''(x) d at the iterate x.
  const double *x = variable().data();
  const ExponentialPotential phi = adhesion_;
  loops::for_each(n_, [&](std::int64_t i) { product[i] += phi.d2phi(x[i]) * direction[i]; });
}

bool PrimalFormulation::separates(const double *x) const {
  // Only a tensile load on the adhesive wall pulls the surfaces apart (a user's potential
  // takes no load control; the plain wall takes no tensile load).
  if (control_ != Control::mean_pressure || !(target_ < 0.0) || !adhesive_) return false;
  if (contact_fraction(x, nullptr) > 0.0) return false;
  // No pixel on the wall. Along the separation x + t (every unknown, t >= 0; the elastic
  // energy does not change, the mean mode being out of it) the objective's slope is
  // sum_i phi'(x_i + t) + N pbar and its curvature sum_i phi''(x_i + t) < 0: where the slope
  // is negative at t = 0 it falls ever faster, without bound, and no minimum lies ahead.
  const ExponentialPotential phi = adhesion_;
  const double pull =
      loops::sum(grid_.reductions(), n_, [&](std::int64_t i) { return phi.dphi(x[i]); });
  return pull + target_ * pixels_ < 0.0;
}

double PrimalFormulation::error(const double *x, const double *gradient) const {
  // Under mean-gap control the mean pressure is the multiplier of the mean.
  return bound_residual(grid_.reductions(), unknowns_, n_, x, gradient, 0.0,
                        control_ == Control::mean_gap);
}

double PrimalFormulation::contact_fraction(const double *x, const double *) const {
  // The pixels on the wall: finish() stores the iterate's gap, whose active set holds exact
  // zeros (the projection onto x >= 0 makes them).
  const double n = pixels_;
  return loops::sum(grid_.reductions(), n_,
                    [&](std::int64_t i) { return x[i] > 0.0 ? 0.0 : 1.0; }) /
         n;
}

double PrimalFormulation::interaction_slopes(const double *gap, double *slope) {
  if (potential_ == nullptr) {
    const ExponentialPotential phi = adhesion_;
    loops::for_each(n_, [&](std::int64_t i) { slope[i] = phi.dphi(gap[i] > 0.0 ? gap[i] : 0.0); });
    return phi.dphi(0.0);
  }
  // The gaps clipped to the wall (the iterate's are >= 0 bitwise, but a warm start's need
  // not be), then phi' at once, and at the wall.
  double *clipped = d2phi_.data();
  loops::for_each(n_, [&](std::int64_t i) { clipped[i] = gap[i] > 0.0 ? gap[i] : 0.0; });
  potential_->evaluate(n_, clipped, phi_.data(), slope, nullptr);
  const double zero = 0.0;
  double phi0 = 0.0, slope0 = 0.0;
  potential_->evaluate(1, &zero, &phi0, &slope0, nullptr);
  return slope0;
}

void PrimalFormulation::touch_at_zero_load() {
  // Without adhesion and without load every uniform separation of a state is as good (the
  // elastic energy sees no mean mode, the load does no work): the state reported is the one
  // that touches, the limit of small loads, as under penetration control at delta = 0.
  if (control_ != Control::mean_pressure || load_ != 0.0 || adhesive_ || potential_ != nullptr)
    return;
  double *x = variable().data();
  const double lowest =
      -loops::maximum(grid_.reductions(), n_, [&](std::int64_t i) { return -x[i]; });
  if (!(lowest > 0.0)) return;
  // The lowest pixels exactly on the wall.
  loops::for_each(unknowns_, [&](std::int64_t i) {
    x[i] = i < n_ && x[i] == lowest ? 0.0 : x[i] - lowest;
  });
}

bool PrimalFormulation::finish() {
  touch_at_zero_load();
  // The elastic pressure of the iterate, p = K u (scaled), into the state's pressure array
  // (on a surface beyond the grid, the grid's part of it; beyond, it is the residual).
  double *p = state_.pressure.data();
  if (substrate_.surface_beyond_grid()) {
    elastic_pressure(surface_unknowns_.data(), surface_pressure_.data());
    std::copy(surface_pressure_.data(), surface_pressure_.data() + n_, p);
    std::copy(surface_unknowns_.data(), surface_unknowns_.data() + n_, state_.gap.data());
  } else {
    elastic_pressure(state_.gap.data(), p);
  }
  double *g = state_.gap.data();
  // The interaction's pressure -phi'(g): 0 without adhesion; tensile, at most w/rho at the
  // wall, with it; a user's potential's own. On the wall the pressure can be no lower than
  // -phi'(0). slope[i] is phi'(g_i) on the open pixels.
  const bool interacting = adhesive_ || potential_ != nullptr;
  Field slopes;
  double wall_tension = 0.0;
  if (interacting) {
    slopes = Field(static_cast<std::size_t>(n_));
    wall_tension = -interaction_slopes(g, slopes.data());
  }
  const double *slope = slopes.data();
  if (control_ == Control::mean_gap) {
    // The multiplier: on the free pixels K u + pbar + phi'(g) = 0 at the optimum, so pbar is
    // minus the mean of K u + phi'(g) there. With no free pixel (a mean gap of 0) any pbar
    // with p >= -phi'(0) on the wall fits; the smallest is taken.
    const auto s = loops::sums<2>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
      const double free = g[i] > 0.0 ? 1.0 : 0.0;
      const double interaction = interacting && g[i] > 0.0 ? slope[i] : 0.0;
      sum[0] += free * (p[i] + interaction);
      sum[1] += free;
    });
    const double pbar =
        s[1] > 0.0
            ? -s[0] / s[1]
            : wall_tension -
                  loops::maximum(grid_.reductions(), n_, [&](std::int64_t i) { return -p[i]; });
    loops::for_each(n_, [&](std::int64_t i) { p[i] += pbar; });
  }
  // The state is the hard wall's reading of the iterate: where the gap is open, the pressure
  // the interaction exerts there (none without adhesion, -phi'(g) with it: at the optimum K u
  // differs from it only by the residual); on the wall K u, clipped below at -phi'(0)
  // (0 without adhesion), since the wall can push but not pull, and what lies below is the
  // residual of the iterate. The gap stored is the iterate's own: >= 0 however the solve
  // ended, and exactly 0 on its active set, so that the contact set (g = 0) is the solver's
  // and the last history row counts the same pixels. The displacement the stored pressure
  // makes differs from the one of that gap by K^-1 of what the reading changed, at most the
  // iterate's error (in units of P) on each pixel.
  const double pressure = pressure_unit_, n = pixels_, length = length_unit_;
  const double mean_pressure = loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    const double on_wall = p[i] > wall_tension ? p[i] : wall_tension;
    const double read = interacting ? (g[i] > 0.0 ? -slope[i] : on_wall)
                                    : (g[i] > 0.0 ? 0.0 : (p[i] > 0.0 ? p[i] : 0.0));
    p[i] = read * pressure;
    return p[i] / n;
  });
  // The penetration, from the state as stored (its mean gap, its pressure):
  //  - under penetration control the one given;
  //  - under mean-gap control from the convention mean u = pbar/K~(0):
  //    delta = pbar/K~(0) - mean g - mean(h - max h);
  //  - under load control the one the stored state says: the mean of u - (h - max h) - g
  //    over the grid, u = K^-1 p the displacement of the stored pressure. On a periodic
  //    substrate mean u = pbar/K~(0), so that it is the mean-gap formula; on a free one it
  //    takes the padded operator (one FFT pair).
  const double top = max_height_;
  const auto penetration = [&](double mean_gap) {
    if (control_ == Control::penetration) return penetration_ * length;
    const double mean_height = loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
      return (heights_[i] - top) / n;
    });
    if (substrate_.has_k0()) return mean_pressure / substrate_.k0() - mean_gap - mean_height;
    Field displacement = grid_.make_field();
    double *u = displacement.data();
    substrate_.apply_compliance(p, u, spectrum_.data());
    counters_.transforms += 2;
    return loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
      return (u[i] - (heights_[i] - top) - g[i]) / n;
    });
  };
  // The gap stored is the iterate's (-0.0 and a warm start's < 0 onto the wall).
  return system_.store_solved_state(
      [&](std::int64_t i) {
        const double gi = g[i] * length;
        return SolvedPixel{p[i], gi, !(gi > 0.0 || std::isnan(gi))};
      },
      penetration, pressure_unit_);
}

bool PrimalFormulation::snaps_eagerly() const {
  if (!adhesive_) return false;
  // Nearer to resolved the eager jumps cost iterations. On the challenge's scene
  // (asperity_challenge --range-scale) at 1024^2, zones of 0.52, 0.62 and 0.75 pixel took
  // 141, 177 and 225 iterations eagerly against 94, 93 and 71 (at 2048^2, 0.52 and 0.62:
  // 513 and 157 against 124 and 98); at 0.35 and 0.43 pixel 45 and 84 against 102 and 123
  // (at 2048^2 73 and 117 against 171 and 211).
  if (!(resolution(system_).ratio <= far_from_resolved)) return false;
  // Before this formulation holds the state (hold_state, in the constructor), a solve holds
  // it only where the state is a cold solve's own: on a coarse level (nested_grids.cpp), and
  // in both stages of a continuation in the range (solver.cpp), which run on cold starts
  // only.
  return system_.state_held_by_solve() || !system_.carries_pressure();
}

}  // namespace asp
