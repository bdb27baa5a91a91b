// SPDX-License-Identifier: GPL-2.0-or-later
// Strong scaling of threads: the same solve on 1 and on 2 (or more) threads, at the sizes
// given, for pk, bugnicourt and lbfgs_fourier. For each solver and thread count: the time per
// iteration of a fixed number of iterations (the tolerance out of reach), that time in FFT
// pairs of the grid with the same threads (measured in the same run), and the parallel
// efficiency t(1) / (threads t(threads)). Scenes: a self-affine surface (Hurst 0.8, rms slope
// 0.1, roll-off a quarter of the box, short cutoff 4 pixels) on a periodic substrate, E* = 1;
// pk and bugnicourt under a mean pressure of 0.005 E* (a few percent of contact), lbfgs_fourier
// with the exponential soft wall of the soft-wall benchmark's rough scene (range 0.5 pixels)
// under penetration control.
//
// usage: asperity_thread_scaling [--size N]... [--threads T] [--iterations K]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "physics/surface_statistics.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

namespace {

struct Run {
  double per_iteration = 0.0;  // seconds
  double pair = 0.0;           // seconds of one FFT pair with the same threads
};

std::shared_ptr<asp::Grid> make_grid(std::int64_t n, int threads) {
  auto grid = asp::Grid::create(2, n, n, static_cast<double>(n), static_cast<double>(n));
  grid->set_fft_planning(asp::FftPlanning::estimate);
  grid->set_threads(threads);
  return grid;
}

std::vector<double> rough(const asp::Grid &grid) {
  asp::SelfAffineParameters p;
  p.hurst = 0.8;
  p.long_cutoff = grid.lx();
  p.rolloff = 0.25 * grid.lx();
  p.short_cutoff = 4.0;
  p.norm = asp::RoughnessNorm::rms_slope;
  p.target = 0.1;
  p.seed = 1;
  std::vector<double> h(static_cast<std::size_t>(grid.n_pixels()));
  asp::self_affine_topography(grid, p, h.data());
  return h;
}

Run measure(const char *algorithm, std::int64_t n, int threads, int iterations) {
  auto grid = make_grid(n, threads);
  const std::vector<double> h = rough(*grid);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  asp::Control control = asp::Control::mean_pressure;
  double value = 0.005;
  if (std::strcmp(algorithm, "lbfgs_fourier") == 0) {
    const double rc = 1.0 / asp::surface_statistics(*grid, h.data()).rms_curvature;
    system.set_soft_wall(2.10e3 * rc, 0.5, 2.05 * rc, 0.5);
    control = asp::Control::penetration;
    value = 0.05 * system.height_range();
  }
  asp::Solver solver(algorithm);
  solver.set_option("tolerance", 1e-300);
  solver.set_option("stall_window", 0.0);
  // A first short solve makes the plans and the substrate's tables; then the timed one.
  solver.set_option("max_iterations", 2.0);
  solver.solve(system, control, value);
  system.reset_state();
  solver.set_option("max_iterations", static_cast<double>(iterations));
  const auto start = std::chrono::steady_clock::now();
  solver.solve(system, control, value);
  const double seconds = bench::seconds_since(start);
  Run r;
  r.per_iteration = seconds / static_cast<double>(solver.report().iterations);
  r.pair = bench::fft_pair_seconds(*grid);
  return r;
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<std::int64_t> sizes;
  int threads = 2, iterations = 40;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--size" && has_value) sizes.push_back(std::atoll(argv[++i]));
    else if (arg == "--threads" && has_value) threads = std::atoi(argv[++i]);
    else if (arg == "--iterations" && has_value) iterations = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--size N]... [--threads T] [--iterations K]\n", argv[0]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {2048, 4096};
  if (threads < 2 || iterations < 1) return 2;
  std::printf("%-14s %6s %8s %12s %12s %10s %11s\n", "solver", "size", "threads", "ms/iter",
              "pair ms", "pairs/it", "efficiency");
  for (std::int64_t n : sizes)
    for (const char *algorithm : {"pk", "bugnicourt", "lbfgs_fourier"}) {
      const Run one = measure(algorithm, n, 1, iterations);
      const Run many = measure(algorithm, n, threads, iterations);
      std::printf("%-14s %6lld %8d %12.2f %12.2f %10.2f %11s\n", algorithm,
                  static_cast<long long>(n), 1, 1e3 * one.per_iteration, 1e3 * one.pair,
                  one.per_iteration / one.pair, "");
      std::printf("%-14s %6lld %8d %12.2f %12.2f %10.2f %10.0f%%\n", algorithm,
                  static_cast<long long>(n), threads, 1e3 * many.per_iteration,
                  1e3 * many.pair, many.per_iteration / many.pair,
                  100.0 * one.per_iteration / (threads * many.per_iteration));
      std::fflush(stdout);
    }
  return 0;
}
