// SPDX-License-Identifier: GPL-2.0-or-later
// Iterations against the grid (not a test).
//
// By default: Polonsky-Keer as published (preconditioner none, restart entry), then with each
// value of its `preconditioner` option and its default restart rule, on the scene of
// asperity_pk_benchmark (periodic half-space, E* 1, self-affine surface with H 0.8, roll-off
// at L/4, short cutoff 8 pixels, rms slope 0.1, mean pressure 0.002), to the tolerance 1e-8.
// With --challenge: `bugnicourt` (or the --algorithm given) on the gap on the
// contact-mechanics challenge's scene
// (asperity_challenge: a 100 um box, H 0.8, roll-off 20 um, short cutoff 0.1 um, rms slope 1,
// one surface at every size, challenge_scene.hpp; E* 25 MPa, exponential adhesion
// w 50 mJ/m^2, rho 2.071 nm) under penetration control at
// 1.5 um, to the tolerance 1e-6. With --levels L (an integer or "auto") each of those solves
// is also run with nested grids (the option "levels" = L). One cold solve per size and row.
//
// For each size and row it prints the iterations (on the grid itself), the transforms (of
// every level, a coarse one's weighted by its share of the pixels: the report's count), the
// seconds of the solve, the growth of the iterations from the size before (per doubling of
// N when the sizes double), the contact fraction, the energy (elastic + interaction, the
// q = 0 term included: what the solve minimises, at the same penetration), and the largest
// difference of the pressure from that of the first row, over the largest pressure (all
// meet the same tolerance, so they differ by about that much, unless they found different
// states). The grid is planned with FFTW_ESTIMATE, so that the planner's timing does not add
// noise to the seconds; they are rough on a busy machine, the iterations are not.
//
// With --preconditioner P only the rows of that value are run (on the challenge's scene,
// which otherwise runs the algorithm's default, too). With --algorithm NAME the
// bench scene is solved by that solver instead of pk (its rows then try each value of
// `preconditioner` where it has the option), and each --option K=V is set on every solve,
// after the row's own options.
//
// usage: asperity_iteration_scaling [--free] [--challenge] [--levels L] [--preconditioner P]
//                                   [--algorithm NAME] [--option K=V ...] [N ...]
//        (default sizes: 512 1024 2048; with --challenge 1024)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/challenge_scene.hpp"
#include "core/grid.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/registry.hpp"
#include "solvers/solver.hpp"

namespace {

struct Row {
  std::string preconditioner;  // empty where the algorithm has no such option
  std::string levels;          // "0", a count or "auto"
  std::string restart;         // pk's restart rule; empty: the default
};

bool has_option(const asp::AlgorithmSpec &spec, const std::string &name) {
  for (const auto &option : spec.options)
    if (option.name == name) return true;
  return false;
}

}  // namespace

