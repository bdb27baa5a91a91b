// SPDX-License-Identifier: GPL-2.0-or-later
// The thesis's comparisons of the unconstrained solvers on soft walls (not a test): its
// Table 4 scene (thesis section 4.2.3, Figs. 23 and 25), the same with a hundred times the
// interaction range (section 4.2.4.2, Figs. 26 and 27), and a 2D adhesive rough scene.
//
// Table 4, as we read it: 1D, 1024 points on a period of 1024 (the pixel is the unit of
// length), E* = 1, a self-affine profile with H = 0.8, no roll-off, long cutoff the period and
// short cutoff 0.01 of it (10.24 pixels); the profile's rms slope is not given: we take 0.1.
// R_c = 1/h''_rms. The potential is eq. 13, gamma_r exp(-2g/rho) - gamma_a exp(-g/rho), with
// one range rho for both exponentials. The table gives an "interaction length" of 2.56e-4
// and gamma_att = 2.05 R_c, gamma_rep = 2.10e3 R_c without units; we read the length as a
// fraction of the period (rho = 2.56e-4 x 1024 = 0.262 pixels) and the coefficients as
// written, with E* = 1 and the pixel as units. The well of this potential lies at
// g = rho ln(2 gamma_r/gamma_a) = 7.6 rho, its depth (the work of adhesion) is
// gamma_a^2/(4 gamma_r). The scene is solved under penetration control, the crest pressed to
// a gap of -5 % of the height range (contact fraction 8 %). With a hundred times the range the
// well lies a hundred times farther out, and the crest is moved out with it, to sit as deep
// inside the well as before (contact 14 %). --penetration overrides.
//
// The 2D scene: N^2 pixels on a period of N, E* = 1, H = 0.8, no roll-off, short cutoff 8
// pixels, rms slope 0.1, seed 1; the same potential with rho = 0.5 pixels and the Table 4
// coefficients scaled by the surface's own R_c.
//
// Printed per solver: iterations, evaluations, FFTs, seconds, time per iteration and per
// evaluation in FFT pairs (the pair of the grid timed in the same run), how the solve ended,
// the contact fraction, the energy's relative difference from the lowest energy any solver
// reached, the iterations to relative energy errors of 1e-5 and 1e-10 (from the recorded
// history; '-' if never), and the solver's memory per pixel. Last, where an iteration's time
// goes, as asperity_pk_benchmark splits it: its transforms in FFT pairs (`FFTs/it`), what a
// pair cost inside the solve in reference pairs (`in solve`: the library's transforms timed
// where they run, core/transform_clock.hpp), and the rest of the iteration's time in field
// streams (`streams`: 8 bytes per pixel read or written, bench::field_stream_seconds), less
// the wall's potential at its own price for every evaluation (`wall`, in reference pairs: one
// evaluation of the potential over the grid, its exponentials with the gap read and phi and
// phi' written). The history is recorded, so the rest includes its passes (the objective and
// the contact area of every iteration). The reference pair, the stream and the potential are
// timed before every solve, and the best of those timings is the price.
//
// usage: asperity_soft_wall_benchmark [--scene table4|table4-long|rough] [--size N]
//                                     [--tolerance T] [--penetration D]
//                                     [--max-iterations M] [--option NAME=VALUE ...]
//                                     [SOLVER ...]
//        (--option sets a numeric option on every listed solver that has it)
//        (defaults: table4; size 1024 (table4) or 512 (rough); tolerance 1e-10 for 1D, 1e-8
//         for 2D; the five unconstrained solvers)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_common.hpp"
#include "core/error.hpp"
#include "core/transform_clock.hpp"
#include "physics/interaction.hpp"
#include "physics/potential.hpp"
#include "physics/surface_statistics.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

