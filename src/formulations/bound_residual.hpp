// SPDX-License-Identifier: GPL-2.0-or-later
// The error measure of DESIGN.md section 2 for a bound-constrained problem: the largest
// residual of the optimality conditions, with the gradient in pressure units. Where the
// unknown is above its bound the gradient must vanish (|r|); where it sits on the bound the
// gradient may only point into the feasible set (max(-r, 0)). Under a mean-value constraint
// the gradient counts relative to its mean over the free unknowns, the constraint's multiplier.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>

#include "core/reductions.hpp"

namespace asp {

// The mean of the gradient over the free unknowns (x > lower), 0 if there is none: the
// multiplier of a mean-value constraint, as the optimality conditions define it.
double mean_over_free(const Reductions &reductions, std::int64_t n, const double *x,
                      const double *gradient, double lower);

// Over n unknowns of which the first `bounded` carry the bound and the mean constraint; the
// others are free of both (their residual is |gradient|). NaN in the gradient is returned as
// NaN, so that the monitor sees it.
double bound_residual(const Reductions &reductions, std::int64_t n, std::int64_t bounded,
                      const double *x, const double *gradient, double lower,
                      bool mean_constrained);

// The residual gathered element by element before the multiplier is known, so that a solver
// can fuse it into a pass of its own and still measure exactly what bound_residual measures
// (which is built from the same two functions). Per unknown, gather_bound_residual raises two
// maxima, which start at -infinity: the largest gradient over the free unknowns and the
// largest negated gradient over all; and it adds g - g to a sum, which stays 0 unless an entry
// is not finite. bound_residual_at then gives the largest residual at the multiplier `shift`,
//     max(max_free g - shift, shift - min g, 0)
// (|g - shift| on the free unknowns is the larger of g - shift and shift - g; on the bound
// only shift - g counts, and only where it is positive). It equals the largest of the
// residuals taken one by one exactly, not only to rounding: rounding is monotone, so the
// largest fl(g_i - shift) is fl(max_i g_i - shift).
constexpr int bound_residual_maxima = 2;

// For one entry (V = double) or two (lanes::Pair, core/lanes.hpp).
template <class V>
inline void gather_bound_residual(V x, V gradient, V lower, V *maxima, V &finite_check) {
  const V g = gradient;
  maxima[0] = ((x > lower) & (g > maxima[0])) ? g : maxima[0];
  maxima[1] = -g > maxima[1] ? -g : maxima[1];
  finite_check += g - g;
}

inline double bound_residual_at(const double *maxima, double finite_check, double shift) {
  if (!(finite_check == 0.0) || !std::isfinite(shift))
    return std::numeric_limits<double>::quiet_NaN();
  double largest = 0.0;
  for (const double v : {maxima[0] - shift, shift + maxima[1]})
    largest = v > largest ? v : largest;
  return largest;
}

}  // namespace asp
