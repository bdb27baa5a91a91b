// SPDX-License-Identifier: GPL-2.0-or-later
// Benchmark of a solver (Polonsky-Keer by default) on 2D rough scenes (not a test), on the
// periodic half-space or, with --free, on the free one (whose transforms are of the grid
// zero-padded to 2N x 2N).
//
// For each grid it prints the FFTW_MEASURE planning time of the substrate's r2c/c2r pair (the
// padded one with --free), the time of one r2c + c2r pair with those plans (the best of
// timings made before each solve, as the solves' time is the best of several), the solver's time
// per iteration with the library's default planning (or FFTW_ESTIMATE with --estimate), their
// ratio, the iterations to the tolerance, the memory per pixel of the box that the system and
// the solve hold, and the cost of recording the history (best solve with history on against
// best with it off, in per cent). It also prints the objective evaluations of a solve, the
// time per evaluation and its ratio to the FFT pair. Last, where the iteration's time goes:
// `in FFTs`, its transforms in FFT pairs (the solver's count of transforms per iteration,
// halved); `in solve`, what a pair cost inside the solve, in reference pairs (the library's
// transforms timed where they run, core/transform_clock.hpp: inside a solve they start from
// memory, and the machine's speed moves between the reference's timing and the solve's);
// `stream`, the time to stream one field of the grid (8 bytes per pixel read or written,
// bench::field_stream_seconds) in reference pairs; and `streams`, the rest of the iteration's
// time (less its transforms at their price in the solve) in such streams: what its
// element-wise passes cost, in the fields they read and write. An iteration's floor is its
// transforms at their price in the solve plus the fields its passes must touch at the
// stream's price. For lbfgsb it also prints `gather`: one gather of the rows of its stored
// pairs at the unknowns it lists (the contact's pixels), timed as the library does it, in
// streams; that read is part of its floor.
//
// With --penetration the solver runs under penetration control, at the penetration of pk's
// solution at the benchmark's mean pressure (so the contact fraction is the same); without
// it, under load control. --option NAME=VALUE sets an option of the solver (a number, or
// else a string), and may be repeated.
//
// usage: asperity_pk_benchmark [--estimate] [--free] [--algorithm NAME] [--penetration]
//                              [--option NAME=VALUE ...] [N ...]
//        (default: pk on sizes 512 1024 2048)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/lbfgsb_floor.hpp"
#include "core/aligned_field.hpp"
#include "core/grid.hpp"
#include "core/transform_clock.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

using bench::fft_pair_seconds;
using bench::seconds_since;

namespace {

// What lbfgsb must read beyond its field streams: the rows of W (its 2m stored columns) at the
// unknowns it lists, those in contact (or out of it, if fewer). The Cauchy point's sums over
// the free unknowns and the subspace step need them; they are the contact's pixels, a few
// per cent of the grid in patches, whose gaps the prefetchers do not follow. Timed here as
// the library gathers them (each listed unknown's row read at once, the rows eight entries
// ahead fetched), on fields of the grid's size, the best of five: seconds per gather.
double row_gather_seconds(const std::vector<double> &pressure, int columns) {
  const auto n = static_cast<std::int64_t>(pressure.size());
  std::int64_t in_contact = 0;
  for (double p : pressure) in_contact += p > 0.0 ? 1 : 0;
  const bool contact_listed = in_contact <= n / 2;
  std::vector<std::int64_t> list;
  for (std::int64_t i = 0; i < n; ++i)
    if ((pressure[static_cast<std::size_t>(i)] > 0.0) == contact_listed) list.push_back(i);
  std::vector<asp::Field> w(static_cast<std::size_t>(columns),
                            asp::Field(static_cast<std::size_t>(n), 1.0));
  std::vector<const double *> column;
  for (const asp::Field &f : w) column.push_back(f.data());
  double best = 1e300, total = 0.0;
  constexpr std::size_t ahead = 8;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t p = 0; p < list.size(); ++p) {
      if (p + ahead < list.size())
        for (const double *c : column) __builtin_prefetch(c + list[p + ahead]);
      double row = 0.0;
      for (const double *c : column) row += c[list[p]];
      total += row;
    }
    best = std::min(best, seconds_since(start));
  }
  if (total < 0.0) std::printf(" ");  // keeps the sums from being optimised away
  return best;
}

}  // namespace

