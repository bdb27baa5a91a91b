// SPDX-License-Identifier: GPL-2.0-or-later
// Many small solves, as a finite-element code makes them: one solve per integration point,
// warm-started from the point's last state, on grids of 64 x 64 and 128 x 128. Through the
// public C API (what such a code calls), the time per call and calls per second of
//   - asp_system_create + asp_system_destroy on an existing grid,
//   - asp_system_reset, asp_system_set_topography,
//   - a warm solve from a state that is already converged (one evaluation, nothing to do),
//   - a warm solve after a change of the penetration by 1e-3 of itself, with its iterations,
//   - a cold solve (reset, then solve), with its iterations,
// for pk and bugnicourt (hard wall) and lbfgs_fourier (soft wall), all under penetration
// control; on one thread, and on T threads at once (std::thread, each thread its own system
// and solver), first all on one shared grid, then each on a grid of its own. Every grid runs
// its solves on one thread (asp_grid_set_threads(grid, 1)): the work is spread over the
// integration points, not inside one small transform.
//
// On one thread the time per call is the calling thread's processor time (user and system),
// which a machine shared with other jobs disturbs far less than the wall time; calls per
// second there are its inverse. On T threads the calls per second are all the threads' calls
// over the wall time: what the machine delivered, other jobs and all.
//
// The overhead of a solve beyond its iterations. A warm converged solve makes one evaluation,
// one FFT pair and its passes. The time of one evaluation is taken as the time of the
// solver's iterations per FFT pair: from two solves of K1 = 10 and K2 = 110 iterations from
// the same cold state, (t(K2) - t(K1)) / (P(K2) - P(K1)) with P the FFT pairs (transforms
// over 2), each time in processor time and the best of 7 (the machine's noise only ever adds
// time). The overhead is the warm converged solve's time less that, relative to the warm
// converged solve and to the warm solve after a small change; the warm converged solve's
// whole time relative to the latter bounds it from above without any estimate.
//
// The scene is bench/scaling_scene.hpp's: a self-affine surface (Hurst 0.8, rms slope 0.1,
// roll-off a quarter of the box, short cutoff 4 pixels, seed 1) on a periodic substrate of
// E* = 1, pixel size 1; pk and bugnicourt at the penetration of a mean pressure of 0.005 E*
// (a few percent of contact), lbfgs_fourier with the exponential soft wall of range 0.5
// pixels at 0.05 of the height range. Default tolerance (1e-8).
//
// usage: asperity_small_solves [--size N]... [--threads T] [--seconds S]
//        (defaults: 64 and 128; T = the processors the machine has; S = 0.2 seconds per
//         timed batch, the best of 3 batches)
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <time.h>  // clock_gettime (POSIX)

#include "asperity/asperity.h"

