// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/lbfgsb.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "core/lanes.hpp"
#include "core/loops.hpp"
#include "formulations/bound_residual.hpp"
#include "formulations/dual_formulation.hpp"
#include "solvers/line_search.hpp"
#include "formulations/primal_formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/nested_grids.hpp"

namespace asp {
namespace {

// The line search's parameters, L-BFGS-B's: sufficient decrease 1e-3, curvature 0.9 (loose,
// as quasi-Newton methods want, so that the unit step is nearly always taken), interval
// width 0.1; and at most 20 evaluations per search.
constexpr LineSearchSettings line_search_settings{1e-3, 0.9, 0.1, 20};
// The largest step of a search along a direction no bound limits.
constexpr double unbounded_step = 1e10;

constexpr double infinity = std::numeric_limits<double>::infinity();

// An unknown's part of the direction from its x_bar: returns d = max(x_bar, bound) - x, and
// adds its shares of the sums g.d and d.d and of the maximum of -(step to the bound), whose
// negative is the largest feasible step. (The division is by d, or by -1 where d does not
// point to the bound: no lane divides by zero if the compiler evaluates both sides.)
inline double finish_unknown(double x, double g, double bound, double x_bar, double *sum,
                             double &max) {
  const double d = (x_bar > bound ? x_bar : bound) - x;
  sum[0] += g * d;
  sum[1] += d * d;
  const bool towards = d < 0.0;
  const double limit = towards ? -(bound - x) / (towards ? d : -1.0) : -infinity;
  max = max > limit ? max : limit;
  return d;
}

// What a line search did.
enum class Search { accepted, no_descent, failed, not_finite };

// The algorithm's state between its steps: the iterate x (the formulation's variable), its
// gradient g and value, the compact matrix, and the work fields of one iteration.
class Lbfgsb {
 public:
  Lbfgsb(Formulation &f, int memory)
      : f_(f),
        n_(f.size()),
        total_(static_cast<std::int64_t>(f.total_size())),
        bound_{f.bounded_size(), f.lower_bound()},
        reductions_(f.reductions()),
        x_(f.variable().data()),
        g_(static_cast<std::size_t>(n_)),
        trial_gradient_(static_cast<std::size_t>(n_)),
        x_old_(static_cast<std::size_t>(n_)),
        // The direction takes the formulation's spare array if it lends one: of the four
        // fields it is the one that never changes hands (the gradients swap, x_old goes into
        // the pairs' memory).
        d_field_(f.spare_array() != nullptr ? 0 : static_cast<std::size_t>(n_)),
        d_(f.spare_array() != nullptr ? f.spare_array() : d_field_.data()),
        bfgs_(n_, memory, reductions_) {}

  // The paper's algorithm, step by step, from x projected onto the bound: Cauchy point,
  // subspace minimisation, line search, update of the pairs, test for convergence.
  void run(Monitor &monitor) {
    project_start();
    value_ = f_.value_and_gradient(x_, g_.data());
    if (monitor.should_stop(0, observe(f_, x_, g_.data(), value_, monitor))) return;
    bool first = true;
    for (std::int64_t iteration = 1;;) {
      const CauchyPoint cauchy = generalized_cauchy_point(
          x_, g_.data(), n_, bound_.bounded, bound_.lower, bfgs_, reductions_, work_);
      subspace_minimisation(cauchy);
      const Search search = line_search(first);
      if (search == Search::not_finite) {
        monitor.declare_breakdown();
        return;
      }
      if (search != Search::accepted) {
        // The model's direction is no use (rounding near the solution, or a poor memory):
        // start again from the steepest descent with no pairs. Without pairs there is no
        // descent left short of the tolerance: the iterate is stationary to rounding.
        if (bfgs_.pairs() == 0) {
          monitor.declare_stalled();
          return;
        }
        bfgs_.forget();
        continue;
      }
      first = false;
      update_memory();
      if (monitor.should_stop(iteration,
                              observe(f_, x_, g_.data(), trial_error_, value_, monitor)))
        return;
      ++iteration;
    }
  }

 private:
  // The start must be feasible: x <- max(x, lower), which changes no feasible entry (there is
  // no mean constraint to restore: lbfgsb() refuses one).
  void project_start() { f_.project(x_); }

