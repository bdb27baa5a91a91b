// SPDX-License-Identifier: GPL-2.0-or-later
// The generalized Cauchy point of L-BFGS-B (Byrd, Lu, Nocedal & Zhu, SIAM J. Sci. Comput. 16,
// 1995, section 4; thesis section 3.1.6): the first local minimiser of the quasi-Newton model
// along the projected steepest-descent path, with the sums over the unknowns it leaves free
// that the subspace minimisation needs. Step 2 of lbfgsb.cpp's algorithm.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/lanes.hpp"
#include "core/reductions.hpp"
#include "solvers/compact_bfgs.hpp"

namespace asp {

// The bound of unknown i: `lower` on the first `bounded` unknowns, none on the others. A
// value, so that the kernels hold it in registers.
struct Bound {
  std::int64_t bounded;
  double lower;
  double operator()(std::int64_t i) const {
    return i < bounded ? lower : -std::numeric_limits<double>::infinity();
  }
  // The bounds of the entries a value of type V holds from i on (core/lanes.hpp).
  template <class V>
  V at(std::int64_t i) const {
    if constexpr (lanes::width<V> == 1)
      return (*this)(i);
    else
      return V{(*this)(i), (*this)(i + 1)};
  }
};

// Whether unknown i sits on the bound at the point t of the projected path x(t): it was on
// the bound with g pushing outwards (t = 0), or its breakpoint (x_i - lower)/g_i is at most
// t, tested without a division. The one place that decides it for every pass. (Where
// rounding makes it disagree with the heap's order, the unknown's breakpoint equals t to
// rounding: it is on the bound either way.)
inline bool at_bound(double x, double g, double lower, double t) {
  return g > 0.0 && x - lower <= t * g;
}
#if defined(__GNUC__)
// The same test on two entries: a mask.
inline auto at_bound(lanes::Pair x, lanes::Pair g, lanes::Pair lower, double t) {
  return (g > 0.0) & (x - lower <= t * g);
}
#endif

// Whether a set of about `size` of `total` unknowns (over all processes) is better listed by
// its complement: the same choice on every process, from global counts.
inline bool list_complement(std::int64_t size, std::int64_t total) { return size > total / 2; }

// The generalized Cauchy point (step 2 of the algorithm, open for tests): along the
// projected steepest-descent path x(t) = max(x - t g, lower), the first local minimiser t of
// the model m(x(t)) = g.(x(t) - x) + (x(t) - x).B (x(t) - x)/2, B the compact matrix. The
// breakpoints t_i = (x_i - lower)/g_i (g_i > 0) are visited in increasing order from a heap,
// with the paper's updates of the slope and the curvature on each segment.
struct CauchyPoint {
  double t = 0.0;              // the point is max(x - t g, lower)
  std::vector<double> c;       // W^T (x(t) - x)
  std::int64_t at_bound = 0;   // unknowns at the bound at x(t)
  // Over the free unknowns at x(t) (those off the bound), with w_i row i of W: the sums of
  // g_i w_i (2k) and of w_i w_i^T (2k x 2k, row-major), which the subspace minimisation
  // needs. Formed over the free unknowns at t = 0, less each breakpoint the path passed.
  std::vector<double> free_gradient, free_gram;
  // Whether the work's list came back holding every unknown off the bound at t = 0, in
  // order (a superset, in order, of those off it at x(t)).
  bool listed_free = false;
  // Whether the work's rows came back holding those of W at the listed unknowns (when the free
  // ones are listed and few): the subspace minimisation needs them again, and a sweep of
  // the copy costs less than a second gather. See kept_row_entry.
  bool kept_rows = false;
};
using Indices = std::vector<std::int64_t, FieldAllocator<std::int64_t>>;
struct Breakpoint {
  double t;
  std::int64_t i;
};
using Breakpoints = std::vector<Breakpoint, FieldAllocator<Breakpoint>>;
// The rows are gathered and kept in blocks of this many listed unknowns (the last block
// shorter), a block's 2k columns one after another: entry j of the row of the p-th of
// `listed` unknowns.
constexpr std::int64_t kept_row_block = 256;
inline double kept_row_entry(const Field &rows, int columns, std::int64_t listed,
                             std::int64_t p, int j) {
  const std::int64_t begin = p - p % kept_row_block;
  const std::int64_t length = std::min(kept_row_block, listed - begin);
  return rows[static_cast<std::size_t>(begin * columns + j * length + (p - begin))];
}
// The work space of generalized_cauchy_point, kept by the caller between iterations.
struct CauchyWork {
  Indices list;      // the listed unknowns (see CauchyPoint::listed_free)
  Breakpoints heap;  // the breakpoints the path has not passed
  Field rows;        // the rows of W at the listed unknowns (see CauchyPoint::kept_rows)
  // Which set the last call listed: the guess that lets one pass count the unknowns on the
  // bound and list them.
  enum class Listed { none_yet, free, on_bound } last_listed = Listed::none_yet;
};
// The bound x >= lower holds on the first `bounded` of the n unknowns, none on the others.
// g must be the gradient of bfgs's last add_pair (its products with the pairs, W^T g, are
// used).
CauchyPoint generalized_cauchy_point(const double *x, const double *g, std::int64_t n,
                                     std::int64_t bounded, double lower,
                                     const CompactBfgs &bfgs, const Reductions &reductions,
                                     CauchyWork &work);

}  // namespace asp
