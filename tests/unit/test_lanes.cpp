// SPDX-License-Identifier: GPL-2.0-or-later
// The loops over two lanes (core/lanes.hpp, loops::sums_and_maxima_in_lanes and
// for_each_in_lanes): every entry once, at every parity of the length and across chunks;
// selects by mask lane by lane; sums exact on integers and the same bits for any thread
// count; a NaN entry reaching the sums.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/lanes.hpp"
#include "core/loops.hpp"
#include "core/reductions.hpp"
#include "core/threads.hpp"

namespace {

using asp::lanes::Pair;

// Sums of v and of its positive part (a select), the count, the largest v and the largest -v.
template <class Fields>
std::pair<std::array<double, 3>, std::array<double, 2>> lane_sums(const Fields &v,
                                                                  std::int64_t n) {
  const asp::LocalReductions local;
  const double *p = v.data();
  return asp::loops::sums_and_maxima_in_lanes<3, 2>(
      local, n, [=](std::int64_t i, auto *sum, auto *max) {
        using V = std::remove_pointer_t<decltype(sum)>;
        const V x = asp::lanes::load<V>(p + i);
        const V zero = asp::lanes::splat<V>(0.0);
        sum[0] += x;
        sum[1] += x > zero ? x : zero;
        sum[2] += asp::lanes::splat<V>(1.0);
        max[0] = x > max[0] ? x : max[0];
        max[1] = -x > max[1] ? -x : max[1];
      });
}

TEST(Lanes, SumsAndMaximaCoverEveryEntryAtEveryParity) {
  const std::int64_t chunk = asp::loops::chunk_entries;
  for (const std::int64_t n : {std::int64_t{1}, std::int64_t{2}, std::int64_t{3},
                               std::int64_t{1003}, chunk + 1, 3 * chunk + 5}) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (std::int64_t i = 0; i < n; ++i) v[i] = static_cast<double>((i * 7) % 23) - 11.0;
    // The last entry alone holds the largest value: a lane that missed it would show.
    v[n - 1] = 100.0;
    double sum = 0.0, positive = 0.0, smallest = HUGE_VAL;
    for (const double x : v) {
      sum += x;
      positive += x > 0.0 ? x : 0.0;
      smallest = std::min(smallest, x);
    }
    const auto r = lane_sums(v, n);
    EXPECT_EQ(r.first[0], sum) << n;  // integers: exact in any order
    EXPECT_EQ(r.first[1], positive) << n;
    EXPECT_EQ(r.first[2], static_cast<double>(n)) << n;
    EXPECT_EQ(r.second[0], 100.0) << n;
    EXPECT_EQ(r.second[1], -smallest) << n;
  }
  const auto none = lane_sums(std::vector<double>{}, 0);
  EXPECT_EQ(none.first[2], 0.0);
  EXPECT_EQ(none.second[0], -HUGE_VAL);
}

TEST(Lanes, SumsAreTheSameBitsOnAnyThreadCount) {
  const std::int64_t n = 5 * asp::loops::chunk_entries + 3;
  std::vector<double> v(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) v[i] = std::sin(0.37 * static_cast<double>(i)) / 3.0;
  std::pair<std::array<double, 3>, std::array<double, 2>> one, two;
  {
    const asp::ThreadScope threads(1);
    one = lane_sums(v, n);
  }
  {
    const asp::ThreadScope threads(2);
    two = lane_sums(v, n);
  }
  EXPECT_EQ(one.first, two.first);
  EXPECT_EQ(one.second, two.second);
}

TEST(Lanes, ANotFiniteEntryReachesTheSums) {
  for (const std::int64_t at : {std::int64_t{0}, std::int64_t{1}, std::int64_t{6}}) {
    std::vector<double> v(7, 1.0);
    v[at] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(lane_sums(v, 7).first[0])) << at;
  }
}

TEST(Lanes, ForEachWritesEveryEntryOnce) {
  for (const std::int64_t n : {std::int64_t{1}, std::int64_t{2}, std::int64_t{5},
                               2 * asp::loops::chunk_entries + 1}) {
    std::vector<double> in(static_cast<std::size_t>(n)), out(in.size(), -1.0);
    for (std::int64_t i = 0; i < n; ++i) in[i] = static_cast<double>(i) - 2.5;
    const double *a = in.data();
    double *b = out.data();
    asp::loops::for_each_in_lanes(n, [=](std::int64_t i, auto lanes_of) {
      using V = decltype(lanes_of);
      const V x = asp::lanes::load<V>(a + i);
      const V zero = asp::lanes::splat<V>(0.0);
      asp::lanes::store(b + i, x > zero ? x : zero);  // the projection onto x >= 0
    });
    for (std::int64_t i = 0; i < n; ++i) ASSERT_EQ(out[i], std::max(in[i], 0.0)) << n << " " << i;
  }
}

}  // namespace
