// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/bound_residual.hpp"

#include <cmath>

#include "core/loops.hpp"

namespace asp {

namespace {

// Near the optimum the gradient is nearly the same on every free unknown (the multiplier),
// often far larger than its spread: summed as it is, rounding would grow with the number of
// terms and hide the spread. It is summed relative to one of its free values instead, the
// first this process holds (the largest of those over processes, so that all use one).
double free_pivot(const Reductions &reductions, std::int64_t n, const double *x,
                  const double *gradient, double lower) {
  std::int64_t first = 0;
  while (first < n && !(x[first] > lower)) ++first;
  double pivot = first < n ? gradient[first] : -HUGE_VAL;
  reductions.combine_maxima(&pivot, 1);
  return pivot > -HUGE_VAL ? pivot : 0.0;
}

}  // namespace

double mean_over_free(const Reductions &reductions, std::int64_t n, const double *x,
                      const double *gradient, double lower) {
  const double pivot = free_pivot(reductions, n, x, gradient, lower);
  const auto sums = loops::sums<2>(reductions, n, [&](std::int64_t i, double *s) {
    const double free = x[i] > lower ? 1.0 : 0.0;
    s[0] += free * (gradient[i] - pivot);
    s[1] += free;
  });
  return sums[1] > 0.0 ? pivot + sums[0] / sums[1] : 0.0;
}

double bound_residual(const Reductions &reductions, std::int64_t n, std::int64_t bounded,
                      const double *x, const double *gradient, double lower,
                      bool mean_constrained) {
  // One pass: the multiplier's sums (as mean_over_free takes them) and the extremes. The
  // unknowns from `bounded` on have no bound (as if it were -infinity); a mean constraint
  // concerns all unknowns, which formulations only impose where all are bounded.
  const auto bound = [&](std::int64_t i) { return i < bounded ? lower : -HUGE_VAL; };
  const double pivot = mean_constrained ? free_pivot(reductions, n, x, gradient, lower) : 0.0;
  const auto r = loops::sums_and_maxima<3, bound_residual_maxima>(
      reductions, n, [&](std::int64_t i, double *sum, double *max) {
        const double free = x[i] > bound(i) ? 1.0 : 0.0;
        sum[0] += free * (gradient[i] - pivot);
        sum[1] += free;
        gather_bound_residual(x[i], gradient[i], bound(i), max, sum[2]);
      });
  const double shift =
      mean_constrained && r.first[1] > 0.0 ? pivot + r.first[0] / r.first[1] : 0.0;
  return bound_residual_at(r.second.data(), r.first[2], shift);
}

}  // namespace asp
