// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer driver of the C API (include/asperity/asperity.h).
//
// The input is read as a short program: each step picks a call (grids, topography generators,
// systems, interactions, solvers and their options, solves, getters, destruction in any order)
// and its arguments, among them doubles that may be NaN, infinite, huge or denormal, counts that
// do not match the arrays and NULL pointers. The header is a contract for every such input, and
// this driver checks it after every call, stopping the process (so that libFuzzer reports the
// input) when it is broken:
//   - every call returns one of the documented status codes, and ASP_ERR_INTERNAL never;
//   - after a failure asp_last_error_message() is not empty, and an output handle is NULL;
//     after a success it is empty;
//   - a topography call that fails writes nothing into the caller's array;
//   - after ASP_OK every number returned is finite (scalars, fields, statistics, spectra,
//     reports, histories);
//   - a solve returns a termination reason of its family, converged only with
//     ASP_TERMINATION_CONVERGED and then with an error that met the tolerance, and no more
//     iterations than allowed;
//   - nothing crashes, leaks or runs into undefined behaviour (AddressSanitizer, UBSan).
// Grids are kept to at most 64 x 64 pixels (4096 in 1D) and solves to at most 200 iterations, so
// that every input runs in milliseconds and a slow input is a finding, not the size of a grid.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "asperity/asperity.h"

namespace {

constexpr int64_t max_iterations_cap = 200;
constexpr int max_steps = 48;
constexpr int max_solves = 4;

[[noreturn]] void broken(const char *what, int line) {
  std::fprintf(stderr, "C API contract broken (fuzz_c_api.cpp:%d): %s; last error: '%s'\n", line,
               what, asp_last_error_message());
  __builtin_trap();
}
#define EXPECT(condition) \
  do {                    \
    if (!(condition)) broken(#condition, __LINE__); \
  } while (0)

// The documented status codes, and the message that goes with success or failure. With
// ASPERITY_FUZZ_TRACE set in the environment every call is printed, to read a reproducer.
int checked(int status, const char *call, int line) {
  static const bool trace = std::getenv("ASPERITY_FUZZ_TRACE") != nullptr;
  if (trace) std::fprintf(stderr, "%d: %s -> %d %s\n", line, call, status, asp_last_error_message());
  if (status < ASP_OK || status > ASP_ERR_IO) broken("status outside the documented codes", line);
  if (status == ASP_ERR_INTERNAL) broken("ASP_ERR_INTERNAL", line);
  const char *message = asp_last_error_message();
  if (message == nullptr) broken("asp_last_error_message() is NULL", line);
  if (status != ASP_OK && message[0] == '\0') broken("failure without a message", line);
  if (status == ASP_OK && message[0] != '\0') broken("success with an error message", line);
  return status;
}
#define CALL(expression) checked((expression), #expression, __LINE__)

bool trace_enabled() { return std::getenv("ASPERITY_FUZZ_TRACE") != nullptr; }

// The arguments of a call, in trace mode.
template <typename... Args>
void note(const char *format, Args... args) {
  if (trace_enabled()) std::fprintf(stderr, format, args...);
}

bool finite_all(const double *values, int64_t n) {
  for (int64_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i])) return false;
  return true;
}

