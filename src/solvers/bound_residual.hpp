// The error measure of DESIGN.md section 2 for a bound-constrained problem: the largest
// residual of the optimality conditions, with the gradient in pressure units. Where the
// unknown is above its bound the gradient must vanish (|r|); where it sits on the bound the
// gradient may only point into the feasible set (max(-r, 0)). Under a mean-value constraint
// the gradient counts relative to its mean over the free unknowns, the constraint's multiplier.
#pragma once

#include <cstdint>

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

}  // namespace asp
