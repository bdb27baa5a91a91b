// SPDX-License-Identifier: GPL-2.0-or-later
// Two entries of a field at once, for the kernels that select by comparing values (a
// projection, x > lower ? x : lower; a test of the bound). GCC keeps such a comparison as a
// branch under -ftrapping-math (the default), and a loop with a branch stays scalar; the
// same comparison on a vector of two doubles is a mask, and the select a blend, with no
// branch. Such a kernel is written once, for a value type V that is either double (one
// entry) or Pair (two), with load/store/splat below and the operators both types share
// (arithmetic, comparisons, and the conditional `mask ? a : b`, which GCC and Clang take for
// vectors as for scalars; the same select written with bitwise operations on the lanes, GCC
// moved through general registers, twice as slow); loops::sums_and_maxima_in_lanes and
// loops::for_each_in_lanes run it. Sixteen bytes are the x86-64 baseline the library is
// built for (SSE2).
//
// A kernel on Pair evaluates every lane, as a vector unit does: its divisions must not
// divide by zero on a lane the scalar form would have skipped (select the divisor first).
#pragma once

#include <cstring>

namespace asp {
namespace lanes {

// GCC and Clang (and the compilers that take their extensions) give two lanes; any other
// C++17 compiler runs the same kernels on one, as scalar loops.
#if defined(__GNUC__)
typedef double Pair __attribute__((vector_size(16)));
#else
using Pair = double;
#endif

template <class V>
constexpr int width = static_cast<int>(sizeof(V) / sizeof(double));

template <class V>
V load(const double *p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

template <class V>
void store(double *p, V v) {
  std::memcpy(p, &v, sizeof v);
}

template <class V>
V splat(double a) {
  if constexpr (width<V> == 1)
    return a;
  else
    return V{a, a};
}

// The lanes' sum and largest value (a NaN lane may be dropped from the latter, as by the
// loops' maxima).
template <class V>
double lane_sum(V v) {
  if constexpr (width<V> == 1)
    return v;
  else
    return v[0] + v[1];
}
template <class V>
double lane_max(V v) {
  if constexpr (width<V> == 1)
    return v;
  else
    return v[1] > v[0] ? v[1] : v[0];
}

}  // namespace lanes
}  // namespace asp
