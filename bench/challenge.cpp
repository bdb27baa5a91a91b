// SPDX-License-Identifier: GPL-2.0-or-later
// The contact-mechanics challenge's scene (Müser et al., Tribol. Lett. 65, 118 (2017)) at a
// chosen resolution (not a test): a periodic self-affine surface on a 100 um box, Hurst 0.8,
// roll-off at 20 um, short cutoff 0.1 um, rms slope 1 (seed 1); E* = 25 MPa; the hard wall
// with exponential adhesion, w = 50 mJ/m^2, rho = 2.071 nm. The surface is the same at every
// size from 2048^2 on (drawn on 2048^2, which holds all its modes, and resampled:
// challenge_scene.hpp; rms height 0.731 um), and on smaller grids its modes below their
// Nyquist wavevector; the challenge's resolution is 16384^2 or more, where rho is a third of a
// pixel.
//
// Solved under penetration control (default 1.5 um, a few percent of repulsive contact at
// 2048^2 to 8192^2), or under mean-gap control with --mean-gap (1.2 um gives 2 to 3 percent),
// cold, with `bugnicourt` on the gap unless told otherwise. Printed: the
// surface's statistics, the memory the system and the solve hold per pixel (the peak of the
// library's fields, counted by its allocator) and the process's peak resident size, the FFT
// pair of the grid with the same threads (skipped with --no-pair), progress every minute,
// and the solve's iterations, time, time per iteration in FFT pairs, error, contact and
// attractive fractions, the energy, and how it ended.
//
// With --settling K,K,... the scene is solved again from rest after the solve, once for each
// K, stopped after K iterations, and the contact set there is compared with the converged
// one's: the pixels on the wall in one and not in the other, how far (in pixels, the
// chessboard distance on the periodic grid) the converged state's missing ones lie from the
// nearest pixel on the wall at K, and the median gap of the missing ones in units of rho.
// It shows how the contact set settles during a solve. (With bugnicourt's default
// continuation in the range each re-solve is a continued cold solve: a K within its first
// stage compares the contact set of the longer range's scene.)
//
// With --range-scale S the range is S times the challenge's 2.071 nm (the work of adhesion
// kept): a variant of the scene whose cohesive zone a grid resolves the better the larger S.
// (bugnicourt's default continuation in the range, its option range_continuation, is set
// with --option range_continuation=F, 0 for none.)
//
// With --trace the progress line (iteration, seconds, error) is printed at every iteration of
// the solve on the system's grid (both stages of a continuation in the range; the coarse
// levels report none) instead of once a minute.
//
// usage: asperity_challenge [--size N] [--threads T] [--algorithm NAME[:VARIABLE]]
//                           [--penetration D | --mean-gap G] [--tolerance T]
//                           [--max-iterations K] [--no-pair] [--estimate]
//                           [--settling K,K,...] [--range-scale S] [--trace]
//                           [--option NAME=VALUE]   (an option of the algorithm: a number,
//                                                    or else a word; repeatable)
//        (defaults: 16384, the library's default threads, bugnicourt:gap, 1.5e-6 m, 1e-6,
//         100000, measured FFT plans (--estimate: FFTW_ESTIMATE, which saves the planning,
//         about 40 s at 16384^2, for a pair 1.6 times slower there))
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/challenge_scene.hpp"
#include "core/aligned_field.hpp"
#include "core/error.hpp"
#include "physics/surface_statistics.hpp"
#include "physics/system.hpp"
#include "solvers/solver.hpp"

namespace {

constexpr double box = bench::challenge_box, modulus = 25e6, work = 0.05, range = 2.071e-9;

struct Options {
  long size = 16384;
  int threads = 0;  // 0: the library's default
  std::string algorithm = "bugnicourt";
  std::string variable = "gap";
  double penetration = 1.5e-6;
  double mean_gap = 0.0;  // > 0: mean-gap control at this mean gap instead of the penetration
  double tolerance = 1e-6;
  double max_iterations = 1e5;
  bool pair = true;
  bool estimate = false;  // FFTW_ESTIMATE plans instead of measured ones
  double range_scale = 1.0;   // --range-scale: the scene's range in units of the challenge's
  std::vector<std::pair<std::string, std::string>> choices;  // --option NAME=VALUE
  std::vector<double> settling;  // --settling: the iteration counts to compare at
  bool trace = false;            // --trace: the error at every iteration
};

// The pixels on the wall (g = 0) of the system's state.
std::vector<char> wall_pixels(const asp::System &system) {
  const asp::Field &gap = system.state().gap;
  std::vector<char> on(gap.size());
  for (std::size_t i = 0; i < on.size(); ++i) on[i] = gap[i] == 0.0;
  return on;
}

// Every pixel's chessboard distance to the nearest pixel of `set` on the periodic n x n grid
// (-1 where the set is empty), by a breadth-first search from all of the set at once.
std::vector<int> distance_to(const std::vector<char> &set, long n) {
  std::vector<int> distance(set.size(), -1);
  std::deque<long> front;
  for (long i = 0; i < static_cast<long>(set.size()); ++i)
    if (set[static_cast<std::size_t>(i)]) {
      distance[static_cast<std::size_t>(i)] = 0;
      front.push_back(i);
    }
  while (!front.empty()) {
    const long i = front.front();
    front.pop_front();
    const long x = i / n, y = i % n;
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        const auto j = static_cast<std::size_t>(((x + dx + n) % n) * n + (y + dy + n) % n);
        if (distance[j] < 0) {
          distance[j] = distance[static_cast<std::size_t>(i)] + 1;
          front.push_back(static_cast<long>(j));
        }
      }
  }
  return distance;
}

