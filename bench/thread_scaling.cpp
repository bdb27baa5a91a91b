// SPDX-License-Identifier: GPL-2.0-or-later
// Strong scaling of threads: the same solve on 1 and on 2 (or more) threads, at the sizes
// given, for pk, bugnicourt and lbfgs_fourier. For each solver and thread count: the time per
// iteration of a fixed number of iterations (the tolerance out of reach), that time in FFT
// pairs of the grid with the same threads (measured in the same run), and the parallel
// efficiency t(1) / (threads t(threads)). The scenes are bench/scaling_scene.hpp's.
//
// usage: asperity_thread_scaling [--size N]... [--threads T] [--iterations K]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/scaling_scene.hpp"

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

Run measure(const char *algorithm, std::int64_t n, int threads, int iterations) {
  auto grid = make_grid(n, threads);
  bench::ScalingScene scene = bench::scaling_scene(grid, algorithm);
  asp::Solver solver(algorithm);
  bench::warm_up(solver, scene, iterations);
  const auto start = std::chrono::steady_clock::now();
  solver.solve(*scene.system, scene.control, scene.value);
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