namespace {

double batch_seconds = 0.2;

void ok(int status, const char *what) {
  if (status != ASP_OK) {
    std::fprintf(stderr, "asperity_small_solves: %s failed: %s\n", what,
                 asp_last_error_message());
    std::exit(1);
  }
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The processor time of the calling thread, user and system (page faults included). On a
// machine shared with other jobs the wall time of a call also holds the time others ran
// instead, which varies from run to run by more than the differences measured here; on a
// quiet machine the two agree for calls on one thread (every grid here has one).
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Processor seconds per call of `call` on this thread: the best of 3 batches of batch_seconds
// of wall time each (the machine's noise only ever adds time).
double per_call(const std::function<void()> &call) {
  double best = 1e300;
  for (int batch = 0; batch < 3; ++batch) {
    std::int64_t calls = 0;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_seconds();
    do {
      call();
      ++calls;
    } while (seconds_since(start) < batch_seconds);
    best = std::min(best, (thread_seconds() - cpu_start) / static_cast<double>(calls));
  }
  return best;
}

enum class Algorithm { pk, bugnicourt, lbfgs_fourier };
const char *name_of(Algorithm a) {
  return a == Algorithm::pk ? "pk" : a == Algorithm::bugnicourt ? "bugnicourt" : "lbfgs_fourier";
}

// What every integration point shares: the heights, the penetrations of the hard and the
// soft wall, and the soft wall's parameters.
struct Scene {
  std::int64_t n = 0;
  std::vector<double> heights;
  double hard_penetration = 0.0;
  double soft_penetration = 0.0;
  double gamma_r = 0.0, gamma_a = 0.0;
};

asp_grid *new_grid(std::int64_t n) {
  asp_grid *grid = nullptr;
  ok(asp_grid_create_2d(n, n, static_cast<double>(n), static_cast<double>(n), &grid),
     "asp_grid_create_2d");
  ok(asp_grid_set_threads(grid, 1), "asp_grid_set_threads");
  return grid;
}

Scene make_scene(asp_grid *grid, std::int64_t n) {
  Scene s;
  s.n = n;
  s.heights.resize(static_cast<std::size_t>(n * n));
  const double lx = static_cast<double>(n);
  ok(asp_topography_self_affine(grid, 0.8, lx, 0.25 * lx, 4.0, ASP_RMS_SLOPE, 0.1, 1,
                                s.heights.data(), n * n),
     "asp_topography_self_affine");
  double rms_height = 0.0, rms_slope = 0.0, rms_curvature = 0.0;
  ok(asp_topography_statistics(grid, s.heights.data(), n * n, &rms_height, &rms_slope,
                               &rms_curvature),
     "asp_topography_statistics");
  const double rc = 1.0 / rms_curvature;
  s.gamma_r = 2.10e3 * rc;
  s.gamma_a = 2.05 * rc;
  const auto range = std::minmax_element(s.heights.begin(), s.heights.end());
  s.soft_penetration = 0.05 * (*range.second - *range.first);

  // The penetration of a mean pressure of 0.005 E*.
  asp_system *system = nullptr;
  asp_solver *solver = nullptr;
  ok(asp_system_create(grid, 1.0, &system), "asp_system_create");
  ok(asp_system_set_topography(system, s.heights.data(), n * n), "asp_system_set_topography");
  ok(asp_solver_create("pk", &solver), "asp_solver_create");
  ok(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.005), "asp_solver_solve");
  ok(asp_system_get(system, ASP_PENETRATION, &s.hard_penetration), "asp_system_get");
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  return s;
}

// One integration point: a system on the grid with the scene's heights and the algorithm's
// interaction, its solver, and the penetration it is solved at.
struct Point {
  asp_system *system = nullptr;
  asp_solver *solver = nullptr;
  double penetration = 0.0;
  Point(asp_grid *grid, const Scene &s, Algorithm a) {
    ok(asp_system_create(grid, 1.0, &system), "asp_system_create");
    ok(asp_system_set_topography(system, s.heights.data(), s.n * s.n),
       "asp_system_set_topography");
    if (a == Algorithm::lbfgs_fourier)
      ok(asp_system_set_soft_wall(system, s.gamma_r, 0.5, s.gamma_a, 0.5),
         "asp_system_set_soft_wall");
    ok(asp_solver_create(name_of(a), &solver), "asp_solver_create");
    penetration = a == Algorithm::lbfgs_fourier ? s.soft_penetration : s.hard_penetration;
  }
  ~Point() {
    asp_solver_destroy(solver);
    asp_system_destroy(system);
  }
  Point(const Point &) = delete;
  Point &operator=(const Point &) = delete;

  void solve(double value) {
    ok(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, value), "asp_solver_solve");
  }
  std::int64_t iterations() const {
    std::int64_t k = 0;
    ok(asp_solver_iterations(solver, &k), "asp_solver_iterations");
    return k;
  }
  std::int64_t transforms() const {
    std::int64_t k = 0;
    ok(asp_solver_transforms(solver, &k), "asp_solver_transforms");
    return k;
  }
  std::int64_t evaluations() const {
    std::int64_t k = 0;
    ok(asp_solver_evaluations(solver, &k), "asp_solver_evaluations");
    return k;
  }
  bool converged() const {
    int c = 0;
    ok(asp_solver_converged(solver, &c), "asp_solver_converged");
    return c != 0;
  }
};

// The operations timed, each a call on an integration point (set up by `prepare`).
enum class Operation { create_destroy, reset, set_topography, warm_converged, warm_changed, cold };

struct Case {
  std::string label;
  Operation operation;
  Algorithm algorithm;
};

