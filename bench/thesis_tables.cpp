// The thesis's comparison of the constrained solvers (not a test): its Table 2 scene at about
// 10 % and above 90 % contact (thesis Figs. 15 and 19).
//
// Table 2: 1024^2 pixels on a unit box, E* = 1, a self-affine surface with H = 0.8, long
// cutoff 0.5, short cutoff 0.2, rms slope 1. For each contact case a reference solve under load
// control (tolerance 1e-10) gives the penetration; every solver then starts cold and solves
// under penetration control at that penetration, so that solvers offering only that control
// (lbfgsb) run the same problem. Printed per solver: iterations, objective evaluations, FFTs,
// seconds, time per iteration and per evaluation in FFT pairs (the pair timed in the same run
// with the grid's plans), the final error and how the solve ended, the contact fraction, the
// relative difference of the elastic energy from the reference, and the solver's memory per
// pixel (the peak of the fields it allocates; the system's own fields are listed once).
//
// usage: asperity_thesis_tables [--size N] [--case low|high|both] [--tolerance T]
//                               [SOLVER[:VARIABLE] ...]
//        (default: 1024, both cases, tolerance 1e-8, pk bugnicourt:pressure bugnicourt:gap
//         lbfgsb:pressure lbfgsb:gap; a solver this build lacks is reported and skipped)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "core/error.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

namespace {

struct Request {
  std::string algorithm;
  std::string variable;  // empty: the algorithm has no such option
  std::string label() const { return variable.empty() ? algorithm : algorithm + ":" + variable; }
};

struct ContactCase {
  const char *name;
  double mean_pressure;  // chosen for the contact fraction in the name (printed)
};

double total_elastic_energy(const asp::System &system) {
  return system.elastic_energy() + system.mean_mode_energy();
}

bool configure(asp::Solver &solver, const Request &request, double tolerance) {
  solver.set_option("tolerance", tolerance);
  solver.set_option("max_iterations", 100000.0);
  solver.set_option("stall_window", 5000.0);
  if (!request.variable.empty()) solver.set_option("variable", request.variable);
  return true;
}

void run_case(asp::System &system, const ContactCase &c, const std::vector<Request> &requests,
              double tolerance, double fft_pair) {
  const std::int64_t pixels = system.grid().n_pixels();

  // The reference: load control, tight tolerance, with the solver that converges there.
  asp::Solver reference("pk");
  reference.set_option("tolerance", 1e-10);
  reference.set_option("max_iterations", 100000.0);
  system.reset_state();
  reference.solve(system, asp::Control::mean_pressure, c.mean_pressure);
  const double penetration = system.state().penetration;
  const double energy = total_elastic_energy(system);
  std::printf("\n%s contact: mean pressure %g -> penetration %.10g, contact fraction %.4f "
              "(reference: pk, load control, tolerance 1e-10, %s after "
              "%lld iterations)\n",
              c.name, c.mean_pressure, penetration, system.contact_fraction(),
              asp::termination_name(reference.report().termination),
              static_cast<long long>(reference.report().iterations));
  std::printf("%-20s %7s %7s %8s %9s %8s %8s %9s %-16s %8s %10s %7s\n", "solver", "iters",
              "evals", "FFTs", "seconds", "it/pair", "ev/pair", "error", "end", "contact",
              "dE/E", "B/px");
  for (const Request &request : requests) {
    std::unique_ptr<asp::Solver> solver;
    try {
      solver = std::make_unique<asp::Solver>(request.algorithm);
      configure(*solver, request, tolerance);
    } catch (const asp::Error &e) {
      std::printf("%-20s not available: %s\n", request.label().c_str(), e.what());
      continue;
    }
    system.reset_state();
    const std::int64_t before = asp::field_bytes_in_use();
    asp::reset_field_bytes_peak();
    try {
      solver->solve(system, asp::Control::penetration, penetration);
    } catch (const asp::Error &e) {
      std::printf("%-20s refused: %s\n", request.label().c_str(), e.what());
      continue;
    }
    const double bytes = static_cast<double>(asp::field_bytes_peak() - before) / pixels;
    const asp::SolveReport &r = solver->report();
    const double iterations = static_cast<double>(std::max<std::int64_t>(r.iterations, 1));
    const double evaluations = static_cast<double>(std::max<std::int64_t>(r.evaluations, 1));
    std::printf("%-20s %7lld %7lld %8lld %9.2f %8.2f %8.2f %9.2e %-16s %8.4f %+10.2e %7.1f\n",
                request.label().c_str(), static_cast<long long>(r.iterations),
                static_cast<long long>(r.evaluations), static_cast<long long>(r.transforms),
                r.seconds, r.seconds / iterations / fft_pair, r.seconds / evaluations / fft_pair,
                r.error, asp::termination_name(r.termination), system.contact_fraction(),
                total_elastic_energy(system) / energy - 1.0, bytes);
    std::fflush(stdout);
  }
}

int usage(const char *program) {
  std::fprintf(stderr,
               "usage: %s [--size N] [--case low|high|both] [--tolerance T] "
               "[SOLVER[:VARIABLE] ...]\n",
               program);
  return 2;
}

}  // namespace

