// SPDX-License-Identifier: GPL-2.0-or-later
// The time the library spends in its transforms, for the benchmarks that split a solve's time
// into its transforms and the rest (bench/pk_benchmark.cpp). A reference pair timed outside the
// solve prices the transforms only as well as the machine holds still: on a shared machine the
// same pair can take half as long again a few seconds later. Timed where they run, the
// transforms are priced at what they cost in the solve, data coming from memory included.
// Off unless a benchmark turns it on: reading the clock twice costs about as much as a
// transform of a few hundred points.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

namespace asp {
namespace transform_clock {

std::atomic<bool> &enabled_flag();
std::atomic<std::int64_t> &nanoseconds_total();

// Turns the clock on or off; the total is kept.
inline void enable(bool on) { enabled_flag().store(on, std::memory_order_relaxed); }
// Seconds in transforms, over every thread, since the last reset.
inline double seconds() {
  return 1e-9 * static_cast<double>(nanoseconds_total().load(std::memory_order_relaxed));
}
inline void reset() { nanoseconds_total().store(0, std::memory_order_relaxed); }

// Times its own lifetime into the total, when the clock is on: one for each transform.
class Scope {
 public:
  Scope() : on_(enabled_flag().load(std::memory_order_relaxed)) {
    if (on_) start_ = std::chrono::steady_clock::now();
  }
  ~Scope() {
    if (!on_) return;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    nanoseconds_total().fetch_add(
        std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count(),
        std::memory_order_relaxed);
  }
  Scope(const Scope &) = delete;
  Scope &operator=(const Scope &) = delete;

 private:
  bool on_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace transform_clock
}  // namespace asp
