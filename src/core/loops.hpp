// SPDX-License-Identifier: GPL-2.0-or-later
// The element-wise loops of the library: for-each and reductions over the pixels (or spectral
// entries) this process owns. Every kernel is a lambda handed to one of these helpers, so
// that vectorisation, threads and a distributed grid are decided here and not in each
// solver. Sums and maxima over the local entries are combined across the grid's parts by its
// Reductions (the identity on one process).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/reductions.hpp"

namespace asp {
namespace loops {

// body(i) for i in [0, n).
template <class Body>
void for_each(std::int64_t n, Body &&body) {
#pragma omp simd
  for (std::int64_t i = 0; i < n; ++i) body(i);
}

// The sum of value(i) over all entries.
template <class Value>
double sum(const Reductions &reductions, std::int64_t n, Value &&value) {
  double total = 0.0;
#pragma omp simd reduction(+ : total)
  for (std::int64_t i = 0; i < n; ++i) total += value(i);
  reductions.combine_sums(&total, 1);
  return total;
}

// The largest value(i) over all entries (-infinity for none; NaN may be dropped).
template <class Value>
double maximum(const Reductions &reductions, std::int64_t n, Value &&value) {
  double largest = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(max : largest)
  for (std::int64_t i = 0; i < n; ++i) {
    const double v = value(i);
    largest = v > largest ? v : largest;
  }
  reductions.combine_maxima(&largest, 1);
  return largest;
}

// K sums at once: body(i, sum) adds entry i's terms to sum[0..K-1].
template <int K, class Body>
std::array<double, K> sums(const Reductions &reductions, std::int64_t n, Body &&body) {
  double sum[K] = {};
#pragma omp simd reduction(+ : sum[:K])
  for (std::int64_t i = 0; i < n; ++i) body(i, sum);
  reductions.combine_sums(sum, K);
  std::array<double, K> out;
  for (int k = 0; k < K; ++k) out[k] = sum[k];
  return out;
}

// K sums and one maximum: body(i, sum, max) adds to sum[0..K-1] and raises max. The maximum
// of an empty range is -infinity. A NaN offered to the maximum may be dropped (comparisons
// with NaN are false), so kernels that must notice NaN also add the value to a sum.
template <int K, class Body>
std::array<double, K + 1> sums_and_max(const Reductions &reductions, std::int64_t n,
                                       Body &&body) {
  double sum[K] = {};
  double max = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(+ : sum[:K]) reduction(max : max)
  for (std::int64_t i = 0; i < n; ++i) body(i, sum, max);
  reductions.combine_sums(sum, K);
  reductions.combine_maxima(&max, 1);
  std::array<double, K + 1> out;
  for (int k = 0; k < K; ++k) out[k] = sum[k];
  out[K] = max;
  return out;
}

// count sums, with count known only at run time: body(begin, end, sum) adds the terms of the
// entries [begin, end) to sum[0..count-1]. The entries come in blocks small enough to stay
// in the first-level cache, so that a body may pass over its block several times (once per
// stored vector, say) while every array is read from memory once.
template <class Body>
void block_sums(const Reductions &reductions, std::int64_t n, int count, double *sum,
                Body &&body) {
  constexpr std::int64_t block = 256;
  std::fill(sum, sum + count, 0.0);
  for (std::int64_t begin = 0; begin < n; begin += block)
    body(begin, std::min(n, begin + block), sum);
  reductions.combine_sums(sum, count);
}

// The entries i in [0, n) with keep(i), in increasing order, appended to out (a container
// of indices). Not vectorised: it writes a variable number of entries.
template <class Indices, class Keep>
void select(std::int64_t n, Keep &&keep, Indices &out) {
  for (std::int64_t i = 0; i < n; ++i)
    if (keep(i)) out.push_back(i);
}

// K sums and M maxima: body(i, sum, max) adds to sum[0..K-1] and raises max[0..M-1]. The
// maximum of an empty range is -infinity; as for sums_and_max, a NaN offered to a maximum may
// be dropped.
template <int K, int M, class Body>
std::pair<std::array<double, K>, std::array<double, M>> sums_and_maxima(
    const Reductions &reductions, std::int64_t n, Body &&body) {
  double sum[K] = {};
  double max[M];
  for (int m = 0; m < M; ++m) max[m] = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(+ : sum[:K]) reduction(max : max[:M])
  for (std::int64_t i = 0; i < n; ++i) body(i, sum, max);
  reductions.combine_sums(sum, K);
  reductions.combine_maxima(max, M);
  std::pair<std::array<double, K>, std::array<double, M>> out;
  for (int k = 0; k < K; ++k) out.first[k] = sum[k];
  for (int m = 0; m < M; ++m) out.second[m] = max[m];
  return out;
}

}  // namespace loops
}  // namespace asp