int main(int argc, char **argv) {
  long size = 1024;
  std::string which = "both";
  double tolerance = 1e-8;
  std::vector<Request> requests;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--size" && i + 1 < argc) {
      size = std::strtol(argv[++i], nullptr, 10);
      if (size < 8 || size > 16384) return usage(argv[0]);
    } else if (arg == "--case" && i + 1 < argc) {
      which = argv[++i];
      if (which != "low" && which != "high" && which != "both") return usage(argv[0]);
    } else if (arg == "--tolerance" && i + 1 < argc) {
      tolerance = std::strtod(argv[++i], nullptr);
      if (!(tolerance > 0.0)) return usage(argv[0]);
    } else if (!arg.empty() && arg[0] != '-') {
      const auto colon = arg.find(':');
      requests.push_back(colon == std::string::npos
                             ? Request{arg, ""}
                             : Request{arg.substr(0, colon), arg.substr(colon + 1)});
    } else {
      return usage(argv[0]);
    }
  }
  if (requests.empty())
    requests = {{"pk", ""},
                {"bugnicourt", "pressure"},
                {"bugnicourt", "gap"},
                {"lbfgsb", "pressure"},
                {"lbfgsb", "gap"}};

  auto grid = asp::Grid::create(2, size, size, 1.0, 1.0);
  asp::SelfAffineParameters params;
  params.hurst = 0.8;
  params.long_cutoff = 0.5;
  params.rolloff = 0.5;
  params.short_cutoff = 0.2;
  params.norm = asp::RoughnessNorm::rms_slope;
  params.target = 1.0;
  params.seed = 1;
  std::vector<double> heights(static_cast<std::size_t>(grid->n_pixels()));
  asp::self_affine_topography(*grid, params, heights.data());

  const std::int64_t empty = asp::field_bytes_in_use();
  asp::System system(grid, 1.0);
  system.set_topography(heights.data());
  const double system_bytes =
      static_cast<double>(asp::field_bytes_in_use() - empty) / grid->n_pixels();
  const double fft_pair = bench::fft_pair_seconds(*grid);
  std::printf("thesis Table 2: %ld^2 pixels, unit box, E* 1, H 0.8, cutoffs 0.5 and 0.2, rms "
              "slope 1, seed 1; tolerance %.0e; FFT pair %.3f ms; the system holds %.1f "
              "B/pixel\n",
              size, tolerance, 1e3 * fft_pair, system_bytes);

  const ContactCase cases[] = {{"low (about 10 %)", 0.05}, {"high (above 90 %)", 0.8}};
  for (const ContactCase &c : cases) {
    const bool low = &c == &cases[0];
    if (which == "both" || (which == "low") == low) run_case(system, c, requests, tolerance, fft_pair);
  }
  return 0;
}
