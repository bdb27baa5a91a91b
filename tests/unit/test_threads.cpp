// SPDX-License-Identifier: GPL-2.0-or-later
// Distinct systems may be solved from distinct threads, also when they share a grid (and so
// its FFT plans, which are created lazily behind a lock).
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "scene.hpp"

namespace {

std::vector<double> solve_on(const std::shared_ptr<asp::Grid> &grid, std::uint64_t seed) {
  const std::vector<double> h = asp_test::rough_surface(*grid, seed);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  asp_test::solve_pk(system, asp::Control::mean_pressure, 0.005, 1e-10);
  return asp_test::field_vector(system.state().pressure);
}

TEST(Threads, ConcurrentSolvesOnASharedGridMatchSerialOnes) {
  const std::vector<double> serial_a = solve_on(asp_test::grid_2d(96, 96, 1.0, 1.0), 1);
  const std::vector<double> serial_b = solve_on(asp_test::grid_2d(96, 96, 1.0, 1.0), 2);
  for (int round = 0; round < 3; ++round) {
    auto shared = asp_test::grid_2d(96, 96, 1.0, 1.0);  // plans not made yet: both threads race
    std::vector<double> a, b;
    std::thread first([&] { a = solve_on(shared, 1); });
    std::thread second([&] { b = solve_on(shared, 2); });
    first.join();
    second.join();
    EXPECT_EQ(a, serial_a);
    EXPECT_EQ(b, serial_b);
  }
}

}  // namespace
