// SPDX-License-Identifier: GPL-2.0-or-later
// The extreme-scene matrix: every solver of the build on scenes at the edges of what the
// library accepts (tiny and huge interaction ranges, weak and strong adhesion, contact near
// 0 % and above 99 %, moduli and boxes far from 1, odd, prime and strip grids, flat surfaces,
// zero load, tensile load beyond pull-off, warm starts from every other step of a sweep),
// through the public C interface only.
//
// Each cell (scene x solver) must end in one of these ways, and the program fails otherwise:
//   - refused, when the documented rules say the solver does not serve the scene (and only
//     then), with asp_solver_supports and asp_solver_solve agreeing and the state unchanged;
//   - converged, within max_iterations, on a finite state that meets its constraints and
//     its control and passes the scene's oracle (a closed form, the same scene in other
//     units, or the other solvers' result where the solution is unique);
//   - not converged, only where listed in kExpectedUnconverged (or where the scene has no
//     equilibrium at all), with a truthful termination reason, a finite state and the
//     iteration limit respected.
// A cell listed in kKnownDefects is reported but does not fail the program; such a cell that
// passes fails it, so that the list stays current.
//
//   asperity_robustness_matrix              run the matrix, print failures, exit 1 on any
//   asperity_robustness_matrix --markdown   also print the matrix as a Markdown table
//   asperity_robustness_matrix --verbose    also print every cell's numbers
#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "asperity/asperity.h"

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define ASPERITY_ROBUSTNESS_POSIX 1
#endif

namespace {

constexpr double kPi = 3.14159265358979323846;
bool verbose = false;  // --verbose: every solve's numbers and the oracles' deviations

// ------------------------------------------------------------------------------------------
// Solvers: one column per algorithm and variable.
// ------------------------------------------------------------------------------------------
struct Column {
  const char *label;
  const char *algorithm;
  const char *variable;  // nullptr: the algorithm has no "variable" option
};

const Column kColumns[] = {
    {"pk", "pk", nullptr},
    {"bugnicourt (pressure)", "bugnicourt", "pressure"},
    {"bugnicourt (gap)", "bugnicourt", "gap"},
    {"lbfgsb (pressure)", "lbfgsb", "pressure"},
    {"lbfgsb (gap)", "lbfgsb", "gap"},
    {"lbfgs", "lbfgs", nullptr},
    {"lbfgs_fourier", "lbfgs_fourier", nullptr},
    {"gfmd", "gfmd", nullptr},
    {"fire", "fire", nullptr},
    {"fire_mass_weighted", "fire_mass_weighted", nullptr},
};
constexpr int kColumnCount = sizeof kColumns / sizeof kColumns[0];

bool is_unconstrained(const Column &c) {
  return std::strcmp(c.algorithm, "pk") != 0 && std::strcmp(c.algorithm, "bugnicourt") != 0 &&
         std::strcmp(c.algorithm, "lbfgsb") != 0;
}
bool on_gap(const Column &c) {
  return c.variable != nullptr && std::strcmp(c.variable, "gap") == 0;
}

// ------------------------------------------------------------------------------------------
// Scenes
// ------------------------------------------------------------------------------------------
enum class Kind { hard, adhesive, soft, lennard_jones, user_soft, user_hard, user_nan };

struct Scene {
  int dim = 1;
  int64_t nx = 64, ny = 1;
  double lx = 1, ly = 1;
  bool free_substrate = false;
  double modulus = 1;
  std::vector<double> h;
  Kind kind = Kind::hard;
  double w = 0, rho = 0;                  // adhesion; Lennard-Jones: w and z0 = rho
  double gr = 0, rr = 0, ga = 0, ra = 0;  // exponential soft wall
  bool nan_hard_wall = false;             // Kind::user_nan with the hard wall
  double k0 = 0;                          // K~(0) if set (0: the default)
  double tensile = 0;                     // the interaction's largest tensile stress
  double slope_pressure = 0;              // E* h'_rms/2 (periodic), from this file's DFT
  int64_t n() const { return nx * ny; }
  bool hard_wall() const {
    return kind == Kind::hard || kind == Kind::adhesive || kind == Kind::user_hard ||
           (kind == Kind::user_nan && nan_hard_wall);
  }
};

// The soft wall, written out here from docs/conventions.md (with its quadratic continuation
// below the thresholds), to check the library's states independently.
struct Exp {  // a exp(-g/r) continued below g = t by its Taylor expansion
  double a, r, t;
  double d(double g) const {
    const double gg = std::max(g, t), e = a * std::exp(-gg / r);
    return -e / r + (g < t ? e / (r * r) * (g - t) : 0.0);
  }
  double d2(double g) const { return a * std::exp(-std::max(g, t) / r) / (r * r); }
  double v(double g) const {
    const double e = a * std::exp(-std::max(g, t) / r), x = g < t ? g - t : 0.0;
    return e - e / r * x + e / (2 * r * r) * x * x;
  }
};

double dphi(const Scene &s, double g) {
  switch (s.kind) {
    case Kind::hard: return 0;
    case Kind::adhesive:
    case Kind::user_hard: return s.w / s.rho * std::exp(-std::max(g, 0.0) / s.rho);
    case Kind::soft:
    case Kind::user_soft:
    case Kind::user_nan: {
      if (s.nan_hard_wall) return s.w / s.rho * std::exp(-std::max(g, 0.0) / s.rho);
      const Exp rep{s.gr, s.rr / 2, -20 * s.rr}, att{s.ga, s.ra, -40 * s.ra};
      return rep.d(g) - att.d(g);
    }
    case Kind::lennard_jones: {
      const double z0 = s.rho, t = z0 / 2;
      if (g < t) return -4536 * s.w / z0 + 91584 * s.w / (z0 * z0) * (g - t);
      const double a = std::pow(z0 / g, 3);
      return 4.5 * s.w / g * (a - a * a * a);
    }
  }
  return 0;
}

double d2phi(const Scene &s, double g) {
  switch (s.kind) {
    case Kind::hard: return 0;
    case Kind::adhesive:
    case Kind::user_hard: return -s.w / (s.rho * s.rho) * std::exp(-std::max(g, 0.0) / s.rho);
    case Kind::soft:
    case Kind::user_soft:
    case Kind::user_nan: {
      const Exp rep{s.gr, s.rr / 2, -20 * s.rr}, att{s.ga, s.ra, -40 * s.ra};
      return rep.d2(g) - att.d2(g);
    }
    case Kind::lennard_jones: {
      const double z0 = s.rho;
      if (g < z0 / 2) return 91584 * s.w / (z0 * z0);
      const double a = std::pow(z0 / g, 3);
      return 4.5 * s.w / (g * g) * (10 * a * a * a - 4 * a);
    }
  }
  return 0;
}

double phi(const Scene &s, double g) {  // of the potentials given by callback
  if (s.kind == Kind::user_hard || s.nan_hard_wall)
    return -s.w * std::exp(-std::max(g, 0.0) / s.rho);
  const Exp rep{s.gr, s.rr / 2, -20 * s.rr}, att{s.ga, s.ra, -40 * s.ra};
  return rep.v(g) - att.v(g);
}

// The user's potentials: the same functions through the callback.
int user_potential(int64_t n, const double *gap, double *p, double *dp, double *d2p, void *data) {
  const Scene &s = *static_cast<const Scene *>(data);
  for (int64_t i = 0; i < n; ++i) {
    p[i] = phi(s, gap[i]);
    dp[i] = dphi(s, gap[i]);
    if (d2p != nullptr) d2p[i] = d2phi(s, gap[i]);
    if (s.kind == Kind::user_nan) dp[i] = std::nan("");
  }
  return 0;
}

// The largest tensile stress max phi'(g) of a soft wall, by scanning its gaps.
double largest_tensile_stress(const Scene &s) {
  if (s.kind == Kind::hard) return 0;
  if (s.kind == Kind::adhesive || s.kind == Kind::user_hard || s.nan_hard_wall) return s.w / s.rho;
  double best = 0;
  const double scale = std::max({s.ra, s.rr, s.rho});
  const double lo = s.kind == Kind::lennard_jones ? s.rho / 2 : -s.rr, hi = 60 * scale;
  for (int i = 0; i <= 20000; ++i) best = std::max(best, dphi(s, lo + (hi - lo) * i / 20000.0));
  return best;
}

// ------------------------------------------------------------------------------------------
// Independent elasticity: p = K u with K~(q) = E*|q|/2 and the system's K~(0), by a plain
// (separable) discrete Fourier transform, for the periodic substrate.
// ------------------------------------------------------------------------------------------
double wavevector(int64_t k, int64_t n, double l) {
  const int64_t kk = k <= n / 2 ? k : k - n;
  return 2 * kPi * static_cast<double>(kk) / l;
}

void dft_axis(std::vector<std::complex<double>> &f, int64_t nx, int64_t ny, bool along_x,
              int sign) {
  const int64_t n = along_x ? nx : ny, lines = along_x ? ny : nx;
  if (n == 1) return;
  std::vector<std::complex<double>> tw(n), line(n), out(n);
  for (int64_t k = 0; k < n; ++k)
    tw[k] = std::polar(1.0, sign * 2 * kPi * static_cast<double>(k) / static_cast<double>(n));
  for (int64_t l = 0; l < lines; ++l) {
    for (int64_t i = 0; i < n; ++i) line[i] = along_x ? f[i + nx * l] : f[l + nx * i];
    for (int64_t k = 0; k < n; ++k) {
      std::complex<double> s = 0;
      for (int64_t i = 0; i < n; ++i) s += line[i] * tw[(k * i) % n];
      out[k] = s;
    }
    for (int64_t k = 0; k < n; ++k) (along_x ? f[k + nx * l] : f[l + nx * k]) = out[k];
  }
}

std::vector<double> apply_stiffness(const Scene &s, double k0, const std::vector<double> &u) {
  const int64_t nx = s.nx, ny = s.ny, n = s.n();
  std::vector<std::complex<double>> f(u.begin(), u.end());
  dft_axis(f, nx, ny, true, -1);
  dft_axis(f, nx, ny, false, -1);
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i) {
      const double qx = wavevector(i, nx, s.lx), qy = wavevector(j, ny, s.ly);
      const double q = std::hypot(qx, qy);
      f[i + nx * j] *= (i == 0 && j == 0 ? k0 : s.modulus * q / 2) / static_cast<double>(n);
    }
  dft_axis(f, nx, ny, true, 1);
  dft_axis(f, nx, ny, false, 1);
  std::vector<double> p(n);
  for (int64_t i = 0; i < n; ++i) p[i] = f[i].real();
  return p;
}

// E* h'_rms/2, the documented reference pressure of a periodic scene, with h'_rms^2 the sum
// over q of q^2 |h^_q|^2 (h^ the DFT over N).
double slope_pressure(const Scene &s) {
  std::vector<std::complex<double>> f(s.h.begin(), s.h.end());
  dft_axis(f, s.nx, s.ny, true, -1);
  dft_axis(f, s.nx, s.ny, false, -1);
  double sum = 0;
  const double n = static_cast<double>(s.n());
  for (int64_t j = 0; j < s.ny; ++j)
    for (int64_t i = 0; i < s.nx; ++i) {
      const double qx = wavevector(i, s.nx, s.lx), qy = wavevector(j, s.ny, s.ly);
      sum += (qx * qx + qy * qy) * std::norm(f[i + s.nx * j] / n);
    }
  return s.modulus * std::sqrt(sum) / 2;
}

// The stiffness of one pixel, the diagonal of K: (1/N) sum over q of K~(q); on a free
// substrate 1/C(0), C(0) = 4 ln(1 + sqrt 2) dx/(pi E*) for square pixels.
double pixel_stiffness(const Scene &s, double k0) {
  if (s.free_substrate)
    return kPi * s.modulus /
           (4 * std::log(1 + std::sqrt(2.0)) * (s.lx / static_cast<double>(s.nx)));
  double sum = 0;
  for (int64_t j = 0; j < s.ny; ++j)
    for (int64_t i = 0; i < s.nx; ++i)
      sum += (i == 0 && j == 0)
                 ? k0
                 : s.modulus / 2 * std::hypot(wavevector(i, s.nx, s.lx), wavevector(j, s.ny, s.ly));
  return sum / static_cast<double>(s.n());
}

// The compliance of one pixel on itself, (1/N) sum over q of 1/K~(q), periodic substrate.
double pixel_compliance(const Scene &s, double k0) {
  double sum = 0;
  for (int64_t j = 0; j < s.ny; ++j)
    for (int64_t i = 0; i < s.nx; ++i)
      sum +=
          (i == 0 && j == 0)
              ? 1 / k0
              : 2 / (s.modulus * std::hypot(wavevector(i, s.nx, s.lx), wavevector(j, s.ny, s.ly)));
  return sum / static_cast<double>(s.n());
}