int main(int argc, char **argv) {
  bool free = false, challenge = false;
  std::string levels, algorithm, only;
  std::vector<std::pair<std::string, std::string>> options;
  std::vector<long> sizes;
  for (int i = 1; i < argc; ++i) {
    char *end = nullptr;
    const long n = std::strtol(argv[i], &end, 10);
    if (std::strcmp(argv[i], "--free") == 0) {
      free = true;
    } else if (std::strcmp(argv[i], "--challenge") == 0) {
      challenge = true;
    } else if (std::strcmp(argv[i], "--levels") == 0 && i + 1 < argc) {
      levels = argv[++i];
    } else if (std::strcmp(argv[i], "--preconditioner") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else if (std::strcmp(argv[i], "--algorithm") == 0 && i + 1 < argc) {
      algorithm = argv[++i];
    } else if (std::strcmp(argv[i], "--option") == 0 && i + 1 < argc &&
               std::strchr(argv[i + 1], '=') != nullptr) {
      const std::string word = argv[++i];
      const std::size_t equals = word.find('=');
      options.emplace_back(word.substr(0, equals), word.substr(equals + 1));
    } else if (end != argv[i] && *end == '\0' && n >= 2 && n <= 16384) {
      sizes.push_back(n);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--free] [--challenge] [--levels L] [--preconditioner P] "
                   "[--algorithm NAME] [--option K=V ...] [N ...]  (grid sizes 2 to 16384, "
                   "L a count or auto)\n",
                   argv[0]);
      return 2;
    }
  }
  if (sizes.empty())
    sizes = challenge ? std::vector<long>{1024} : std::vector<long>{512, 1024, 2048};

  if (algorithm.empty()) algorithm = challenge ? "bugnicourt" : "pk";
  // The challenge's solves are long: there only the preconditioner asked for, if any, has
  // rows of its own (otherwise the algorithm's default).
  const bool preconditioned = has_option(asp::find_algorithm(algorithm), "preconditioner") &&
                              (!challenge || !only.empty());
  std::vector<Row> rows;
  // pk as published first: no preconditioner, Polonsky & Keer's restart, no levels.
  if (!challenge && has_option(asp::find_algorithm(algorithm), "restart") &&
      (only.empty() || only == "none"))
    rows.push_back({"none", "0", "entry"});
  for (const char *p : {"none", "fourier"}) {
    if (!preconditioned && std::strcmp(p, "none") != 0) continue;
    if (preconditioned && !only.empty() && only != p) continue;
    rows.push_back({preconditioned ? p : "", "0", ""});
    if (!levels.empty()) rows.push_back({preconditioned ? p : "", levels, ""});
  }

  const double box = challenge ? bench::challenge_box : 1.0, modulus = challenge ? 25e6 : 1.0;
  const double slope = 0.1, mean_pressure = 0.002, penetration = 1.5e-6;
  const double tolerance = challenge ? 1e-6 : 1e-8;
  if (challenge)
    std::printf("%s (gap) on the challenge's scene, %s, penetration %.3g m, "
                "tolerance %.0e\n",
                algorithm.c_str(), free ? "free half-space" : "periodic half-space",
                penetration, tolerance);
  else
    std::printf("%s on the %s, self-affine surface (H 0.8, roll-off L/4, short cutoff 8 px, "
                "rms slope %.2g), E* %.1f, mean pressure %.3g, tolerance %.0e\n",
                algorithm.c_str(), free ? "free half-space" : "periodic half-space", slope, modulus,
                mean_pressure, tolerance);
  std::printf("%6s %15s %6s %8s %7s %10s %9s %8s %9s %14s %12s\n", "N", "preconditioner",
              "levels", "restart", "iters", "transforms", "seconds", "growth", "contact", "energy",
              "dp/max p");
  std::vector<long> previous(rows.size(), 0);
  for (long n : sizes) {
    auto grid = asp::Grid::create(2, n, n, box, box);
    grid->set_fft_planning(asp::FftPlanning::estimate);
    std::vector<double> heights(static_cast<std::size_t>(grid->n_pixels()));
    if (challenge) {
      bench::challenge_heights(*grid, heights.data());
    } else {
      asp::SelfAffineParameters params;
      params.hurst = 0.8;
      params.long_cutoff = box;
      params.rolloff = 0.25;
      params.short_cutoff = 8.0 / n;
      params.norm = asp::RoughnessNorm::rms_slope;
      params.target = slope;
      params.seed = 1;
      asp::self_affine_topography(*grid, params, heights.data());
    }
    asp::System system(grid, modulus,
                       free ? asp::SubstrateKind::free : asp::SubstrateKind::periodic);
    system.set_topography(heights.data());
    if (challenge) system.set_adhesion(0.05, 2.071e-9);

    std::vector<double> first;
    for (std::size_t v = 0; v < rows.size(); ++v) {
      asp::Solver solver(algorithm);
      solver.set_option("tolerance", tolerance);
      if (challenge) {
        if (has_option(solver.algorithm(), "variable"))
          solver.set_option("variable", std::string("gap"));
        solver.set_option("max_iterations", 1e5);
      }
      if (preconditioned) solver.set_option("preconditioner", rows[v].preconditioner);
      bench::set_option(solver, "levels", rows[v].levels);
      if (!rows[v].restart.empty()) solver.set_option("restart", rows[v].restart);
      for (const auto &option : options)
        bench::set_option(solver, option.first, option.second);
      system.reset_state();
      if (challenge)
        solver.solve(system, asp::Control::penetration, penetration);
      else
        solver.solve(system, asp::Control::mean_pressure, mean_pressure);
      const asp::SolveReport &r = solver.report();
      const asp::Field &p = system.state().pressure;
      double difference = 0.0, largest = 0.0;
      if (v == 0) {
        first.assign(p.data(), p.data() + p.size());
      } else {
        for (std::size_t i = 0; i < first.size(); ++i) {
          difference = std::max(difference, std::fabs(p[i] - first[i]));
          largest = std::max(largest, std::fabs(first[i]));
        }
      }
      const double energy =
          system.elastic_energy() + system.mean_mode_energy() + system.interaction_energy();
      const long iterations = static_cast<long>(r.iterations);
      char growth[32] = "";
      if (previous[v] > 0)
        std::snprintf(growth, sizeof growth, "%.2f",
                      static_cast<double>(iterations) / static_cast<double>(previous[v]));
      previous[v] = iterations;
      std::printf("%6ld %15s %6s %8s %7ld %10lld %9.2f %8s %9.4f %14.8e %12.1e%s\n", n,
                  rows[v].preconditioner.empty() ? "-" : rows[v].preconditioner.c_str(),
                  rows[v].levels.c_str(),
                  rows[v].restart.empty() ? "-" : rows[v].restart.c_str(),
                  iterations, static_cast<long long>(r.transforms), r.seconds, growth,
                  system.contact_fraction(), energy, v == 0 ? 0.0 : difference / largest,
                  r.converged() ? "" : "  (not converged)");
      std::fflush(stdout);
    }
  }
  return 0;
}