namespace {

struct Options {
  std::string scene = "table4";
  long size = 0;
  double tolerance = 0.0;
  double penetration = std::numeric_limits<double>::quiet_NaN();
  double max_iterations = 200000;
  std::vector<std::pair<std::string, double>> options;
  std::vector<std::string> solvers;
};

struct Run {
  std::string solver;
  bool ran = false;
  asp::SolveReport report;
  asp::History history;
  double energy = 0.0;
  double contact = 0.0;
  double bytes_per_pixel = 0.0;
  double transform_seconds = 0.0;  // in the library's transforms
};

// The energy a solve minimises in physical units under penetration control.
double total_energy(const asp::System &system) {
  return system.elastic_energy() + system.mean_mode_energy() + system.interaction_energy();
}

// The first iteration whose recorded objective is within `relative` of the reference, or -1.
long long iterations_to(const asp::History &history, double reference, double relative) {
  const int objective = static_cast<int>(asp::HistoryColumn::objective);
  const int iteration = static_cast<int>(asp::HistoryColumn::iteration);
  for (const auto &row : history)
    if ((row[objective] - reference) <= relative * std::fabs(reference))
      return static_cast<long long>(row[iteration]);
  return -1;
}

// The time of one evaluation of the system's potential over its grid, best of five.
double potential_seconds(const asp::System &system) {
  const asp::PotentialInteraction *wall = asp::potential_interaction(system.interaction());
  if (wall == nullptr) return 0.0;
  const std::int64_t n = system.grid().n_pixels();
  asp::Field gap(static_cast<std::size_t>(n)), phi(gap.size()), dphi(gap.size());
  const double range = wall->potential().length_scale();
  for (std::int64_t i = 0; i < n; ++i)
    gap[static_cast<std::size_t>(i)] = range * static_cast<double>(i % 97) / 8.0;
  double best = 1e300;
  for (int k = 0; k < 5; ++k) {
    const auto start = std::chrono::steady_clock::now();
    wall->potential().evaluate(n, gap.data(), phi.data(), dphi.data(), nullptr);
    best = std::min(best, bench::seconds_since(start));
  }
  return best;
}

void compare(asp::System &system, double penetration, const Options &o, double tolerance,
             double fft_pair) {
  std::vector<Run> runs;
  const asp::Grid &grid = system.grid();
  const std::int64_t pixels = grid.n_pixels();
  double stream = bench::field_stream_seconds(grid);
  double wall = potential_seconds(system);
  asp::transform_clock::enable(true);
  for (const std::string &name : o.solvers) {
    Run run;
    run.solver = name;
    try {
      asp::Solver solver(name);
      solver.set_option("tolerance", tolerance);
      solver.set_option("max_iterations", o.max_iterations);
      for (const auto &option : o.options) {
        try {
          solver.set_option(option.first, option.second);
        } catch (const asp::Error &) {
          // Not an option of this solver.
        }
      }
      solver.set_option("stall_window", 20000.0);
      solver.set_history(true);
      system.reset_state();
      fft_pair = std::min(fft_pair, bench::fft_pair_seconds(grid));
      stream = std::min(stream, bench::field_stream_seconds(grid));
      wall = std::min(wall, potential_seconds(system));
      const std::int64_t before = asp::field_bytes_in_use();
      asp::reset_field_bytes_peak();
      asp::transform_clock::reset();
      solver.solve(system, asp::Control::penetration, penetration);
      run.transform_seconds = asp::transform_clock::seconds();
      run.bytes_per_pixel = static_cast<double>(asp::field_bytes_peak() - before) / pixels;
      run.report = solver.report();
      run.history = solver.history();
      run.energy = total_energy(system);
      run.contact = system.contact_fraction();
      run.ran = true;
    } catch (const asp::Error &e) {
      std::printf("%-20s not run: %s\n", name.c_str(), e.what());
    }
    runs.push_back(std::move(run));
  }
  // The lowest energy any solver reached, in its final state or on its way.
  double reference = std::numeric_limits<double>::infinity();
  const int objective = static_cast<int>(asp::HistoryColumn::objective);
  for (const Run &run : runs) {
    if (!run.ran) continue;
    reference = std::min(reference, run.energy);
    for (const auto &row : run.history) reference = std::min(reference, row[objective]);
  }
  std::printf("lowest energy reached: %.15g\n", reference);
  std::printf("reference FFT pair %.4g ms, field stream %.4g ms, wall's potential %.4g ms (%.2f "
              "pairs; best of the timings before each solve)\n",
              1e3 * fft_pair, 1e3 * stream, 1e3 * wall, wall / fft_pair);
  std::printf("%-20s %7s %7s %8s %9s %8s %8s %-16s %8s %10s %8s %8s %7s %8s %8s %8s\n",
              "solver", "iters", "evals", "FFTs", "seconds", "it/pair", "ev/pair", "end",
              "contact", "dE/E", "to 1e-5", "to 1e-10", "B/px", "FFTs/it", "in solve",
              "streams");
  for (const Run &run : runs) {
    if (!run.ran) continue;
    const asp::SolveReport &r = run.report;
    const double iterations = static_cast<double>(std::max<std::int64_t>(r.iterations, 1));
    const double evaluations = static_cast<double>(std::max<std::int64_t>(r.evaluations, 1));
    const long long to5 = iterations_to(run.history, reference, 1e-5);
    const long long to10 = iterations_to(run.history, reference, 1e-10);
    const std::string at5 = to5 < 0 ? "-" : std::to_string(to5);
    const std::string at10 = to10 < 0 ? "-" : std::to_string(to10);
    const double pairs = 0.5 * static_cast<double>(r.transforms);
    const double pair_in_solve = bench::pair_in_solve(run.transform_seconds, r.transforms);
    const double rest =
        (r.seconds - run.transform_seconds - static_cast<double>(r.evaluations) * wall) /
        iterations;
    std::printf("%-20s %7lld %7lld %8lld %9.3f %8.2f %8.2f %-16s %8.4f %+10.2e %8s %8s %7.1f "
                "%8.2f %8.2f %8.1f\n",
                run.solver.c_str(), static_cast<long long>(r.iterations),
                static_cast<long long>(r.evaluations), static_cast<long long>(r.transforms),
                r.seconds, r.seconds / iterations / fft_pair, r.seconds / evaluations / fft_pair,
                asp::termination_name(r.termination), run.contact,
                run.energy / reference - 1.0, at5.c_str(), at10.c_str(), run.bytes_per_pixel,
                pairs / iterations, pair_in_solve / fft_pair, rest / stream);
  }
}

// The Table 4 potential for a surface of curvature radius rc and interaction range rho.
void set_table4_potential(asp::System &system, double rc, double rho) {
  system.set_soft_wall(2.10e3 * rc, rho, 2.05 * rc, rho);
}

void table4(const Options &o, double range_factor) {
  const long n = o.size > 0 ? o.size : 1024;
  const double period = static_cast<double>(n);
  auto grid = asp::Grid::create(1, n, 1, period, 1.0);
  asp::SelfAffineParameters params;
  params.hurst = 0.8;
  params.long_cutoff = period;
  params.rolloff = period;
  params.short_cutoff = 0.01 * period;
  params.norm = asp::RoughnessNorm::rms_slope;
  params.target = 0.1;
  params.seed = 1;
  std::vector<double> heights(static_cast<std::size_t>(n));
  asp::self_affine_topography(*grid, params, heights.data());
  const asp::SurfaceStatistics stats = asp::surface_statistics(*grid, heights.data());
  const double rc = 1.0 / stats.rms_curvature;
  const double rho = 2.56e-4 * period * range_factor;

  asp::System system(grid, 1.0);
  system.set_topography(heights.data());
  set_table4_potential(system, rc, rho);
  // The crest at the same depth inside the potential's well, g* = rho ln(2 gamma_r/gamma_a),
  // whatever the range: at a gap of -5 % of the height range with Table 4's range.
  const double well = std::log(2.0 * 2.10e3 / 2.05);
  const double penetration = std::isnan(o.penetration)
                                 ? 0.05 * system.height_range() - (range_factor - 1.0) *
                                                                      2.56e-4 * period * well
                                 : o.penetration;
  const double tolerance = o.tolerance > 0.0 ? o.tolerance : 1e-10;
  const double fft_pair = bench::fft_pair_seconds(*grid);
  const double work = 2.05 * 2.05 / (4.0 * 2.10e3) * rc;
  std::printf("thesis Table 4%s: %ld points, period %g, E* 1, H 0.8, short cutoff %g, rms "
              "slope %.3g, rms height %.4g, R_c %.4g; soft wall gamma_r %.4g, gamma_a %.4g, rho "
              "%.4g (work of adhesion %.4g, Tabor parameter %.3g); penetration %.6g; tolerance "
              "%.0e; FFT pair %.3f us\n",
              range_factor == 1.0 ? "" : " with 100x the interaction range", n, period,
              0.01 * period, stats.rms_slope, stats.rms_height, rc, 2.10e3 * rc, 2.05 * rc, rho,
              work, std::cbrt(rc * work * work / (rho * rho * rho)), penetration, tolerance,
              1e6 * fft_pair);
  compare(system, penetration, o, tolerance, fft_pair);
}

void rough(const Options &o) {
  const long n = o.size > 0 ? o.size : 512;
  const double period = static_cast<double>(n);
  auto grid = asp::Grid::create(2, n, n, period, period);
  asp::SelfAffineParameters params;
  params.hurst = 0.8;
  params.long_cutoff = period;
  params.rolloff = period;
  params.short_cutoff = 8.0;
  params.norm = asp::RoughnessNorm::rms_slope;
  params.target = 0.1;
  params.seed = 1;
  std::vector<double> heights(static_cast<std::size_t>(grid->n_pixels()));
  asp::self_affine_topography(*grid, params, heights.data());
  const asp::SurfaceStatistics stats = asp::surface_statistics(*grid, heights.data());
  const double rc = 1.0 / stats.rms_curvature;
  const double rho = 0.5;

  asp::System system(grid, 1.0);
  system.set_topography(heights.data());
  set_table4_potential(system, rc, rho);
  const double penetration =
      std::isnan(o.penetration) ? 0.05 * system.height_range() : o.penetration;
  const double tolerance = o.tolerance > 0.0 ? o.tolerance : 1e-8;
  const double fft_pair = bench::fft_pair_seconds(*grid);
  std::printf("2D adhesive rough scene: %ld^2 pixels, period %g, E* 1, H 0.8, short cutoff 8, "
              "rms slope %.3g, R_c %.4g; soft wall gamma_r %.4g, gamma_a %.4g, rho %g; "
              "penetration %.6g; tolerance %.0e; FFT pair %.3f ms\n",
              n, period, stats.rms_slope, rc, 2.10e3 * rc, 2.05 * rc, rho, penetration,
              tolerance, 1e3 * fft_pair);
  compare(system, penetration, o, tolerance, fft_pair);
}

int usage(const char *program) {
  std::fprintf(stderr,
               "usage: %s [--scene table4|table4-long|rough] [--size N] [--tolerance T] "
               "[--max-iterations M] [--option NAME=VALUE] "
               "[--penetration D] [SOLVER ...]\n",
               program);
  return 2;
}

}  // namespace

