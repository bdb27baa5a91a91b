// SPDX-License-Identifier: GPL-2.0-or-later
// The element-wise loops of the library: for-each and reductions over the pixels (or spectral
// entries) this process owns. Every kernel is a lambda handed to one of these helpers, so
// that vectorisation, threads and a distributed grid are decided here and not in each
// solver. Sums and maxima over the local entries are combined across the grid's parts by its
// Reductions (the identity on one process).
//
// Threads: a loop of at least parallel_entries entries runs on loop_threads() threads (the
// grid's count during a solve, core/threads.hpp), the library's own (core/thread_pool.hpp):
// it is cut into jobs of chunk_entries entries, which the calling thread and the helpers that
// get a core take one after another. Reductions add up each chunk on its own, and then the
// chunks' results in chunk order, whichever thread did which chunk: their results are the
// same bits for any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/lanes.hpp"
#include "core/reductions.hpp"
#include "core/thread_pool.hpp"
#include "core/threads.hpp"

namespace asp {
namespace loops {

// Loops shorter than this run on one thread: below it, waking threads costs more than the
// work they would share.
constexpr std::int64_t parallel_entries = 32768;

// The threads a loop of n entries runs on.
inline int threads_for(std::int64_t n) {
  const int threads = loop_threads();
  return threads > 1 && n >= parallel_entries ? threads : 1;
}

// body(begin, end) for consecutive pieces of [0, n), `piece` indices each (the last one
// shorter), on up to `threads` threads, in no particular order.
template <class Body>
void in_pieces(std::int64_t n, std::int64_t piece, int threads, Body &&body) {
  const std::int64_t pieces = (n + piece - 1) / piece;
  if (threads > 1 && pieces > 1) {
    thread_pool::run_jobs(threads, pieces, [&](std::int64_t k) {
      body(k * piece, std::min(n, (k + 1) * piece));
    });
    return;
  }
  body(std::int64_t{0}, n);
}

// Reductions add up chunks of this many entries, then the chunks in order.
constexpr std::int64_t chunk_entries = 16384;

// Each chunk of `chunk` indices of [0, n) reduces its indices into its own Partial
// (reduce(begin, end, partial)), on `threads` threads; the partials are then folded in chunk
// order (fold(total, partial)). The result does not depend on `threads`.
template <class Partial, class Reduce, class Fold>
Partial reduce_in_chunks(std::int64_t n, std::int64_t chunk, int threads, const Partial &initial,
                         Reduce &&reduce, Fold &&fold) {
  const std::int64_t chunks = std::max<std::int64_t>(1, (n + chunk - 1) / chunk);
  if (chunks == 1) {
    Partial total = initial;
    reduce(std::int64_t{0}, n, total);
    return total;
  }
  std::vector<Partial> partials(static_cast<std::size_t>(chunks), initial);
  auto one = [&](std::int64_t c) {
    reduce(c * chunk, std::min(n, (c + 1) * chunk), partials[static_cast<std::size_t>(c)]);
  };
  if (threads > 1) {
    thread_pool::run_jobs(threads, chunks, one);
  } else {
    for (std::int64_t c = 0; c < chunks; ++c) one(c);
  }
  Partial total = partials[0];
  for (std::int64_t c = 1; c < chunks; ++c) fold(total, partials[static_cast<std::size_t>(c)]);
  return total;
}

// The same over entries, in chunks of chunk_entries.
template <class Partial, class Reduce, class Fold>
Partial reduce_in_parts(std::int64_t n, const Partial &initial, Reduce &&reduce, Fold &&fold) {
  return reduce_in_chunks(n, chunk_entries, threads_for(n), initial,
                          std::forward<Reduce>(reduce), std::forward<Fold>(fold));
}

// body(i) for i in [0, n).
template <class Body>
void for_each(std::int64_t n, Body &&body) {
  in_pieces(n, chunk_entries, threads_for(n), [&](std::int64_t begin, std::int64_t end) {
#pragma omp simd
    for (std::int64_t i = begin; i < end; ++i) body(i);
  });
}

// The sum of value(i) over all entries.
template <class Value>
double sum(const Reductions &reductions, std::int64_t n, Value &&value) {
  double total = reduce_in_parts(
      n, 0.0,
      [&](std::int64_t begin, std::int64_t end, double &part) {
        double s = 0.0;
#pragma omp simd reduction(+ : s)
        for (std::int64_t i = begin; i < end; ++i) s += value(i);
        part = s;
      },
      [](double &total, double part) { total += part; });
  reductions.combine_sums(&total, 1);
  return total;
}

// An OpenMP max reduction starts each lane from "the least representable value", which
// compilers read as -infinity (GCC) or -DBL_MAX (Clang): a part without a value above it
// reads -DBL_MAX with the latter. Both are taken as none (-infinity), so that a maximum over
// no value, or over NaN only, is the same whatever the compiler.
inline double none_if_lowest(double m) {
  return m > -std::numeric_limits<double>::max() ? m : -std::numeric_limits<double>::infinity();
}

// The largest value(i) over all entries (-infinity for none; NaN may be dropped).
template <class Value>
double maximum(const Reductions &reductions, std::int64_t n, Value &&value) {
  constexpr double none = -std::numeric_limits<double>::infinity();
  double largest = reduce_in_parts(
      n, none,
      [&](std::int64_t begin, std::int64_t end, double &part) {
        double m = none;
#pragma omp simd reduction(max : m)
        for (std::int64_t i = begin; i < end; ++i) {
          const double v = value(i);
          m = v > m ? v : m;
        }
        part = none_if_lowest(m);
      },
      [](double &total, double part) { total = part > total ? part : total; });
  reductions.combine_maxima(&largest, 1);
  return largest;
}

// K sums at once: body(i, sum) adds entry i's terms to sum[0..K-1].
template <int K, class Body>
std::array<double, K> sums(const Reductions &reductions, std::int64_t n, Body &&body) {
  std::array<double, K> out = reduce_in_parts(
      n, std::array<double, K>{},
      [&](std::int64_t begin, std::int64_t end, std::array<double, K> &part) {
        double sum[K] = {};
#pragma omp simd reduction(+ : sum[:K])
        for (std::int64_t i = begin; i < end; ++i) body(i, sum);
        for (int k = 0; k < K; ++k) part[k] = sum[k];
      },
      [](std::array<double, K> &total, const std::array<double, K> &part) {
        for (int k = 0; k < K; ++k) total[k] += part[k];
      });
  reductions.combine_sums(out.data(), K);
  return out;
}

// K sums and one maximum: body(i, sum, max) adds to sum[0..K-1] and raises max. The maximum
// of an empty range is -infinity. A NaN offered to the maximum may be dropped (comparisons
// with NaN are false), so kernels that must notice NaN also add the value to a sum.
template <int K, class Body>
std::array<double, K + 1> sums_and_max(const Reductions &reductions, std::int64_t n,
                                       Body &&body) {
  std::array<double, K + 1> initial{};
  initial[K] = -std::numeric_limits<double>::infinity();
  std::array<double, K + 1> out = reduce_in_parts(
      n, initial,
      [&](std::int64_t begin, std::int64_t end, std::array<double, K + 1> &part) {
        double sum[K] = {};
        double max = -std::numeric_limits<double>::infinity();
        // A copy of the kernel per piece: no store of the loop can reach a local's
        // captures, so that they stay in registers (through `body` every store to a field
        // would make them load again).
        auto kernel = body;
#pragma omp simd reduction(+ : sum[:K]) reduction(max : max)
        for (std::int64_t i = begin; i < end; ++i) kernel(i, sum, max);
        for (int k = 0; k < K; ++k) part[k] = sum[k];
        part[K] = none_if_lowest(max);
      },
      [](std::array<double, K + 1> &total, const std::array<double, K + 1> &part) {
        for (int k = 0; k < K; ++k) total[k] += part[k];
        total[K] = part[K] > total[K] ? part[K] : total[K];
      });
  reductions.combine_sums(out.data(), K);
  reductions.combine_maxima(&out[K], 1);
  return out;
}

// count sums, with count known only at run time: body(begin, end, sum) adds the terms of the
// entries [begin, end) to sum[0..count-1]. The entries come in blocks of at most `block`,
// small enough to stay in a cache, so that a body may pass over its block several times
// (once per stored vector, say) while every array is read from memory once. The default
// keeps a few arrays' blocks in the first-level cache; a body that sweeps many other arrays
// once per block wants longer ones (sweep_block below). Blocks longer than chunk_entries are
// also the chunks, so that the sums depend on n and `block`, not on the thread count.
constexpr std::int64_t block_entries = 256;
template <class Body>
void block_sums(const Reductions &reductions, std::int64_t n, int count, double *sum,
                Body &&body, std::int64_t block = block_entries) {
  const std::vector<double> total = reduce_in_chunks(
      n, std::max(chunk_entries, block), threads_for(n),
      std::vector<double>(static_cast<std::size_t>(count), 0.0),
      [&](std::int64_t begin, std::int64_t end, std::vector<double> &part) {
        for (std::int64_t b = begin; b < end; b += block) body(b, std::min(end, b + block), part.data());
      },
      [](std::vector<double> &total, const std::vector<double> &part) {
        for (std::size_t k = 0; k < total.size(); ++k) total[k] += part[k];
      });
  std::copy(total.begin(), total.end(), sum);
  reductions.combine_sums(sum, count);
}

// The block for a body of block_sums that sweeps many arrays once per block, for n entries.
// Each of those arrays is then read in pieces of `block` entries, one piece after another's
// of the other arrays: short pieces restart the prefetchers at every one. At 2048^2, ten
// arrays read in pieces of 2048 entries took 1.5 times as long as read whole one after
// another, and in pieces of 32768 entries or more no longer. At most n/64 (at least 2048),
// so that the threads still share the chunks, and a function of n alone.
inline std::int64_t sweep_block(std::int64_t n) {
  return std::clamp<std::int64_t>(n / 64, 2048, 65536);
}

// The entries i in [0, n) with keep(i), in increasing order, appended to out (a container
// of indices). Not vectorised: it writes a variable number of entries.
template <class Indices, class Keep>
void select(std::int64_t n, Keep &&keep, Indices &out) {
  for (std::int64_t i = 0; i < n; ++i)
    if (keep(i)) out.push_back(i);
}

// K sums and M maxima, as sums_and_maxima and sums_and_maxima_in_lanes return them.
template <int K, int M>
using SumsAndMaxima = std::pair<std::array<double, K>, std::array<double, M>>;

// The chunks' sums and maxima, each chunk's from reduce(begin, end, part), folded in chunk
// order and combined across the grid's parts. The maximum of no value is -infinity.
template <int K, int M, class Reduce>
SumsAndMaxima<K, M> reduce_sums_and_maxima(const Reductions &reductions, std::int64_t n,
                                           Reduce &&reduce) {
  using Result = SumsAndMaxima<K, M>;
  Result initial{};
  initial.second.fill(-std::numeric_limits<double>::infinity());
  Result out = reduce_in_parts(n, initial, std::forward<Reduce>(reduce),
                               [](Result &total, const Result &part) {
                                 for (int k = 0; k < K; ++k) total.first[k] += part.first[k];
                                 for (int m = 0; m < M; ++m)
                                   total.second[m] = part.second[m] > total.second[m]
                                                         ? part.second[m]
                                                         : total.second[m];
                               });
  reductions.combine_sums(out.first.data(), K);
  reductions.combine_maxima(out.second.data(), M);
  return out;
}

// K sums and M maxima: body(i, sum, max) adds to sum[0..K-1] and raises max[0..M-1]. The
// maximum of an empty range is -infinity; as for sums_and_max, a NaN offered to a maximum may
// be dropped.
template <int K, int M, class Body>
SumsAndMaxima<K, M> sums_and_maxima(const Reductions &reductions, std::int64_t n,
                                    Body &&body) {
  return reduce_sums_and_maxima<K, M>(
      reductions, n, [&](std::int64_t begin, std::int64_t end, SumsAndMaxima<K, M> &part) {
        double sum[K] = {};
        double max[M];
        for (int m = 0; m < M; ++m) max[m] = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(+ : sum[:K]) reduction(max : max[:M])
        for (std::int64_t i = begin; i < end; ++i) body(i, sum, max);
        for (int k = 0; k < K; ++k) part.first[k] = sum[k];
        for (int m = 0; m < M; ++m) part.second[m] = none_if_lowest(max[m]);
      });
}

// for_each for a kernel written for both value types of core/lanes.hpp: body(i, V{})
// handles the entries i and i + 1 with V = lanes::Pair, entry i alone with V = double (the
// last entry of a piece of odd length).
template <class Body>
void for_each_in_lanes(std::int64_t n, Body &&body) {
  in_pieces(n, chunk_entries, threads_for(n), [&](std::int64_t begin, std::int64_t end) {
    auto kernel = body;  // a copy per piece, as in sums_and_max
    constexpr int width = lanes::width<lanes::Pair>;
    std::int64_t i = begin;
    for (; i + width <= end; i += width) kernel(i, lanes::Pair{});
    if constexpr (width > 1)
      if (i < end) kernel(i, 0.0);
  });
}

// sums_and_maxima for a kernel written for both value types of core/lanes.hpp:
// body(i, sum, max), with sum and max arrays of lanes::Pair, handles the entries i and i + 1;
// with arrays of double, entry i alone (the last entry of a chunk of odd length; every entry
// where Pair is a double). Each chunk adds up its two lanes at its end, so that the results
// still depend on n alone.
template <int K, int M, class Body>
SumsAndMaxima<K, M> sums_and_maxima_in_lanes(const Reductions &reductions, std::int64_t n,
                                             Body &&body) {
  using lanes::Pair;
  constexpr double none = -std::numeric_limits<double>::infinity();
  return reduce_sums_and_maxima<K, M>(
      reductions, n, [&](std::int64_t begin, std::int64_t end, SumsAndMaxima<K, M> &part) {
        Pair sum[K], max[M];
        for (int k = 0; k < K; ++k) sum[k] = lanes::splat<Pair>(0.0);
        for (int m = 0; m < M; ++m) max[m] = lanes::splat<Pair>(none);
        // A copy of the kernel per piece, as in sums_and_max.
        auto kernel = body;
        constexpr int width = lanes::width<Pair>;
        std::int64_t i = begin;
        for (; i + width <= end; i += width) kernel(i, sum, max);
        double last_sum[K] = {}, last_max[M];
        for (int m = 0; m < M; ++m) last_max[m] = none;
        if constexpr (width > 1)
          if (i < end) kernel(i, last_sum, last_max);
        for (int k = 0; k < K; ++k) part.first[k] = lanes::lane_sum(sum[k]) + last_sum[k];
        for (int m = 0; m < M; ++m) {
          const double lane = lanes::lane_max(max[m]);
          part.second[m] = last_max[m] > lane ? last_max[m] : lane;
        }
      });
}

}  // namespace loops
}  // namespace asp
