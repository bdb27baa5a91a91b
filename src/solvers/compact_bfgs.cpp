// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/compact_bfgs.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "core/loops.hpp"
#include "solvers/pair_products.hpp"

namespace asp {

bool solve_small(std::vector<double> &a, int size, double *b, int count) {
  const auto at = [&](int r, int c) -> double & {
    return a[static_cast<std::size_t>(r) * size + c];
  };
  const auto rhs = [&](int r, int c) -> double & {
    return b[static_cast<std::size_t>(c) * size + r];
  };
  for (int col = 0; col < size; ++col) {
    int pivot = col;
    for (int r = col + 1; r < size; ++r)
      if (std::fabs(at(r, col)) > std::fabs(at(pivot, col))) pivot = r;
    if (!(std::fabs(at(pivot, col)) > 0.0)) return false;
    if (pivot != col) {
      for (int c = 0; c < size; ++c) std::swap(at(pivot, c), at(col, c));
      for (int c = 0; c < count; ++c) std::swap(rhs(pivot, c), rhs(col, c));
    }
    for (int r = col + 1; r < size; ++r) {
      const double factor = at(r, col) / at(col, col);
      if (factor == 0.0) continue;
      for (int c = col; c < size; ++c) at(r, c) -= factor * at(col, c);
      for (int c = 0; c < count; ++c) rhs(r, c) -= factor * rhs(col, c);
    }
  }
  for (int c = 0; c < count; ++c)
    for (int r = size - 1; r >= 0; --r) {
      double v = rhs(r, c);
      for (int j = r + 1; j < size; ++j) v -= at(r, j) * rhs(j, c);
      rhs(r, c) = v / at(r, r);
    }
  return true;
}

CompactBfgs::CompactBfgs(std::int64_t n, int memory, const Reductions &reductions)
    : n_(n),
      memory_(memory),
      reductions_(reductions),
      pair_products_(pair_products(best_kernel_variant())) {
  const auto m = static_cast<std::size_t>(memory);
  s_.resize(m);
  y_.resize(m);
  ss_.assign(m * m, 0.0);
  sy_.assign(m * m, 0.0);
  yy_.assign(m * m, 0.0);
  sg_.assign(m, 0.0);
  yg_.assign(m, 0.0);
}

void CompactBfgs::times_middle(const double *v, double *out) const {
  const int size = columns();
  for (int r = 0; r < size; ++r) {
    double sum = 0.0;
    for (int c = 0; c < size; ++c) sum += middle_[static_cast<std::size_t>(r) * size + c] * v[c];
    out[r] = sum;
  }
}

bool CompactBfgs::add_pair(const double *x, Field &x_old, const double *g, Field &g_old) {
  // Sums: for each stored pair j, s.s_j, s.y_j, y.s_j, y.y_j, g.s_j, g.y_j; then s.s, s.y,
  // y.y, g.s, g.y of the new pair.
  const int k = k_;
  const int own = 6 * k;
  std::vector<double> sums(static_cast<std::size_t>(own + 5));
  std::vector<const double *> stored_s(static_cast<std::size_t>(k)), stored_y(stored_s);
  for (int j = 0; j < k; ++j) {
    stored_s[j] = s_[slot(j)].data();
    stored_y[j] = y_[slot(j)].data();
  }
  // One pass over blocks long enough for the prefetchers (loops::sweep_block), in the
  // variant this CPU runs best (pair_products.hpp).
  const PairBlock block{x, g, x_old.data(), g_old.data(), stored_s.data(), stored_y.data(), k};
  const PairProducts products = pair_products_;
  loops::block_sums(
      reductions_, n_, own + 5, sums.data(),
      [&](std::int64_t begin, std::int64_t end, double *sum) {
        products(block, begin, end, sum);
      },
      loops::sweep_block(n_));
  for (int j = 0; j < k; ++j) {
    sg_[j] = sums[6 * j + 4];
    yg_[j] = sums[6 * j + 5];
  }
  const double new_ss = sums[own], new_sy = sums[own + 1], new_yy = sums[own + 2];
  const bool kept = std::isfinite(new_ss + new_sy + new_yy) &&
                    new_sy > std::numeric_limits<double>::epsilon() * new_yy;
  if (!kept) {
    refresh();
    return false;
  }

  // The oldest pair leaves when the memory is full: the products shift by one.
  const auto m = static_cast<std::size_t>(memory_);
  int first = 0;  // the first stored pair that stays
  if (k_ == memory_) {
    first = 1;
    for (int a = 1; a < k_; ++a)
      for (int b = 1; b < k_; ++b) {
        ss_[(a - 1) * m + (b - 1)] = ss_[a * m + b];
        sy_[(a - 1) * m + (b - 1)] = sy_[a * m + b];
        yy_[(a - 1) * m + (b - 1)] = yy_[a * m + b];
      }
    for (int a = 1; a < k_; ++a) {
      sg_[a - 1] = sg_[a];
      yg_[a - 1] = yg_[a];
    }
    oldest_ = (oldest_ + 1) % memory_;
    --k_;
  }
  const int last = k_;  // the new pair's index in history order
  const auto newest = static_cast<std::size_t>(last);
  for (int j = first; j < k; ++j) {
    const auto b = static_cast<std::size_t>(j - first);
    const double *p = &sums[6 * static_cast<std::size_t>(j)];
    ss_[newest * m + b] = ss_[b * m + newest] = p[0];
    sy_[newest * m + b] = p[1];  // s_new.y_b
    sy_[b * m + newest] = p[2];  // s_b.y_new
    yy_[newest * m + b] = yy_[b * m + newest] = p[3];
  }
  ss_[newest * m + newest] = new_ss;
  sy_[newest * m + newest] = new_sy;
  yy_[newest * m + newest] = new_yy;
  sg_[newest] = sums[own + 3];
  yg_[newest] = sums[own + 4];
  // The new pair takes the fields; the caller gets those of the slot it fills.
  const int fill = slot(last);
  std::swap(s_[fill], x_old);
  std::swap(y_[fill], g_old);
  if (x_old.size() != static_cast<std::size_t>(n_)) x_old = Field(static_cast<std::size_t>(n_));
  if (g_old.size() != static_cast<std::size_t>(n_)) g_old = Field(static_cast<std::size_t>(n_));
  ++k_;
  theta_ = new_yy / new_sy;
  if (!refresh()) {
    forget();
    return false;
  }
  return true;
}

void CompactBfgs::forget() {
  k_ = 0;
  oldest_ = 0;
  theta_ = 1.0;
  refresh();
}

bool CompactBfgs::refresh() {
  const int k = k_, size = 2 * k_;
  const auto m = static_cast<std::size_t>(memory_);
  const auto two = static_cast<std::size_t>(size);
  column_.resize(two);
  scale_.resize(two);
  wtg_.resize(two);
  for (int j = 0; j < k; ++j) {
    column_[j] = y_[slot(j)].data();
    scale_[j] = 1.0;
    column_[k + j] = s_[slot(j)].data();
    scale_[k + j] = theta_;
    wtg_[j] = yg_[j];
    wtg_[k + j] = theta_ * sg_[j];
  }
  // W^T W = [[Y^T Y, theta Y^T S], [theta S^T Y, theta^2 S^T S]], and the inverse of M,
  // [[-D, L^T], [L, theta S^T S]], L_ab = s_a.y_b for a > b.
  gram_.assign(two * two, 0.0);
  std::vector<double> inverse(two * two, 0.0);
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b) {
      const double sy_ab = sy_[a * m + b], sy_ba = sy_[b * m + a];
      gram_[a * two + b] = yy_[a * m + b];
      gram_[a * two + k + b] = theta_ * sy_ba;
      gram_[(k + a) * two + b] = theta_ * sy_ab;
      gram_[(k + a) * two + k + b] = theta_ * theta_ * ss_[a * m + b];
      inverse[a * two + b] = a == b ? -sy_ab : 0.0;
      inverse[a * two + k + b] = b > a ? sy_ba : 0.0;
      inverse[(k + a) * two + b] = a > b ? sy_ab : 0.0;
      inverse[(k + a) * two + k + b] = theta_ * ss_[a * m + b];
    }
  middle_.assign(two * two, 0.0);
  for (int j = 0; j < size; ++j) middle_[j * two + j] = 1.0;
  // Column j of the identity solved for is row j of M^T = M (M is symmetric).
  return size == 0 || solve_small(inverse, size, middle_.data(), size);
}

}  // namespace asp
