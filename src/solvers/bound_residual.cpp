#include "solvers/bound_residual.hpp"

#include <cmath>

#include "core/loops.hpp"

namespace asp {

double mean_over_free(const Reductions &reductions, std::int64_t n, const double *x,
                      const double *gradient, double lower) {
  // Near the optimum the gradient is nearly the same on every free unknown (the multiplier),
  // often far larger than its spread: summed as it is, rounding would grow with the number of
  // terms and hide the spread. It is summed relative to one of its free values instead, the
  // first this process holds (the largest of those over processes, so that all use one).
  std::int64_t first = 0;
  while (first < n && !(x[first] > lower)) ++first;
  double pivot = first < n ? gradient[first] : -HUGE_VAL;
  reductions.combine_maxima(&pivot, 1);
  if (!(pivot > -HUGE_VAL)) pivot = 0.0;
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
  const double shift =
      mean_constrained ? mean_over_free(reductions, bounded, x, gradient, lower) : 0.0;
  // The residuals are also summed, only to notice NaN, which a maximum may drop.
  const auto r = loops::sums_and_max<1>(reductions, n, [&](std::int64_t i, double *sum,
                                                           double &max) {
    const bool on_bound = i < bounded && !(x[i] > lower);
    const double g = gradient[i] - (i < bounded ? shift : 0.0);
    const double v = on_bound ? (g > 0.0 ? 0.0 : -g) : std::fabs(g);
    max = max > v ? max : v;
    sum[0] += v;
  });
  if (!std::isfinite(r[0])) return r[0];
  return r[1] > 0.0 ? r[1] : 0.0;
}

}  // namespace asp