  // Step 3: the minimiser of the model over the unknowns the Cauchy point leaves free, by
  // the direct primal method: on the free set the model's Hessian is theta I - Z^T W M W^T Z,
  // whose inverse Sherman-Morrison-Woodbury gives through 2k x 2k matrices. Its minimiser,
  // for a free unknown,
  //     x_bar_i = x_i - g_i/theta + w_i.u,  u = M c/theta - N^-1 M W^T Z r/theta^2,
  // with r the model's reduced gradient at the Cauchy point and N = I - M W^T Z Z^T W/theta;
  // on the bound at the Cauchy point, x_bar_i = lower. Then Morales & Nocedal's remark:
  // x_bar is projected onto the bound, and if the step to it is no descent direction, the
  // unprojected step is cut back to the bound instead. Leaves d = x_bar - x, x_old = x.
  void subspace_minimisation(const CauchyPoint &cauchy) {
    const int k2 = bfgs_.columns();
    const double theta = bfgs_.theta(), t = cauchy.t;
    const auto size = static_cast<std::size_t>(k2);
    const std::int64_t free_count = total_ - cauchy.at_bound;
    u_.assign(size, 0.0);
    if (k2 > 0) {
      // W^T Z r = (1 - theta t) sum_free g_i w_i - (Z^T W)^T Z^T W M c, since on the free
      // set x_cauchy - x = -t g.
      const std::vector<double> &a = cauchy.free_gradient, &gram = cauchy.free_gram;
      std::vector<double> mc(size), rhs(size), v(size);
      bfgs_.times_middle(cauchy.c.data(), mc.data());
      for (std::size_t r = 0; r < size; ++r) {
        double kmc = 0.0;
        for (std::size_t c = 0; c < size; ++c) kmc += gram[r * size + c] * mc[c];
        rhs[r] = (1.0 - theta * t) * a[r] - kmc;
      }
      bfgs_.times_middle(rhs.data(), v.data());
      // N = I - M K/theta, K = Z^T W ^T Z^T W (symmetric, so M K's columns are M times K's).
      std::vector<double> mk(size * size), column(size), product(size);
      for (std::size_t c = 0; c < size; ++c) {
        for (std::size_t r = 0; r < size; ++r) column[r] = gram[r * size + c];
        bfgs_.times_middle(column.data(), product.data());
        for (std::size_t r = 0; r < size; ++r)
          mk[r * size + c] = (r == c ? 1.0 : 0.0) - product[r] / theta;
      }
      if (solve_small(mk, k2, v.data(), 1)) {
        for (std::size_t j = 0; j < size; ++j) u_[j] = mc[j] / theta - v[j] / (theta * theta);
      } else {
        // N singular to working precision: keep the Cauchy point's own direction.
        for (std::size_t j = 0; j < size; ++j) u_[j] = mc[j] / theta;
      }
    }
    if (!project_subspace_step(cauchy, free_count)) backtrack_subspace_step(cauchy);
  }