std::vector<Case> cases() {
  std::vector<Case> c = {{"system create + destroy", Operation::create_destroy, Algorithm::pk},
                         {"system reset", Operation::reset, Algorithm::pk},
                         {"set topography", Operation::set_topography, Algorithm::pk}};
  for (Algorithm a : {Algorithm::pk, Algorithm::bugnicourt, Algorithm::lbfgs_fourier}) {
    const std::string name = name_of(a);
    c.push_back({name + " warm, converged", Operation::warm_converged, a});
    c.push_back({name + " warm, delta * (1 + 1e-3)", Operation::warm_changed, a});
    c.push_back({name + " cold", Operation::cold, a});
  }
  return c;
}

// The call of a case on a point, readied: a converged state for the warm solves. Each call of
// the small-change case moves to the other of two penetrations 1e-3 apart, so that every call
// is a warm solve after a small change.
std::function<void()> call_of(const Case &c, asp_grid *grid, const Scene &s, Point &p) {
  const std::int64_t n = s.n * s.n;
  switch (c.operation) {
    case Operation::create_destroy:
      return [grid] {
        asp_system *system = nullptr;
        ok(asp_system_create(grid, 1.0, &system), "asp_system_create");
        asp_system_destroy(system);
      };
    case Operation::reset:
      return [&p] { ok(asp_system_reset(p.system), "asp_system_reset"); };
    case Operation::set_topography:
      return [&p, &s, n] {
        ok(asp_system_set_topography(p.system, s.heights.data(), n), "asp_system_set_topography");
      };
    case Operation::warm_converged:
      p.solve(p.penetration);
      return [&p] { p.solve(p.penetration); };
    case Operation::warm_changed: {
      p.solve(p.penetration);
      auto flip = std::make_shared<bool>(false);
      return [&p, flip] {
        *flip = !*flip;
        p.solve(*flip ? p.penetration * (1.0 + 1e-3) : p.penetration);
      };
    }
    case Operation::cold:
      return [&p] {
        ok(asp_system_reset(p.system), "asp_system_reset");
        p.solve(p.penetration);
      };
  }
  return [] {};
}

// Calls per second of `threads` threads at once, each with its own point, on one shared grid
// or each on a grid of its own: all calls over the wall time of the batch, the best of 3.
double rate_on_threads(const Case &c, const Scene &s, asp_grid *shared, int threads) {
  std::vector<asp_grid *> grids;
  std::vector<std::unique_ptr<Point>> points;
  std::vector<std::function<void()>> calls;
  for (int t = 0; t < threads; ++t) {
    asp_grid *grid = shared != nullptr ? shared : new_grid(s.n);
    if (shared == nullptr) grids.push_back(grid);
    points.emplace_back(new Point(grid, s, c.algorithm));
    calls.push_back(call_of(c, grid, s, *points.back()));
  }
  double best = 0.0;
  for (int batch = 0; batch < 3; ++batch) {
    std::atomic<int> ready{0};
    std::atomic<bool> go{false};
    std::vector<std::int64_t> counts(static_cast<std::size_t>(threads), 0);
    std::vector<std::thread> team;
    std::chrono::steady_clock::time_point start;
    for (int t = 0; t < threads; ++t)
      team.emplace_back([&, t] {
        ++ready;
        while (!go.load()) std::this_thread::yield();
        std::int64_t k = 0;
        do {
          calls[static_cast<std::size_t>(t)]();
          ++k;
        } while (seconds_since(start) < batch_seconds);
        counts[static_cast<std::size_t>(t)] = k;
      });
    while (ready.load() < threads) std::this_thread::yield();
    start = std::chrono::steady_clock::now();
    go = true;
    for (std::thread &member : team) member.join();
    const double elapsed = seconds_since(start);
    std::int64_t total = 0;
    for (std::int64_t k : counts) total += k;
    best = std::max(best, static_cast<double>(total) / elapsed);
  }
  points.clear();
  for (asp_grid *grid : grids) asp_grid_destroy(grid);
  return best;
}

// Seconds per FFT pair of an algorithm's iterations: two solves from the same cold state, of
// K1 and K2 iterations (the tolerance out of reach), each the best of 7.
double seconds_per_pair(asp_grid *grid, const Scene &s, Algorithm a) {
  Point p(grid, s, a);
  ok(asp_solver_set_tolerance(p.solver, 1e-300), "asp_solver_set_tolerance");
  ok(asp_solver_set_option(p.solver, "stall_window", 0.0), "asp_solver_set_option");
  const std::int64_t k1 = 10, k2 = 110;
  double t[2] = {1e300, 1e300};
  std::int64_t transforms[2] = {0, 0};
  for (int repeat = 0; repeat < 7; ++repeat) {
    for (int which = 0; which < 2; ++which) {
      ok(asp_solver_set_max_iterations(p.solver, which == 0 ? k1 : k2), "max_iterations");
      ok(asp_system_reset(p.system), "asp_system_reset");
      const double start = thread_seconds();
      p.solve(p.penetration);
      t[which] = std::min(t[which], thread_seconds() - start);
      transforms[which] = p.transforms();
    }
  }
  return transforms[1] > transforms[0]
             ? 2.0 * (t[1] - t[0]) / static_cast<double>(transforms[1] - transforms[0])
             : 0.0;
}