// The bytes of the input, read front to back; zeros once they are used up.
class Input {
 public:
  Input(const uint8_t *data, size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  int pick(int choices) { return byte() % choices; }
  bool flag() { return byte() & 1; }
  uint32_t u32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | byte();
    return v;
  }
  int64_t i64() {
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v = (v << 8) | byte();
    int64_t s;
    std::memcpy(&s, &v, sizeof s);
    return s;
  }
  // A double: mostly from a table of the values that break arithmetic and of ordinary ones,
  // sometimes any 64-bit pattern.
  double real() {
    static const double table[] = {0.0,
                                   -0.0,
                                   1.0,
                                   -1.0,
                                   0.5,
                                   2.0,
                                   0.1,
                                   1e-3,
                                   1e-8,
                                   1e-12,
                                   10.0,
                                   1e3,
                                   1e10,
                                   1e-300,
                                   1e300,
                                   std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::quiet_NaN(),
                                   0.8,
                                   0.05,
                                   0.25,
                                   3.0};
    constexpr int n_table = sizeof table / sizeof table[0];
    const uint8_t b = byte();
    if (b < 3 * n_table) return table[b % n_table];
    if (b < 240) return (b - 3 * n_table) * 0.01;  // a smooth range of small values
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits = (bits << 8) | byte();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  // A count near `n` (the right one most often), or any integer.
  int64_t count_near(int64_t n) {
    switch (pick(8)) {
      case 0: return n + 1;
      case 1: return n - 1;
      case 2: return 0;
      case 3: return -1 - (byte() % 4);
      case 4: return static_cast<int64_t>(byte() % 64) + 1;
      default: return n;
    }
  }
  std::string text(size_t max_length) {
    const size_t length = byte() % (max_length + 1);
    std::string s;
    for (size_t i = 0; i < length && !empty(); ++i) s += static_cast<char>(byte());
    return s.c_str();  // up to the first NUL, as a C string would be read
  }

 private:
  const uint8_t *data_;
  size_t size_;
  size_t pos_ = 0;
};

struct Pixels {
  int64_t nx = 0, ny = 0, n = 0;
};

Pixels shape_of(const asp_grid *grid) {
  Pixels p;
  int dimension = 0;
  if (grid != nullptr && CALL(asp_grid_get_shape(grid, &dimension, &p.nx, &p.ny, &p.n)) == ASP_OK)
    EXPECT((dimension == 1 || dimension == 2) && p.nx >= 1 && p.ny >= 1 && p.n == p.nx * p.ny);
  return p;
}

// The user potential: a smooth well, finite for every finite gap, or one that refuses (returns
// non-zero) or writes a NaN after some calls, as the input chose.
struct PotentialBehaviour {
  int mode = 0;        // 0 well behaved, 1 returns non-zero, 2 writes NaN
  int64_t after = 0;   // calls before it misbehaves
  int64_t calls = 0;
};

int user_potential(int64_t n, const double *gap, double *phi, double *dphi, double *d2phi,
                   void *user_data) {
  auto *behaviour = static_cast<PotentialBehaviour *>(user_data);
  const bool misbehave = behaviour->mode != 0 && behaviour->calls++ >= behaviour->after;
  if (misbehave && behaviour->mode == 1) return 3;
  for (int64_t i = 0; i < n; ++i) {
    // A quadratic repulsion below 0 and an exponential attraction above, both finite for every
    // finite gap.
    const double g = gap[i];
    if (g < 0) {
      phi[i] = -0.5 + 0.5 * g * g + 0.5 * g;
      dphi[i] = g + 0.5;
      if (d2phi) d2phi[i] = 1.0;
    } else {
      const double e = std::exp(-g);
      phi[i] = -0.5 * e;
      dphi[i] = 0.5 * e;
      if (d2phi) d2phi[i] = -0.5 * e;
    }
  }
  if (misbehave && n > 0) dphi[n / 2] = std::numeric_limits<double>::quiet_NaN();
  return 0;
}

struct Progress {
  int64_t cancel_at = -1;  // the iteration at which to return non-zero (-1 never)
};

int progress(int64_t iteration, double seconds, double error, void *user_data) {
  EXPECT(iteration >= 0);
  EXPECT(std::isfinite(seconds) && seconds >= 0);
  (void)error;  // may be DBL_MAX before the starting point is finite, always a number
  EXPECT(!std::isnan(error));
  const auto *p = static_cast<const Progress *>(user_data);
  return p->cancel_at >= 0 && iteration >= p->cancel_at ? 1 : 0;
}

const char *const algorithm_names[] = {"pk",   "bugnicourt", "lbfgsb", "lbfgs", "lbfgs_fourier",
                                       "fire", "fire_mass_weighted", "gfmd"};
const char *const option_names[] = {"tolerance",      "max_iterations",   "stall_window",
                                    "variable",       "memory",           "time_step",
                                    "max_time_step",  "time_step_growth", "time_step_shrink",
                                    "mixing",         "mixing_decay",     "delay",
                                    "damping"};

const char *option_name(Input &in, std::string &scratch) {
  const int k = in.pick(16);
  if (k < 13) return option_names[k];
  if (k == 15) return nullptr;
  scratch = in.text(16);
  return scratch.c_str();
}

// The key families of the header, plus values of other families and arbitrary ones.
int scalar_key(Input &in) {
  const int k = in.pick(20);
  if (k < 15) return 301 + k;
  if (k == 15) return 401;
  if (k == 16) return 316;
  if (k == 17) return 300;
  return static_cast<int>(in.u32());
}
int field_key(Input &in) {
  const int k = in.pick(8);
  if (k < 4) return 401 + k;
  if (k == 4) return 301;
  if (k == 5) return 405;
  return static_cast<int>(in.u32());
}
int control_key(Input &in) {
  const int k = in.pick(8);
  if (k < 3) return 501 + k;
  if (k < 6) return 501 + k % 2;
  if (k == 6) return 401;
  return static_cast<int>(in.u32());
}
int history_key(Input &in) {
  const int k = in.pick(10);
  if (k < 7) return 601 + k;
  if (k == 7) return 608;
  if (k == 8) return 501;
  return static_cast<int>(in.u32());
}

// Caps the iteration count of a solver (the driver's, not the contract's limit).
void cap_iterations(asp_solver *solver) {
  double current = 0;
  if (solver == nullptr) return;
  CALL(asp_solver_get_option(solver, "max_iterations", &current));
  if (!(current <= max_iterations_cap)) CALL(asp_solver_set_max_iterations(solver, max_iterations_cap));
}

struct State {
  asp_grid *grid = nullptr;
  asp_system *systems[2] = {nullptr, nullptr};
  asp_solver *solvers[2] = {nullptr, nullptr};
  int64_t pixels[2] = {0, 0};  // of each system's grid
  PotentialBehaviour potential;
  Progress progresses[2];
  int solves = 0;

