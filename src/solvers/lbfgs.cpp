// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/lbfgs.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "solvers/line_search.hpp"
#include "solvers/monitor.hpp"

namespace asp {
namespace {

// The line search's parameters: sufficient decrease 1e-4 and curvature 0.9 (Nocedal &
// Wright's choice for quasi-Newton methods, so that the unit step is nearly always taken),
// interval width 0.1; at most 20 evaluations per search.
constexpr LineSearchSettings line_search_settings{1e-4, 0.9, 0.1, 20};
constexpr double largest_step = 1e10;

class Lbfgs {
 public:
  Lbfgs(Formulation &f, int memory)
      : f_(f),
        n_(f.size()),
        memory_(memory),
        x_(f.variable().data()),
        g_(static_cast<std::size_t>(n_)),
        trial_gradient_(static_cast<std::size_t>(n_)),
        x_old_(static_cast<std::size_t>(n_)),
        d_(static_cast<std::size_t>(n_)),
        s_(static_cast<std::size_t>(memory)),
        y_(static_cast<std::size_t>(memory)),
        alpha_(static_cast<std::size_t>(memory)),
        rho_(static_cast<std::size_t>(memory)) {}

  void run(Monitor &monitor) {
    value_ = f_.value_and_gradient(x_, g_.data());
    if (monitor.should_stop(0, observe(f_, x_, g_.data(), value_, monitor))) return;
    for (std::int64_t iteration = 1;;) {
      two_loop_direction();
      const LineSearchResult search = line_search();
      if (search == LineSearchResult::not_finite) {
        monitor.declare_breakdown();
        return;
      }
      if (search == LineSearchResult::failed) {
        // The memory's direction is no use (rounding near the solution, or pairs from a
        // region of other curvature): start again from steepest descent. Without pairs
        // there is no descent left short of the tolerance.
        if (pairs_ == 0) {
          monitor.declare_stalled();
          return;
        }
        pairs_ = 0;
        continue;
      }
      update_memory();
      if (monitor.should_stop(iteration, observe(f_, x_, g_.data(), value_, monitor))) return;
      ++iteration;
    }
  }

 private:
  double dot(const Field &a, const Field &b) const { return f_.dot(a.data(), b.data()); }

  // d = -H g by the two-loop recursion over the stored pairs, newest first; H0 = gamma I
  // with gamma = s.y/y.y of the newest pair (1 without pairs: the formulations are scaled so
  // that the elastic stiffness of a pixel, or of a mode, is 1). Each pass over the fields
  // applies one pair's update to d and sums the inner product the next step needs with the
  // updated d, so that the recursion reads each stored field once: 2m + 1 passes for m
  // pairs instead of 4m + 2.
  void two_loop_direction() {
    double *d = d_.data();
    const double *g = g_.data();
    const Reductions &reductions = f_.reductions();
    // d <- scale (d + c v), then the sum of w.d.
    const auto update_then_dot = [&](double scale, double c, const double *v, const double *w) {
      return loops::sum(reductions, n_, [&](std::int64_t i) {
        d[i] = scale * (d[i] + c * v[i]);
        return w[i] * d[i];
      });
    };
    const int m = pairs_;
    // The first loop, newest pair (k = 0) to oldest: a = rho s.d, d <- d - a y.
    const auto newest_first = [&](int k) { return slot(m - 1 - k); };
    const double *first = m > 0 ? s_[newest_first(0)].data() : g;
    double product = loops::sum(reductions, n_, [&](std::int64_t i) {
      d[i] = -g[i];
      return first[i] * d[i];
    });
    for (int k = 0; k < m; ++k) {
      const int j = newest_first(k);
      alpha_[j] = rho_[j] * product;
      // The last update of the first loop also applies H0 and starts the second loop, which
      // needs the oldest pair's y.d.
      const bool last = k + 1 == m;
      const double *next = last ? y_[slot(0)].data() : s_[newest_first(k + 1)].data();
      product = update_then_dot(last ? gamma_ : 1.0, -alpha_[j], y_[j].data(), next);
    }
    // The second loop, oldest pair to newest: b = rho y.d, d <- d + (a - b) s; the last pass
    // sums the slope g.d.
    for (int k = 0; k < m; ++k) {
      const int j = slot(k);
      const double b = rho_[j] * product;
      const double *next = k + 1 == m ? g : y_[slot(k + 1)].data();
      product = update_then_dot(1.0, alpha_[j] - b, s_[j].data(), next);
    }
    slope_ = product;
    if (!(slope_ < 0.0) && std::isfinite(slope_) && pairs_ > 0) {
      // Not a descent direction (the pairs no longer describe the curvature): steepest
      // descent, without the memory.
      pairs_ = 0;
      two_loop_direction();
    }
  }

