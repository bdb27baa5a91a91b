// SPDX-License-Identifier: GPL-2.0-or-later
// The contact-mechanics challenge's scene (Müser et al., Tribol. Lett. 65, 118 (2017)) at a
// chosen resolution (not a test): a periodic self-affine surface on a 100 um box, Hurst 0.8,
// roll-off at 20 um, short cutoff 0.1 um, rms slope 1 (seed 1); E* = 25 MPa; the hard wall
// with exponential adhesion, w = 50 mJ/m^2, rho = 2.071 nm. The generator keys its modes by
// the wavevector, so every size above 1000^2 (where the short cutoff lies above the Nyquist
// wavelength) holds the same modes, up to the factor that gives the rms slope on that grid
// (rms heights 0.73 um at 2048^2, 0.79 um at 4096^2); the challenge's resolution is 16384^2
// or more, where rho is a third of a pixel.
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
// With --range-continuation F the solve is preceded by one of the same scene with the range
// F rho, to the tolerance 1e-3, from whose state the solve with rho starts; both are printed,
// and the iterations of the two together.
//
// usage: asperity_challenge [--size N] [--threads T] [--algorithm NAME[:VARIABLE]]
//                           [--penetration D | --mean-gap G] [--tolerance T]
//                           [--max-iterations K] [--no-pair] [--estimate]
//                           [--range-continuation F]
//                           [--option NAME=VALUE]   (an option of the algorithm: a number,
//                                                    or else a word; repeatable)
//        (defaults: 16384, the library's default threads, bugnicourt:gap, 1.5e-6 m, 1e-6,
//         100000, measured FFT plans (--estimate: FFTW_ESTIMATE, which saves the planning,
//         about 40 s at 16384^2, for a pair 1.6 times slower there))
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_common.hpp"
#include "core/aligned_field.hpp"
#include "core/error.hpp"
#include "physics/surface_statistics.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

namespace {

constexpr double box = 100e-6, modulus = 25e6, work = 0.05, range = 2.071e-9;

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
  double range_factor = 0.0;  // > 0: a first solve with this multiple of the range
  std::vector<std::pair<std::string, std::string>> choices;  // --option NAME=VALUE
};

// A line a minute, so that an hour-long solve shows where it is.
struct Progress {
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
};

int report_progress(std::int64_t iteration, double seconds, double error, void *data) {
  auto *progress = static_cast<Progress *>(data);
  if (bench::seconds_since(progress->last) >= 60.0) {
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
  asp::SelfAffineParameters params;
  params.hurst = 0.8;
  params.long_cutoff = box;
  params.rolloff = 20e-6;
  params.short_cutoff = 0.1e-6;
  params.norm = asp::RoughnessNorm::rms_slope;
  params.target = 1.0;
  params.seed = 1;

  const auto start = std::chrono::steady_clock::now();
  const std::int64_t empty = asp::field_bytes_in_use();
  asp::System system(grid, modulus);
  {
    std::vector<double> heights(static_cast<std::size_t>(grid->n_pixels()));
    asp::self_affine_topography(*grid, params, heights.data());
    system.set_topography(heights.data());
  }
  system.set_adhesion(work, range);
  const double pixels = static_cast<double>(grid->n_pixels());
  const double system_bytes = static_cast<double>(asp::field_bytes_in_use() - empty) / pixels;
  const asp::SurfaceStatistics stats =
      asp::surface_statistics(*grid, system.heights().data());
  std::printf("challenge scene: %ld^2 pixels (%.3g nm each), 100 um box, H 0.8, roll-off 20 um, "
              "short cutoff 0.1 um, seed 1: rms height %.4g um, rms slope %.4g, rms curvature "
              "1/(%.4g nm); E* 25 MPa, w 50 mJ/m^2, rho 2.071 nm; %d threads; made in %.1f s\n",
              o.size, 1e9 * box / static_cast<double>(o.size), 1e6 * stats.rms_height,
              stats.rms_slope, 1e9 / stats.rms_curvature, grid->threads(),
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
  solver.set_progress(report_progress, &progress);
  asp::reset_field_bytes_peak();
  const std::int64_t before = asp::field_bytes_in_use();
  const bool by_mean_gap = o.mean_gap > 0.0;
  const asp::Control control = by_mean_gap ? asp::Control::mean_gap : asp::Control::penetration;
  const double target = by_mean_gap ? o.mean_gap : o.penetration;
  std::int64_t first_iterations = 0;
  if (o.range_factor > 0.0) {
    system.set_adhesion(work, o.range_factor * range);
    solver.set_option("tolerance", 1e-3);
    solver.solve(system, control, target);
    const asp::SolveReport &first = solver.report();
    first_iterations = first.iterations;
    std::printf("range %.4g nm, tolerance 1e-3: %s after %lld iterations in %.1f s; contact "
                "%.4f %%\n",
                1e9 * o.range_factor * range, asp::termination_name(first.termination),
                static_cast<long long>(first.iterations), first.seconds,
                100.0 * system.contact_fraction());
    system.set_adhesion(work, range);
    solver.set_option("tolerance", o.tolerance);
  }
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
  if (o.range_factor > 0.0)
    std::printf("with the solve at %g rho: %lld iterations\n", o.range_factor,
                static_cast<long long>(first_iterations + r.iterations));
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
  return 0;
}

int usage(const char *program) {
  std::fprintf(stderr,
               "usage: %s [--size N] [--threads T] [--algorithm NAME[:VARIABLE]] "
               "[--penetration D | --mean-gap G] [--tolerance T] [--max-iterations K] [--no-pair] "
               "[--estimate] [--range-continuation F] [--option NAME=VALUE]\n",
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
    } else if (arg == "--estimate") {
      o.estimate = true;
    } else if (arg == "--range-continuation" && has_value) {
      o.range_factor = std::strtod(argv[++i], nullptr);
      if (!(o.range_factor > 0.0 && std::isfinite(o.range_factor))) return usage(argv[0]);
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