void report_size(std::int64_t n, int threads) {
  asp_grid *grid = new_grid(n);
  const Scene s = make_scene(grid, n);
  std::printf("\n%lld x %lld, %d thread%s for the parallel columns\n",
              static_cast<long long>(n), static_cast<long long>(n), threads,
              threads == 1 ? "" : "s");
  std::printf("%-38s %12s %12s %14s %14s %8s\n", "call", "cpu us/call", "1 thread /s",
              "T, one grid /s", "T, grid each /s", "iter.");
  for (const Case &c : cases()) {
    Point p(grid, s, c.algorithm);
    const std::function<void()> call = call_of(c, grid, s, p);
    const double seconds = per_call(call);
    std::string iterations = "";
    if (c.operation == Operation::warm_converged || c.operation == Operation::warm_changed ||
        c.operation == Operation::cold) {
      // After the timed calls: the last call's iterations (the small change: the mean of a
      // step up and a step down).
      std::int64_t k = p.iterations();
      if (c.operation == Operation::warm_changed) {
        call();
        k += p.iterations();
        iterations = std::to_string(static_cast<double>(k) / 2.0).substr(0, 5);
      } else {
        iterations = std::to_string(k);
      }
      if (c.operation == Operation::warm_converged && (p.evaluations() != 1 || !p.converged()))
        iterations += " (" + std::to_string(p.evaluations()) + " evaluations!)";
    }
    const double shared = rate_on_threads(c, s, grid, threads);
    const double own = rate_on_threads(c, s, nullptr, threads);
    std::printf("%-38s %12.1f %12.0f %14.0f %14.0f %8s\n", c.label.c_str(), 1e6 * seconds,
                1.0 / seconds, shared, own, iterations.c_str());
  }

  std::printf("\noverhead of a warm converged solve beyond one evaluation of the iterations "
              "(1 thread)\n");
  std::printf("%-14s %10s %10s %10s %10s %12s %14s %12s\n", "algorithm", "warm us",
              "eval. us", "overhead", "changed us", "/ warm conv.", "/ warm changed",
              "warm/changed");
  for (Algorithm a : {Algorithm::pk, Algorithm::bugnicourt, Algorithm::lbfgs_fourier}) {
    Point p(grid, s, a);
    const double warm = per_call(call_of({"", Operation::warm_converged, a}, grid, s, p));
    Point q(grid, s, a);
    const double changed = per_call(call_of({"", Operation::warm_changed, a}, grid, s, q));
    const double evaluation = seconds_per_pair(grid, s, a);
    const double overhead = warm - evaluation;
    std::printf("%-14s %10.1f %10.1f %10.1f %10.1f %11.1f%% %13.1f%% %11.1f%%\n", name_of(a),
                1e6 * warm, 1e6 * evaluation, 1e6 * overhead, 1e6 * changed,
                100.0 * overhead / warm, 100.0 * overhead / changed, 100.0 * warm / changed);
  }
  asp_grid_destroy(grid);
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<std::int64_t> sizes;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--size" && i + 1 < argc)
      sizes.push_back(std::atoll(argv[++i]));
    else if (arg == "--threads" && i + 1 < argc)
      threads = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--seconds" && i + 1 < argc)
      batch_seconds = std::atof(argv[++i]);
    else {
      std::fprintf(stderr,
                   "usage: asperity_small_solves [--size N]... [--threads T] [--seconds S]\n");
      return 2;
    }
  }
  if (sizes.empty()) sizes = {64, 128};
  std::printf("asperity %s: many small solves; calls per second, best of 3 batches of %g s\n",
              asp_version_string(), batch_seconds);
  for (std::int64_t n : sizes) report_size(n, threads);
  return 0;
}