  // The memory is a ring: pair k (0 the oldest) of pairs_ sits in slot (newest_ - pairs_ + 1
  // + k) mod memory.
  int slot(int k) const { return (newest_ - pairs_ + 1 + k + 2 * memory_) % memory_; }

  // Along d from x, for the strong Wolfe conditions. On success x, g and
  // value_ are the accepted point's and x_old the previous one.
  LineSearchResult line_search() {
    if (!std::isfinite(slope_)) return LineSearchResult::not_finite;
    if (!(slope_ < 0.0)) return LineSearchResult::failed;
    double *x = x_, *x_old = x_old_.data();
    const double *d = d_.data();
    loops::for_each(n_, [&](std::int64_t i) { x_old[i] = x[i]; });
    const auto move_to = [&](double step) {
      loops::for_each(n_, [&](std::int64_t i) { x[i] = x_old[i] + step * d[i]; });
    };
    // Without pairs the direction is the gradient, whose scale says nothing about the step:
    // the first trial is then 1/|d| (capped at 1), as in L-BFGS-B, so that a start deep inside
    // a stiff wall, with forces of any size, is not met with a step of any size.
    double first = 1.0;
    if (pairs_ == 0) first = std::min(1.0, 1.0 / std::sqrt(dot(d_, d_)));
    const LineSearchResult result = search_line(
        line_search_settings, value_, slope_, first, largest_step,
        [&](double step, double &value, double &slope) {
          move_to(step);
          value = f_.value_and_gradient(x, trial_gradient_.data());
          slope = dot(trial_gradient_, d_);
        },
        &value_);
    if (result != LineSearchResult::accepted) move_to(0.0);
    return result;
  }

  // s = x - x_old, y = g_new - g enter the memory if s.y > 0 (the curvature condition, which
  // the strong Wolfe conditions guarantee up to rounding); the new gradient becomes g. They
  // are written into the slot after the newest, the oldest pair's when the memory is full,
  // so that a pair that fails the condition costs the oldest one.
  void update_memory() {
    const int j = (newest_ + 1) % memory_;
    // A slot's arrays are made when it is first filled: a solve that converges in a few
    // iterations (a warm start) makes only the pairs it stores, one that starts converged
    // none.
    if (s_[j].empty()) {
      s_[j] = Field(static_cast<std::size_t>(n_));
      y_[j] = Field(static_cast<std::size_t>(n_));
    }
    double *s = s_[j].data(), *y = y_[j].data();
    const double *x = x_, *x_old = x_old_.data(), *g = g_.data(), *g_new = trial_gradient_.data();
    const auto sums = loops::sums<2>(f_.reductions(), n_, [&](std::int64_t i, double *sum) {
      s[i] = x[i] - x_old[i];
      y[i] = g_new[i] - g[i];
      sum[0] += s[i] * y[i];
      sum[1] += y[i] * y[i];
    });
    std::swap(g_, trial_gradient_);
    if (!(sums[0] > 0.0) || !(sums[1] > 0.0)) {
      if (pairs_ == memory_) --pairs_;
      return;
    }
    newest_ = j;
    rho_[j] = 1.0 / sums[0];
    gamma_ = sums[0] / sums[1];
    if (pairs_ < memory_) ++pairs_;
  }

  Formulation &f_;
  std::int64_t n_;
  int memory_;
  double *x_;
  double value_ = 0.0, slope_ = 0.0, gamma_ = 1.0;
  Field g_, trial_gradient_, x_old_, d_;
  std::vector<Field> s_, y_;
  std::vector<double> alpha_, rho_;
  int pairs_ = 0;
  int newest_ = -1;
};

}  // namespace

void lbfgs(Formulation &f, Monitor &monitor, int memory) {
  if (f.constrains_mean() || std::isfinite(f.lower_bound()))
    throw Error(Status::internal, "lbfgs runs on unconstrained formulations only");
  Lbfgs algorithm(f, memory);
  algorithm.run(monitor);
}

}  // namespace asp
