// SPDX-License-Identifier: GPL-2.0-or-later
// The passes over the unknowns that Bugnicourt's algorithm (bugnicourt.cpp) makes, fused so
// that an iteration reads and writes each array as few times as the data dependencies allow:
//  - gather: at a new iterate, one pass learns the multiplier of the mean constraint (the
//    gradient's mean over the free unknowns) and the error measure (bound_residual's, from
//    the gradient's extremes, which need no multiplier), and without a mean constraint also
//    the sum of the conjugate coefficient beta; under one, beta's sums depend on the
//    multiplier (through the unknowns on the bound that the projection keeps), and take a
//    second pass;
//  - direct: the projected gradient and the new direction, with the descent r.d along it, in
//    one pass;
//  - step (quadratic objectives): the move with the mean restored, the gradient followed from
//    the Hessian product, and the gather at the new iterate, in one pass (after a sum of the
//    moved iterate under a mean constraint);
//  - trial (separable objectives): the move, the quadratic part's gradient followed, the local
//    term's state and the objective at the new point, into trial arrays; on request the
//    jumps across the local term's instability (snaps onto the wall, peels off it).
// The kernels are kept lean on purpose: a pass over arrays that fit in cache costs its
// arithmetic, not its memory traffic.
// The unknowns are pixels (real space), whose inner product is the plain sum.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "formulations/bound_residual.hpp"
#include "formulations/formulation.hpp"
#include "formulations/local_term.hpp"

namespace asp {

// The projection of the gradient at an iterate onto the directions that keep it feasible.
// With the unknowns the projection keeps, N (the free ones, and those on the bound whose
// gradient does not push them out of the feasible set): r = g - shift on N, 0 elsewhere,
// then r <- r - again on N so that a step along r keeps the mean.
struct Projection {
  double shift = 0.0;  // the multiplier of the mean constraint: g's mean over the free unknowns
  double again = 0.0;  // the mean of g - shift over N (0 without a mean constraint)
  double beta = 0.0;   // r.(H d_old) / (d_old.H d_old), 0 for a restart
  double error = 0.0;  // the formulation's error measure (bound_residual) at the iterate
};

// What a step did to the iterate and, for a quadratic objective, whether the gradient was
// followed and the projection gathered in the same pass (not when the bound cut the step or
// when the caller asked for an evaluation; then the gradient must be evaluated).
struct Step {
  bool followed = false;
  Projection projection;
};

// A trial point y of a separable objective f = Q + sum psi, against the iterate x: whether the
// bound cut the step (then the followed gradient of Q is not that of y), and the changes of
// Q and of the sum of the local term's states from x to y. The changes are summed element by
// element, not taken as differences of the values: the values can be far larger than their
// changes (Q(0), the energy of the undeformed surface pressed in, is part of every Q(x)).
struct Trial {
  bool cut = false;
  double quadratic_change = 0.0;
  double state_change = 0.0;
  double states = 0.0;  // the sum of the states at y
};

class BugnicourtPasses {
 public:
  explicit BugnicourtPasses(Formulation &f)
      : f_(f),
        n_(f.size()),
        total_(f.total_size()),
        bounded_(f.bounded_size()),
        lower_(f.lower_bound()),
        mean_(f.constrains_mean()),
        reductions_(f.reductions()) {
    // The mean is restored by scaling every unknown, which keeps the followed gradient exact;
    // that is the constraint only where every unknown is bounded.
    if (mean_ && bounded_ != n_)
      throw Error(Status::internal,
                  "bugnicourt: a mean constraint on some unknowns only is not supported");
  }

  // The projection at x with gradient(i); product(i) is (H d_old)_i, the Hessian product of
  // the last direction, and curvature d_old.H d_old (not positive: beta = 0). pivot: a value
  // near the multiplier (the previous one), relative to which the gradient is summed.
  template <class Gradient, class Product>
  Projection gather(const double *x, Gradient &&gradient, Product &&product, double curvature,
                    double pivot) const {
    const auto pass = [&](auto mean) {
      return loops::sums_and_maxima<sums, maxima>(
          reductions_, n_, [&](std::int64_t i, double *sum, double *max) {
            gather_one<decltype(mean)::value>(x[i], bound(i), gradient(i), product(i), pivot, sum, max);
          });
    };
    const Gathered a = mean_ ? pass(std::true_type()) : pass(std::false_type());
    return conclude(x, a, gradient, product, curvature, pivot);
  }