  // x_bar projected onto the bound: d = max(x_bar, lower) - x, x_old <- x, with the sums
  // finish_direction() forms, in the same pass. Returns whether d is a descent direction
  // (g.d < 0). The model's correction w_i.u is added over the free unknowns only: in the pass
  // if they are many; from the list if they are few, the pass then finishing the unknowns on
  // the bound and the list the free ones. The kernels read the fields and the bound through
  // locals: through the members every store to d would make them load again.
  bool project_subspace_step(const CauchyPoint &cauchy, std::int64_t free_count) {
    const int k2 = bfgs_.columns();
    const double inverse_theta = 1.0 / bfgs_.theta(), t = cauchy.t;
    const double *x = x_, *g = g_.data(), *u = u_.data();
    double *d = d_, *x_old = x_old_.data();
    const Bound bound = bound_;
    // The free unknowns, when they are few, from a list. The Cauchy point's, with its kept
    // rows, serves as it is (the unknowns the path took to the bound are skipped);
    // otherwise those it took leave it, or a pass lists the free ones.
    const bool listed = k2 > 0 && !list_complement(free_count, total_);
    const auto fixed = [=](std::int64_t i) { return at_bound(x[i], g[i], bound(i), t); };
    const bool kept = listed && cauchy.kept_rows;
    Indices &list = work_.list;
    if (listed && !kept) {
      if (cauchy.listed_free) {
        list.erase(std::remove_if(list.begin(), list.end(), fixed), list.end());
      } else {
        list.clear();
        loops::select(n_, [&](std::int64_t i) { return !fixed(i); }, list);
      }
    }
    const CompactBfgs &bfgs = bfgs_;
    const auto finish = [=](std::int64_t i, double x_bar, double *sum, double &max) {
      d[i] = finish_unknown(x[i], g[i], bound(i), x_bar, sum, max);
    };
    std::array<double, 3> s;
    if (listed) {
      // The unknowns on the bound are finished here (x_bar = lower, d = lower - x); the free
      // ones get x - g/theta, and their correction and finish from the list. Two unknowns
      // at a time (core/lanes.hpp), a free one adding nothing to the sums. Where d < 0 the
      // step to the bound is d itself: finish_unknown's -(lower - x)/d is -1 exactly, with
      // no division.
      const auto body = [=](std::int64_t i, auto *sum, auto *max) {
        using V = std::remove_pointer_t<decltype(sum)>;
        const V xi = lanes::load<V>(x + i), gi = lanes::load<V>(g + i);
        const V bi = bound.at<V>(i);
        lanes::store(x_old + i, xi);
        const auto on_bound = at_bound(xi, gi, bi, t);
        const V finished = on_bound ? bi - xi : lanes::splat<V>(0.0);
        sum[0] += gi * finished;
        sum[1] += finished * finished;
        const V limit = finished < 0.0 ? lanes::splat<V>(-1.0) : lanes::splat<V>(-infinity);
        max[0] = max[0] > limit ? max[0] : limit;
        lanes::store(d + i, on_bound ? finished : xi - gi * inverse_theta);
      };
      const auto r = loops::sums_and_maxima_in_lanes<2, 1>(reductions_, n_, body);
      s = {r.first[0], r.first[1], r.second[0]};
      // One sweep of the list, each unknown's row of W read at once: from the kept copy, or
      // gathered, the rows a few entries ahead fetched while this one is summed (the list's
      // gaps defeat the prefetchers).
      constexpr std::int64_t ahead = 8;
      const auto listed_count = static_cast<std::int64_t>(list.size());
      const std::int64_t *at = list.data();
      std::vector<double> weight(static_cast<std::size_t>(k2));
      for (int j = 0; j < k2; ++j) weight[j] = bfgs.scale(j) * u[j];
      double sums[2] = {0.0, 0.0}, max = -infinity;
      for (std::int64_t p = 0; p < listed_count; ++p) {
        const std::int64_t i = at[p];
        double correction = 0.0;
        if (kept) {
          if (fixed(i)) continue;
          for (int j = 0; j < k2; ++j)
            correction += kept_row_entry(work_.rows, k2, listed_count, p, j) * weight[j];
        } else {
          if (p + ahead < listed_count) bfgs.prefetch_row(at[p + ahead]);
          correction = bfgs.row_times(i, u);
        }
        finish(i, d[i] + correction, sums, max);
      }
      reductions_.combine_sums(sums, 2);
      reductions_.combine_maxima(&max, 1);
      s[0] += sums[0];
      s[1] += sums[1];
      s[2] = std::max(s[2], max);
    } else {
      const auto body = [=, &bfgs](std::int64_t i, double *sum, double &max) {
        x_old[i] = x[i];
        if (fixed(i))
          finish(i, bound(i), sum, max);
        else
          finish(i, x[i] - g[i] * inverse_theta + (k2 > 0 ? bfgs.row_times(i, u) : 0.0), sum,
                 max);
      };
      s = loops::sums_and_max<2>(reductions_, n_, body);
    }
    return take_direction_sums(s);
  }

  // The backtracked step: x_bar = x_cauchy + alpha (x_unprojected - x_cauchy) on the free
  // unknowns, alpha <= 1 the largest that keeps every one feasible.
  void backtrack_subspace_step(const CauchyPoint &cauchy) {
    const double inverse_theta = 1.0 / bfgs_.theta(), t = cauchy.t;
    const double *x = x_, *g = g_.data(), *u = u_.data();
    double *d = d_;
    const CompactBfgs &bfgs = bfgs_;
    const int k2 = bfgs_.columns();
    const Bound bound = bound_;
    // d <- the unprojected step from the Cauchy point, 0 at the bound.
    loops::for_each(n_, [&](std::int64_t i) {
      const double cauchy_i = x[i] - t * g[i];
      d[i] = at_bound(x[i], g[i], bound(i), t)
                 ? 0.0
                 : x[i] - g[i] * inverse_theta + (k2 > 0 ? bfgs.row_times(i, u) : 0.0) -
                       cauchy_i;
    });
    const double alpha = std::min(
        1.0, -loops::maximum(reductions_, n_, [&](std::int64_t i) {
          const double cauchy_i = x[i] - t * g[i];
          return d[i] < 0.0 ? -(bound(i) - cauchy_i) / d[i] : -infinity;
        }));
    loops::for_each(n_, [&](std::int64_t i) {
      d[i] = at_bound(x[i], g[i], bound(i), t) ? bound(i) : x[i] - t * g[i] + alpha * d[i];
    });
    finish_direction();
  }