// --settling: the converged contact set against those of solves stopped early.
void report_settling(const Options &o, asp::Solver &solver, asp::System &system,
                     asp::Control control, double target) {
  const std::vector<char> converged = wall_pixels(system);
  std::printf("settling of the contact set (%ld pixels on the wall when converged):\n",
              static_cast<long>(std::count(converged.begin(), converged.end(), 1)));
  for (const double iterations : o.settling) {
    system.reset_state();
    solver.set_option("max_iterations", iterations);
    solver.solve(system, control, target);
    const std::vector<char> early = wall_pixels(system);
    const std::vector<int> distance = distance_to(early, o.size);
    long missing = 0, extra = 0;
    int farthest = 0;
    std::vector<double> gaps;
    for (std::size_t i = 0; i < early.size(); ++i) {
      if (converged[i] && !early[i]) {
        ++missing;
        farthest = std::max(farthest, distance[i]);
        gaps.push_back(system.state().gap[i] / (o.range_scale * range));
      }
      if (early[i] && !converged[i]) ++extra;
    }
    double median = 0.0;
    if (!gaps.empty()) {
      std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
      median = gaps[gaps.size() / 2];
    }
    std::printf("  after %5.0f iterations: %ld missing (farthest %d px from the wall, median "
                "gap %.2f rho), %ld extra\n",
                iterations, missing, farthest, median, extra);
    std::fflush(stdout);
  }
}

// A line a minute, so that an hour-long solve shows where it is; with --trace, a line every
// iteration.
struct Progress {
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  bool every = false;  // --trace: a line every iteration
};

int report_progress(std::int64_t iteration, double seconds, double error, void *data) {
  auto *progress = static_cast<Progress *>(data);
  if (progress->every || bench::seconds_since(progress->last) >= 60.0) {
    progress->last = std::chrono::steady_clock::now();
    std::printf("  iteration %lld, %.0f s, error %.3e\n", static_cast<long long>(iteration),
                seconds, error);
    std::fflush(stdout);
  }
  return 0;
}

int run(const Options &o) {
  auto grid = asp::Grid::create(2, o.size, o.size, box, box);
  if (o.threads > 0) grid->set_threads(o.threads);
  if (o.estimate) grid->set_fft_planning(asp::FftPlanning::estimate);

  const auto start = std::chrono::steady_clock::now();
  const std::int64_t empty = asp::field_bytes_in_use();
  asp::System system(grid, modulus);
  {
    std::vector<double> heights(static_cast<std::size_t>(grid->n_pixels()));
    bench::challenge_heights(*grid, heights.data());
    system.set_topography(heights.data());
  }
  const double rho = o.range_scale * range;
  system.set_adhesion(work, rho);
  const double pixels = static_cast<double>(grid->n_pixels());
  const double system_bytes = static_cast<double>(asp::field_bytes_in_use() - empty) / pixels;
  const asp::SurfaceStatistics stats =
      asp::surface_statistics(*grid, system.heights().data());
  std::printf("challenge scene: %ld^2 pixels (%.3g nm each), 100 um box, H 0.8, roll-off 20 um, "
              "short cutoff 0.1 um, seed 1: rms height %.4g um, rms slope %.4g, rms curvature "
              "1/(%.4g nm); E* 25 MPa, w 50 mJ/m^2, rho %.4g nm; %d threads; made in %.1f s\n",
              o.size, 1e9 * box / static_cast<double>(o.size), 1e6 * stats.rms_height,
              stats.rms_slope, 1e9 / stats.rms_curvature, 1e9 * rho, grid->threads(),
              bench::seconds_since(start));
  std::fflush(stdout);

  double pair = 0.0;
  if (o.pair) {
    pair = bench::fft_pair_seconds(*grid);
    std::printf("FFT pair: %.4g s\n", pair);
    std::fflush(stdout);
  }

  asp::Solver solver(o.algorithm);
  if (!o.variable.empty()) solver.set_option("variable", o.variable);
  for (const auto &choice : o.choices) bench::set_option(solver, choice.first, choice.second);
  solver.set_option("tolerance", o.tolerance);
  solver.set_option("max_iterations", o.max_iterations);
  Progress progress;
  progress.every = o.trace;
  solver.set_progress(report_progress, &progress);
  asp::reset_field_bytes_peak();
  const std::int64_t before = asp::field_bytes_in_use();
  const bool by_mean_gap = o.mean_gap > 0.0;
  const asp::Control control = by_mean_gap ? asp::Control::mean_gap : asp::Control::penetration;
  const double target = by_mean_gap ? o.mean_gap : o.penetration;
  solver.solve(system, control, target);
  const double solve_bytes = static_cast<double>(asp::field_bytes_peak() - before) / pixels;

  const asp::SolveReport &r = solver.report();
  const double per_iteration = r.seconds / static_cast<double>(r.iterations > 0 ? r.iterations : 1);
  std::printf("%s%s%s at %s %.4g um, tolerance %.0e: %s after %lld iterations "
              "(%lld evaluations, %lld transforms) in %.1f s, %.3f s per iteration",
              o.algorithm.c_str(), o.variable.empty() ? "" : ":", o.variable.c_str(),
              by_mean_gap ? "mean gap" : "penetration",
              1e6 * (by_mean_gap ? o.mean_gap : o.penetration), o.tolerance, asp::termination_name(r.termination),
              static_cast<long long>(r.iterations), static_cast<long long>(r.evaluations),
              static_cast<long long>(r.transforms), r.seconds, per_iteration);
  if (pair > 0.0) std::printf(" (%.2f FFT pairs)", per_iteration / pair);
  std::printf("; error %.3e\n", r.error);
  std::printf("contact %.4f %%, attractive %.4f %%, mean pressure %.4g kPa, mean gap %.4g nm, "
              "penetration %.4g um\n",
              100.0 * system.contact_fraction(), 100.0 * system.attractive_fraction(),
              1e-3 * system.mean_pressure(), 1e9 * system.mean_gap(),
              1e6 * system.state().penetration);
  // The energy a solve minimises at fixed penetration, to compare the states two solves reach.
  const double elastic = system.elastic_energy() + system.mean_mode_energy();
  const double interaction = system.interaction_energy();
  std::printf("energy %.9e J (elastic %.6e J, interaction %.6e J)\n", elastic + interaction,
              elastic, interaction);
  std::printf("memory: system %.1f B/pixel, solve %.1f B/pixel, together %.1f B/pixel "
              "(%.2f GiB); the process's peak resident size %.2f GiB\n",
              system_bytes, solve_bytes, system_bytes + solve_bytes,
              (system_bytes + solve_bytes) * pixels / (1024.0 * 1024.0 * 1024.0),
              bench::peak_resident_bytes() / (1024.0 * 1024.0 * 1024.0));
  if (!o.settling.empty()) report_settling(o, solver, system, control, target);
  return 0;
}

