// SPDX-License-Identifier: GPL-2.0-or-later
// Iterations against the grid (not a test): Polonsky-Keer with each value of its
// `preconditioner` option on the scene of asperity_pk_benchmark (periodic half-space, E* 1,
// self-affine surface with H 0.8, roll-off at L/4, short cutoff 8 pixels, rms slope 0.1, mean
// pressure 0.002), to the tolerance 1e-8, one cold solve per size and option value.
//
// For each size and option value it prints the iterations, the transforms, the seconds of
// the solve, the growth of the iterations from the size before (per doubling of N when the
// sizes double), the contact fraction, and the largest difference of the pressure from that
// of the first option value, over the largest pressure (both solves meet the same tolerance,
// so they differ by about that much). The grid is planned with FFTW_ESTIMATE, so that the
// planner's timing does not add noise to the seconds; they are rough on a busy machine, the
// iterations are not.
//
// usage: asperity_iteration_scaling [--free] [N ...]   (default: 512 1024 2048)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

int main(int argc, char **argv) {
  bool free = false;
  std::vector<long> sizes;
  for (int i = 1; i < argc; ++i) {
    char *end = nullptr;
    const long n = std::strtol(argv[i], &end, 10);
    if (std::strcmp(argv[i], "--free") == 0) {
      free = true;
    } else if (end != argv[i] && *end == '\0' && n >= 2 && n <= 16384) {
      sizes.push_back(n);
    } else {
      std::fprintf(stderr, "usage: %s [--free] [N ...]  (grid sizes 2 to 16384)\n", argv[0]);
      return 2;
    }
  }
  if (sizes.empty()) sizes = {512, 1024, 2048};

  const double tolerance = 1e-8, modulus = 1.0, slope = 0.1, mean_pressure = 0.002;
  const std::vector<std::string> values = {"none", "fourier"};
  std::printf("pk on the %s, self-affine surface (H 0.8, roll-off L/4, short cutoff 8 px, "
              "rms slope %.2g), E* %.1f, mean pressure %.3g, tolerance %.0e\n",
              free ? "free half-space" : "periodic half-space", slope, modulus, mean_pressure,
              tolerance);
  std::printf("%6s %15s %7s %10s %9s %8s %9s %12s\n", "N", "preconditioner", "iters",
              "transforms", "seconds", "growth", "contact", "dp/max p");
  std::vector<long> previous(values.size(), 0);
  for (long n : sizes) {
    auto grid = asp::Grid::create(2, n, n, 1.0, 1.0);
    grid->set_fft_planning(asp::FftPlanning::estimate);
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
    asp::System system(grid, modulus,
                       free ? asp::SubstrateKind::free : asp::SubstrateKind::periodic);
    system.set_topography(heights.data());

    std::vector<double> first;
    for (std::size_t v = 0; v < values.size(); ++v) {
      asp::Solver solver("pk");
      solver.set_option("tolerance", tolerance);
      solver.set_option("preconditioner", values[v]);
      system.reset_state();
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
      const long iterations = static_cast<long>(r.iterations);
      char growth[32] = "";
      if (previous[v] > 0)
        std::snprintf(growth, sizeof growth, "%.2f",
                      static_cast<double>(iterations) / static_cast<double>(previous[v]));
      previous[v] = iterations;
      std::printf("%6ld %15s %7ld %10lld %9.2f %8s %9.4f %12.1e%s\n", n, values[v].c_str(),
                  iterations, static_cast<long long>(r.transforms), r.seconds, growth,
                  system.contact_fraction(), v == 0 ? 0.0 : difference / largest,
                  r.converged() ? "" : "  (not converged)");
      std::fflush(stdout);
    }
  }
  return 0;
}