// The largest displacement a pressure of at most 1 on every pixel can make, periodic
// substrate: the l1 norm over the grid of the compliance's kernel c(x) = (1/N) sum over q of
// exp(iqx)/K~(q), by the plain DFT (0 without a K~(0), whose mean mode is then not the
// pressure's).
double compliance_l1(const Scene &s, double k0) {
  if (!(k0 > 0)) return 0;
  const int64_t nx = s.nx, ny = s.ny, n = s.n();
  std::vector<std::complex<double>> f(static_cast<size_t>(n));
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i)
      f[i + nx * j] =
          (i == 0 && j == 0)
              ? 1 / k0
              : 2 / (s.modulus * std::hypot(wavevector(i, nx, s.lx), wavevector(j, ny, s.ly)));
  dft_axis(f, nx, ny, true, 1);
  dft_axis(f, nx, ny, false, 1);
  double sum = 0;
  for (const auto &c : f) sum += std::fabs(c.real()) / static_cast<double>(n);
  return sum;
}

// ------------------------------------------------------------------------------------------
// One solve and what it left
// ------------------------------------------------------------------------------------------
struct Outcome {
  int status = ASP_OK;
  std::string message;
  int reason = 0;
  int64_t iterations = 0;
  double error = 0, mean_p = 0, delta = 0, mean_gap = 0, contact = 0, pref = 0, k0 = 0;
  std::string history_problem;  // "" when the history agrees with the report
  double pref_library = 0;      // ASP_REFERENCE_PRESSURE; pref is this file's own (see read_state)
  double elastic = 0;
  bool scalars_finite = true;
  // Whether the solver's unknown is the gap (option "variable" = "gap"): its state is the
  // iterate's gap and the pressure that gap reads, whose displacement differs from the
  // iterate's by the solve's residual (check_rules, "consistent").
  bool on_gap = false;
  std::vector<double> p, g, u;
};

struct Handles {
  asp_grid *grid = nullptr;
  asp_system *system = nullptr;
  ~Handles() {
    asp_system_destroy(system);
    asp_grid_destroy(grid);
  }
};

// Builds the scene's grid and system; returns "" or why it could not.
std::string build(Scene &s, Handles &hd) {
  int st = s.dim == 1 ? asp_grid_create_1d(s.nx, s.lx, &hd.grid)
                      : asp_grid_create_2d(s.nx, s.ny, s.lx, s.ly, &hd.grid);
  if (st == ASP_OK) st = asp_grid_set_threads(hd.grid, 1);
  // Every grid of the program plans with FFTW's estimates: plans measured by timing differ
  // from run to run (and, through the process's wisdom, reach later grids), and with them
  // the last bits of every transform, which changes the iteration counts of the stiffest
  // scenes by a few percent between runs; with estimates the table reproduces exactly.
  if (st == ASP_OK) st = asp_grid_set_fft_planning(hd.grid, ASP_FFT_ESTIMATE);
  if (st == ASP_OK)
    st = s.free_substrate ? asp_system_create_free(hd.grid, s.modulus, &hd.system)
                          : asp_system_create(hd.grid, s.modulus, &hd.system);
  if (st == ASP_OK) st = asp_system_set_topography(hd.system, s.h.data(), s.n());
  if (st == ASP_OK && s.k0 > 0) st = asp_system_set_k0(hd.system, s.k0);
  if (st == ASP_OK) {
    switch (s.kind) {
      case Kind::hard: break;
      case Kind::adhesive: st = asp_system_set_adhesion(hd.system, s.w, s.rho); break;
      case Kind::soft: st = asp_system_set_soft_wall(hd.system, s.gr, s.rr, s.ga, s.ra); break;
      case Kind::lennard_jones: st = asp_system_set_lennard_jones(hd.system, s.w, s.rho); break;
      case Kind::user_soft: st = asp_system_set_potential(hd.system, user_potential, &s, 0); break;
      case Kind::user_nan:
        st = asp_system_set_potential(hd.system, user_potential, &s, s.nan_hard_wall ? 1 : 0);
        break;
      case Kind::user_hard: st = asp_system_set_potential(hd.system, user_potential, &s, 1); break;
    }
  }
  if (st != ASP_OK) return std::string("scene refused: ") + asp_last_error_message();
  s.tensile = largest_tensile_stress(s);
  s.slope_pressure = s.free_substrate ? 0 : slope_pressure(s);
  return "";
}