int main(int argc, char **argv) {
  bool estimate = false, free = false, penetration_control = false;
  std::string algorithm = "pk";
  std::vector<std::pair<std::string, std::string>> options;
  std::vector<long> sizes;
  for (int i = 1; i < argc; ++i) {
    char *end = nullptr;
    const long n = std::strtol(argv[i], &end, 10);
    if (std::strcmp(argv[i], "--estimate") == 0) {
      estimate = true;
    } else if (std::strcmp(argv[i], "--free") == 0) {
      free = true;
    } else if (std::strcmp(argv[i], "--algorithm") == 0 && i + 1 < argc) {
      algorithm = argv[++i];
    } else if (std::strcmp(argv[i], "--penetration") == 0) {
      penetration_control = true;
    } else if (std::strcmp(argv[i], "--option") == 0 && i + 1 < argc &&
               std::strchr(argv[i + 1], '=') != nullptr) {
      const std::string option = argv[++i];
      const std::size_t equals = option.find('=');
      options.emplace_back(option.substr(0, equals), option.substr(equals + 1));
    } else if (end != argv[i] && *end == '\0' && n >= 2 && n <= 16384) {
      sizes.push_back(n);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--estimate] [--free] [--algorithm NAME] [--penetration] "
                   "[--option NAME=VALUE ...] [N ...]  (grid sizes 2 to 16384)\n",
                   argv[0]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {512, 1024, 2048};

  const double tolerance = 1e-8, modulus = 1.0, slope = 0.1, mean_pressure = 0.002;
  std::string settings;
  for (const auto &o : options) settings += " " + o.first + "=" + o.second;
  std::printf("%s%s on the %s, self-affine surface (H 0.8, roll-off L/4, short cutoff "
              "8 px, rms slope %.2g), E* %.1f, %s %.3g, tolerance %.0e; solver "
              "plans: FFTW %s; reference pair: FFTW MEASURE%s\n",
              algorithm.c_str(), settings.c_str(),
              free ? "free half-space" : "periodic half-space", slope, modulus,
              penetration_control ? "penetration of pk's solution at mean pressure"
                                  : "mean pressure",
              mean_pressure, tolerance, estimate ? "ESTIMATE" : "MEASURE",
              free ? ", of the padded 2N x 2N grid" : "");
  std::printf("%6s %10s %12s %12s %7s %6s %6s %9s %7s %9s %9s %8s %9s %8s %8s %8s %8s%s\n",
              "N", "plan s", "FFT pair ms", "iter ms", "ratio", "iters", "evals", "eval ms",
              "ratio", "solve s", "contact", "B/pixel", "history", "in FFTs", "in solve",
              "stream", "streams", algorithm == "lbfgsb" ? "   gather" : "");
  for (long n : sizes) {
    // The reference: a pair planned with FFTW_MEASURE, and how long that planning took. With
    // the default planning it is the solver's own grid, so that both time the same plans
    // (MEASURE picks among candidates by timing them, and may pick differently each time).
    auto grid = asp::Grid::create(2, n, n, 1.0, 1.0);
    auto reference = grid;
    if (estimate) {
      grid->set_fft_planning(asp::FftPlanning::estimate);
      reference = asp::Grid::create(2, n, n, 1.0, 1.0);
    }
    const std::int64_t transform_n = free ? 2 * n : n;
    const auto plan_start = std::chrono::steady_clock::now();
    reference->real_fft(transform_n, transform_n);
    const double planning = seconds_since(plan_start);
    // The reference pair and the stream are timed again before every solve below, and the
    // best of all those timings taken, as for the solves: on a shared machine one timing of
    // the same 2048^2 pair can take half as long again as the next (53 to 81 ms within
    // seconds), and a reference timed once would move the ratios by as much.
    double fft = fft_pair_seconds(*reference, transform_n, transform_n);
    double stream = bench::field_stream_seconds(*grid);

    asp::SelfAffineParameters params;
    params.hurst = 0.8;
    params.long_cutoff = 1.0;
    params.rolloff = 0.25;
    params.short_cutoff = 8.0 / n;
    params.norm = asp::RoughnessNorm::rms_slope;
    params.target = slope;
    params.seed = 1;
    std::vector<double> heights(static_cast<std::size_t>(grid->n_pixels()));
    asp::self_affine_topography(*grid, params, heights.data());

    const std::int64_t before = asp::field_bytes_in_use();
    asp::System system(grid, modulus,
                       free ? asp::SubstrateKind::free : asp::SubstrateKind::periodic);
    system.set_topography(heights.data());
    // The peak is taken from here, after the transient copies that the surface statistics
    // make when the topography is set and the scratch fields of the free substrate's plans;
    // the system's own fields are in use and count.
    if (free) grid->padded_fft();
    asp::reset_field_bytes_peak();
    asp::Control control = asp::Control::mean_pressure;
    double value = mean_pressure;
    if (penetration_control) {
      asp::Solver pk("pk");
      pk.set_option("tolerance", 1e-10);
      pk.solve(system, asp::Control::mean_pressure, mean_pressure);
      control = asp::Control::penetration;
      value = system.state().penetration;
      asp::reset_field_bytes_peak();
    }
    asp::Solver solver(algorithm);
    solver.set_option("tolerance", tolerance);
    // An iteration's cost is measured on the grid itself: no nested grids unless asked for.
    solver.set_option("levels", 0.0);
    for (const auto &o : options) bench::set_option(solver, o.first, o.second);
    // Best of several cold solves, with the history off and on alternately: the machine's
    // noise only ever adds time.
    const int runs = n <= 1024 ? 14 : 6;
    asp::SolveReport r, with_history;
    double evaluations = 0.0;
    std::int64_t peak = 0;
    double transform_seconds = 0.0;  // in the transforms of the best solve without history
    asp::transform_clock::enable(true);
    for (int run = 0; run < runs; ++run) {
      const bool recording = run % 2 == 1;
      solver.set_history(recording);
      system.reset_state();
      fft = std::min(fft, fft_pair_seconds(*reference, transform_n, transform_n));
      stream = std::min(stream, bench::field_stream_seconds(*grid));
      // The memory of the solve alone: the timings' scratch fields are gone by now.
      asp::reset_field_bytes_peak();
      asp::transform_clock::reset();
      solver.solve(system, control, value);
      peak = std::max(peak, asp::field_bytes_peak());
      asp::SolveReport &best = recording ? with_history : r;
      if (run < 2 || solver.report().seconds < best.seconds) {
        best = solver.report();
        if (!recording) transform_seconds = asp::transform_clock::seconds();
      }
      evaluations = static_cast<double>(solver.report().evaluations);
    }
    const double bytes_per_pixel = static_cast<double>(peak - before) / grid->n_pixels();
    const double history_cost = 100.0 * (with_history.seconds / r.seconds - 1.0);
    const double per_iteration = r.seconds / std::max<std::int64_t>(r.iterations, 1);
    const double per_evaluation = r.seconds / std::max(evaluations, 1.0);
    // The iteration split: its transforms in pairs (from the solver's own count), and the rest
    // of its time in field streams, the element-wise passes' currency.
    const double in_transforms = 0.5 * static_cast<double>(r.transforms) /
                                 static_cast<double>(std::max<std::int64_t>(r.iterations, 1));
    const double pair_in_solve = bench::pair_in_solve(transform_seconds, r.transforms);
    const double rest_in_streams = (per_iteration - in_transforms * pair_in_solve) / stream;
    // lbfgsb's gather of W's rows at the listed unknowns, in streams (`gather`): its floor
    // counts it once per iteration, as the library needs it (the step reads the rows that the
    // Cauchy point kept).
    std::string gather, passes;
    if (algorithm == "lbfgsb") {
      const int memory = static_cast<int>(solver.option("memory"));
      const std::vector<double> pressure(system.state().pressure.begin(),
                                         system.state().pressure.end());
      const std::vector<double> gap(system.state().gap.begin(), system.state().gap.end());
      const double gather_streams = row_gather_seconds(pressure, 2 * memory) / stream;
      char text[32];
      std::snprintf(text, sizeof text, " %8.1f", gather_streams);
      gather = text;
      // The floor measured pass by pass (lbfgsb_floor.hpp): the Cauchy point, the step and
      // the products once per iteration, the trial point, the slope and the gradient once
      // per evaluation.
      const bench::LbfgsbFloor least = bench::lbfgsb_floor_seconds(pressure, gap, memory);
      const double per_iteration_evaluations =
          evaluations / static_cast<double>(std::max<std::int64_t>(r.iterations, 1));
      const double passes_streams =
          (least.products + least.cauchy + least.step +
           per_iteration_evaluations * (least.trial + least.slope + least.gradient)) /
          stream;
      const double measured_floor =
          in_transforms * pair_in_solve / fft + (passes_streams + gather_streams) * stream / fft;
      char line[512];
      std::snprintf(line, sizeof line,
                    "\n       lbfgsb's passes at their least, in streams: products %.1f, "
                    "cauchy %.1f, step %.1f, trial %.1f, slope %.1f, gradient %.1f "
                    "(%.2f evaluations per iteration); with the gather %.1f: floor %.2f "
                    "pairs, iteration / floor %.2f",
                    least.products / stream, least.cauchy / stream, least.step / stream,
                    least.trial / stream, least.slope / stream, least.gradient / stream,
                    per_iteration_evaluations, passes_streams + gather_streams, measured_floor,
                    per_iteration / fft / measured_floor);
      passes = line;
    }
    std::printf("%6ld %10.2f %12.3f %12.3f %7.2f %6lld %6.0f %9.3f %7.2f %9.2f %9.4f %8.1f "
                "%+8.1f%% %8.2f %8.2f %8.3f %8.1f%s%s\n",
                n, planning, 1e3 * fft, 1e3 * per_iteration, per_iteration / fft,
                static_cast<long long>(r.iterations), evaluations, 1e3 * per_evaluation,
                per_evaluation / fft, r.seconds, system.contact_fraction(), bytes_per_pixel,
                history_cost, in_transforms, pair_in_solve / fft, stream / fft, rest_in_streams,
                gather.c_str(), r.converged() ? "" : "  (not converged)");
    if (!passes.empty()) std::printf("%s\n", passes.c_str());
    std::fflush(stdout);
  }
  return 0;
}