  ~State() {
    asp_grid_destroy(grid);
    for (asp_system *s : systems) asp_system_destroy(s);
    for (asp_solver *s : solvers) asp_solver_destroy(s);
  }
};

// A caller's array: the count the call is told, and a buffer of exactly that many doubles (at
// least one), filled with a marker so that a failed call can be seen to have written nothing.
struct Array {
  explicit Array(int64_t n) : n(n), values(n > 0 ? static_cast<size_t>(n) : 1, marker) {}
  static constexpr double marker = 12345.678;
  bool untouched() const {
    for (double v : values)
      if (v != marker) return false;
    return true;
  }
  int64_t n;
  std::vector<double> values;
};

void make_grid(State &s, Input &in) {
  asp_grid *grid = reinterpret_cast<asp_grid *>(&s);  // a non-NULL marker
  int status;
  if (in.flag()) {
    const int64_t nx = in.flag() ? 1 + in.byte() % 64 : 1 + (in.u32() % 4096);
    const int64_t size = in.pick(16) == 0 ? -in.byte() : nx;
    const double lx = in.real();
    note("  1D grid nx %lld lx %.17g\n", static_cast<long long>(size), lx);
    status = CALL(asp_grid_create_1d(size, lx, &grid));
  } else {
    const int64_t nx = 1 + in.byte() % 64, ny = 1 + in.byte() % 64;
    const int64_t size_x = in.pick(16) == 0 ? 0 : nx;
    const double lx = in.real(), ly = in.real();
    note("  2D grid %lld x %lld, box %.17g x %.17g\n", static_cast<long long>(size_x),
         static_cast<long long>(ny), lx, ly);
    status = CALL(asp_grid_create_2d(size_x, ny, lx, ly, &grid));
  }
  if (status != ASP_OK) {
    EXPECT(grid == nullptr);
    return;
  }
  EXPECT(grid != nullptr);
  asp_grid_destroy(s.grid);  // systems made on the old grid keep it alive
  s.grid = grid;
  double lx = 0, ly = 0;
  CALL(asp_grid_get_box(grid, &lx, &ly));
  EXPECT(std::isfinite(lx) && lx > 0 && std::isfinite(ly) && ly > 0);
  // FFTW's measuring planner is slow for a fuzzer and adds nothing to what is checked here.
  if (!in.flag()) CALL(asp_grid_set_fft_planning(grid, ASP_FFT_ESTIMATE));
}

void grid_settings(State &s, Input &in) {
  asp_grid *grid = in.pick(16) == 0 ? nullptr : s.grid;
  switch (in.pick(4)) {
    case 0: {
      const int k = in.pick(4);
      const int planning = k == 0 ? ASP_FFT_ESTIMATE : k == 1 ? ASP_FFT_MEASURE
                                                     : k == 2 ? 201 : static_cast<int>(in.u32());
      CALL(asp_grid_set_fft_planning(grid, planning));
      break;
    }
    case 1: {
      // A thread count up to 4 (a valid request for thousands of threads would only be slow),
      // or an invalid one.
      const int threads = in.flag() ? 1 + in.pick(4) : -static_cast<int>(in.byte());
      CALL(asp_grid_set_threads(grid, threads));
      break;
    }
    case 2: {
      int threads = 0;
      if (CALL(asp_grid_get_threads(grid, &threads)) == ASP_OK) EXPECT(threads >= 1);
      break;
    }
    default: {
      int64_t local_ny = -1, offset = -1, local = -1;
      if (CALL(asp_grid_get_slab(grid, &local_ny, &offset, &local)) == ASP_OK) {
        const Pixels p = shape_of(grid);
        EXPECT(local_ny == p.ny && offset == 0 && local == p.n);
      }
    }
  }
}

void topography(State &s, Input &in, std::vector<double> &heights) {
  const Pixels p = shape_of(s.grid);
  const asp_grid *grid = in.pick(32) == 0 ? nullptr : s.grid;
  Array a(in.count_near(p.n));
  const int which = in.pick(10);
  // The generators fill a fresh array (of markers); the analyses read the current heights.
  if (which >= 6 && static_cast<int64_t>(heights.size()) == a.n && a.n > 0) a.values = heights;
  double *h = in.pick(32) == 0 ? nullptr : a.values.data();
  int status = ASP_OK;
  switch (which) {
    case 0: status = CALL(asp_topography_flat(grid, h, a.n)); break;
    case 1: status = CALL(asp_topography_sphere(grid, in.real(), h, a.n)); break;
    case 2: status = CALL(asp_topography_paraboloid(grid, in.real(), h, a.n)); break;
    case 3: {
      const int64_t px = static_cast<int8_t>(in.byte()), py = static_cast<int8_t>(in.byte());
      status = CALL(asp_topography_sinusoid(grid, in.real(), px, py, h, a.n));
      break;
    }
    case 4: {
      const double amplitude = in.real(), ripple = in.real();
      status = CALL(asp_topography_double_sinewave(grid, amplitude, ripple,
                                                   static_cast<int8_t>(in.byte()), h, a.n));
      break;
    }
    case 5: {
      const double hurst = in.real(), long_cutoff = in.real(), rolloff = in.real(),
                   short_cutoff = in.real();
      const int normalise = in.flag() ? ASP_RMS_HEIGHT + in.pick(2) : static_cast<int>(in.u32());
      const double target = in.real();
      note("  hurst %.17g long %.17g rolloff %.17g short %.17g normalise %d target %.17g\n", hurst,
           long_cutoff, rolloff, short_cutoff, normalise, target);
      status = CALL(asp_topography_self_affine(grid, hurst, long_cutoff, rolloff, short_cutoff,
                                               normalise, target, in.i64(), h, a.n));
      break;
    }
    case 6: {
      // Statistics of the current heights.
      double rms[3] = {-1, -1, -1};
      const bool ask = in.flag();
      const int st = CALL(asp_topography_statistics(grid, h, a.n, &rms[0], ask ? &rms[1] : nullptr,
                                                    ask ? &rms[2] : nullptr));
      if (st == ASP_OK) EXPECT(finite_all(rms, 3));
      return;
    }
    case 7: {
      const std::vector<double> before = a.values;
      const int mode = in.flag() ? ASP_DETREND_MEAN + in.pick(3) : static_cast<int>(in.u32());
      const int st = CALL(asp_topography_detrend(grid, mode, h, a.n));
      if (st == ASP_OK) {
        EXPECT(finite_all(a.values.data(), a.n));
        heights = a.values;
      } else {
        EXPECT(std::memcmp(a.values.data(), before.data(), before.size() * sizeof(double)) == 0);
      }
      return;
    }
    case 8: {
      const int64_t bins = in.flag() ? 1 + in.byte() % 32 : in.count_near(p.n);
      Array q(bins), c(bins);
      const int st = CALL(asp_topography_power_spectrum(grid, h, a.n, bins, q.values.data(),
                                                        c.values.data()));
      if (st == ASP_OK) {
        EXPECT(finite_all(q.values.data(), bins) && finite_all(c.values.data(), bins));
      } else {
        EXPECT(q.untouched() && c.untouched());
      }
      return;
    }
    default: {
      // Arbitrary heights, including non-finite ones.
      const int64_t n = a.n > 0 ? a.n : 0;
      const int fill = in.pick(4);
      for (int64_t i = 0; i < n; ++i)
        a.values[static_cast<size_t>(i)] = fill == 0 ? in.real() : fill == 1 ? 0.0 : std::sin(0.37 * i);
      heights.assign(a.values.begin(), a.values.begin() + n);
      return;
    }
  }
  if (status == ASP_OK) {
    EXPECT(a.n == p.n && finite_all(a.values.data(), a.n));
    heights.assign(a.values.begin(), a.values.end());
  } else {
    EXPECT(which < 6 && a.untouched());
  }
}

void make_system(State &s, Input &in) {
  const int slot = in.pick(2);
  asp_system *system = reinterpret_cast<asp_system *>(&s);
  const asp_grid *grid = in.pick(32) == 0 ? nullptr : s.grid;
  const double modulus = in.real();
  note("  system slot %d, modulus %.17g\n", slot, modulus);
  const int status = in.flag() ? CALL(asp_system_create(grid, modulus, &system))
                               : CALL(asp_system_create_free(grid, modulus, &system));
  if (status != ASP_OK) {
    EXPECT(system == nullptr);
    return;
  }
  EXPECT(system != nullptr);
  asp_system_destroy(s.systems[slot]);
  s.systems[slot] = system;
  s.pixels[slot] = shape_of(grid).n;
}

void system_settings(State &s, Input &in, const std::vector<double> &heights) {
  asp_system *system = s.systems[in.pick(2)];
  if (system == nullptr && in.flag()) return;
  switch (in.pick(10)) {
    case 0: {
      const int64_t n = in.count_near(static_cast<int64_t>(heights.size()));
      std::vector<double> h(n > 0 ? static_cast<size_t>(n) : 1, 0.0);
      std::copy(heights.begin(), heights.begin() + std::min<int64_t>(heights.size(), h.size()),
                h.begin());
      CALL(asp_system_set_topography(system, in.pick(32) == 0 ? nullptr : h.data(), n));
      break;
    }
    case 1: {
      const double w = in.real(), range = in.real();
      note("  adhesion %.17g %.17g\n", w, range);
      CALL(asp_system_set_adhesion(system, w, range));
      break;
    }
    case 2: {
      const double gr = in.real(), rr = in.real(), ga = in.real(), ra = in.real();
      note("  soft wall %.17g %.17g %.17g %.17g\n", gr, rr, ga, ra);
      CALL(asp_system_set_soft_wall(system, gr, rr, ga, ra));
      break;
    }
    case 3: {
      const double w = in.real(), z0 = in.real();
      note("  Lennard-Jones %.17g %.17g\n", w, z0);
      CALL(asp_system_set_lennard_jones(system, w, z0));
      break;
    }
    case 4: CALL(asp_system_set_hard_wall(system)); break;
    case 5: {
      s.potential.mode = in.pick(3);
      s.potential.after = in.byte() % 8;
      s.potential.calls = 0;
      const asp_potential_fn fn = in.pick(16) == 0 ? nullptr : user_potential;
      CALL(asp_system_set_potential(system, fn, &s.potential, in.flag()));
      break;
    }
    case 6: {
      const double k0 = in.real();
      note("  k0 %.17g\n", k0);
      CALL(asp_system_set_k0(system, k0));
      break;
    }
    case 7: {
      const double reference = in.real();
      note("  reference pressure %.17g\n", reference);
      CALL(asp_system_set_reference_pressure(system, reference));
      break;
    }
    default: CALL(asp_system_reset(system)); break;
  }
}

void make_solver(State &s, Input &in) {
  const int slot = in.pick(2);
  asp_solver *solver = reinterpret_cast<asp_solver *>(&s);
  std::string scratch;
  const int k = in.pick(10);
  const char *name = k < 8 ? algorithm_names[k] : k == 8 ? nullptr : (scratch = in.text(24)).c_str();
  note("  solver slot %d: %s\n", slot, name ? name : "(NULL)");
  if (CALL(asp_solver_create(name, &solver)) != ASP_OK) {
    EXPECT(solver == nullptr);
    return;
  }
  EXPECT(solver != nullptr);
  asp_solver_destroy(s.solvers[slot]);
  s.solvers[slot] = solver;
  cap_iterations(solver);
}

void solver_settings(State &s, Input &in) {
  const int slot = in.pick(2);
  asp_solver *solver = s.solvers[slot];
  if (solver == nullptr && in.flag()) return;
  std::string scratch, value_text;
  switch (in.pick(8)) {
    case 0: {
      const char *name = option_name(in, scratch);
      const double value = in.real();
      note("  option %s = %.17g\n", name ? name : "(NULL)", value);
      CALL(asp_solver_set_option(solver, name, value));
      break;
    }
    case 1: {
      const char *name = option_name(in, scratch);
      const int k = in.pick(4);
      const char *value = k == 0 ? "pressure" : k == 1 ? "gap" : k == 2 ? nullptr
                                                                : (value_text = in.text(12)).c_str();
      note("  option %s = \"%s\"\n", name ? name : "(NULL)", value ? value : "(NULL)");
      CALL(asp_solver_set_option_string(solver, name, value));
      break;
    }
    case 2: {
      const char *name = option_name(in, scratch);
      double value = std::numeric_limits<double>::quiet_NaN();
      if (CALL(asp_solver_get_option(solver, name, &value)) == ASP_OK) EXPECT(std::isfinite(value));
      char buffer[32];
      int64_t length = -1;
      const int64_t size = in.pick(4) == 0 ? 0 : static_cast<int64_t>(sizeof buffer);
      int64_t *length_out = in.flag() ? &length : nullptr;
      const int st = CALL(asp_solver_get_option_string(solver, name, size ? buffer : nullptr, size,
                                                       length_out));
      if (st == ASP_OK && size && length_out)
        EXPECT(static_cast<int64_t>(std::strlen(buffer)) == length);
      break;
    }
    case 3: {
      const double tolerance = in.real();
      note("  tolerance %.17g\n", tolerance);
      CALL(asp_solver_set_tolerance(solver, tolerance));
      break;
    }
    case 4: {
      const int64_t n = in.flag() ? in.byte() % (max_iterations_cap + 1) : in.i64();
      note("  max_iterations %lld\n", static_cast<long long>(n));
      CALL(asp_solver_set_max_iterations(solver, n));
      break;
    }
    case 5: CALL(asp_solver_set_history(solver, in.byte())); break;
    case 6: {
      s.progresses[slot].cancel_at = in.flag() ? in.byte() % 16 : -1;
      CALL(asp_solver_set_progress(solver, in.pick(4) == 0 ? nullptr : progress, &s.progresses[slot]));
      break;
    }
    default: {
      std::vector<char> buffer(1 + in.byte() % 64 * 32);
      int64_t length = -1;
      const int st = CALL(asp_solver_describe(solver, buffer.data(),
                                              static_cast<int64_t>(buffer.size()), &length));
      if (st == ASP_OK) EXPECT(length > 0 && static_cast<size_t>(length) == std::strlen(buffer.data()));
      if (st == ASP_ERR_SIZE_MISMATCH)
        EXPECT(std::strlen(buffer.data()) == buffer.size() - 1 && length >= int64_t(buffer.size()));
    }
  }
  cap_iterations(solver);
}

// The state of a system, after a solve or at any time: finite numbers.
void check_system(const asp_system *system) {
  if (system == nullptr) return;
  for (int key = ASP_CONTACT_FRACTION; key <= ASP_ADHESION_RANGE; ++key) {
    double value = std::numeric_limits<double>::quiet_NaN();
    if (CALL(asp_system_get(system, key, &value)) == ASP_OK) EXPECT(std::isfinite(value));
  }
}

void check_fields(const asp_system *system, int64_t n) {
  std::vector<double> values(static_cast<size_t>(n));
  for (int field = ASP_FIELD_PRESSURE; field <= ASP_FIELD_TOPOGRAPHY; ++field) {
    if (CALL(asp_system_get_field(system, field, values.data(), n)) == ASP_OK)
      EXPECT(finite_all(values.data(), n));
  }
}

void solve(State &s, Input &in) {
  if (s.solves >= max_solves) return;
  ++s.solves;
  const int slot = in.pick(2), system_slot = in.pick(2);
  asp_solver *solver = s.solvers[slot];
  asp_system *system = s.systems[system_slot];
  const int control = control_key(in);
  const double value = in.real();
  note("  solve: solver %d, system %d, control %d, value %.17g\n", slot, system_slot, control,
       value);
  if (solver != nullptr) cap_iterations(solver);
  const int supported = CALL(asp_solver_supports(solver, system, control));
  const int status = CALL(asp_solver_solve(solver, system, control, value));
  if (supported == ASP_ERR_UNSUPPORTED) EXPECT(status != ASP_OK);
  int reason = 0, converged = -1;
  int64_t iterations = -1, evaluations = -1, transforms = -1, length = -1;
  double error = -1, seconds = -1;
  if (status != ASP_OK) {
    if (solver != nullptr) EXPECT(CALL(asp_solver_termination(solver, &reason)) == ASP_ERR_INVALID_STATE);
    return;
  }
  CALL(asp_solver_termination(solver, &reason));
  CALL(asp_solver_converged(solver, &converged));
  CALL(asp_solver_iterations(solver, &iterations));
  CALL(asp_solver_evaluations(solver, &evaluations));
  CALL(asp_solver_transforms(solver, &transforms));
  CALL(asp_solver_final_error(solver, &error));
  CALL(asp_solver_elapsed_seconds(solver, &seconds));
  EXPECT(reason >= ASP_TERMINATION_CONVERGED && reason <= ASP_TERMINATION_BREAKDOWN);
  EXPECT(converged == (reason == ASP_TERMINATION_CONVERGED));
  EXPECT(iterations >= 0 && iterations <= max_iterations_cap);
  EXPECT(evaluations >= 0 && transforms >= 0);
  note("  solved: reason %d, %lld iterations, error %.17g\n", reason,
       static_cast<long long>(iterations), error);
  EXPECT(std::isfinite(error) && error >= 0);
  EXPECT(std::isfinite(seconds) && seconds >= 0);
  if (converged) {
    double tolerance = 0;
    CALL(asp_solver_get_option(solver, "tolerance", &tolerance));
    EXPECT(error <= tolerance);
  }
  check_system(system);
  check_fields(system, s.pixels[system_slot]);
  if (CALL(asp_solver_history_length(solver, &length)) == ASP_OK && length > 0) {
    EXPECT(length <= iterations + 1);
    std::vector<double> column(static_cast<size_t>(length));
    for (int c = ASP_HISTORY_ITERATION; c <= ASP_HISTORY_CONTACT_FRACTION; ++c)
      if (CALL(asp_solver_get_history(solver, c, column.data(), length)) == ASP_OK)
        EXPECT(finite_all(column.data(), length));
  }
}

void getters(State &s, Input &in) {
  const int slot = in.pick(2);
  const asp_system *system = in.pick(32) == 0 ? nullptr : s.systems[slot];
  const asp_solver *solver = in.pick(32) == 0 ? nullptr : s.solvers[slot];
  switch (in.pick(7)) {
    case 0: {
      double value = std::numeric_limits<double>::quiet_NaN();
      if (CALL(asp_system_get(system, scalar_key(in), &value)) == ASP_OK) EXPECT(std::isfinite(value));
      break;
    }
    case 1: {
      const int64_t n = in.count_near(s.pixels[slot]);
      Array a(n);
      const int st = CALL(asp_system_get_field(system, field_key(in), a.values.data(), n));
      if (st == ASP_OK) EXPECT(finite_all(a.values.data(), n));
      break;
    }
    case 2: {
      int64_t length = 0;
      if (CALL(asp_solver_history_length(solver, &length)) != ASP_OK) break;
      const int64_t n = in.count_near(length);
      Array a(n);
      if (CALL(asp_solver_get_history(solver, history_key(in), n ? a.values.data() : nullptr, n)) == ASP_OK)
        EXPECT(finite_all(a.values.data(), n));
      break;
    }
    case 3: {
      double error = -1;
      if (CALL(asp_solver_final_error(solver, &error)) == ASP_OK) EXPECT(std::isfinite(error));
      int64_t iterations = -1;
      CALL(asp_solver_iterations(solver, &iterations));
      int reason = 0;
      CALL(asp_solver_termination(solver, &reason));
      break;
    }
    case 4: {
      char buffer[64];
      int64_t length = -1;
      const int64_t size = static_cast<int64_t>(in.byte() % sizeof buffer);
      int64_t *length_out = in.flag() ? &length : nullptr;
      const int st = CALL(asp_algorithms(size ? buffer : nullptr, size, length_out));
      if (st == ASP_OK && size && length_out)
        EXPECT(static_cast<int64_t>(std::strlen(buffer)) == length);
      break;
    }
    case 5: {
      const char *text = asp_status_string(static_cast<int>(in.u32()) % 16 - 2);
      EXPECT(text != nullptr && text[0] != '\0');
      EXPECT(asp_version_string() != nullptr && asp_abi_version() >= 0);
      break;
    }
    default: {
      // Reading wisdom from a file that does not exist is an I/O error, not a crash.
      EXPECT(CALL(asp_fft_import_wisdom(in.flag() ? "/nonexistent/asperity-wisdom" : nullptr)) != ASP_OK);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  Input in(data, size);
  State s;
  std::vector<double> heights;
  for (int step = 0; step < max_steps && !in.empty(); ++step) {
    switch (in.pick(12)) {
      case 0: make_grid(s, in); break;
      case 1: grid_settings(s, in); break;
      case 2:
      case 3: topography(s, in, heights); break;
      case 4: make_system(s, in); break;
      case 5:
      case 6: system_settings(s, in, heights); break;
      case 7: make_solver(s, in); break;
      case 8: solver_settings(s, in); break;
      case 9: solve(s, in); break;
      case 10: getters(s, in); break;
      default: {
        // Destruction in any order: a system keeps its grid alive.
        switch (in.pick(3)) {
          case 0: asp_grid_destroy(s.grid); s.grid = nullptr; break;
          case 1: {
            const int i = in.pick(2);
            asp_system_destroy(s.systems[i]);
            s.systems[i] = nullptr;
            s.pixels[i] = 0;
            break;
          }
          default: {
            const int i = in.pick(2);
            asp_solver_destroy(s.solvers[i]);
            s.solvers[i] = nullptr;
          }
        }
      }
    }
  }
  for (asp_system *system : s.systems) check_system(system);
  return 0;
}
