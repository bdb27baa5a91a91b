// SPDX-License-Identifier: GPL-2.0-or-later
// The limited-memory BFGS matrix in the compact representation of Byrd, Nocedal & Schnabel
// (Math. Program. 63, 1994), as L-BFGS-B uses it:
//     B = theta I - W M W^T,   W = [Y, theta S],
//     M = [[-D, L^T], [L, theta S^T S]]^-1,
// with S and Y the last k <= m steps s_j = x_{j+1} - x_j and gradient changes y_j (oldest
// first), D = diag(s_j.y_j), L the strictly lower triangle of S^T Y, and theta = y.y/s.y of
// the newest pair. The 2k columns of length n are fields; everything else is k x k or
// 2k x 2k, small and dense. It also keeps W^T W and W^T g for the current gradient g, which
// the Cauchy point and the subspace minimisation need, so that those need not pass over W.
//
// Inner products over the unknowns are plain sums combined by the reductions: the bounds of
// L-BFGS-B act on the unknowns one by one, which needs the unknowns to be orthonormal.
#pragma once

#include <cstdint>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/reductions.hpp"
#include "solvers/pair_products.hpp"

namespace asp {

class CompactBfgs {
 public:
  // At most `memory` pairs of fields of n entries each, allocated as pairs arrive.
  CompactBfgs(std::int64_t n, int memory, const Reductions &reductions);

  int pairs() const { return k_; }
  int columns() const { return 2 * k_; }
  double theta() const { return theta_; }

  // Entry i of column j of W (j < 2k), which is scale(j) times column(j)[i].
  double entry(int j, std::int64_t i) const { return scale_[j] * column_[j][i]; }
  const double *column(int j) const { return column_[j]; }
  double scale(int j) const { return scale_[j]; }
  // w_i^T v for the 2k-vector v: row i of W times v.
  double row_times(std::int64_t i, const double *v) const {
    double sum = 0.0;
    for (int j = 0; j < 2 * k_; ++j) sum += column_[j][i] * (scale_[j] * v[j]);
    return sum;
  }

  // Asks the caches for row i of W ahead of its use: a hint for sweeps of a list of
  // unknowns, whose gaps the hardware's prefetchers do not follow. No effect on results.
  void prefetch_row(std::int64_t i) const {
#if defined(__GNUC__)
    for (int j = 0; j < 2 * k_; ++j) __builtin_prefetch(column_[j] + i);
#else
    (void)i;
#endif
  }
  // M v (2k entries in, 2k out).
  void times_middle(const double *v, double *out) const;
  // W^T W and W^T g (the gradient of the last add_pair or forget), 2k x 2k and 2k.
  const std::vector<double> &gram() const { return gram_; }
  const std::vector<double> &times_gradient() const { return wtg_; }

  // After a step from x_old to x, with gradients g_old and g: writes s = x - x_old into
  // x_old and y = g - g_old into g_old, in one pass that also forms every product of s, y
  // and g with the stored pairs. Keeps the pair unless s.y <= epsilon y.y (the curvature
  // condition fails; the products with g are kept either way); a kept pair takes over the
  // two fields, and x_old and g_old receive the fields of the pair it replaced, or new ones.
  // Returns whether the pair was kept.
  bool add_pair(const double *x, Field &x_old, const double *g, Field &g_old);
  // Forgets every pair (after a failed line search), with W^T g emptied too.
  void forget();

 private:
  int slot(int j) const { return (oldest_ + j) % memory_; }
  // M, W^T W and W^T g from the small products, after every change of the pairs; false if
  // the middle matrix is singular to working precision.
  bool refresh();

  std::int64_t n_;
  int memory_;
  const Reductions &reductions_;
  PairProducts pair_products_;  // the variant this CPU runs best
  int k_ = 0;
  int oldest_ = 0;
  double theta_ = 1.0;
  std::vector<Field> s_, y_;  // memory_ slots each, in ring order
  // k x k products in history order, row-major with stride memory_: ss_[a*m+b] = s_a.s_b,
  // sy_[a*m+b] = s_a.y_b, yy_[a*m+b] = y_a.y_b; and S^T g, Y^T g.
  std::vector<double> ss_, sy_, yy_, sg_, yg_;
  std::vector<double> middle_;  // M, 2k x 2k, row-major
  std::vector<double> gram_;    // W^T W, 2k x 2k
  std::vector<double> wtg_;     // W^T g, 2k
  // The columns of W without theta, and theta or 1 for each.
  std::vector<const double *> column_;
  std::vector<double> scale_;
};

// Solves a x = b in place for `count` right-hand sides (b is size x count, column after
// column) by Gaussian elimination with partial pivoting; a is size x size, row-major, and is
// destroyed. Returns false if a is singular to working precision.
bool solve_small(std::vector<double> &a, int size, double *b, int count);

}  // namespace asp
