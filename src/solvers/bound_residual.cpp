#include "solvers/bound_residual.hpp"

#include <cmath>

#include "core/loops.hpp"

namespace asp {

double mean_over_free(const Reductions &reductions, std::int64_t n, const double *x,
                      const double *gradient, double lower) {
  const auto sums = loops::sums<2>(reductions, n, [&](std::int64_t i, double *s) {
    const double free = x[i] > lower ? 1.0 : 0.0;
    s[0] += free * gradient[i];
    s[1] += free;
  });
  return sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
}

double bound_residual(const Reductions &reductions, std::int64_t n, const double *x,
                      const double *gradient, double lower, bool mean_constrained) {
  const double shift =
      mean_constrained ? mean_over_free(reductions, n, x, gradient, lower) : 0.0;
  // The residuals are also summed, only to notice NaN, which a maximum may drop.
  const auto r = loops::sums_and_max<1>(reductions, n, [&](std::int64_t i, double *sum,
                                                           double &max) {
    const double g = gradient[i] - shift;
    const double v = x[i] > lower ? std::fabs(g) : (g > 0.0 ? 0.0 : -g);
    max = max > v ? max : v;
    sum[0] += v;
  });
  if (!std::isfinite(r[0])) return r[0];
  return r[1] > 0.0 ? r[1] : 0.0;
}

}  // namespace asp
