// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/detrend.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"
#include "core/reductions.hpp"

namespace asp {
namespace {

constexpr int largest_basis = 6;
using Terms = std::array<double, largest_basis>;

// The basis of the fit at a pixel, in coordinates scaled to (-1, 1) about the box's centre,
// so that the normal equations stay well conditioned whatever the grid's size and units:
// 1, X, Y, X^2, X Y, Y^2, of which the mode uses the first `count` (1D: 1, X, X^2).
int basis_size(Detrend mode, int dimension) {
  switch (mode) {
    case Detrend::mean: return 1;
    case Detrend::plane: return dimension == 1 ? 2 : 3;
    case Detrend::curvature: return dimension == 1 ? 3 : 6;
  }
  return 1;
}

Terms basis(double x, double y, int dimension) {
  if (dimension == 1) return {1.0, x, x * x, 0.0, 0.0, 0.0};
  return {1.0, x, y, x * x, x * y, y * y};
}

// Solves the k x k symmetric system G c = b by Gaussian elimination with partial pivoting; a
// pivot below 1e-12 of its column's scale marks a term the grid cannot determine, whose
// coefficient is then 0.
Terms solve_normal_equations(std::array<Terms, largest_basis> g, Terms b, int k) {
  std::array<bool, largest_basis> dropped{};
  Terms scale{};
  for (int i = 0; i < k; ++i) scale[i] = std::fabs(g[i][i]);
  for (int column = 0; column < k; ++column) {
    int pivot = column;
    for (int row = column + 1; row < k; ++row)
      if (std::fabs(g[row][column]) > std::fabs(g[pivot][column])) pivot = row;
    if (!(std::fabs(g[pivot][column]) > 1e-12 * scale[column])) {
      dropped[column] = true;
      for (int row = 0; row < k; ++row) g[row][column] = 0.0;
      continue;
    }
    std::swap(g[pivot], g[column]);
    std::swap(b[pivot], b[column]);
    for (int row = column + 1; row < k; ++row) {
      const double factor = g[row][column] / g[column][column];
      for (int c = column; c < k; ++c) g[row][c] -= factor * g[column][c];
      b[row] -= factor * b[column];
    }
  }
  Terms c{};
  for (int row = k - 1; row >= 0; --row) {
    if (dropped[row] || g[row][row] == 0.0) continue;
    double sum = b[row];
    for (int j = row + 1; j < k; ++j) sum -= g[row][j] * c[j];
    c[row] = sum / g[row][row];
  }
  return c;
}

}  // namespace

void detrend_topography(const Grid &grid, Detrend mode, double *heights) {
  const std::int64_t n = grid.local_pixels(), nx = grid.nx(), ny = grid.ny();
  const std::int64_t first_row = grid.row_offset();
  require_finite_array(heights, n, "heights");
  const int dimension = grid.dimension(), k = basis_size(mode, dimension);
  // Pixel centres relative to the box's centre, over half the box: in (-1, 1).
  const double cx = 0.5 * static_cast<double>(nx - 1), cy = 0.5 * static_cast<double>(ny - 1);
  const double per_x = 2.0 / static_cast<double>(nx), per_y = 2.0 / static_cast<double>(ny);
  const auto terms_at = [&](std::int64_t i) {
    const double x = (static_cast<double>(i % nx) - cx) * per_x;
    const double y = (static_cast<double>(first_row + i / nx) - cy) * per_y;
    return basis(x, y, dimension);
  };

  // The normal equations, summed over the pixels; heights relative to their largest
  // magnitude, so that the squares of heights near the largest double are never formed.
  const Reductions &reductions = grid.reductions();
  const double largest =
      loops::maximum(reductions, n, [&](std::int64_t i) { return std::fabs(heights[i]); });
  if (largest == 0.0) return;
  const double per_height = 1.0 / largest;
  // Sums: the k right-hand sides, then the k x k Gram matrix by rows.
  std::vector<double> sums(static_cast<std::size_t>(k + k * k));
  loops::block_sums(reductions, n, k + k * k, sums.data(),
                    [&](std::int64_t begin, std::int64_t end, double *sum) {
                      for (std::int64_t i = begin; i < end; ++i) {
                        const Terms t = terms_at(i);
                        const double h = heights[i] * per_height;
                        for (int r = 0; r < k; ++r) {
                          sum[r] += t[r] * h;
                          for (int c = 0; c < k; ++c) sum[k + r * k + c] += t[r] * t[c];
                        }
                      }
                    });
  std::array<Terms, largest_basis> gram{};
  Terms right{};
  for (int r = 0; r < k; ++r) {
    right[r] = sums[static_cast<std::size_t>(r)];
    for (int c = 0; c < k; ++c) gram[r][c] = sums[static_cast<std::size_t>(k + r * k + c)];
  }
  const Terms coefficients = solve_normal_equations(gram, right, k);

  // The detrended heights into a copy first, so that a refusal leaves the caller's intact.
  Field result(static_cast<std::size_t>(n));
  double *out = result.data();
  const double check = loops::sum(reductions, n, [&](std::int64_t i) {
    const Terms t = terms_at(i);
    double fit = 0.0;
    for (int r = 0; r < k; ++r) fit += coefficients[r] * t[r];
    out[i] = heights[i] - fit * largest;
    return 0.0 * out[i];  // NaN if any result is not finite
  });
  if (check != 0.0)
    throw Error(Status::invalid_argument,
                "argument 'heights': the detrended heights would exceed the largest double");
  loops::for_each(n, [&](std::int64_t i) { heights[i] = out[i]; });
}

}  // namespace asp