  // From x_bar in d: d <- max(x_bar, lower) - x, x_old <- x, and the slope g.d, |d|^2 and the
  // largest feasible step along d. Returns whether d descends.
  bool finish_direction() {
    const double *x = x_, *g = g_.data();
    double *d = d_, *x_old = x_old_.data();
    const Bound bound = bound_;
    return take_direction_sums(loops::sums_and_max<2>(
        reductions_, n_, [=](std::int64_t i, double *sum, double &max) {
          x_old[i] = x[i];
          d[i] = finish_unknown(x[i], g[i], bound(i), d[i], sum, max);
        }));
  }

  // The slope g.d, |d| and the largest feasible step from the sums g.d, d.d and the maximum
  // of -(step to the bound). Returns whether d descends.
  bool take_direction_sums(const std::array<double, 3> &s) {
    slope_ = s[0];
    direction_norm_ = std::sqrt(s[1]);
    largest_step_ = std::isfinite(s[2]) ? std::min(-s[2], unbounded_step) : unbounded_step;
    return slope_ < 0.0;
  }

  // Step 4: a line search along d from x_old for the strong Wolfe conditions, with the step
  // at most the largest feasible one. The first iteration tries 1/|d| (capped at the
  // largest step, 1 there, the paper's choice), later ones the unit step. On success x, its
  // gradient (in trial_gradient_) and value_ are the accepted point's; otherwise x is back
  // at x_old.
  Search line_search(bool first) {
    if (!std::isfinite(slope_) || !std::isfinite(direction_norm_)) return Search::not_finite;
    if (!(slope_ < 0.0)) return Search::no_descent;
    const double largest = first ? std::min(1.0, largest_step_) : largest_step_;
    const double step = first ? std::min(1.0 / direction_norm_, largest) : std::min(1.0, largest);
    const LineSearchResult result = search_line(
        line_search_settings, value_, slope_, step, largest,
        [&](double trial, double &value, double &slope) {
          move_to(trial);
          value = f_.value_and_gradient(x_, trial_gradient_.data());
          slope = slope_and_error();
        },
        &value_);
    if (result == LineSearchResult::accepted) return Search::accepted;
    move_to(0.0);
    return result == LineSearchResult::not_finite ? Search::not_finite : Search::failed;
  }

  // The slope g.d at the trial point, and in the same pass the monitor's error there: the
  // bound's residual of x and its gradient, which is what Formulation::error measures of a
  // formulation without a mean constraint (lbfgsb refuses one), to the same bits.
  double slope_and_error() {
    const double *x = x_, *g = trial_gradient_.data(), *d = d_;
    const Bound bound = bound_;
    const auto r = loops::sums_and_maxima_in_lanes<2, bound_residual_maxima>(
        reductions_, n_, [=](std::int64_t i, auto *sum, auto *max) {
          using V = std::remove_pointer_t<decltype(sum)>;
          const V gi = lanes::load<V>(g + i);
          sum[0] += gi * lanes::load<V>(d + i);
          gather_bound_residual(lanes::load<V>(x + i), gi, bound.at<V>(i), max, sum[1]);
        });
    trial_error_ = bound_residual_at(r.second.data(), r.first[1], 0.0);
    return r.first[0];
  }

  // x <- max(x_old + step d, lower): the bound holds bitwise whatever the rounding.
  void move_to(double step) {
    const double *x_old = x_old_.data(), *d = d_;
    double *x = x_;
    const Bound bound = bound_;
    loops::for_each_in_lanes(n_, [=](std::int64_t i, auto lanes_of) {
      using V = decltype(lanes_of);
      const V moved = lanes::load<V>(x_old + i) + step * lanes::load<V>(d + i);
      const V bi = bound.at<V>(i);
      lanes::store(x + i, moved > bi ? moved : bi);
    });
  }

  // Step 5: the pair s = x - x_old, y = g_new - g enters the memory unless the curvature
  // condition fails; the accepted gradient becomes g.
  void update_memory() {
    bfgs_.add_pair(x_, x_old_, trial_gradient_.data(), g_);
    std::swap(g_, trial_gradient_);
  }