int usage(const char *program) {
  std::fprintf(stderr,
               "usage: %s [--size N] [--threads T] [--algorithm NAME[:VARIABLE]] "
               "[--penetration D | --mean-gap G] [--tolerance T] [--max-iterations K] [--no-pair] "
               "[--estimate] [--settling K,K,...] [--range-scale S] "
               "[--trace] "
               "[--option NAME=VALUE]\n",
               program);
  return 2;
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--size" && has_value) {
      o.size = std::strtol(argv[++i], nullptr, 10);
    } else if (arg == "--threads" && has_value) {
      o.threads = std::atoi(argv[++i]);
    } else if (arg == "--algorithm" && has_value) {
      const std::string request = argv[++i];
      const std::size_t colon = request.find(':');
      o.algorithm = request.substr(0, colon);
      o.variable = colon == std::string::npos ? "" : request.substr(colon + 1);
    } else if (arg == "--penetration" && has_value) {
      o.penetration = std::strtod(argv[++i], nullptr);
    } else if (arg == "--mean-gap" && has_value) {
      o.mean_gap = std::strtod(argv[++i], nullptr);
    } else if (arg == "--tolerance" && has_value) {
      o.tolerance = std::strtod(argv[++i], nullptr);
    } else if (arg == "--max-iterations" && has_value) {
      o.max_iterations = std::strtod(argv[++i], nullptr);
    } else if (arg == "--no-pair") {
      o.pair = false;
    } else if (arg == "--range-scale" && has_value) {
      o.range_scale = std::strtod(argv[++i], nullptr);
      if (!(o.range_scale > 0.0 && std::isfinite(o.range_scale))) return usage(argv[0]);
    } else if (arg == "--trace") {
      o.trace = true;
    } else if (arg == "--estimate") {
      o.estimate = true;
    } else if (arg == "--settling" && has_value) {
      std::stringstream list(argv[++i]);
      for (std::string count; std::getline(list, count, ',');) {
        const double iterations = std::strtod(count.c_str(), nullptr);
        if (!(iterations >= 1.0 && iterations <= 1e9)) return usage(argv[0]);
        o.settling.push_back(std::floor(iterations));
      }
    } else if (arg == "--option" && has_value) {
      const std::string choice = argv[++i];
      const std::size_t equals = choice.find('=');
      if (equals == std::string::npos) return usage(argv[0]);
      o.choices.emplace_back(choice.substr(0, equals), choice.substr(equals + 1));
    } else {
      return usage(argv[0]);
    }
  }
  if (o.size < 2 || o.threads < 0 || !std::isfinite(o.penetration) ||
      !(o.mean_gap >= 0.0 && std::isfinite(o.mean_gap)))
    return usage(argv[0]);
  try {
    return run(o);
  } catch (const asp::Error &e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