bool all_finite(const std::vector<double> &v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

void read_state(const Scene &s, const asp_system *sys, Outcome &o, int control = 0,
                double value = 0) {
  const int keys[] = {ASP_CONTACT_FRACTION,   ASP_MEAN_PRESSURE,    ASP_MEAN_GAP,
                      ASP_ELASTIC_ENERGY,     ASP_PENETRATION,      ASP_TOTAL_FORCE,
                      ASP_REFERENCE_PRESSURE, ASP_MEAN_MODE_ENERGY, ASP_ATTRACTIVE_FRACTION,
                      ASP_REPULSIVE_FORCE,    ASP_ATTRACTIVE_FORCE, ASP_INTERACTION_ENERGY};
  double v[sizeof keys / sizeof keys[0]];
  o.scalars_finite = true;
  for (size_t k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
    v[k] = 0;
    if (asp_system_get(sys, keys[k], &v[k]) != ASP_OK || !std::isfinite(v[k]))
      o.scalars_finite = false;
  }
  o.contact = v[0];
  o.mean_p = v[1];
  o.mean_gap = v[2];
  o.elastic = v[3];
  o.delta = v[4];
  o.pref_library = v[6];
  o.k0 = 0;
  if (!s.free_substrate && (asp_system_get(sys, ASP_K0, &o.k0) != ASP_OK || !std::isfinite(o.k0)))
    o.scalars_finite = false;
  // The reference pressure the checks measure residuals in, found independently: the
  // documented E* h'_rms/2 on a periodic surface with slope (the free substrate's, from
  // differences inside the box, is taken from the library); on a flat surface the scene's
  // own pressures: the control's (the mean pressure asked for, or K~(0) times the
  // penetration asked for) and the interaction's largest tensile stress (for the soft walls
  // max phi'(g), found by scanning the gaps), whichever is larger, else E*.
  const double hr =
      *std::max_element(s.h.begin(), s.h.end()) - *std::min_element(s.h.begin(), s.h.end());
  if (hr > 0) {
    o.pref = s.free_substrate ? o.pref_library : s.slope_pressure;
  } else {
    const double by_control = control == ASP_CONTROL_MEAN_PRESSURE ? std::fabs(value)
                              : control == ASP_CONTROL_PENETRATION ? o.k0 * std::fabs(value)
                                                                   : 0.0;
    o.pref = std::max(by_control, s.tensile);
    if (!(o.pref > 0)) o.pref = s.modulus;
  }
  o.p.assign(s.n(), 0);
  o.g.assign(s.n(), 0);
  o.u.assign(s.n(), 0);
  asp_system_get_field(sys, ASP_FIELD_PRESSURE, o.p.data(), s.n());
  asp_system_get_field(sys, ASP_FIELD_GAP, o.g.data(), s.n());
  asp_system_get_field(sys, ASP_FIELD_DISPLACEMENT, o.u.data(), s.n());
}

// Progress callback: a guard against a solve that runs far longer than its scene needs (a
// hang that still iterates); the cell then fails as cancelled.
struct Guard {
  double limit_seconds;
};
int guard_progress(int64_t, double seconds, double, void *data) {
  return seconds > static_cast<Guard *>(data)->limit_seconds ? 1 : 0;
}

struct Settings {
  double tolerance = 1e-10;
  int64_t max_iterations = 5000;
  int64_t stall_window = -1;  // -1: the default
};

std::string fmt(const char *f, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

int64_t solves = 0;  // solves run, for the summary

Outcome solve(asp_solver *solver, const Scene &s, asp_system *sys, int control, double value) {
  Outcome o;
  ++solves;
  o.status = asp_solver_solve(solver, sys, control, value);
  o.message = asp_last_error_message();
  char variable[16] = "";
  int64_t variable_length = 0;
  o.on_gap = asp_solver_get_option_string(solver, "variable", variable, sizeof variable,
                                          &variable_length) == ASP_OK &&
             std::strcmp(variable, "gap") == 0;
  if (o.status == ASP_OK) {
    asp_solver_termination(solver, &o.reason);
    asp_solver_iterations(solver, &o.iterations);
    asp_solver_final_error(solver, &o.error);
    // The history: one finite row per iteration from the starting point, ending at the
    // reported error (a breakdown reports the last finite one).
    int64_t rows = -1;
    asp_solver_history_length(solver, &rows);
    std::vector<double> it(rows > 0 ? rows : 0), err(rows > 0 ? rows : 0);
    if (rows > 0) {
      asp_solver_get_history(solver, ASP_HISTORY_ITERATION, it.data(), rows);
      asp_solver_get_history(solver, ASP_HISTORY_ERROR, err.data(), rows);
    }
    if (rows != o.iterations + 1)
      o.history_problem = fmt("history of %g rows after %g iterations", static_cast<double>(rows),
                              static_cast<double>(o.iterations));
    else if (it.back() != static_cast<double>(o.iterations))
      o.history_problem = "the history's last iteration is not the reported one";
    else if (o.reason != ASP_TERMINATION_BREAKDOWN && err.back() != o.error)
      o.history_problem =
          fmt("the history's last error %g is not the reported %g", err.back(), o.error);
    else if (o.reason != ASP_TERMINATION_BREAKDOWN && !all_finite(err))
      o.history_problem = "a history error is not finite";
  }
  read_state(s, sys, o, control, value);
  return o;
}

// ------------------------------------------------------------------------------------------
// The rules every solve must keep
// ------------------------------------------------------------------------------------------

// The scale of the numbers in g = u - h + max h - delta, which the consistency's rounding
// allowance is a fraction of.
double consistency_scale(const Scene &s, const Outcome &o) {
  const double hmax = *std::max_element(s.h.begin(), s.h.end());
  const double hmin = *std::min_element(s.h.begin(), s.h.end());
  double umax = 0;
  for (double x : o.u) umax = std::max(umax, std::fabs(x));
  return umax + (hmax - hmin) + std::fabs(o.delta) + std::fabs(hmax);
}

// Checks a finished solve; appends what it broke to `bad`.
void check_rules(const Scene &s, const Settings &set, int control, double value, const Outcome &o,
                 std::vector<std::string> &bad) {
  if (o.status != ASP_OK) {
    bad.push_back("solve returned status " + std::to_string(o.status) + ": " + o.message);
    return;
  }
  if (o.reason == ASP_TERMINATION_CANCELLED) bad.push_back("cancelled by the time guard (hang)");
  if (o.reason < ASP_TERMINATION_CONVERGED || o.reason > ASP_TERMINATION_SEPARATED)
    bad.push_back("termination reason " + std::to_string(o.reason));
  if (o.iterations > set.max_iterations) bad.push_back("more iterations than the limit");
  if (o.reason == ASP_TERMINATION_ITERATION_LIMIT && o.iterations != set.max_iterations)
    bad.push_back("iteration limit reported before the limit");
  if (!o.history_problem.empty()) bad.push_back(o.history_problem);
  if (!std::isfinite(o.error)) bad.push_back("final error not finite");
  if (!o.scalars_finite) bad.push_back("a scalar result is not finite");
  if (!all_finite(o.p) || !all_finite(o.g) || !all_finite(o.u))
    bad.push_back("a field is not finite");
  if (!bad.empty()) return;

  // The state is consistent whatever the ending: g = u - h + max h - delta, to rounding
  // (1e-10 of the scale) where the gap is computed from the displacement. A solve on the gap
  // stores its iterate's gap and the pressure that gap reads (-phi'(g) where it is open,
  // K u clipped at the wall's tension on the wall), and u is K^-1 of that pressure: it
  // differs from the iterate's displacement by K^-1 of what the reading changed, which on
  // every pixel is at most the reported error times p_ref (the error is the largest
  // residual of the optimality conditions, in units of p_ref: on an open pixel the
  // reading's change, on the wall its clipped part). So there the allowance adds
  // error x p_ref x |c|_1, the largest displacement of such a pressure
  // (compliance_l1; periodic substrate: the free one has no independent compliance here).
  const double hmax = *std::max_element(s.h.begin(), s.h.end());
  const double scale = consistency_scale(s, o);
  double worst = 0;
  for (int64_t i = 0; i < s.n(); ++i)
    worst = std::max(worst, std::fabs(o.g[i] - (o.u[i] - s.h[i] + hmax - o.delta)));
  // A pressure solve stores the smallest positive double (a subnormal) where the gap its
  // pressure makes is <= 0 off the active set (asp_system_get_field): on a scene of scale 0
  // (a flat at zero load) that is the whole difference, and less than DBL_MIN.
  const double residual_allowance = o.on_gap && s.hard_wall() && !s.free_substrate
                                        ? o.error * o.pref * compliance_l1(s, o.k0)
                                        : 0.0;
  const double allowed = 1e-10 * scale + residual_allowance;
  if (worst > allowed && worst >= DBL_MIN)
    bad.push_back(fmt("gap inconsistent with u, h, delta by %g (allowed %g)", worst, allowed));

  if (o.reason != ASP_TERMINATION_CONVERGED) return;
  if (s.slope_pressure > 0 && s.kind != Kind::user_soft && s.kind != Kind::user_hard &&
      std::fabs(o.pref_library - s.slope_pressure) > 1e-9 * s.slope_pressure)
    bad.push_back(fmt("reference pressure %.12g, documented E* h'rms/2 = %.12g", o.pref_library,
                      s.slope_pressure));
  if (!(o.error <= set.tolerance))
    bad.push_back(fmt("converged with error %g > tolerance", o.error));

  // The control is met.
  if (control == ASP_CONTROL_PENETRATION && std::fabs(o.delta - value) > 1e-12 * std::fabs(value))
    bad.push_back(fmt("penetration %.17g, asked %.17g", o.delta, value));
  if (control == ASP_CONTROL_MEAN_PRESSURE &&
      std::fabs(o.mean_p - value) > 1e-9 * std::fabs(value) + 10 * set.tolerance * o.pref)
    bad.push_back(fmt("mean pressure %.17g, asked %.17g", o.mean_p, value));
  if (control == ASP_CONTROL_MEAN_GAP && std::fabs(o.mean_gap - value) > 1e-9 * std::fabs(value))
    bad.push_back(fmt("mean gap %.17g, asked %.17g", o.mean_gap, value));

  // Constraints and force balance, checked independently of the library's error measure.
  // tol_p: the pressure residual a converged state may keep, tolerance x reference pressure,
  // times 10 for the difference between this plain DFT and the library's FFTs and internal
  // units; tol_g the gap residual, tol_p over the stiffness of one pixel (the library's
  // measure for solvers on the pressure). Plus rounding: 1e-9 of the largest pressure and of
  // the largest K~ times the largest displacement.
  const double kpix = pixel_stiffness(s, o.k0);
  double pmax = 0, ku_max = 0;
  for (double x : o.p) pmax = std::max(pmax, std::fabs(x));
  double umean = 0;
  for (double x : o.u) umean += x / static_cast<double>(s.n());
  for (double x : o.u) ku_max = std::max(ku_max, std::fabs(x - umean));
  const double kmax = s.modulus * kPi * std::hypot(s.nx / s.lx, s.ny > 1 ? s.ny / s.ly : 0.0);
  const double round_p = 1e-9 * (pmax + kmax * ku_max + o.k0 * std::fabs(umean));
  const double tol_p = 10 * set.tolerance * o.pref + round_p;
  const double tol_g = 10 * set.tolerance * o.pref / kpix + 1e-12 * scale;
  const double gap_round = 1e-13 * scale;  // rounding of a gap, for phi'' x dg

  if (s.hard_wall()) {
    const double pmin = (s.kind == Kind::hard) ? 0.0 : -dphi(s, 0.0);
    double gmin = HUGE_VAL, plow = HUGE_VAL;
    for (int64_t i = 0; i < s.n(); ++i) {
      gmin = std::min(gmin, o.g[i]);
      plow = std::min(plow, o.p[i]);
    }
    if (gmin < -tol_g) bad.push_back(fmt("converged with gap %g < 0 (allowed %g)", gmin, -tol_g));
    if (plow < pmin - 1e-12 * std::max(pmax, std::fabs(pmin)))
      bad.push_back(fmt("converged with pressure %g below %g", plow, pmin));
    // Open pixels carry the interaction's pressure -phi'(g) only.
    double worst_open = 0;
    for (int64_t i = 0; i < s.n(); ++i)
      if (o.g[i] > tol_g) {
        const double allowed = tol_p + std::fabs(d2phi(s, o.g[i])) * gap_round;
        worst_open = std::max(worst_open, std::fabs(o.p[i] + dphi(s, o.g[i])) - allowed);
      }
    if (worst_open > 0)
      bad.push_back(fmt("open pixel off balance by %g beyond its allowance", worst_open));
  }
  if (!s.hard_wall()) {
    // A soft wall's pressure is the potential's, -phi'(g), at equilibrium (on any substrate).
    double worst = 0;
    for (int64_t i = 0; i < s.n(); ++i)
      worst = std::max(worst, std::fabs(o.p[i] + dphi(s, o.g[i])) - tol_p -
                                  std::fabs(d2phi(s, o.g[i])) * gap_round);
    if (worst > 0)
      bad.push_back(fmt("pressure differs from -phi'(g) by %g beyond its allowance", worst));
  }
  if (!s.free_substrate) {
    const std::vector<double> ku = apply_stiffness(s, o.k0, o.u);
    double worst_el = 0, worst_soft = 0;
    for (int64_t i = 0; i < s.n(); ++i) {
      worst_el = std::max(worst_el, std::fabs(ku[i] - o.p[i]) - tol_p);
      if (!s.hard_wall()) {
        const double allowed = tol_p + std::fabs(d2phi(s, o.g[i])) * gap_round;
        worst_soft = std::max(worst_soft, std::fabs(ku[i] + dphi(s, o.g[i])) - allowed);
      }
    }
    if (verbose)
      std::fprintf(stderr,
                   "      balance: p_ref %g (library %g), tol_p %g, |Ku - p| %g, |Ku + phi'| %g "
                   "beyond allowances\n",
                   o.pref, o.pref_library, tol_p, worst_el, worst_soft);
    if (worst_el > 0)
      bad.push_back(fmt("pressure differs from K u by %g beyond %g", worst_el + tol_p, tol_p));
    if (worst_soft > 0)
      bad.push_back(fmt("K u + phi'(g) off balance by %g beyond its allowance", worst_soft));
  }
}

// ------------------------------------------------------------------------------------------
// Cases
// ------------------------------------------------------------------------------------------
struct Step {
  int control;
  double value;
};

using Oracle = std::function<void(const Scene &, const Settings &, const Step &, const Outcome &,
                                  std::vector<std::string> &)>;

struct Case {
  std::string name;
  std::string checks;  // what the oracle is, for the document
  Scene scene;
  std::vector<Step> steps;
  bool pairs = false;   // warm starts from every other step (and a cold start for each)
  bool chain = false;   // a sweep, each step warm-started from the one before
  bool unique = false;  // the problem has one solution: converged solvers agree
  bool no_equilibrium = false;
  Settings settings;
  Oracle oracle;
  // The same scene in units where lengths are times length_scale and pressures times
  // modulus_scale: its dimensionless results must be those of `baseline`.
  std::string baseline;
  double length_scale = 1, modulus_scale = 1;
};

// Honest non-convergence: these cells may end unconverged with a truthful reason.
struct Listed {
  const char *scene;
  const char *column;
  const char *why;
};
const Listed kExpectedUnconverged[] = {
    {"soft wall, Tabor 3", "gfmd",
     "its error stays near 10 for more than the default stall_window of 1000 iterations, then "
     "falls: stalled at 1736 iterations; with stall_window 5000 it converges in 2082"},
    {"soft wall, Tabor 30", "fire",
     "its error stays near 12 for more than the default stall_window of 1000 iterations: "
     "stalled at 1645 iterations; with stall_window 5000 it converges in 3171"},
    // Under a tensile mean pressure the energy of a finite-range potential is unbounded below
    // as the body moves away (the load does work without limit), so the equilibrium is a
    // local minimum behind an energy barrier; these solvers' steps cross the barrier and the
    // body runs away. The reason is truthful (stalled); fire finds the local minimum.
    {"soft wall, flat, tensile load within reach", "lbfgs", "runs away past the barrier"},
    {"soft wall, flat, tensile load within reach", "lbfgs_fourier", "runs away past the barrier"},
    {"soft wall, flat, tensile load within reach", "gfmd", "runs away past the barrier"},
    {"soft wall, flat, tensile load, tolerance 1e-4", "gfmd", "runs away past the barrier"},
    // The load drives the mean displacement 1e25 into a wall of range 1e20 (lbfgs_fourier
    // converges there). These solvers' steps are sized by the elastic modes or by the
    // gradient, and do not reach that far; on the displacement the variable would hold no
    // more than 1e-16 of the penetration there anyway.
    {"soft wall of range 1e20 on a unit box, under load", "lbfgs",
     "its first line search does not reach the penetration of 1e25 (stalled at iteration 0)"},
    {"soft wall of range 1e20 on a unit box, under load", "gfmd",
     "its steps, sized by the elastic modes, do not reach the penetration of 1e25"},
    {"soft wall of range 1e20 on a unit box, under load", "fire",
     "its steps, sized by the elastic modes, do not reach the penetration of 1e25"},
    {"soft wall of range 1e20 on a unit box, under load", "fire_mass_weighted",
     "its steps, sized by the elastic modes, do not reach the penetration of 1e25"},
};
// Real defects of the library, found by this matrix, reported until they are fixed. None at
// present; the two it found are fixed and their cells now pass: a soft wall on a surface
// without slope measured its errors against gamma_a/rho_a instead of its largest tensile
// stress (flat scenes reported "converged" with the load unbalanced), and
// asp_solver_supports accepted mean-pressure control on a free substrate that the solve then
// refused. (An entry with a null scene stands for none.)
const Listed kKnownDefects[] = {
    {nullptr, "", ""},
};

const Listed *find(const Listed *list, size_t n, const std::string &scene, const char *column) {
  for (size_t i = 0; i < n; ++i)
    if (list[i].scene != nullptr && scene == list[i].scene &&
        std::strcmp(column, list[i].column) == 0)
      return &list[i];
  return nullptr;
}

// The rules of the registry as the header documents them: "" if the column serves the scene
// under the control, otherwise the short reason.
std::string expected_refusal(const Column &c, const Scene &s, const Step &step) {
  const std::string alg = c.algorithm;
  const bool soft = s.kind == Kind::soft || s.kind == Kind::lennard_jones ||
                    s.kind == Kind::user_soft || (s.kind == Kind::user_nan && !s.nan_hard_wall);
  if (is_unconstrained(c)) {
    if (!soft) return "hard wall";
    if (step.control == ASP_CONTROL_MEAN_GAP) return "control";
    if (s.free_substrate && (alg != "lbfgs" && alg != "fire")) return "free substrate";
    if (s.free_substrate && step.control == ASP_CONTROL_MEAN_PRESSURE) return "control";
    return "";
  }
  if (soft) return "soft wall";
  const bool gap = on_gap(c);
  if ((s.kind == Kind::user_hard || s.kind == Kind::user_nan) && !(alg == "lbfgsb" && gap))
    return "user potential";
  if (s.kind == Kind::adhesive && !gap) return "adhesion";
  // lbfgsb keeps no mean: penetration control, and on the gap load control (a work term).
  if (alg == "lbfgsb" && !gap && step.control != ASP_CONTROL_PENETRATION) return "control";
  if (alg == "lbfgsb" && step.control == ASP_CONTROL_MEAN_GAP) return "control";
  // The gap takes load control with the hard wall, with or without adhesion, not with a
  // user's potential.
  if ((s.kind == Kind::user_hard || s.kind == Kind::user_nan) &&
      step.control == ASP_CONTROL_MEAN_PRESSURE)
    return "control";
  if (!gap && step.control == ASP_CONTROL_MEAN_GAP) return "control";
  if (gap && s.free_substrate && step.control == ASP_CONTROL_MEAN_GAP) return "control";
  if (step.control == ASP_CONTROL_MEAN_PRESSURE && step.value < 0 && s.kind != Kind::adhesive)
    return "tensile load";
  return "";
}

// ---------------------------------------------------------------- oracles
// Westergaard: h = h0 cos(2 pi x/lambda) along the strip's long axis, N pixels per period.
//   full contact (pbar >= p* = pi E* h0/lambda): p = pbar + p* cos(2 pi x/lambda), exact on the
//   grid (a single mode); tolerance 10 tol p_ref + 1e-9 p* (solver tolerance and rounding);
//   partial contact: pbar/p* = sin^2(pi a/lambda); the contact fraction 2a/lambda is
//   resolved to a pixel at each of the two contact edges, so |c - 2a/lambda| <= 2/N
//   (measured: at most 1.02 pixels over every cell of the matrix); the pressure at the
//   crest, 2 pbar/sin(pi a/lambda), within 1 % (measured: at most 0.2 % at N = 64, at 14 %
//   contact, where the contact is narrowest; the solver tolerance adds 1e-9 of p_ref).
Oracle westergaard(double h0, double lambda, int64_t n_period, bool along_y = false) {
  return [=](const Scene &s, const Settings &set, const Step &, const Outcome &o,
             std::vector<std::string> &bad) {
    const double pstar = kPi * s.modulus * h0 / lambda;
    if (o.mean_p >= pstar * (1 - 1e-9)) {
      if (o.contact != 1.0) bad.push_back(fmt("Westergaard full contact: contact %g", o.contact));
      double worst = 0;
      for (int64_t j = 0; j < s.ny; ++j)
        for (int64_t i = 0; i < s.nx; ++i) {
          const double x = along_y ? j * s.ly / s.ny : i * s.lx / s.nx;
          worst = std::max(worst, std::fabs(o.p[i + s.nx * j] - o.mean_p -
                                            pstar * std::cos(2 * kPi * x / lambda)));
        }
      if (worst > 10 * set.tolerance * o.pref + 1e-9 * pstar)
        bad.push_back(fmt("Westergaard full contact: pressure off by %g (p* %g)", worst, pstar));
      return;
    }
    const double a = lambda / kPi * std::asin(std::sqrt(std::max(o.mean_p, 0.0) / pstar));
    if (verbose)
      std::fprintf(stderr,
                   "      Westergaard: contact %g - theory %g = %.3g pixels; crest %g, theory %g\n",
                   o.contact, 2 * a / lambda, (o.contact - 2 * a / lambda) * n_period, o.p[0],
                   o.mean_p > 0 ? 2 * o.mean_p / std::sin(kPi * a / lambda) : 0.0);
    if (std::fabs(o.contact - 2 * a / lambda) > 2.0 / n_period)
      bad.push_back(fmt("Westergaard: contact %g, theory %g (pbar/p* %g)", o.contact,
                        2 * a / lambda, o.mean_p / pstar));
    if (o.mean_p > 1e-3 * pstar) {
      const double crest = 2 * o.mean_p / std::sin(kPi * a / lambda);
      if (std::fabs(o.p[0] - crest) > 0.01 * crest)
        bad.push_back(fmt("Westergaard: crest pressure %g, theory %g", o.p[0], crest));
    }
  };
}

// A single Fourier mode h0 cos(2 pi x/lx) cos(2 pi y/ly) in full contact: p = pbar + E* |q| h0/2
// cos cos exactly (the normalisation check of DESIGN.md section 5); tolerance as Westergaard's.
Oracle single_mode_full() {
  return [](const Scene &s, const Settings &set, const Step &, const Outcome &o,
            std::vector<std::string> &bad) {
    const double h0 = *std::max_element(s.h.begin(), s.h.end());
    const double q = 2 * kPi * std::hypot(1 / s.lx, 1 / s.ly), amp = s.modulus * q * h0 / 2;
    double worst = 0;
    for (int64_t j = 0; j < s.ny; ++j)
      for (int64_t i = 0; i < s.nx; ++i)
        worst = std::max(
            worst, std::fabs(o.p[i + s.nx * j] - o.mean_p -
                             amp * std::cos(2 * kPi * i / s.nx) * std::cos(2 * kPi * j / s.ny)));
    if (o.contact != 1.0) bad.push_back(fmt("single mode: contact %g, not full", o.contact));
    if (worst > 10 * set.tolerance * o.pref + 1e-9 * amp)
      bad.push_back(fmt("single mode: pressure off by %g (amplitude %g)", worst, amp));
  };
}

// A flat surface: every field uniform. Hard wall without adhesion, exactly: under mean
// pressure p = pbar, g = 0; under penetration delta > 0 p = K~(0) delta, g = 0 (periodic);
// delta <= 0 p = 0, g = -delta. Tolerance: 10 tol p_ref + 1e-12 of the values (rounding).
Oracle flat() {
  return [](const Scene &s, const Settings &set, const Step &step, const Outcome &o,
            std::vector<std::string> &bad) {
    const auto spread = [](const std::vector<double> &v) {
      return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
    };
    const double tp = 10 * set.tolerance * o.pref + 1e-12 * std::fabs(o.mean_p);
    if (spread(o.p) > tp) bad.push_back(fmt("flat: pressure not uniform (spread %g)", spread(o.p)));
    if (spread(o.g) > 1e-12 * (std::fabs(o.mean_gap) + std::fabs(o.delta)) +
                          10 * set.tolerance * o.pref / std::max(o.k0, 1e-300))
      bad.push_back(fmt("flat: gap not uniform (spread %g)", spread(o.g)));
    if (s.kind != Kind::hard) return;
    double pe = 0, ge = 0;
    if (step.control == ASP_CONTROL_MEAN_PRESSURE) {
      pe = step.value;
    } else if (step.control == ASP_CONTROL_PENETRATION) {
      if (s.free_substrate) return;
      pe = step.value > 0 ? o.k0 * step.value : 0;
      ge = step.value > 0 ? 0 : -step.value;
    } else {
      ge = step.value;
    }
    if (std::fabs(o.mean_p - pe) > tp + 1e-12 * std::fabs(pe))
      bad.push_back(fmt("flat: pressure %g, exact %g", o.mean_p, pe));
    if (std::fabs(o.mean_gap - ge) >
        1e-12 * std::fabs(ge) + 10 * set.tolerance * o.pref / std::max(o.k0, 1e-300))
      bad.push_back(fmt("flat: gap %g, exact %g", o.mean_gap, ge));
  };
}

// One pixel in contact (the apex of a sphere at a tiny load): contact fraction exactly 1/N;
// under mean pressure the apex carries N pbar; under penetration it carries delta/c0, c0 the
// compliance of one pixel on itself ((1/N) sum 1/K~(q) periodic; 4 ln(1 + sqrt 2) dx/(pi E*)
// free). Tolerance 2 tol p_ref: the solver's residual is a gap residual times the pixel
// stiffness k, or a pressure residual, and c0 k >= 1, so the apex pressure is off by at most
// tol p_ref; doubled for rounding.
Oracle single_pixel(int64_t apex) {
  return [=](const Scene &s, const Settings &set, const Step &step, const Outcome &o,
             std::vector<std::string> &bad) {
    const double n = static_cast<double>(s.n());
    if (o.contact != 1 / n)
      bad.push_back(fmt("single pixel: contact fraction %g, not 1/N = %g", o.contact, 1 / n));
    double expected, slack = 2 * set.tolerance * o.pref;
    if (step.control == ASP_CONTROL_MEAN_PRESSURE) {
      // The whole load on the apex. A solver on the gap meets the load to tol p_ref in the
      // mean only (the open pixels' residuals, each up to tol p_ref, are read as no
      // pressure), so the apex may miss n pbar by n tol p_ref more.
      expected = n * step.value;
      slack += n * set.tolerance * o.pref;
    } else {
      const double c0 = s.free_substrate
                            ? 4 * std::log(1 + std::sqrt(2.0)) * (s.lx / s.nx) / (kPi * s.modulus)
                            : pixel_compliance(s, o.k0);
      expected = step.value / c0;
    }
    if (std::fabs(o.p[apex] - expected) > slack + 1e-12 * expected)
      bad.push_back(fmt("single pixel: apex pressure %.12g, exact %.12g", o.p[apex], expected));
  };
}

// Hertz (free substrate, paraboloid of radius R): F = 4/3 E* sqrt(R) delta^(3/2). The
// discretisation error of the force with the contact radius a resolved by n pixels: measured
// 0.04 % at n = 8 (49^2) and 0.08 % at n = 4 (25^2); tolerance 1 % at n = 8 and 2 % at n = 4.
Oracle hertz(double radius, double tolerance) {
  return [=](const Scene &s, const Settings &, const Step &step, const Outcome &o,
             std::vector<std::string> &bad) {
    const double f = 4.0 / 3 * s.modulus * std::sqrt(radius) * std::pow(step.value, 1.5);
    const double got = o.mean_p * s.lx * s.ly;
    if (verbose)
      std::fprintf(stderr, "      Hertz: force %g, theory %g, relative %.3g\n", got, f,
                   got / f - 1);
    if (std::fabs(got - f) > tolerance * f)
      bad.push_back(fmt("Hertz: force %g, theory %g", got, f));
  };
}

// No contact at all: every pixel open, contact fraction 0.
Oracle detached() {
  return [](const Scene &, const Settings &, const Step &, const Outcome &o,
            std::vector<std::string> &bad) {
    if (o.contact != 0) bad.push_back(fmt("detached: contact fraction %g", o.contact));
  };
}

// Zero load or penetration: the undeformed body touches the highest pixels with no pressure.
// A gap solver keeps them on the wall (its active set, g = 0), a pressure solver has no
// active set (p = 0 everywhere): the contact fraction is the share of the highest pixels or 0.
Oracle touching() {
  return [](const Scene &s, const Settings &, const Step &, const Outcome &o,
            std::vector<std::string> &bad) {
    const double top = *std::max_element(s.h.begin(), s.h.end());
    const double highest = static_cast<double>(std::count(s.h.begin(), s.h.end(), top)) /
                           static_cast<double>(s.h.size());
    if (o.contact != 0 && o.contact != highest)
      bad.push_back(fmt("touching: contact fraction %g, neither 0 nor the highest pixels' %g",
                        o.contact, highest));
  };
}

// ------------------------------------------------------------------------------------------
// Scene builders
// ------------------------------------------------------------------------------------------
Scene strip(int64_t nx, int64_t ny, double l, double h0, bool along_y = false) {
  Scene s;
  s.dim = 2;
  s.nx = nx;
  s.ny = ny;
  s.lx = along_y ? 1.0 : l;
  s.ly = along_y ? l : 1.0;
  s.h.resize(nx * ny);
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i)
      s.h[i + nx * j] = h0 * std::cos(2 * kPi * static_cast<double>(along_y ? j : i) /
                                      static_cast<double>(along_y ? ny : nx));
  return s;
}

Scene line(int64_t n, double l, double h0) {
  Scene s;
  s.dim = 1;
  s.nx = n;
  s.ny = 1;
  s.lx = l;
  s.h.resize(n);
  for (int64_t i = 0; i < n; ++i) s.h[i] = h0 * std::cos(2 * kPi * i / static_cast<double>(n));
  return s;
}

Scene square(int64_t n, double l) {
  Scene s;
  s.dim = 2;
  s.nx = s.ny = n;
  s.lx = s.ly = l;
  s.h.assign(n * n, 0.0);
  return s;
}

// h = -r^2/(2R) about the centre pixel (n odd puts the apex on a pixel).
Scene paraboloid(int64_t n, double l, double radius) {
  Scene s = square(n, l);
  const double dx = l / n;
  for (int64_t j = 0; j < n; ++j)
    for (int64_t i = 0; i < n; ++i) {
      const double x = (i - n / 2) * dx, y = (j - n / 2) * dx;
      s.h[i + n * j] = -(x * x + y * y) / (2 * radius);
    }
  return s;
}

// The thesis's Table 4 profile, reduced: 1D, 128 pixels of unit length, self-affine with
// Hurst 0.8 from the box down to 4 pixels, rms slope 0.1, seed 1. Returns R_c = 1/h''_rms.
Scene table4_profile(double *rc) {
  Scene s;
  s.dim = 1;
  s.nx = 128;
  s.lx = 128;
  s.h.assign(128, 0.0);
  asp_grid *g = nullptr;
  double curv = 1;
  if (asp_grid_create_1d(128, 128.0, &g) == ASP_OK) {
    asp_grid_set_fft_planning(g, ASP_FFT_ESTIMATE);  // see build()
    asp_topography_self_affine(g, 0.8, 128.0, 128.0, 4.0, ASP_RMS_SLOPE, 0.1, 1, s.h.data(), 128);
    asp_topography_statistics(g, s.h.data(), 128, nullptr, nullptr, &curv);
  }
  asp_grid_destroy(g);
  *rc = 1 / curv;
  return s;
}

// The thesis's soft wall (Table 4): gamma_r = 2100 R_c, gamma_a = 2.05 R_c, one range rho.
// With a Tabor parameter given instead, the same ratio gamma_r/gamma_a and the work of
// adhesion gamma_a^2/(4 gamma_r) = w from mu^3 = R w^2/(E*^2 rho^3).
void soft_wall(Scene &s, double rc, double rho, double tabor = -1) {
  s.kind = Kind::soft;
  s.rr = s.ra = rho;
  if (tabor < 0) {
    s.gr = 2100 * rc;
    s.ga = 2.05 * rc;
  } else {
    const double ratio = 2100 / 2.05,
                 w = std::sqrt(std::pow(tabor, 3) * s.modulus * s.modulus * std::pow(rho, 3) / rc);
    s.ga = 4 * ratio * w;
    s.gr = ratio * s.ga;
  }
}

// The penetration of table4.toml: the crest pressed 5 % of the height range past the well.
double table4_penetration(const Scene &s) {
  const double range =
      *std::max_element(s.h.begin(), s.h.end()) - *std::min_element(s.h.begin(), s.h.end());
  const double well = s.rr * std::log(2 * s.gr / s.ga);
  return 0.05 * range - well;
}

Scene scaled(Scene s, double length, double modulus) {
  s.lx *= length;
  if (s.dim == 2) s.ly *= length;
  for (double &x : s.h) x *= length;
  s.modulus *= modulus;
  s.w *= modulus * length;
  s.rho *= length;
  s.gr *= modulus * length;
  s.ga *= modulus * length;
  s.rr *= length;
  s.ra *= length;
  return s;
}

std::vector<Case> make_cases() {
  std::vector<Case> cs;
  const auto add = [&](Case c) { cs.push_back(std::move(c)); };

  // ---- Westergaard (1D sinusoid, hard wall), 64 pixels per period, E* = 1, lambda = 1.
  // Periodic 1D K~(0) = E* pi/lx; p* = pi E* h0/lambda.
  const double h0 = 0.01, pstar = kPi * h0, k0_1d = kPi;
  {
    Case c;
    c.name = "Westergaard 1D, 50 % contact (penetration)";
    c.checks = "sin^2 law: contact within 2 pixels, crest pressure within 1 %";
    c.scene = line(64, 1.0, h0);
    c.steps = {{ASP_CONTROL_PENETRATION, 0.012}};
    c.unique = true;
    c.oracle = westergaard(h0, 1.0, 64);
    add(c);
    c.name = "Westergaard 1D, 50 % contact (mean pressure)";
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.5 * pstar}};
    add(c);
    c.name = "Westergaard 1D, full contact (penetration)";
    c.checks = "full contact: pressure pbar + p* cos, exact";
    c.steps = {{ASP_CONTROL_PENETRATION, h0 + 1.5 * pstar / k0_1d}};
    add(c);
    c.name = "Westergaard 1D, > 99 % contact (mean pressure)";
    c.checks = "sin^2 law near full contact; contact fraction above 0.99";
    c.scene = line(256, 1.0, h0);
    c.oracle = westergaard(h0, 1.0, 256);
    {
      const double s = std::sin(kPi * 0.996 / 2);
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, pstar * s * s}};
    }
    add(c);
    c.name = "Westergaard 1D, > 99 % contact (penetration)";
    {
      const double s = std::sin(kPi * 0.996 / 2);
      c.steps = {{ASP_CONTROL_PENETRATION, h0 + pstar * s * s / k0_1d}};
    }
    add(c);
    c.name = "Westergaard 1D, mean gap 10 % of h0";
    c.checks = "sin^2 law (mean-gap control)";
    c.scene = line(64, 1.0, h0);
    c.oracle = westergaard(h0, 1.0, 64);
    c.steps = {{ASP_CONTROL_MEAN_GAP, 0.1 * h0}};
    add(c);
  }
  // ---- Grids: prime, strips both ways, odd 2D, 1 x 1.
  {
    Case c;
    c.name = "1D prime grid, 127 pixels (penetration)";
    c.checks = "Westergaard sin^2 law";
    c.scene = line(127, 1.0, h0);
    c.steps = {{ASP_CONTROL_PENETRATION, 0.012}};
    c.unique = true;
    c.oracle = westergaard(h0, 1.0, 127);
    add(c);
    c.name = "N x 1 strip, 64 x 1 (penetration)";
    c.scene = strip(64, 1, 1.0, h0);
    c.steps = {{ASP_CONTROL_PENETRATION, 0.006}};
    c.oracle = westergaard(h0, 1.0, 64);
    add(c);
    c.name = "1 x N strip, 1 x 64 (penetration)";
    c.scene = strip(1, 64, 1.0, h0, true);
    c.oracle = westergaard(h0, 1.0, 64, true);
    add(c);
    c.name = "2D prime grid 31 x 37, single mode, full contact";
    c.checks = "single Fourier mode: pressure amplitude E* q h0/2, exact";
    c.scene = square(31, 1.0);
    c.scene.ny = 37;
    c.scene.h.resize(31 * 37);
    for (int j = 0; j < 37; ++j)
      for (int i = 0; i < 31; ++i)
        c.scene.h[i + 31 * j] = h0 * std::cos(2 * kPi * i / 31) * std::cos(2 * kPi * j / 37);
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 3 * pstar}};
    c.oracle = single_mode_full();
    add(c);
    c.name = "2D prime grid 31 x 37, single mode, partial contact";
    c.checks = "all converged solvers agree";
    c.steps = {{ASP_CONTROL_PENETRATION, 0.011}};
    c.oracle = nullptr;
    add(c);
    c.name = "1 x 1 grid, penetration";
    c.checks = "flat: uniform, p = K~(0) delta";
    c.scene = square(1, 1.0);
    c.steps = {{ASP_CONTROL_PENETRATION, 0.01}};
    c.oracle = flat();
    add(c);
  }
  // ---- Flat surfaces and zero load.
  {
    Case c;
    c.scene = square(16, 1.0);
    c.unique = true;
    c.oracle = flat();
    c.checks = "flat: uniform fields, exact pressure and gap";
    c.name = "flat, mean pressure";
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.01}};
    add(c);
    c.name = "flat, penetration";
    c.steps = {{ASP_CONTROL_PENETRATION, 0.01}};
    add(c);
    c.name = "flat, negative penetration (apart)";
    c.steps = {{ASP_CONTROL_PENETRATION, -0.01}};
    add(c);
    c.name = "flat, mean gap";
    c.steps = {{ASP_CONTROL_MEAN_GAP, 0.01}};
    add(c);
    c.name = "flat, zero load";
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.0}};
    c.oracle = [flat = flat(), touching = touching()](const Scene &s, const Settings &t,
                                                      const Step &step, const Outcome &o,
                                                      std::vector<std::string> &bad) {
      flat(s, t, step, o, bad);
      touching(s, t, step, o, bad);
    };
    c.checks = "flat: uniform fields, exact pressure and gap; touching everywhere or nowhere";
    add(c);
    c.name = "sinusoid, zero load";
    c.checks = "touching at the top, zero pressure";
    c.scene = line(64, 1.0, h0);
    c.oracle = touching();
    add(c);
    c.name = "sinusoid, zero penetration";
    c.steps = {{ASP_CONTROL_PENETRATION, 0.0}};
    add(c);
    c.name = "sinusoid, tensile load (non-adhesive)";
    c.checks = "refused: no equilibrium without adhesion";
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, -0.01}};
    c.no_equilibrium = true;
    add(c);
  }
  // ---- Contact near 0: a single pixel.
  {
    Case c;
    c.checks = "one pixel in contact: fraction 1/N, apex pressure exact";
    c.scene = paraboloid(33, 1.0, 1.0);
    c.unique = true;
    c.oracle = single_pixel(16 + 33 * 16);
    c.name = "single pixel, periodic sphere (mean pressure)";
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 1e-6}};
    add(c);
    c.name = "single pixel, periodic sphere (penetration)";
    c.steps = {{ASP_CONTROL_PENETRATION, 1e-5}};
    add(c);
    c.name = "single pixel, free sphere (penetration)";
    c.scene.free_substrate = true;
    add(c);
    c.name = "Hertz, free substrate 49 x 49 (penetration)";
    c.checks = "Hertz force within 1 % (contact radius 8 pixels)";
    c.scene = paraboloid(49, 1.0, 1.0);
    c.scene.free_substrate = true;
    c.steps = {{ASP_CONTROL_PENETRATION, std::pow(8.0 / 49, 2)}};
    c.oracle = hertz(1.0, 0.01);
    add(c);
    c.name = "Hertz, free substrate 25 x 25 (penetration)";
    c.checks = "Hertz force within 2 % (contact radius 4 pixels)";
    c.scene = paraboloid(25, 1.0, 1.0);
    c.scene.free_substrate = true;
    c.steps = {{ASP_CONTROL_PENETRATION, std::pow(4.0 / 25, 2)}};
    c.oracle = hertz(1.0, 0.02);
    add(c);
    const double units[][2] = {{1e-9, 1e9}, {1e3, 1e-6}};
    for (const auto &u : units) {
      c.name = fmt("Hertz in units: box %g, E* %g", u[0], u[1]);
      c.checks = "dimensionless results of the unit scene, relative 1e-6; Hertz within 1 %";
      c.scene = scaled(paraboloid(49, 1.0, 1.0), u[0], u[1]);
      c.scene.free_substrate = true;
      c.steps = {{ASP_CONTROL_PENETRATION, std::pow(8.0 / 49, 2) * u[0]}};
      c.oracle = hertz(u[0], 0.01);
      c.baseline = "Hertz, free substrate 49 x 49 (penetration)";
      c.length_scale = u[0];
      c.modulus_scale = u[1];
      add(c);
    }
  }
  // ---- A rough surface (thesis Table 2, reduced): 64 x 64, Hurst 0.8, rms slope 0.1,
  // from the box down to 4 pixels; about 10 % and above 99 % contact.
  {
    Case c;
    c.scene = square(64, 1.0);
    asp_grid *g = nullptr;
    if (asp_grid_create_2d(64, 64, 1.0, 1.0, &g) == ASP_OK &&
        asp_grid_set_fft_planning(g, ASP_FFT_ESTIMATE) == ASP_OK)  // see build()
      asp_topography_self_affine(g, 0.8, 1.0, 1.0, 4.0 / 64, ASP_RMS_SLOPE, 0.1, 1,
                                 c.scene.h.data(), 64 * 64);
    asp_grid_destroy(g);
    const double range = *std::max_element(c.scene.h.begin(), c.scene.h.end()) -
                         *std::min_element(c.scene.h.begin(), c.scene.h.end());
    c.unique = true;
    c.checks = "all converged solvers agree";
    c.name = "rough 64 x 64, about 10 % contact (penetration)";
    c.steps = {{ASP_CONTROL_PENETRATION, 0.45 * range}};
    add(c);
    c.name = "rough 64 x 64, above 99 % contact (penetration)";
    c.steps = {{ASP_CONTROL_PENETRATION, 1.6 * range}};
    add(c);
    c.name = "rough 64 x 64, light load (mean pressure)";
    c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.002}};
    add(c);
    c.name = "rough 64 x 64, free substrate (penetration)";
    c.scene.free_substrate = true;
    c.steps = {{ASP_CONTROL_PENETRATION, 0.45 * range}};
    add(c);
  }
  // ---- Moduli and boxes: the Westergaard scene in other units.
  {
    const double sets[][2] = {{1e-9, 1e-6}, {1e3, 1e9}, {1e-9, 1e9}, {1e3, 1e-6}};
    for (const auto &u : sets) {
      Case c;
      c.name = fmt("Westergaard in units: box %g, E* %g", u[0], u[1]);
      c.checks = "dimensionless results of the unit scene, relative 1e-6; sin^2 law";
      c.scene = scaled(line(64, 1.0, h0), u[0], u[1]);
      c.steps = {{ASP_CONTROL_PENETRATION, 0.012 * u[0]}};
      c.unique = true;
      c.oracle = westergaard(h0 * u[0], u[0], 64);
      c.baseline = "Westergaard 1D, 50 % contact (penetration)";
      c.length_scale = u[0];
      c.modulus_scale = u[1];
      add(c);
    }
  }
  // ---- Adhesive hard wall: a sphere, 32 x 32 on a unit box (pixel 1/32), R = 1, E* = 1,
  // pressed to the Hertz depth of a 4-pixel contact radius. The thesis's Table 3 range is
  // 1.06 pixels and its work of adhesion 1.02 E* pixel; ranges 0.1 pixel to 100 times the
  // thesis's, Tabor parameters 0.1 to 30.
  {
    const double px = 1.0 / 32, delta = std::pow(4 * px, 2);
    const double ranges[] = {0.1 * px, 1.06 * px, 106 * px};
    const char *rnames[] = {"0.1 pixel", "thesis 1.06 pixel", "100x thesis"};
    for (int k = 0; k < 3; ++k) {
      Case c;
      c.name = std::string("adhesive sphere, range ") + rnames[k];
      c.checks = "constraints and independent force balance";
      c.scene = paraboloid(32, 1.0, 1.0);
      c.scene.kind = Kind::adhesive;
      c.scene.w = 1.02 * px;
      c.scene.rho = ranges[k];
      c.steps = {{ASP_CONTROL_PENETRATION, delta}};
      add(c);
    }
    const double tabors[] = {0.1, 1, 3, 10, 30};
    for (double mu : tabors) {
      Case c;
      c.name = fmt("adhesive sphere, Tabor %g", mu);
      c.checks = mu <= 0.1 ? "constraints, force balance; both solvers agree"
                           : "constraints and independent force balance";
      c.scene = paraboloid(32, 1.0, 1.0);
      c.scene.kind = Kind::adhesive;
      c.scene.rho = 1.06 * px;
      c.scene.w = std::sqrt(mu * mu * mu * std::pow(c.scene.rho, 3));
      c.steps = {{ASP_CONTROL_PENETRATION, delta}};
      c.unique = mu <= 0.1;
      add(c);
    }
    Case c;
    c.name = "adhesive sphere, Tabor 0.1, warm starts from every step";
    c.checks = "each step from each other step: the cold-start result";
    c.scene = paraboloid(32, 1.0, 1.0);
    c.scene.kind = Kind::adhesive;
    c.scene.rho = 1.06 * px;
    c.scene.w = std::sqrt(std::pow(0.1, 3) * std::pow(c.scene.rho, 3));
    c.pairs = true;
    c.unique = true;
    c.steps.clear();
    for (double f : {-0.5, 0.0, 0.5, 1.0, 2.0})
      c.steps.push_back({ASP_CONTROL_PENETRATION, f * delta});
    add(c);
    c.pairs = false;
    c.name = "adhesive sphere, pulled far apart";
    c.checks = "detached: no contact";
    c.scene = paraboloid(32, 1.0, 1.0);
    c.scene.kind = Kind::adhesive;
    c.scene.rho = 1.06 * px;
    c.scene.w = 1.02 * px;
    c.steps = {{ASP_CONTROL_PENETRATION, -0.5}};
    c.unique = true;
    c.oracle = detached();
    add(c);
    c.name = "adhesive flat, penetration";
    c.checks = "flat: uniform fields";
    c.scene = square(16, 1.0);
    c.scene.kind = Kind::adhesive;
    c.scene.rho = 1.06 * px;
    c.scene.w = 1.02 * px;
    c.steps = {{ASP_CONTROL_PENETRATION, 0.001}};
    c.oracle = flat();
    add(c);
    c.name = "adhesive sphere, range 0.1 pixel, mean gap";
    c.checks = "constraints and independent force balance (mean-gap control)";
    c.scene = paraboloid(32, 1.0, 1.0);
    c.scene.kind = Kind::adhesive;
    c.scene.w = 1.02 * px;
    c.scene.rho = 0.1 * px;
    c.steps = {{ASP_CONTROL_MEAN_GAP, 0.1}};
    c.oracle = nullptr;
    c.unique = false;
    add(c);
    c.oracle = flat();
    c.checks = "flat: uniform fields";
    c.scene = square(16, 1.0);
    c.scene.kind = Kind::adhesive;
    c.scene.rho = 1.06 * px;
    c.scene.w = 1.02 * px;
    c.name = "adhesive flat, mean gap";
    c.steps = {{ASP_CONTROL_MEAN_GAP, 0.5 * px}};
    add(c);
    c.name = "adhesive sphere in units: box 1e-9, E* 1e9";
    c.checks = "dimensionless results of the unit scene, relative 1e-6";
    c.scene = scaled(paraboloid(32, 1.0, 1.0), 1, 1);
    c.scene.kind = Kind::adhesive;
    c.scene.w = std::sqrt(std::pow(1.06 * px, 3));
    c.scene.rho = 1.06 * px;
    c.scene = scaled(c.scene, 1e-9, 1e9);
    c.steps = {{ASP_CONTROL_PENETRATION, delta * 1e-9}};
    c.oracle = nullptr;
    c.baseline = "adhesive sphere, Tabor 1";
    c.length_scale = 1e-9;
    c.modulus_scale = 1e9;
    add(c);
  }
  // ---- Soft walls: the thesis's Table 4 profile (reduced to 128 pixels).
  {
    double rc = 1;
    const Scene base = table4_profile(&rc);
    const double ranges[] = {0.1, 0.262144, 2.62144, 26.2144};
    const char *rnames[] = {"0.1 pixel", "thesis 0.26 pixel", "10x thesis", "100x thesis"};
    for (int k = 0; k < 4; ++k) {
      Case c;
      c.name = std::string("soft wall, range ") + rnames[k];
      c.checks = "independent force balance";
      c.scene = base;
      soft_wall(c.scene, rc, ranges[k]);
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      c.settings.tolerance = 1e-9;
      c.settings.max_iterations = 20000;
      add(c);
    }
    const double tabors[] = {0.1, 1, 3, 10, 30};
    for (double mu : tabors) {
      Case c;
      c.name = fmt("soft wall, Tabor %g", mu);
      c.checks = "independent force balance";
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144, mu);
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      c.settings.tolerance = 1e-9;
      c.settings.max_iterations = 20000;
      add(c);
    }
    {
      Case c;
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144);
      c.settings.tolerance = 1e-9;
      c.settings.max_iterations = 20000;
      c.name = "soft wall, > 99 % contact";
      c.checks = "independent force balance; contact above 99 %";
      const double range = *std::max_element(base.h.begin(), base.h.end()) -
                           *std::min_element(base.h.begin(), base.h.end());
      c.steps = {{ASP_CONTROL_PENETRATION, 1.5 * range}};
      c.oracle = [](const Scene &, const Settings &, const Step &, const Outcome &o,
                    std::vector<std::string> &bad) {
        if (o.contact <= 0.99) bad.push_back(fmt("contact %g, not above 99 %%", o.contact));
      };
      add(c);
      c.name = "soft wall, apart (no contact)";
      c.checks = "detached: no repulsion anywhere";
      c.steps = {{ASP_CONTROL_PENETRATION, -20.0}};
      c.oracle = detached();
      c.unique = true;
      add(c);
      c.unique = false;
      c.name = "soft wall, zero load";
      c.checks = "independent force balance";
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.0}};
      c.oracle = nullptr;
      add(c);
      c.name = "soft wall, tensile load beyond pull-off";
      c.checks = "no equilibrium: must not converge; truthful reason within the limit";
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, -2 * largest_tensile_stress(c.scene)}};
      c.no_equilibrium = true;
      c.settings.max_iterations = 2000;
      add(c);
      c.no_equilibrium = false;
      c.settings.max_iterations = 20000;
      c.name = "soft wall, mean gap";
      c.checks = "refused: mean-gap control";
      c.steps = {{ASP_CONTROL_MEAN_GAP, 1.0}};
      add(c);
      c.name = "soft wall in units: box 1e-9, E* 1e-6";
      c.checks = "dimensionless results of the unit scene, relative 1e-6";
      c.scene = scaled(c.scene, 1e-9 / 128, 1e-6);
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      c.baseline = "soft wall, range thesis 0.26 pixel";
      c.length_scale = 1e-9 / 128;
      c.modulus_scale = 1e-6;
      add(c);
      c.name = "soft wall in units: box 1e3, E* 1e9";
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144);
      c.scene = scaled(c.scene, 1e3 / 128, 1e9);
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      c.length_scale = 1e3 / 128;
      c.modulus_scale = 1e9;
      add(c);
      c.baseline.clear();
      c.length_scale = c.modulus_scale = 1;
      c.name = "Lennard-Jones wall, z0 0.26 pixel";
      c.checks = "independent force balance";
      c.scene = base;
      c.scene.kind = Kind::lennard_jones;
      c.scene.rho = 0.262144;
      c.scene.w = 2.05 * 2.05 * rc / (4 * 2100);
      c.steps = {{ASP_CONTROL_PENETRATION, 0.05 * range - c.scene.rho}};
      add(c);
      c.name = "user potential (the soft wall), callback";
      c.checks = "independent force balance; the built-in soft wall's result, relative 1e-6";
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144);
      c.scene.kind = Kind::user_soft;
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      c.baseline = "soft wall, range thesis 0.26 pixel";
      add(c);
      c.baseline.clear();
      c.name = "user potential returning NaN";
      c.checks = "ASP_ERR_CALLBACK, state unchanged";
      c.scene.kind = Kind::user_nan;
      add(c);
      c.name = "user potential with hard wall (adhesion), callback";
      c.checks = "constraints, force balance; the built-in adhesion's result, relative 1e-6";
      c.scene = paraboloid(32, 1.0, 1.0);
      c.scene.kind = Kind::user_hard;
      c.scene.rho = 1.06 / 32;
      c.scene.w = std::sqrt(std::pow(1.06 / 32, 3));
      c.steps = {{ASP_CONTROL_PENETRATION, std::pow(4.0 / 32, 2)}};
      c.baseline = "adhesive sphere, Tabor 1";
      add(c);
    }
    // Soft walls on other grids and substrates.
    {
      Case c;
      c.settings.tolerance = 1e-9;
      c.settings.max_iterations = 20000;
      c.checks = "independent force balance; the 1D scene's result, relative 1e-6";
      c.baseline = "soft wall, range thesis 0.26 pixel";
      c.name = "soft wall, 128 x 1 strip";
      c.scene = base;
      c.scene.dim = 2;
      soft_wall(c.scene, rc, 0.262144);
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      add(c);
      c.name = "soft wall, 1 x 128 strip";
      c.scene.nx = 1;
      c.scene.ny = 128;
      c.scene.lx = 1;
      c.scene.ly = 128;
      add(c);
      c.baseline.clear();
      c.checks = "independent force balance";
      c.name = "soft wall, prime grid of 127 pixels";
      c.scene = base;
      c.scene.nx = 127;
      c.scene.lx = 127;
      c.scene.h.assign(127, 0.0);
      {
        asp_grid *g = nullptr;
        if (asp_grid_create_1d(127, 127.0, &g) == ASP_OK &&
            asp_grid_set_fft_planning(g, ASP_FFT_ESTIMATE) == ASP_OK)  // see build()
          asp_topography_self_affine(g, 0.8, 127.0, 127.0, 4.0, ASP_RMS_SLOPE, 0.1, 1,
                                     c.scene.h.data(), 127);
        asp_grid_destroy(g);
      }
      soft_wall(c.scene, rc, 0.262144);
      c.steps = {{ASP_CONTROL_PENETRATION, table4_penetration(c.scene)}};
      add(c);
      // An adhesive soft sphere: unit box, R = 1, range half a pixel, Tabor 1, pressed to
      // the Hertz depth of a 4-pixel contact past the potential's well.
      const auto sphere = [&](int64_t nx, int64_t ny) {
        Scene sc = paraboloid(nx, 1.0, 1.0);
        sc.ny = ny;
        sc.ly = static_cast<double>(ny) / nx;
        sc.h.resize(nx * ny);
        for (int64_t j = 0; j < ny; ++j)
          for (int64_t i = 0; i < nx; ++i) {
            const double x = (i - nx / 2) / static_cast<double>(nx),
                         y = (j - ny / 2) / static_cast<double>(nx);
            sc.h[i + nx * j] = -(x * x + y * y) / 2;
          }
        soft_wall(sc, 1.0, 0.5 / nx, 1.0);
        return sc;
      };
      const auto sphere_depth = [](const Scene &sc) {
        return std::pow(4.0 / sc.nx, 2) - sc.rr * std::log(2 * sc.gr / sc.ga);
      };
      c.name = "soft sphere, 2D prime grid 31 x 37";
      c.scene = sphere(31, 37);
      c.steps = {{ASP_CONTROL_PENETRATION, sphere_depth(c.scene)}};
      add(c);
      c.name = "soft sphere, free substrate 32 x 32";
      c.checks = "constraints (no independent force balance on the free substrate)";
      c.scene = sphere(32, 32);
      c.scene.free_substrate = true;
      c.steps = {{ASP_CONTROL_PENETRATION, sphere_depth(c.scene)}};
      add(c);
      c.name = "soft sphere, free substrate (mean pressure)";
      c.checks = "refused: mean-pressure control on the free substrate";
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.001}};
      add(c);
      c.checks = "flat: uniform fields; independent force balance";
      c.oracle = flat();
      c.name = "soft wall, flat (penetration)";
      c.scene = square(16, 1.0);
      soft_wall(c.scene, 1.0, 0.5 / 16, 1.0);
      c.steps = {{ASP_CONTROL_PENETRATION, 0.01}};
      add(c);
      c.name = "soft wall, flat, zero load";
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 0.0}};
      add(c);
      c.name = "soft wall, flat, tensile load within reach";
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, -0.5 * largest_tensile_stress(c.scene)}};
      add(c);
      c.name = "soft wall, flat, tensile load, tolerance 1e-4";
      c.checks = "flat: uniform fields; independent force balance (a looser tolerance)";
      c.settings.tolerance = 1e-4;
      add(c);
      c.name = "soft wall, tensile load within reach, tolerance 1e-4";
      c.checks = "independent force balance (a looser tolerance)";
      c.oracle = nullptr;
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144);
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, -0.02 * largest_tensile_stress(c.scene)}};
      add(c);
      c.settings.tolerance = 1e-9;
      // A repulsive wall of range 1e20 on a unit box (docs/algorithms.md, "A range far beyond
      // the box"), K~(0) = 1e3: it carries the mean pressure 1 in its continuation, 1e25
      // inside, so the penetration and the gaps are 1e25 while the displacement is 1e-3.
      c.name = "soft wall of range 1e20 on a unit box, under load";
      c.checks = "independent force balance";
      c.scene = paraboloid(31, 1.0, 1.0);
      c.scene.k0 = 1e3;
      c.scene.kind = Kind::soft;
      c.scene.gr = 1e-3;
      c.scene.rr = c.scene.ra = 1e20;
      c.scene.ga = 0;
      c.steps = {{ASP_CONTROL_MEAN_PRESSURE, 1.0}};
      add(c);
      c.oracle = nullptr;
      c.name = "user potential with hard wall returning NaN";
      c.checks = "ASP_ERR_CALLBACK, state unchanged";
      c.scene = paraboloid(32, 1.0, 1.0);
      c.scene.kind = Kind::user_nan;
      c.scene.rho = 1.06 / 32;
      c.scene.w = std::sqrt(std::pow(1.06 / 32, 3));
      c.steps = {{ASP_CONTROL_PENETRATION, std::pow(4.0 / 32, 2)}};
      c.scene.nan_hard_wall = true;
      add(c);
    }
    // Warm starts: a sweep of the soft wall with attraction switched off (one solution per
    // step), from every other step; and the adhesive one loading then unloading.
    {
      Case c;
      c.name = "soft repulsive wall, warm starts from every step";
      c.checks = "each step from each other step: the cold-start result, relative 1e-6";
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144);
      c.scene.ga = 0;
      const double range = *std::max_element(base.h.begin(), base.h.end()) -
                           *std::min_element(base.h.begin(), base.h.end());
      for (double f : {-0.1, 0.02, 0.1, 0.3, 1.2})
        c.steps.push_back({ASP_CONTROL_PENETRATION, f * range});
      c.pairs = true;
      c.unique = true;
      c.settings.tolerance = 1e-9;
      c.settings.max_iterations = 20000;
      add(c);
      c.name = "soft wall (thesis), load and unload sweep";
      c.checks = "independent force balance at each step";
      c.scene = base;
      soft_wall(c.scene, rc, 0.262144);
      c.steps.clear();
      for (double f : {-0.1, 0.0, 0.05, 0.1, 0.2, 0.1, 0.05, 0.0, -0.1})
        c.steps.push_back({ASP_CONTROL_PENETRATION, f * range});
      c.pairs = false;
      c.chain = true;
      c.unique = false;
      add(c);
    }
  }
  {
    Case c;
    c.name = "Westergaard, warm starts from every step";
    c.checks = "each step from each other step: sin^2 law and the cold-start result";
    c.scene = line(64, 1.0, h0);
    for (double d : {-0.005, 0.002, 0.01, 0.018, 0.03})
      c.steps.push_back({ASP_CONTROL_PENETRATION, d});
    c.pairs = true;
    c.unique = true;
    c.oracle = westergaard(h0, 1.0, 64);
    add(c);
    c.name = "Westergaard, warm starts (mean pressure)";
    c.steps.clear();
    for (double f : {0.0, 0.05, 0.5, 0.95, 1.5})
      c.steps.push_back({ASP_CONTROL_MEAN_PRESSURE, f * pstar});
    add(c);
    c.name = "adhesive double sinewave, load and unload";
    c.checks = "constraints and independent force balance at each step";
    c.scene = line(256, 1.0, 1.0);
    for (int64_t i = 0; i < 256; ++i) c.scene.h[i] += 0.05 * std::cos(2 * kPi * 32 * i / 256.0);
    c.scene.modulus = 1 / kPi;
    c.scene.kind = Kind::adhesive;
    c.scene.w = 0.03;
    c.scene.rho = 0.0153;
    c.steps.clear();
    for (double d : {-0.04, 0.0, 0.05, 0.1, 0.2, 0.1, 0.05, 0.0, -0.04})
      c.steps.push_back({ASP_CONTROL_PENETRATION, d});
    c.pairs = false;
    c.chain = true;
    c.unique = false;
    c.oracle = nullptr;
    c.settings.tolerance = 1e-9;
    c.settings.max_iterations = 20000;
    add(c);
  }
  return cs;
}

