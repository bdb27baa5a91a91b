// SPDX-License-Identifier: GPL-2.0-or-later
// L-BFGS-B of Byrd, Lu, Nocedal & Zhu (SIAM J. Sci. Comput. 16, 1995; thesis section 3.1.6)
// for an objective over x >= lower bound: a limited-memory BFGS model in compact form, the
// generalized Cauchy point along the projected steepest-descent path, minimisation of the
// model over the variables the Cauchy point left free (the direct primal method, with Morales
// & Nocedal's projection, ACM TOMS 38, 2011), and a line search for the strong Wolfe
// conditions. Without a bound (lower bound -infinity) it is plain L-BFGS. It needs only the
// generic Formulation: here it runs on the primal (gap) or dual (pressure) formulation of the
// hard wall under penetration control.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/reductions.hpp"
#include "solvers/compact_bfgs.hpp"
#include "formulations/formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/algorithm.hpp"

namespace asp {

AlgorithmSpec lbfgsb_algorithm();

// The algorithm on any formulation without a mean-value constraint, keeping at most `memory`
// pairs; leaves its last iterate in f.variable() (open for tests on small problems).
void lbfgsb(Formulation &f, Monitor &monitor, int memory);

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
