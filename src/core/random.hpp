// SPDX-License-Identifier: GPL-2.0-or-later
// A small, fully specified random generator (xoshiro256** seeded by splitmix64) so that a seed
// gives the same surface on every platform and standard library; std::normal_distribution
// makes no such promise.
#pragma once

#include <cstdint>

namespace asp {

class Random {
 public:
  explicit Random(std::uint64_t seed);
  // A stream of its own for each counter under one seed: what it draws depends on the seed
  // and the counter only, not on what was drawn before (a counter-based generator).
  static Random keyed(std::uint64_t seed, std::uint64_t counter);
  std::uint64_t next_u64();
  double uniform();   // in (0, 1): never 0, so that log() is safe
  double gaussian();  // standard normal, Box-Muller

 private:
  std::uint64_t s_[4];
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace asp