// ------------------------------------------------------------------------------------------
// Running the matrix
// ------------------------------------------------------------------------------------------
struct Cell {
  std::string text;
  std::vector<std::string> failures;
  bool refused = false;
  bool converged_all = false;
  Outcome first;  // the single step's outcome (or the last step's)
  bool has_first = false;
};

const char *reason_name(int r) {
  switch (r) {
    case ASP_TERMINATION_CONVERGED: return "converged";
    case ASP_TERMINATION_ITERATION_LIMIT: return "iteration limit";
    case ASP_TERMINATION_CANCELLED: return "cancelled";
    case ASP_TERMINATION_STALLED: return "stalled";
    case ASP_TERMINATION_BREAKDOWN: return "breakdown";
  }
  return "?";
}

int64_t stall_override = -1;  // --stall-window N: for every solve (a diagnostic)

// Agreement of two converged outcomes of one problem with a unique solution (and of a scene
// with its baseline in other units): the mean pressure over E*, the penetration over the
// length scale and the contact fraction. The residuals of two states each within tol p_ref
// differ by at most about 2 tol p_ref in pressure; allowed 1e-6 relative to the larger of the
// values and p_ref (tolerance 1e-10 .. 1e-9, so the bound keeps 1e3 of margin over the
// solver tolerance while any real difference of solutions is far larger), and for the
// contact fraction one pixel (a pixel at the edge of the contact carries a pressure of the
// order of the tolerance, whose sign two solvers may see differently).
void compare(const Scene &s, const Outcome &a, const Outcome &b, double ls, double ms,
             const char *what, std::vector<std::string> &bad) {
  // a in b's units
  const double ap = a.mean_p * ms, ad = a.delta * ls, ag = a.mean_gap * ls, aref = a.pref * ms;
  const double pscale = std::max({std::fabs(ap), std::fabs(b.mean_p), aref});
  if (std::fabs(ap - b.mean_p) > 1e-6 * pscale)
    bad.push_back(fmt("mean pressure %.10g vs %.10g", b.mean_p, ap) + " (" + what + ")");
  const double dscale = std::max(std::fabs(ad), std::fabs(ag));
  if (std::fabs(ad - b.delta) > 1e-6 * dscale + 1e-6 * aref / pixel_stiffness(s, b.k0))
    bad.push_back(fmt("penetration %.10g vs %.10g", b.delta, ad) + " (" + what + ")");
  // Without any pressure (zero load or penetration on the plain hard wall) the contact is the
  // touching pixels (the highest) for a gap solver and none for a pressure solver: one of
  // each is no disagreement (touching() checks each alone).
  const double top = *std::max_element(s.h.begin(), s.h.end());
  const double highest = static_cast<double>(std::count(s.h.begin(), s.h.end(), top)) /
                         static_cast<double>(s.h.size());
  const bool touching_or_not = a.mean_p == 0.0 && b.mean_p == 0.0 &&
                               ((a.contact == 0.0 && b.contact == highest) ||
                                (a.contact == highest && b.contact == 0.0));
  if (!touching_or_not &&
      std::fabs(a.contact - b.contact) > 1.0 / static_cast<double>(s.n()) + 1e-15)
    bad.push_back(fmt("contact %g vs %g", b.contact, a.contact) + " (" + what + ")");
}