int main(int argc, char **argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--scene" && has_value) {
      o.scene = argv[++i];
      if (o.scene != "table4" && o.scene != "table4-long" && o.scene != "rough")
        return usage(argv[0]);
    } else if (arg == "--size" && has_value) {
      o.size = std::strtol(argv[++i], nullptr, 10);
      if (o.size < 8 || o.size > 16384) return usage(argv[0]);
    } else if (arg == "--option" && has_value) {
      const std::string option = argv[++i];
      const std::size_t equals = option.find('=');
      if (equals == std::string::npos) return usage(argv[0]);
      o.options.emplace_back(option.substr(0, equals),
                             std::strtod(option.c_str() + equals + 1, nullptr));
    } else if (arg == "--max-iterations" && has_value) {
      o.max_iterations = std::strtod(argv[++i], nullptr);
      if (!(o.max_iterations >= 1)) return usage(argv[0]);
    } else if (arg == "--tolerance" && has_value) {
      o.tolerance = std::strtod(argv[++i], nullptr);
      if (!(o.tolerance > 0.0)) return usage(argv[0]);
    } else if (arg == "--penetration" && has_value) {
      o.penetration = std::strtod(argv[++i], nullptr);
      if (!std::isfinite(o.penetration)) return usage(argv[0]);
    } else if (!arg.empty() && arg[0] != '-') {
      o.solvers.push_back(arg);
    } else {
      return usage(argv[0]);
    }
  }
  if (o.solvers.empty())
    o.solvers = {"lbfgs", "lbfgs_fourier", "gfmd", "fire", "fire_mass_weighted"};
  try {
    if (o.scene == "rough")
      rough(o);
    else
      table4(o, o.scene == "table4" ? 1.0 : 100.0);
  } catch (const asp::Error &e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
