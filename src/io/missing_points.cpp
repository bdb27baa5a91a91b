// SPDX-License-Identifier: GPL-2.0-or-later
// Missing points: their description, and filling them by harmonic interpolation.
//
// The filled heights u solve the discrete Laplace equation on the missing points: for each
// missing point, its height times the number of its grid neighbours (up, down, left, right,
// those inside the grid: the edges are not wrapped) equals the sum of their heights, with the
// known heights fixed. Every hole borders a known point (the grid is connected), so the system
// is symmetric positive definite; it is solved by conjugate gradients with the diagonal as
// preconditioner to a relative residual of 1e-15 (or until rounding stops the residual
// shrinking), which handles large holes in O(diameter) iterations. The filled heights are
// kept within the range of the known ones, as the exact solution is.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "io/height_map.hpp"

namespace asp::io {

namespace {

void check_size(const HeightMap &map) {
  if (map.nx < 0 || map.ny < 0 || map.heights.size() != static_cast<size_t>(map.nx * map.ny))
    throw FileError("inconsistent height map: " + std::to_string(map.heights.size()) +
                    " heights for nx = " + std::to_string(map.nx) +
                    ", ny = " + std::to_string(map.ny));
}

}  // namespace

std::string describe_missing(const HeightMap &map) {
  check_size(map);
  int64_t count = 0, first = -1;
  for (size_t i = 0; i < map.heights.size(); ++i)
    if (std::isnan(map.heights[i])) {
      if (first < 0) first = static_cast<int64_t>(i);
      ++count;
    }
  if (count == 0) return "no missing points";
  const std::string where =
      "x = " + std::to_string(first % map.nx) + ", y = " + std::to_string(first / map.nx);
  if (count == 1) return "1 missing point (NaN), at " + where;
  return std::to_string(count) + " missing points (NaN), the first at " + where;
}

int64_t fill_missing(HeightMap &map) {
  check_size(map);
  const int64_t nx = map.nx, ny = map.ny;
  std::vector<double> &h = map.heights;
  // The unknowns: index of each missing point in the system, -1 for known points.
  std::vector<int64_t> unknown(h.size(), -1);
  std::vector<int64_t> where;
  for (size_t i = 0; i < h.size(); ++i)
    if (std::isnan(h[i])) {
      unknown[i] = static_cast<int64_t>(where.size());
      where.push_back(static_cast<int64_t>(i));
    }
  const int64_t m = static_cast<int64_t>(where.size());
  if (m == 0) return 0;
  if (m == nx * ny)
    throw FileError("every one of the " + std::to_string(m) +
                    " heights is missing (NaN): nothing to fill the holes from");

  // The problem is linear in the heights: it is solved for the heights over the power of two
  // `unit` at or just below the largest (so that they lie within [-2, 2] and the squares and
  // sums of the iteration cannot overflow, and the filled heights, bounded by the known ones,
  // come back finite; dividing and multiplying by it is exact).
  double largest = 0.0;
  for (size_t i = 0; i < h.size(); ++i)
    if (unknown[i] < 0) largest = std::max(largest, std::fabs(h[i]));
  if (!std::isfinite(largest))
    throw FileError("a height is not finite: missing points cannot be filled from it");
  int exponent = 0;
  std::frexp(largest, &exponent);
  const double unit = largest > 0.0 ? std::ldexp(1.0, exponent - 1) : 1.0;
  const auto known = [&](size_t i) { return h[i] / unit; };

  // A x = b with A = diag(degree) - adjacency among unknowns, b = sum of known neighbours.
  std::vector<double> diag(m), b(m, 0.0), x(m);
  double known_sum = 0.0;
  int64_t known_count = 0;
  for (size_t i = 0; i < h.size(); ++i)
    if (unknown[i] < 0) {
      known_sum += known(i);
      ++known_count;
    }
  const double mean = known_sum / static_cast<double>(known_count);
  auto for_neighbours = [&](int64_t i, auto &&visit) {
    const int64_t px = i % nx, py = i / nx;
    if (px > 0) visit(i - 1);
    if (px + 1 < nx) visit(i + 1);
    if (py > 0) visit(i - nx);
    if (py + 1 < ny) visit(i + nx);
  };
  for (int64_t k = 0; k < m; ++k) {
    int degree = 0;
    for_neighbours(where[k], [&](int64_t j) {
      ++degree;
      if (unknown[j] < 0) b[k] += known(static_cast<size_t>(j));
    });
    diag[k] = degree;
    x[k] = mean;
  }
  auto apply = [&](const std::vector<double> &v, std::vector<double> &out) {
    for (int64_t k = 0; k < m; ++k) {
      double s = diag[k] * v[k];
      for_neighbours(where[k], [&](int64_t j) {
        if (unknown[j] >= 0) s -= v[unknown[j]];
      });
      out[k] = s;
    }
  };
  std::vector<double> r(m), z(m), p(m), q(m);
  apply(x, q);
  double b_norm = 0.0;
  for (int64_t k = 0; k < m; ++k) {
    r[k] = b[k] - q[k];
    b_norm += b[k] * b[k];
  }
  b_norm = std::sqrt(b_norm);
  // Scale of the answer, so that an all-zero b (known heights all 0) still has a tolerance.
  const double scale = std::max(b_norm, largest / unit);
  const double tolerance = 1e-15 * (scale > 0 ? scale : 1.0);
  double rz = 0.0;
  for (int64_t k = 0; k < m; ++k) {
    z[k] = r[k] / diag[k];
    p[k] = z[k];
    rz += r[k] * z[k];
  }
  const int64_t max_iterations = 2 * m + 100;
  double best = HUGE_VAL;
  int64_t since_best = 0;
  for (int64_t iteration = 0; iteration < max_iterations; ++iteration) {
    double r_norm = 0.0;
    for (int64_t k = 0; k < m; ++k) r_norm += r[k] * r[k];
    r_norm = std::sqrt(r_norm);
    if (r_norm <= tolerance) break;
    // Rounding keeps the residual from falling further: stop after it stalls for a while.
    if (r_norm < 0.5 * best) {
      best = r_norm;
      since_best = 0;
    } else if (++since_best > 50 + m / 10) {
      break;
    }
    apply(p, q);
    double pq = 0.0;
    for (int64_t k = 0; k < m; ++k) pq += p[k] * q[k];
    if (!(pq > 0)) break;
    const double alpha = rz / pq;
    double rz_next = 0.0;
    for (int64_t k = 0; k < m; ++k) {
      x[k] += alpha * p[k];
      r[k] -= alpha * q[k];
      z[k] = r[k] / diag[k];
      rz_next += r[k] * z[k];
    }
    const double beta = rz_next / rz;
    rz = rz_next;
    for (int64_t k = 0; k < m; ++k) p[k] = z[k] + beta * p[k];
  }
  // Each filled height is a weighted mean of known ones (the discrete maximum principle), so
  // it lies within their range; rounding in the iteration can carry it a few ulps beyond,
  // which next to a height of -DBL_MAX overflowed to -infinity. Clamped to that range.
  double lowest = HUGE_VAL, highest = -HUGE_VAL;
  for (size_t i = 0; i < h.size(); ++i)
    if (unknown[i] < 0) {
      lowest = std::min(lowest, known(i));
      highest = std::max(highest, known(i));
    }
  for (int64_t k = 0; k < m; ++k) h[where[k]] = std::clamp(x[k], lowest, highest) * unit;
  map.missing = 0;
  return m;
}

}  // namespace asp::io