Cell run_cell(Case &cs, const Column &col, const Cell *baseline_cell, const Outcome *row_first) {
  Cell cell;
  Scene &s = cs.scene;
  Handles hd;
  const std::string why = build(s, hd);
  if (!why.empty()) {
    cell.text = "scene refused";
    cell.failures.push_back(why);
    return cell;
  }
  asp_solver *solver = nullptr;
  if (asp_solver_create(col.algorithm, &solver) != ASP_OK) {
    cell.text = "not in this build";
    cell.refused = true;
    return cell;
  }
  Guard guard{20.0};
  asp_solver_set_tolerance(solver, cs.settings.tolerance);
  asp_solver_set_max_iterations(solver, cs.settings.max_iterations);
  const int64_t window = stall_override >= 0 ? stall_override : cs.settings.stall_window;
  if (window >= 0) asp_solver_set_option(solver, "stall_window", static_cast<double>(window));
  if (col.variable != nullptr) asp_solver_set_option_string(solver, "variable", col.variable);
  asp_solver_set_progress(solver, guard_progress, &guard);
  asp_solver_set_history(solver, 1);

  // Refusal: the documented rules, asp_solver_supports and asp_solver_solve agree, and a
  // refused solve leaves the state as it was.
  const Step &first = cs.steps.front();
  const std::string expect = expected_refusal(col, s, first);
  const int sup = asp_solver_supports(solver, hd.system, first.control);
  const std::string sup_message = asp_last_error_message();
  if (!expect.empty() || sup != ASP_OK) {
    Outcome before;
    read_state(s, hd.system, before);
    const int st = asp_solver_solve(solver, hd.system, first.control, first.value);
    const std::string msg = asp_last_error_message();
    Outcome after;
    read_state(s, hd.system, after);
    cell.refused = true;
    cell.text = "refused: " + (expect.empty() ? std::string("?") : expect);
    if (expect.empty())
      cell.failures.push_back("refused though documented to serve it: " + sup_message);
    const bool value_refusal = expect == "tensile load";
    if (!value_refusal && sup == ASP_OK)
      cell.failures.push_back("asp_solver_supports accepts what the rules refuse (" + expect + ")");
    if (value_refusal ? st != ASP_ERR_INVALID_ARGUMENT : st != ASP_ERR_UNSUPPORTED)
      cell.failures.push_back("solve returned " + std::to_string(st) + " (" + msg + ")");
    if (!value_refusal && st != sup) cell.failures.push_back("supports and solve disagree");
    if (msg.empty()) cell.failures.push_back("refusal without a message");
    if (before.p != after.p || before.g != after.g || before.delta != after.delta)
      cell.failures.push_back("a refused solve changed the state");
    asp_solver_destroy(solver);
    return cell;
  }

  const bool listed =
      find(kExpectedUnconverged, sizeof kExpectedUnconverged / sizeof kExpectedUnconverged[0],
           cs.name, col.label) != nullptr;
  int converged = 0, total = 0;
  int64_t max_it = 0;
  std::vector<int> reasons;
  const auto finish_step = [&](const Step &step, const Outcome &o, const char *label) {
    std::vector<std::string> bad;
    check_rules(s, cs.settings, step.control, step.value, o, bad);
    ++total;
    max_it = std::max(max_it, o.iterations);
    if (o.status == ASP_OK) reasons.push_back(o.reason);
    const bool conv = o.status == ASP_OK && o.reason == ASP_TERMINATION_CONVERGED;
    if (conv) {
      ++converged;
      if (cs.no_equilibrium) bad.push_back("converged where no equilibrium exists");
      if (bad.empty() && cs.oracle) cs.oracle(s, cs.settings, step, o, bad);
    } else if (o.status == ASP_OK && !cs.no_equilibrium && !listed) {
      bad.push_back(
          std::string("did not converge: ") + reason_name(o.reason) +
          fmt(" after %g iterations, error %g", static_cast<double>(o.iterations), o.error));
    }
    if (verbose)
      std::fprintf(
          stderr,
          "    %s | %s %s: %s, %lld it, error %.3g, pbar %.10g, delta %.10g, gap %.6g, contact "
          "%.6g\n",
          cs.name.c_str(), col.label, label, o.status == ASP_OK ? reason_name(o.reason) : "error",
          static_cast<long long>(o.iterations), o.error, o.mean_p, o.delta, o.mean_gap, o.contact);
    for (auto &b : bad) cell.failures.push_back(std::string(label) + b);
    return conv;
  };

  if (s.kind == Kind::user_nan) {
    // The callback's NaN ends the solve with ASP_ERR_CALLBACK and the state it started from.
    Outcome before;
    read_state(s, hd.system, before);
    const int st = asp_solver_solve(solver, hd.system, first.control, first.value);
    const std::string msg = asp_last_error_message();
    Outcome after;
    read_state(s, hd.system, after);
    cell.text = st == ASP_ERR_CALLBACK ? "error: callback" : "status " + std::to_string(st);
    if (st != ASP_ERR_CALLBACK)
      cell.failures.push_back("solve returned " + std::to_string(st) +
                              ", not ASP_ERR_CALLBACK: " + msg);
    if (msg.find("callback") == std::string::npos && msg.find("potential") == std::string::npos)
      cell.failures.push_back("the message does not name the callback: " + msg);
    if (before.p != after.p || before.g != after.g || before.delta != after.delta)
      cell.failures.push_back("the failed solve changed the state");
    asp_solver_destroy(solver);
    return cell;
  }

  if (cs.pairs) {
    std::vector<Outcome> cold(cs.steps.size());
    std::vector<bool> cold_ok(cs.steps.size());
    for (size_t k = 0; k < cs.steps.size(); ++k) {
      asp_system_reset(hd.system);
      cold[k] = solve(solver, s, hd.system, cs.steps[k].control, cs.steps[k].value);
      cold_ok[k] =
          finish_step(cs.steps[k], cold[k], fmt("cold step %g: ", static_cast<double>(k)).c_str());
    }
    for (size_t j = 0; j < cs.steps.size(); ++j)
      for (size_t k = 0; k < cs.steps.size(); ++k) {
        if (j == k) continue;
        asp_system_reset(hd.system);
        solve(solver, s, hd.system, cs.steps[j].control, cs.steps[j].value);
        const Outcome o = solve(solver, s, hd.system, cs.steps[k].control, cs.steps[k].value);
        const std::string label =
            fmt("step %g from step %g: ", static_cast<double>(k), static_cast<double>(j));
        if (finish_step(cs.steps[k], o, label.c_str()) && cold_ok[k] && cs.unique) {
          std::vector<std::string> bad;
          compare(s, cold[k], o, 1, 1, "cold start", bad);
          for (auto &b : bad) cell.failures.push_back(label + b);
        }
      }
  } else {
    Outcome o;
    for (size_t k = 0; k < cs.steps.size(); ++k) {
      o = solve(solver, s, hd.system, cs.steps[k].control, cs.steps[k].value);
      const std::string label = cs.steps.size() > 1 ? fmt("step %g: ", static_cast<double>(k)) : "";
      finish_step(cs.steps[k], o, label.c_str());
    }
    cell.first = o;
    cell.has_first = o.status == ASP_OK && o.reason == ASP_TERMINATION_CONVERGED;
    if (cell.has_first && baseline_cell != nullptr && baseline_cell->has_first)
      compare(s, baseline_cell->first, o, cs.length_scale, cs.modulus_scale,
              "the same scene in other units", cell.failures);
    if (cell.has_first && cs.unique && row_first != nullptr)
      compare(s, *row_first, o, 1, 1, "the first solver of the row", cell.failures);
  }
  cell.converged_all = converged == total;
  if (total == 1) {
    cell.text = std::string(reasons.empty() ? "error" : reason_name(reasons.front())) + ", " +
                std::to_string(max_it) + " it";
  } else {
    int limit = 0, stalled = 0, broke = 0;
    for (int r : reasons) {
      limit += r == ASP_TERMINATION_ITERATION_LIMIT;
      stalled += r == ASP_TERMINATION_STALLED;
      broke += r == ASP_TERMINATION_BREAKDOWN;
    }
    cell.text = "converged " + std::to_string(converged) + "/" + std::to_string(total);
    if (limit) cell.text += ", limit " + std::to_string(limit);
    if (stalled) cell.text += ", stalled " + std::to_string(stalled);
    if (broke) cell.text += ", breakdown " + std::to_string(broke);
    cell.text += ", <= " + std::to_string(max_it) + " it";
  }
  asp_solver_destroy(solver);
  return cell;
}

