// SPDX-License-Identifier: GPL-2.0-or-later
// Distinct systems may be solved from distinct threads, also when they share a grid (and so
// its FFT plans, which are created lazily behind a lock).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <utility>
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

// Integration points of a finite-element code: each thread solves points of its own (a system
// and a solver each) on one shared grid, warm, one load step after another, the last step a
// repeat of the one before (a solve from a converged state). The states and the iteration
// counts are bit for bit those of the same steps made on one thread. The points are made on
// the calling thread and freed on the solving one, so that fields cross threads (the
// allocator keeps a thread's freed blocks for its next fields).
struct Point {
  std::unique_ptr<asp::System> system;
  std::unique_ptr<asp::Solver> solver;
  asp::Control control;
  double value;
};

std::vector<Point> points_on(const std::shared_ptr<asp::Grid> &grid, std::uint64_t seed) {
  const std::vector<double> h = asp_test::rough_surface(*grid, seed, 0.1, 0.5, 2.0);
  std::vector<Point> points;
  const struct {
    const char *algorithm;
    asp::Control control;
    double value;
  } kinds[] = {{"pk", asp::Control::mean_pressure, 0.01},
               {"bugnicourt", asp::Control::penetration, 0.004},
               {"lbfgs_fourier", asp::Control::penetration, -0.45}};
  for (const auto &kind : kinds) {
    Point p{std::make_unique<asp::System>(grid, 1.0), std::make_unique<asp::Solver>(kind.algorithm),
            kind.control, kind.value};
    p.system->set_topography(h.data());
    if (kind.control == asp::Control::penetration && kind.value < 0.0)
      p.system->set_soft_wall(0.05, 0.3, 0.01, 0.3);
    else if (std::string(kind.algorithm) == "bugnicourt")
      p.solver->set_option("variable", std::string("gap"));
    points.push_back(std::move(p));
  }
  return points;
}

// The load steps of every point, then frees them; the pressures and iteration counts, in turn.
std::vector<double> load_steps(std::vector<Point> points) {
  std::vector<double> out;
  for (Point &p : points) {
    for (double factor : {1.0, 1.001, 1.002, 1.002}) {
      p.solver->solve(*p.system, p.control, factor * p.value);
      EXPECT_TRUE(p.solver->report().converged()) << p.solver->algorithm().name;
      out.push_back(static_cast<double>(p.solver->report().iterations));
    }
    const std::vector<double> pressure = asp_test::field_vector(p.system->state().pressure);
    out.insert(out.end(), pressure.begin(), pressure.end());
  }
  points.clear();
  return out;
}

TEST(Threads, WarmSolvesOfPointsOnASharedGridMatchSerialOnes) {
  const auto serial_grid = asp_test::grid_2d(32, 32, 32.0, 32.0);
  const std::vector<double> serial_a = load_steps(points_on(serial_grid, 5));
  const std::vector<double> serial_b = load_steps(points_on(serial_grid, 6));
  for (int round = 0; round < 2; ++round) {
    const auto shared = asp_test::grid_2d(32, 32, 32.0, 32.0);
    std::vector<Point> points_a = points_on(shared, 5), points_b = points_on(shared, 6);
    std::vector<double> a, b;
    std::thread first([&] { a = load_steps(std::move(points_a)); });
    std::thread second([&] { b = load_steps(std::move(points_b)); });
    first.join();
    second.join();
    EXPECT_EQ(a, serial_a);
    EXPECT_EQ(b, serial_b);
  }
}

}  // namespace