  // d <- -r + beta d on N, 0 elsewhere, with r the projection of gradient(i) at x. Returns
  // the descent r.d and the sum of extra(i, d_i) (0 if the caller needs none).
  template <class Gradient, class Extra>
  std::array<double, 2> direct(const double *x, Gradient &&gradient, const Projection &p,
                               double *d, Extra &&extra) const {
    const double shift = p.shift, again = p.again, beta = p.beta;
    return loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
      const double r = gradient(i) - shift;
      const bool kept = (x[i] > bound(i)) | (r <= 0.0);
      const double projected = kept ? r - again : 0.0;
      const double di = kept ? -projected + beta * d[i] : 0.0;
      d[i] = di;
      sum[0] += projected * di;
      sum[1] += extra(i, di);
    });
  }

  // Preconditioned: z <- M r + own(i) r, M the formulation's preconditioner applied to the
  // projection r of gradient(i) at x (0 off N), own(i) a correction of M's diagonal that the
  // caller gives per unknown (0 for none; its sum with M must stay positive definite), z made
  // mean-free on N under a mean constraint, then
  // d <- -z + beta d on N, 0 elsewhere, with beta = z.(H d_old) / curvature, which keeps d
  // conjugate to d_old (product(i) is (H d_old)_i; curvature d_old.H d_old, not positive for
  // a restart). Returns the descent r.d, negative unless r = 0 (M is positive definite), and
  // the sum of extra(i, d_i). Three passes and M's transform pair.
  template <class Gradient, class Product, class Extra, class Own>
  std::array<double, 2> direct_preconditioned(const double *x, Gradient &&gradient,
                                              const Projection &p, Product &&product,
                                              double curvature, double *z, double *d,
                                              Extra &&extra, Own &&own) const {
    const double shift = p.shift, again = p.again;
    // r_i, and whether i is in N.
    const auto projected = [&](std::int64_t i, bool &kept) {
      const double r = gradient(i) - shift;
      kept = (x[i] > bound(i)) | (r <= 0.0);
      return r - again;
    };
    loops::for_each(n_, [&](std::int64_t i) {
      bool kept;
      const double r = projected(i, kept);
      z[i] = kept ? r : 0.0;
    });
    if (!f_.precondition(z))
      throw Error(Status::internal, "bugnicourt: the formulation offers no preconditioner");
    // z's correction, then over N: its count, the sums of z, of z h and of h.
    const auto s = loops::sums<4>(reductions_, n_, [&](std::int64_t i, double *t) {
      bool kept;
      const double r = projected(i, kept);
      if (kept) z[i] += own(i) * r;
      const double hi = product(i);
      t[0] += kept ? 1.0 : 0.0;
      t[1] += kept ? z[i] : 0.0;
      t[2] += kept ? z[i] * hi : 0.0;
      t[3] += kept ? hi : 0.0;
    });
    const double z_mean = mean_ && s[0] > 0.0 ? s[1] / s[0] : 0.0;
    const double beta = curvature > 0.0 ? (s[2] - z_mean * s[3]) / curvature : 0.0;
    return loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
      bool kept;
      const double r = projected(i, kept);
      const double di = kept ? -(z[i] - z_mean) + beta * d[i] : 0.0;
      d[i] = di;
      sum[0] += kept ? r * di : 0.0;
      sum[1] += extra(i, di);
    });
  }

  // Quadratic objectives: x <- s max(x + alpha d, lower), s restoring the mean (1 without a
  // mean constraint; a uniform iterate if nothing is left above the bound). With follow, in
  // the same pass, g <- s (g + alpha h) + (1 - s) c, the gradient at the new iterate if the
  // bound did not cut the step (h = H d, c the gradient at 0: the gradient is affine), and
  // the projection there (as gather, with curvature = d.h).
  Step step(double *x, const double *d, double alpha, double *g, const double *h,
            const double *c, bool follow, double pivot, double curvature) const {
    Step out;
    double scale = 1.0;
    if (mean_) {
      const auto moved = moved_sum(x, d, alpha);
      if (!(moved[0] > 0.0)) {
        const double uniform = f_.mean_target();
        loops::for_each(n_, [&](std::int64_t i) { x[i] = uniform; });
        return out;
      }
      scale = f_.mean_target() * total_ / moved[0];
      if (moved[1] > 0.0) follow = false;
    }
    if (!follow) {
      loops::for_each(n_, [&](std::int64_t i) {
        const double moved = x[i] + alpha * d[i];
        x[i] = (moved > bound(i) ? moved : bound(i)) * scale;
      });
      return out;
    }
    // The (1 - s) c term only under a mean constraint, so that c is not read without one.
    const auto pass = [&](auto mean) {
      return loops::sums_and_maxima<sums + 1, maxima>(
          reductions_, n_, [&](std::int64_t i, double *sum, double *max) {
            const double moved = x[i] + alpha * d[i];
            const double xi = (moved > bound(i) ? moved : bound(i)) * scale;
            const double gi = decltype(mean)::value
                                  ? scale * (g[i] + alpha * h[i]) + (1.0 - scale) * c[i]
                                  : g[i] + alpha * h[i];
            x[i] = xi;
            g[i] = gi;
            gather_one<decltype(mean)::value>(xi, bound(i), gi, h[i], pivot, sum, max);
            sum[sums] += moved < bound(i) ? 1.0 : 0.0;
          });
    };
    const auto a = mean_ ? pass(std::true_type()) : pass(std::false_type());
    if (a.first[sums] > 0.0) return out;
    Gathered gathered;
    for (int k = 0; k < sums; ++k) gathered.first[k] = a.first[k];
    gathered.second = a.second;
    out.followed = true;
    out.projection = conclude(x, gathered, [&](std::int64_t i) { return g[i]; },
                              [&](std::int64_t i) { return h[i]; }, curvature, pivot);
    return out;
  }

  // Separable objectives f = Q + sum psi: the trial point y = s max(x + alpha d, lower) (s as
  // in step), Q's gradient there followed, qy = s (q + alpha k) + (1 - s) c (k = Q d, c Q's
  // gradient at 0, read only under a mean constraint), and the local term's states there,
  // into y, qy and states_y; with the changes from x, where q and states hold Q's gradient
  // and the states. Q changes by (y - x).(q + qy)/2, exactly for a quadratic, so that the
  // objective at the trial point needs no transform unless the bound cut the step (then qy is
  // evaluated, and quadratic_change gives the change again).
  // With jumps (and no mean constraint), the unknowns near the local term's instability jump
  // across it instead of moving along d:
  //  - a snap: free, where the objective falls all the way to the bound
  //    (LocalTerm::falls_to_wall: unstable on its own with a positive gradient, or, where the
  //    local term is eager, with no rest above the bound in its one-unknown model), it goes
  //    onto the bound (a pixel near the wall that strong adhesion pulls in);
  //  - a peel: unstable on its own (LocalTerm::unstable_alone), on the bound or free, where
  //    the objective falls away from the bound (a negative gradient), it goes where it comes
  //    to rest beyond the instability, the others held (LocalTerm::rest_beyond_instability; a
  //    pixel that the elastic field tears off the wall);
  // both of which a step along d makes only over many iterations (bugnicourt.cpp). A jump
  // counts as a cut.
  Trial trial(const double *x, const double *d, double alpha, const double *q, const double *k,
              const double *c, const double *states, const LocalTerm &psi, double *y,
              double *qy, double *states_y, bool jumps) const {
    Trial out;
    const bool jumping = jumps && !mean_;
    const double slope = psi.slope_per_state();
    double scale = 1.0;
    bool uniform = false;
    if (mean_) {
      const auto moved = moved_sum(x, d, alpha);
      uniform = !(moved[0] > 0.0);
      scale = uniform ? 0.0 : f_.mean_target() * total_ / moved[0];
      out.cut = uniform || moved[1] > 0.0;
    }
    const double level = uniform ? f_.mean_target() : 0.0;
    // The (1 - s) c term only under a mean constraint, so that c is not read without one
    // (where s = 1 and c may be empty).
    const auto pass = [&](auto mean) {
      return loops::sums<4>(reductions_, n_, [&](std::int64_t i, double *sum) {
        const double moved = x[i] + alpha * d[i];
        // Only the bounded unknowns have psi.
        const bool near = jumping && i < bounded_;
        const double gradient = q[i] + slope * states[i];
        const bool snapped =
            near && x[i] > bound(i) && psi.falls_to_wall(x[i], q[i], states[i], bound(i));
        const bool peeled = near && psi.unstable_alone(states[i]) && gradient < 0.0;
        const double yi = snapped  ? bound(i)
                          : peeled ? psi.rest_beyond_instability(x[i], q[i])
                                   : (moved > bound(i) ? moved : bound(i)) * scale + level;
        const double qi = decltype(mean)::value
                              ? scale * (q[i] + alpha * k[i]) + (1.0 - scale) * c[i]
                              : q[i] + alpha * k[i];
        const double ei = i < bounded_ ? psi.state(yi) : 0.0;  // only the bounded have psi
        y[i] = yi;
        qy[i] = qi;
        states_y[i] = ei;
        sum[0] += (yi - x[i]) * (qi + q[i]);
        sum[1] += ei - states[i];
        sum[2] += ei;
        sum[3] += (moved < bound(i) || snapped || peeled) ? 1.0 : 0.0;
      });
    };
    const auto s = mean_ ? pass(std::true_type()) : pass(std::false_type());
    out.cut = out.cut || s[3] > 0.0;
    out.quadratic_change = 0.5 * s[0];
    out.state_change = s[1];
    out.states = s[2];
    return out;
  }

  // Q(y) - Q(x) = (y - x).(q + qy)/2 for a quadratic Q with gradients q at x and qy at y.
  double quadratic_change(const double *x, const double *y, const double *q,
                          const double *qy) const {
    return 0.5 * loops::sum(reductions_, n_,
                            [&](std::int64_t i) { return (y[i] - x[i]) * (q[i] + qy[i]); });
  }

  // The local term's states at x, into states; returns their sum.
  double local_states(const double *x, const LocalTerm &psi, double *states) const {
    return loops::sum(reductions_, n_, [&](std::int64_t i) {
      states[i] = i < bounded_ ? psi.state(x[i]) : 0.0;
      return states[i];
    });
  }

 private:
  // The gather's sums: the free unknowns' count and sum of g - pivot (under a mean
  // constraint), the bound residual's finiteness check, and (without one) the sum of g h over
  // N; its maxima: the bound residual's.
  static constexpr int sums = 4;
  static constexpr int maxima = bound_residual_maxima;
  using Gathered = std::pair<std::array<double, sums>, std::array<double, maxima>>;

  template <bool mean>
  void gather_one(double x, double lower, double g, double h, double pivot, double *sum,
                  double *max) const {
    const bool free = x > lower;
    if (mean) {
      sum[0] += free ? 1.0 : 0.0;
      sum[1] += free ? g - pivot : 0.0;
    } else {
      sum[3] += free | (g <= 0.0) ? g * h : 0.0;
    }
    gather_bound_residual(x, g, lower, max, sum[2]);
  }

  // The projection from a gather. Under a mean constraint, beta's sums take a second pass
  // (with the multiplier known); without one the gather has them.
  template <class Gradient, class Product>
  Projection conclude(const double *x, const Gathered &a, Gradient &&gradient,
                      Product &&product, double curvature, double pivot) const {
    const auto &sum = a.first;
    Projection p;
    p.shift = mean_ && sum[0] > 0.0 ? pivot + sum[1] / sum[0] : 0.0;
    p.error = bound_residual_at(a.second.data(), sum[2], p.shift);
    if (!mean_) {
      p.beta = curvature > 0.0 ? sum[3] / curvature : 0.0;
      return p;
    }
    // Over N: its count, and the sums of r = g - shift, of r h and of h.
    const double shift = p.shift;
    const auto s = loops::sums<4>(reductions_, n_, [&](std::int64_t i, double *t) {
      const double r = gradient(i) - shift;
      const double hi = product(i);
      const bool kept = (x[i] > bound(i)) | (r <= 0.0);
      t[0] += kept ? 1.0 : 0.0;
      t[1] += kept ? r : 0.0;
      t[2] += kept ? r * hi : 0.0;
      t[3] += kept ? hi : 0.0;
    });
    p.again = s[0] > 0.0 ? s[1] / s[0] : 0.0;
    p.beta = curvature > 0.0 ? (s[2] - p.again * s[3]) / curvature : 0.0;
    return p;
  }

  // The sum of max(x + alpha d, lower) and the number of unknowns the bound cuts.
  std::array<double, 2> moved_sum(const double *x, const double *d, double alpha) const {
    return loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
      const double moved = x[i] + alpha * d[i];
      sum[0] += moved > bound(i) ? moved : bound(i);
      sum[1] += moved < bound(i) ? 1.0 : 0.0;
    });
  }

  // The bound of unknown i: lower_bound() on the first bounded_size(), none on the others.
  double bound(std::int64_t i) const { return i < bounded_ ? lower_ : -HUGE_VAL; }

  Formulation &f_;
  std::int64_t n_;
  double total_;  // unknowns over all processes
  std::int64_t bounded_;
  double lower_;
  bool mean_;
  const Reductions &reductions_;
};

}  // namespace asp