// Each check must be able to fail: a converged cell's outcome, perturbed by far less than
// any physical difference but far more than the allowances, must be rejected. Returns what
// was not rejected.
std::vector<std::string> self_test(const Case &cs, const Cell &cell, const Cell *baseline_cell,
                                   const Outcome *row_first) {
  std::vector<std::string> missed;
  const Scene &s = cs.scene;
  const Step &step = cs.steps.front();
  const Outcome &o = cell.first;
  const double n = static_cast<double>(s.n());
  // 1. One pixel's pressure off by 1e-4 (or 1000 tolerances) of the pressure scale (an open pixel
  // where there is one, which the free substrate's checks reach too).
  {
    Outcome x = o;
    size_t at = 0;
    double best = -1;
    for (size_t i = 0; i < x.p.size(); ++i) {
      const double key = s.hard_wall() ? x.g[i] : std::fabs(x.p[i]);
      if (key > best) {
        best = key;
        at = i;
      }
    }
    double pmax = 0;
    for (double v : x.p) pmax = std::max(pmax, std::fabs(v));
    x.p[at] += std::max(1e-4, 1e3 * cs.settings.tolerance) * std::max(pmax, x.pref);
    std::vector<std::string> bad;
    check_rules(s, cs.settings, step.control, step.value, x, bad);
    if (bad.empty()) missed.push_back("a pixel's pressure off by 1e-4 passes the force balance");
  }
  // 1b. One pixel's gap off by 1e-6 of the scale, far above the consistency's allowance
  // (the residual's part at most about 1e-9 of it on the matrix's scenes).
  {
    Outcome x = o;
    const double scale = consistency_scale(s, x);
    size_t at = 0;
    for (size_t i = 0; i < x.g.size(); ++i)
      if (x.g[i] > x.g[at]) at = i;
    if (scale > 0 && !x.g.empty()) {
      x.g[at] += 1e-6 * scale;
      std::vector<std::string> bad;
      check_rules(s, cs.settings, step.control, step.value, x, bad);
      if (bad.empty()) missed.push_back("a pixel's gap off its displacement by 1e-6 passes");
    }
  }
  // 2. "Converged" with an error above the tolerance.
  {
    Outcome x = o;
    x.error = 10 * cs.settings.tolerance;
    std::vector<std::string> bad;
    check_rules(s, cs.settings, step.control, step.value, x, bad);
    if (bad.empty()) missed.push_back("converged above the tolerance passes");
  }
  // 3. The oracle and the comparisons, against single perturbations: (A) the contact three
  // pixels off; (B) every pressure 10 % and 1 % of p_ref up, the mean kept; (C) every other
  // pixel's pressure 1 % of p_ref up; (D) the mean pressure 10 % and 1 % of p_ref up; (E) the
  // mean gap and the penetration 10 % off. The oracle must reject at least one (each oracle
  // checks only some of these quantities), a comparison both (A) and (D).
  const double hr =
      *std::max_element(s.h.begin(), s.h.end()) - *std::min_element(s.h.begin(), s.h.end());
  std::vector<Outcome> perturbed(5, o);
  perturbed[0].contact += (o.contact + 3 / n <= 1 ? 3 / n : -3 / n);
  for (double &v : perturbed[1].p) v = 1.1 * v + 0.01 * o.pref;
  for (size_t i = 1; i < o.p.size(); i += 2) perturbed[2].p[i] += 0.01 * o.pref;
  perturbed[3].mean_p = 1.1 * o.mean_p + 0.01 * o.pref;
  perturbed[4].mean_gap = 1.1 * o.mean_gap + 1e-3 * (hr + std::fabs(o.delta));
  perturbed[4].delta = 1.1 * o.delta + 1e-3 * (hr + std::fabs(o.mean_gap));
  if (cs.oracle) {
    int rejected = 0;
    for (const auto &x : perturbed) {
      std::vector<std::string> bad;
      cs.oracle(s, cs.settings, step, x, bad);
      rejected += !bad.empty();
    }
    if (rejected == 0) missed.push_back("the oracle accepts every perturbed state");
  }
  const auto compare_rejects = [&](const Outcome &a, double ls, double ms, const char *what) {
    for (int k : {0, 3}) {
      std::vector<std::string> bad;
      compare(s, a, perturbed[k], ls, ms, "", bad);
      if (bad.empty())
        missed.push_back(std::string(what) + " accepts perturbation " + "AD"[k == 3]);
    }
  };
  if (baseline_cell != nullptr && baseline_cell->has_first)
    compare_rejects(baseline_cell->first, cs.length_scale, cs.modulus_scale,
                    "the comparison with the unit scene");
  if (cs.unique && row_first != nullptr && row_first != &cell.first)
    compare_rejects(*row_first, 1, 1, "the comparison between solvers");
  return missed;
}

}  // namespace

