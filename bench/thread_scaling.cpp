// SPDX-License-Identifier: GPL-2.0-or-later
// Strong scaling of threads: the same solve on 1 and on 2 (or more) threads, at the sizes
// given, for pk, bugnicourt and lbfgs_fourier. For each solver and thread count, of a solve
// of a fixed number of iterations (the tolerance out of reach): the seconds before its first
// iteration (setup), the time per iteration after it, that time in FFT pairs of the grid with
// the same threads (measured in the same run), and the parallel efficiency
// t(1) / (threads t(threads)) per iteration and of the whole solve, each the best of a few
// solves. The scenes are bench/scaling_scene.hpp's.
//
// usage: asperity_thread_scaling [--size N]... [--algorithm NAME]... [--threads T]
//                                [--iterations K] [--repeats R] [--estimate]
//        (defaults: 2048 and 4096; pk, bugnicourt and lbfgs_fourier; 2 threads; 40
//         iterations; the best of 3 solves; measured plans, --estimate for FFTW_ESTIMATE)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/scaling_scene.hpp"

namespace {

struct Run {
  bench::SolveTimes times;  // seconds
  double pair = 0.0;        // seconds of one FFT pair with the same threads
};

// Plans for the solver and for the reference pair alike: measured (the library's default) or,
// with --estimate, FFTW_ESTIMATE, which skips the planning but gives slower transforms.
bool estimate_plans = false;

std::shared_ptr<asp::Grid> make_grid(std::int64_t n, int threads) {
  auto grid = asp::Grid::create(2, n, n, static_cast<double>(n), static_cast<double>(n));
  if (estimate_plans) grid->set_fft_planning(asp::FftPlanning::estimate);
  grid->set_threads(threads);
  return grid;
}

// The best of `repeats` solves from the same cold state (the machine's noise only ever adds
// time), each time taken on its own: setup, per iteration, in all.
Run measure(const char *algorithm, std::int64_t n, int threads, int iterations, int repeats) {
  auto grid = make_grid(n, threads);
  bench::ScalingScene scene = bench::scaling_scene(grid, algorithm);
  asp::Solver solver(algorithm);
  bench::warm_up(solver, scene, iterations);
  Run r;
  for (int k = 0; k < repeats; ++k) {
    scene.system->reset_state();
    const bench::SolveTimes t = bench::timed_solve(solver, scene);
    const auto least = [k](double &best, double now) { best = k == 0 ? now : std::min(best, now); };
    least(r.times.setup, t.setup);
    least(r.times.per_iteration, t.per_iteration);
    least(r.times.total, t.total);
  }
  r.pair = bench::fft_pair_seconds(*grid);
  return r;
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<std::int64_t> sizes;
  std::vector<std::string> algorithms;
  int threads = 2, iterations = 40, repeats = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--size" && has_value) sizes.push_back(std::atoll(argv[++i]));
    else if (arg == "--algorithm" && has_value) algorithms.push_back(argv[++i]);
    else if (arg == "--threads" && has_value) threads = std::atoi(argv[++i]);
    else if (arg == "--iterations" && has_value) iterations = std::atoi(argv[++i]);
    else if (arg == "--repeats" && has_value) repeats = std::atoi(argv[++i]);
    else if (arg == "--estimate") estimate_plans = true;
    else {
      std::fprintf(stderr,
                   "usage: %s [--size N]... [--algorithm NAME]... [--threads T] "
                   "[--iterations K] [--repeats R] [--estimate]\n",
                   argv[0]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {2048, 4096};
  if (algorithms.empty()) algorithms = {"pk", "bugnicourt", "lbfgs_fourier"};
  std::printf("%-14s %6s %8s %9s %12s %12s %10s %11s %11s\n", "solver", "size", "threads",
              "setup s", "ms/iter", "pair ms", "pairs/it", "efficiency", "solve eff.");
  for (std::int64_t n : sizes)
    for (const std::string &name : algorithms) {
      const char *algorithm = name.c_str();
      Run one, many;
      try {
        one = measure(algorithm, n, 1, iterations, repeats);
        many = measure(algorithm, n, threads, iterations, repeats);
      } catch (const asp::Error &e) {
        // The scenes are pk's, bugnicourt's and lbfgs_fourier's; another solver may refuse them.
        std::fprintf(stderr, "%s: %s\n", algorithm, e.what());
        return 1;
      }
      const auto row = [&](int t, const Run &r, const char *efficiency, const char *solve) {
        std::printf("%-14s %6lld %8d %9.2f %12.2f %12.2f %10.2f %11s %11s\n", algorithm,
                    static_cast<long long>(n), t, r.times.setup, 1e3 * r.times.per_iteration,
                    1e3 * r.pair, r.times.per_iteration / r.pair, efficiency, solve);
      };
      const auto percent = [&](double one_thread, double many_threads) {
        char text[16];
        std::snprintf(text, sizeof text, "%.0f%%", 100.0 * one_thread / (threads * many_threads));
        return std::string(text);
      };
      row(1, one, "", "");
      row(threads, many, percent(one.times.per_iteration, many.times.per_iteration).c_str(),
          percent(one.times.total, many.times.total).c_str());
      std::fflush(stdout);
    }
  return 0;
}
