// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/transform_clock.hpp"

namespace asp {
namespace transform_clock {

std::atomic<bool> &enabled_flag() {
  static std::atomic<bool> on{false};
  return on;
}

std::atomic<std::int64_t> &nanoseconds_total() {
  static std::atomic<std::int64_t> total{0};
  return total;
}

}  // namespace transform_clock
}  // namespace asp