int main(int argc, char **argv) {
  bool markdown = false;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--markdown") == 0)
      markdown = true;
    else if (std::strcmp(argv[i], "--verbose") == 0)
      verbose = true;
    else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
      only = argv[++i];
    else if (std::strcmp(argv[i], "--stall-window") == 0 && i + 1 < argc)
      stall_override = std::atoll(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--markdown] [--verbose] [--only TEXT] [--stall-window N]\n",
                   argv[0]);
      return 2;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<Case> cases = make_cases();
  if (!only.empty()) {
    // The scenes whose name contains TEXT, with the scenes they are compared with.
    std::vector<Case> kept;
    for (const auto &c : cases)
      if (c.name.find(only) != std::string::npos) {
        for (const auto &b : cases)
          if (!c.baseline.empty() && b.name == c.baseline) kept.push_back(b);
        kept.push_back(c);
      }
    cases = kept;
  }
  std::vector<std::vector<Cell>> cells(cases.size());
  // The library never prints: while the matrix runs (without --verbose), the standard output
  // and error go to a file in the working directory, which must stay empty. A program that
  // stops there (a sanitizer's report, say) leaves the file for reading.
#ifdef ASPERITY_ROBUSTNESS_POSIX
  const char *capture_path = "robustness_captured_output.txt";
  std::fflush(stdout);
  std::fflush(stderr);
  std::FILE *captured = verbose ? nullptr : std::fopen(capture_path, "w+");
  if (captured) std::fprintf(stderr, "(output while solving goes to %s)\n", capture_path);
  std::fflush(stderr);
  const int saved_out = captured ? dup(1) : -1, saved_err = captured ? dup(2) : -1;
  if (captured) {
    dup2(fileno(captured), 1);
    dup2(fileno(captured), 2);
  }