  Formulation &f_;
  std::int64_t n_;
  std::int64_t total_;  // unknowns over all processes
  const Bound bound_;  // the formulation's: lower_bound() on its first bounded_size() unknowns
  const Reductions &reductions_;
  double *x_;
  double value_ = 0.0;
  Field g_, trial_gradient_, x_old_;
  Field d_field_;  // empty when the direction is the formulation's spare array
  double *d_;
  CompactBfgs bfgs_;
  std::vector<double> u_;
  double slope_ = 0.0, direction_norm_ = 0.0, largest_step_ = 0.0;
  double trial_error_ = 0.0;  // the monitor's error at the last trial point
  CauchyWork work_;  // the Cauchy point's, whose list and rows the step reads
};

bool on_the_gap(const OptionValues &options) { return options.text("variable") == "gap"; }

// L-BFGS-B keeps the unknowns in a box, but no mean-value equality: it serves penetration
// control on either variable, and load control on the gap, whose formulation takes the load
// as a work term without a constraint (not with a user's potential: see
// primal_formulation.hpp).
constexpr const char *load_with_potential =
    "under a tensile load the separation of the surfaces cannot be told from a user's "
    "potential's values";

Offer offer_for(const OptionValues &options) {
  if (on_the_gap(options))
    return {{Control::penetration, Control::mean_pressure},
            false,
            {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential},
            true,
            "variable = gap",
            {},
            "",
            {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential},
            false,
            load_with_potential};
  return {{Control::penetration},
          false,
          {InteractionFamily::hard_wall},
          false,
          "variable = pressure",
          {},
          "",
          {},
          false,
          ""};
}

template <class Variable>
void run_on(System &system, Control control, double value, int memory, Monitor &monitor) {
  Variable formulation(system, control, value);
  lbfgsb(formulation, monitor, memory);
  conclude(formulation, system, monitor);
}

void run(System &system, Control control, double value, const OptionValues &options,
         Monitor &monitor) {
  const int memory = static_cast<int>(options.number("memory"));
  if (on_the_gap(options))
    run_on<PrimalFormulation>(system, control, value, memory, monitor);
  else
    run_on<DualFormulation>(system, control, value, memory, monitor);
}

}  // namespace

void lbfgsb(Formulation &f, Monitor &monitor, int memory) {
  if (f.constrains_mean())
    throw Error(Status::internal, "lbfgsb cannot keep a mean-value constraint");
  Lbfgsb algorithm(f, memory);
  algorithm.run(monitor);
}

AlgorithmSpec lbfgsb_algorithm() {
  AlgorithmSpec spec;
  spec.name = "lbfgsb";
  spec.summary =
      "Byrd, Lu, Nocedal & Zhu's limited-memory BFGS for bound constraints (L-BFGS-B, SIAM "
      "J. Sci. Comput. 1995; thesis section 3.1.6) on the pressure (the complementary energy, "
      "as for pk; no adhesion) or on the gap (the elastic energy plus the interaction "
      "energy; with or without adhesion), under penetration control, and on the gap also "
      "under load control";
  spec.controls = {Control::penetration, Control::mean_pressure};
  spec.offer_for = offer_for;
  spec.interactions = {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential};
  spec.callbacks = true;
  spec.options = {
      {"variable", OptionType::choice, 0.0, 0.0, 0.0, false, {"pressure", "gap"},
       "the unknown: pressure (the dual problem; no adhesion) or gap (the primal; with or "
       "without adhesion, or a user's potential with the hard wall); penetration control on "
       "either, mean-pressure control on the gap (tensile loads included; not with a "
       "user's potential)"},
      {"memory", OptionType::integer, 5, 1, 100, false, {},
       "the number of step and gradient-change pairs the quasi-Newton matrix keeps (16 bytes "
       "per pixel each)"},
  };
  // Nested grids by default: on the bench scene to 1e-8 (on the gap) they take 0.62 to 0.83
  // times the time of a plain solve from 512^2 to 2048^2, and their iterations grow 1.06
  // times from 1024^2 to 2048^2 against 1.35 (docs/performance.md, "Nested grids with
  // bugnicourt and lbfgsb"). Below 128 pixels a side, from a warm start and with a user's
  // potential, none are taken.
  spec.default_levels = levels_auto;
  spec.run = run;
  return spec;
}

}  // namespace asp