#endif
  int failures = 0, defects = 0;
  std::vector<std::string> report;
  for (size_t r = 0; r < cases.size(); ++r) {
    const Case *base = nullptr;
    size_t base_row = 0;
    for (size_t b = 0; b < r; ++b)
      if (cases[b].name == cases[r].baseline) {
        base = &cases[b];
        base_row = b;
      }
    const Outcome *row_first = nullptr;
    cells[r].reserve(kColumnCount);  // row_first points into the row
    for (int c = 0; c < kColumnCount; ++c) {
      const Cell *bc = base != nullptr ? &cells[base_row][c] : nullptr;
      cells[r].push_back(run_cell(cases[r], kColumns[c], bc, row_first));
      const Cell &cell = cells[r].back();
      if (row_first == nullptr && cell.has_first) row_first = &cells[r].back().first;
      const Listed *defect = find(kKnownDefects, sizeof kKnownDefects / sizeof kKnownDefects[0],
                                  cases[r].name, kColumns[c].label);
      if (defect != nullptr) {
        ++defects;
        if (cell.failures.empty()) {
          ++failures;
          report.push_back(cases[r].name + " | " + kColumns[c].label +
                           ": listed as a known defect but passes; remove it from kKnownDefects");
        } else {
          cells[r].back().text = "DEFECT: " + cell.text;
          report.push_back(cases[r].name + " | " + kColumns[c].label + ": known defect (" +
                           defect->why + "): " + cell.failures.front());
        }
      } else if (!cell.failures.empty()) {
        ++failures;
        for (const auto &f : cell.failures)
          report.push_back(cases[r].name + " | " + kColumns[c].label + ": " + f);
      }
    }
  }
#ifdef ASPERITY_ROBUSTNESS_POSIX
  if (captured) {
    std::fflush(stdout);
    std::fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);
    std::fseek(captured, 0, SEEK_END);
    const long printed = std::ftell(captured);
    std::fclose(captured);
    if (printed == 0) std::remove(capture_path);
    if (printed != 0) {
      ++failures;
      report.push_back("the library printed " + std::to_string(printed) +
                       " bytes while solving (in " + capture_path + ")");
    }
  }
#endif
  // The checks can fail: each converged cell's state, perturbed, must be rejected.
  int self_tests = 0;
  for (size_t r = 0; r < cases.size(); ++r) {
    const Case *base = nullptr;
    size_t base_row = 0;
    for (size_t b = 0; b < r; ++b)
      if (cases[b].name == cases[r].baseline) {
        base = &cases[b];
        base_row = b;
      }
    const Outcome *row_first = nullptr;
    for (int c = 0; c < kColumnCount; ++c) {
      const Cell &cell = cells[r][c];
      if (!cell.has_first || !cell.failures.empty()) continue;
      if (row_first == nullptr) row_first = &cell.first;
      ++self_tests;
      for (const auto &m :
           self_test(cases[r], cell, base != nullptr ? &cells[base_row][c] : nullptr, row_first)) {
        ++failures;
        report.push_back(cases[r].name + " | " + kColumns[c].label + ": a check cannot fail: " + m);
      }
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (markdown) {
    std::printf("| scene | checks |");
    for (const auto &c : kColumns) std::printf(" %s |", c.label);
    std::printf("\n|---|---|");
    for (int c = 0; c < kColumnCount; ++c) std::printf("---|");
    std::printf("\n");
    for (size_t r = 0; r < cases.size(); ++r) {
      std::printf("| %s | %s |", cases[r].name.c_str(), cases[r].checks.c_str());
      for (const auto &cell : cells[r]) std::printf(" %s |", cell.text.c_str());
      std::printf("\n");
    }
    std::printf("\nNot converged, and expected not to (a truthful reason within the limit):\n\n");
    for (const auto &l : kExpectedUnconverged)
      std::printf("- %s, `%s`: %s.\n", l.scene, l.column, l.why);
    std::printf("\nKnown defects (cells marked DEFECT):\n\n");
    bool any = false;
    for (const auto &l : kKnownDefects)
      if (l.scene != nullptr) {
        std::printf("- %s, `%s`: %s.\n", l.scene, l.column, l.why);
        any = true;
      }
    if (!any) std::printf("none.\n");
  }
  for (const auto &line : report) std::fprintf(stderr, "%s\n", line.c_str());
  std::fprintf(stderr,
               "%zu scenes x %d solvers, %lld solves: %d failures, %d known defects, %d cells "
               "shown to reject a perturbed state, %.1f s\n",
               cases.size(), kColumnCount, static_cast<long long>(solves), failures, defects,
               self_tests, seconds);
  return failures == 0 ? 0 : 1;
}
