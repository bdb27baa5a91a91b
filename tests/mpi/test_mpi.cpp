// SPDX-License-Identifier: GPL-2.0-or-later
// asperity on MPI, through the C API (asperity_mpi.h), run by ctest under mpirun with 1, 2
// and 3 processes. Each process also builds the same scene on a grid of its own (serial) and
// compares its rows:
//   - generators: the distributed surface is the serial one, to the bit, for any process
//     count, on even and odd grids, on a grid with fewer rows than processes and on one with
//     fewer spectral columns (which the processes hold of the transposed spectrum);
//   - solvers: every algorithm (and the options of the iterations against the grid: pk's
//     restart rule, the preconditioners, nested grids, bugnicourt's range continuation), on a
//     rough non-adhesive and a rough adhesive scene, on an even
//     and an odd grid, on the periodic and (where it takes it) the free substrate, gives the serial pressure and gap to 1e-10 of their largest magnitude,
//     and the serial scalars to 1e-10 relative. The processes' sums are added in a different
//     order than the serial ones and FFTW-MPI rounds differently from serial FFTW: rounding
//     differences of 1e-16 that a solve to 1e-11 amplifies by far less than 1e6;
//   - bad input on one process (an array with NaN, a wrong count, different grid sizes, a
//     failing callback, a cancel) is reported on every process with the same status, without
//     a hang, and the handles stay usable.
// Prints one line per failed check (on the failing process) and exits non-zero if any failed.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "../option_list.hpp"
#include "asperity/asperity_mpi.h"

namespace {

int rank = 0, ranks = 1;
int failures = 0;

void fail(const std::string &what) {
  std::fprintf(stderr, "[process %d of %d] FAILED: %s\n", rank, ranks, what.c_str());
  ++failures;
}

void require_ok(int status, const std::string &what) {
  if (status != ASP_OK)
    fail(what + ": status " + std::to_string(status) + ": " + asp_last_error_message());
}

struct Slab {
  int64_t rows = 0, offset = 0, pixels = 0;
};

Slab slab_of(const asp_grid *grid) {
  Slab s;
  require_ok(asp_grid_get_slab(grid, &s.rows, &s.offset, &s.pixels), "asp_grid_get_slab");
  return s;
}

// This process's rows of a whole field.
std::vector<double> rows_of(const std::vector<double> &whole, int64_t nx, const Slab &s) {
  return std::vector<double>(whole.begin() + nx * s.offset,
                             whole.begin() + nx * (s.offset + s.rows));
}

// A pointer for an array of this process's rows: NULL when it holds none, as a caller may.
double *data_or_null(std::vector<double> &v) { return v.empty() ? nullptr : v.data(); }

struct Grids {
  asp_grid *serial = nullptr, *distributed = nullptr;
  int64_t nx = 0, ny = 0;
  Slab slab;
  Grids(int64_t nx_, int64_t ny_) : nx(nx_), ny(ny_) {
    require_ok(asp_grid_create_2d(nx, ny, double(nx), double(ny), &serial), "serial grid");
    require_ok(asp_grid_create_mpi(MPI_COMM_WORLD, nx, ny, double(nx), double(ny), &distributed),
               "distributed grid");
    slab = slab_of(distributed);
  }
  ~Grids() {
    asp_grid_destroy(serial);
    asp_grid_destroy(distributed);
  }
};

std::vector<double> rough(asp_grid *grid, int64_t count, uint64_t seed) {
  std::vector<double> h(static_cast<size_t>(count));
  require_ok(asp_topography_self_affine(grid, 0.8, 64.0, 16.0, 4.0, ASP_RMS_SLOPE, 0.1,
                                        static_cast<int64_t>(seed), data_or_null(h), count),
             "asp_topography_self_affine");
  return h;
}

// ---- the processes' slabs ------------------------------------------------------------------

void slabs_cover_the_grid(int64_t nx, int64_t ny) {
  Grids g(nx, ny);
  int64_t mine[2] = {g.slab.offset, g.slab.rows};
  std::vector<int64_t> all(2 * static_cast<size_t>(ranks));
  MPI_Allgather(mine, 2, MPI_INT64_T, all.data(), 2, MPI_INT64_T, MPI_COMM_WORLD);
  int64_t next = 0;
  for (int r = 0; r < ranks; ++r) {
    const int64_t offset = all[2 * r], rows = all[2 * r + 1];
    if (rows > 0 && offset != next)
      fail("slabs of " + std::to_string(ny) + " rows are not in order");
    if (rows > 0) next = offset + rows;
  }
  if (next != ny) fail("slabs of " + std::to_string(ny) + " rows do not cover the grid");
  if (g.slab.pixels != nx * g.slab.rows) fail("local pixels differ from nx * local rows");
}

// ---- generators ----------------------------------------------------------------------------

void generators_give_the_serial_surface(int64_t nx, int64_t ny) {
  Grids g(nx, ny);
  const std::string where = std::to_string(nx) + "x" + std::to_string(ny);
  const std::vector<double> whole = rough(g.serial, nx * ny, 42);
  const std::vector<double> mine = rough(g.distributed, g.slab.pixels, 42);
  if (mine != rows_of(whole, nx, g.slab))
    fail("self-affine surface " + where + " is not the serial one");

  std::vector<double> a(static_cast<size_t>(nx * ny)), b(static_cast<size_t>(g.slab.pixels));
  require_ok(asp_topography_sinusoid(g.serial, 1.0, 2, 3, a.data(), nx * ny), "sinusoid");
  require_ok(asp_topography_sinusoid(g.distributed, 1.0, 2, 3, data_or_null(b), g.slab.pixels),
             "sinusoid");
  if (b != rows_of(a, nx, g.slab)) fail("sinusoid " + where + " is not the serial one");
  require_ok(asp_topography_sphere(g.serial, 40.0, a.data(), nx * ny), "sphere");
  require_ok(asp_topography_sphere(g.distributed, 40.0, data_or_null(b), g.slab.pixels), "sphere");
  if (b != rows_of(a, nx, g.slab)) fail("sphere " + where + " is not the serial one");

  // Statistics and detrending are of the whole surface.
  double serial[3], distributed[3];
  require_ok(asp_topography_statistics(g.serial, whole.data(), nx * ny, &serial[0], &serial[1],
                                       &serial[2]),
             "statistics");
  std::vector<double> local = mine;
  require_ok(asp_topography_statistics(g.distributed, data_or_null(local), g.slab.pixels,
                                       &distributed[0], &distributed[1], &distributed[2]),
             "statistics");
  for (int k = 0; k < 3; ++k)
    if (std::fabs(serial[k] - distributed[k]) > 1e-12 * std::fabs(serial[k]))
      fail("statistic " + std::to_string(k) + " of " + where + " differs");
  std::vector<double> tilted = whole;
  for (int64_t j = 0; j < ny; ++j)
    for (int64_t i = 0; i < nx; ++i) tilted[i + nx * j] += 0.01 * i - 0.02 * j + 3.0;
  std::vector<double> tilted_mine = rows_of(tilted, nx, g.slab);
  require_ok(asp_topography_detrend(g.serial, ASP_DETREND_PLANE, tilted.data(), nx * ny),
             "detrend");
  require_ok(asp_topography_detrend(g.distributed, ASP_DETREND_PLANE, data_or_null(tilted_mine),
                                    g.slab.pixels),
             "detrend");
  const std::vector<double> expected = rows_of(tilted, nx, g.slab);
  for (size_t k = 0; k < expected.size(); ++k)
    if (std::fabs(expected[k] - tilted_mine[k]) > 1e-12) {
      fail("plane detrending of " + where + " differs");
      break;
    }
}

// ---- solvers -------------------------------------------------------------------------------

// adhesive: a cohesive zone of 3.5 pixels (resolved); unresolved: of 0.16 pixel, where
// bugnicourt's range continuation ("auto") acts.
enum class Wall { hard, adhesive, unresolved, soft };

struct Case {
  const char *algorithm;
  const char *variable;
  Wall wall;
  int control;
  bool free_substrate = false;  // the free (non-periodic) half-space instead of the periodic
  const char *options = "";     // more options, "name=value" separated by spaces
};

// The options of a case, set on the solver.
void set_options(asp_solver *solver, const std::string &options) {
  for (const asp_test::OptionWord &o : asp_test::option_list(options)) {
    if (o.numeric)
      require_ok(asp_solver_set_option(solver, o.name.c_str(), o.number), o.name);
    else
      require_ok(asp_solver_set_option_string(solver, o.name.c_str(), o.text.c_str()), o.name);
  }
}

struct Outcome {
  std::vector<double> pressure, gap;
  double scalars[4] = {0, 0, 0, 0};  // mean pressure, mean gap, contact fraction, elastic energy
  int converged = 0;
  int64_t iterations = 0;
  double transforms = 0.0;  // of every level, a coarse level's weighted by its pixels
  double stiffness = 0.0;  // asp_solver_normal_stiffness of the converged state
};

Outcome solve(asp_grid *grid, int64_t count, const std::vector<double> &heights, const Case &c,
              double penetration) {
  Outcome out;
  asp_system *system = nullptr;
  asp_solver *solver = nullptr;
  if (c.free_substrate)
    require_ok(asp_system_create_free(grid, 1.0, &system), "asp_system_create_free");
  else
    require_ok(asp_system_create(grid, 1.0, &system), "asp_system_create");
  std::vector<double> h = heights;
  require_ok(asp_system_set_topography(system, data_or_null(h), count), "set_topography");
  if (c.wall == Wall::adhesive) require_ok(asp_system_set_adhesion(system, 0.02, 0.3), "adhesion");
  if (c.wall == Wall::unresolved)
    require_ok(asp_system_set_adhesion(system, 5e-4, 0.01), "adhesion");
  if (c.wall == Wall::soft)
    require_ok(asp_system_set_soft_wall(system, 0.05, 0.3, 0.01, 0.3), "soft wall");
  require_ok(asp_solver_create(c.algorithm, &solver), "asp_solver_create");
  require_ok(asp_solver_set_tolerance(solver, 1e-11), "tolerance");
  require_ok(asp_solver_set_max_iterations(solver, 20000), "max_iterations");
  if (*c.variable != '\0')
    require_ok(asp_solver_set_option_string(solver, "variable", c.variable), "variable");
  set_options(solver, c.options);
  // Mean pressure 0.005 E*, or the penetration given; a mean gap of half of it.
  const double value = c.control == ASP_CONTROL_PENETRATION ? penetration
                       : c.control == ASP_CONTROL_MEAN_GAP  ? 0.5 * penetration
                                                            : 0.005;
  require_ok(asp_solver_solve(solver, system, c.control, value),
             std::string("solve ") + c.algorithm);
  require_ok(asp_solver_converged(solver, &out.converged), "converged");
  require_ok(asp_solver_iterations(solver, &out.iterations), "iterations");
  require_ok(asp_solver_get(solver, ASP_REPORT_TRANSFORMS, &out.transforms), "transforms");
  if (out.converged)
    require_ok(asp_solver_normal_stiffness(solver, system, &out.stiffness), "normal stiffness");
  out.pressure.resize(static_cast<size_t>(count));
  out.gap.resize(static_cast<size_t>(count));
  require_ok(asp_system_get_field(system, ASP_FIELD_PRESSURE, data_or_null(out.pressure), count),
             "pressure");
  require_ok(asp_system_get_field(system, ASP_FIELD_GAP, data_or_null(out.gap), count), "gap");
  const int keys[4] = {ASP_MEAN_PRESSURE, ASP_MEAN_GAP, ASP_CONTACT_FRACTION, ASP_ELASTIC_ENERGY};
  for (int k = 0; k < 4; ++k) require_ok(asp_system_get(system, keys[k], &out.scalars[k]), "get");
  asp_solver_destroy(solver);
  asp_system_destroy(system);
  return out;
}

double largest(const std::vector<double> &v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

double largest_difference(const std::vector<double> &a, const std::vector<double> &b) {
  double m = 0.0;
  for (size_t k = 0; k < a.size(); ++k) m = std::max(m, std::fabs(a[k] - b[k]));
  return m;
}

void solver_gives_the_serial_result(const Case &c, int64_t nx, int64_t ny) {
  Grids g(nx, ny);
  const std::string name = std::string(c.algorithm) +
                           (*c.variable ? std::string("/") + c.variable : "") +
                           (c.wall == Wall::hard         ? " hard"
                            : c.wall == Wall::adhesive   ? " adhesive"
                            : c.wall == Wall::unresolved ? " unresolved"
                                                         : " soft") +
                           (c.free_substrate ? " free" : "") + c.options + " " +
                           std::to_string(nx) + "x" + std::to_string(ny);
  const std::vector<double> whole = rough(g.serial, nx * ny, 7);
  const double range =
      *std::max_element(whole.begin(), whole.end()) - *std::min_element(whole.begin(), whole.end());
  const double penetration = 0.15 * range;
  const Outcome serial = solve(g.serial, nx * ny, whole, c, penetration);
  const Outcome distributed =
      solve(g.distributed, g.slab.pixels, rows_of(whole, nx, g.slab), c, penetration);
  if (!serial.converged || !distributed.converged) {
    fail(name + ": did not converge (serial " + std::to_string(serial.converged) +
         ", distributed " + std::to_string(distributed.converged) + ")");
    return;
  }
  // The largest magnitudes are those of the whole fields, the same on every process.
  double scale[2] = {largest(serial.pressure), largest(serial.gap)};
  const std::vector<double> p = rows_of(serial.pressure, nx, g.slab),
                            u = rows_of(serial.gap, nx, g.slab);
  double difference[2] = {largest_difference(p, distributed.pressure),
                          largest_difference(u, distributed.gap)};
  MPI_Allreduce(MPI_IN_PLACE, difference, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  char line[256];
  std::snprintf(
      line, sizeof line, "%s: pressure %.1e, gap %.1e of their largest; %lld/%lld iterations",
      name.c_str(), difference[0] / scale[0], difference[1] / scale[1],
      static_cast<long long>(serial.iterations), static_cast<long long>(distributed.iterations));
  if (rank == 0) std::printf("%s\n", line);
  if (difference[0] > 1e-10 * scale[0] || difference[1] > 1e-10 * scale[1]) fail(line);
  for (int k = 0; k < 4; ++k)
    if (std::fabs(serial.scalars[k] - distributed.scalars[k]) >
        1e-10 * std::fabs(serial.scalars[k]) + 1e-300)
      fail(name + ": scalar " + std::to_string(k) + " " + std::to_string(serial.scalars[k]) +
           " vs " + std::to_string(distributed.scalars[k]));
  // Nested grids and the range continuation: the same levels and stages solved, with the
  // same iterations on each (a distributed solve that skipped its levels or its first stage
  // would count other transforms).
  if ((std::strstr(c.options, "levels=") != nullptr ||
       std::strstr(c.options, "range_continuation=") != nullptr) &&
      std::fabs(serial.transforms - distributed.transforms) > 1e-12 * serial.transforms)
    fail(name + ": transforms " + std::to_string(serial.transforms) + " vs " +
         std::to_string(distributed.transforms));
  // The stiffness: conjugate gradients whose sums run in another order, on states that agree
  // to 1e-10, with the same contact set.
  if (std::fabs(serial.stiffness - distributed.stiffness) > 1e-9 * std::fabs(serial.stiffness))
    fail(name + ": normal stiffness " + std::to_string(serial.stiffness) + " vs " +
         std::to_string(distributed.stiffness));
}

// ---- bad input on one process --------------------------------------------------------------

void expect_everywhere(int status, int expected, const std::string &what) {
  if (status != expected) {
    fail(what + ": status " + std::to_string(status) + ", expected " + std::to_string(expected) +
         " (" + asp_last_error_message() + ")");
    return;
  }
  if (ranks > 1 && std::strstr(asp_last_error_message(), "on process") == nullptr)
    fail(what + ": the message does not name the failing process: " + asp_last_error_message());
}

int failing_callback(int64_t n, const double *, double *phi, double *dphi, double *d2phi, void *) {
  for (int64_t i = 0; i < n; ++i) {
    phi[i] = 0.0;
    dphi[i] = 0.0;
    if (d2phi) d2phi[i] = 0.0;
  }
  return rank == ranks - 1 ? 1 : 0;  // the last process's callback fails
}

int cancel_on_last(int64_t iteration, double, double, void *) {
  return rank == ranks - 1 && iteration >= 3 ? 1 : 0;
}

void bad_input_on_one_process_fails_on_all() {
  const int last = ranks - 1;
  Grids g(32, 24);
  std::vector<double> h = rough(g.distributed, g.slab.pixels, 3);
  asp_system *system = nullptr;
  require_ok(asp_system_create(g.distributed, 1.0, &system), "system");

  std::vector<double> bad = h;
  if (rank == last && !bad.empty()) bad[0] = NAN;
  expect_everywhere(asp_system_set_topography(system, data_or_null(bad), g.slab.pixels),
                    ASP_ERR_INVALID_ARGUMENT, "NaN heights on the last process");
  const int64_t count = rank == last ? g.slab.pixels + 1 : g.slab.pixels;
  std::vector<double> longer(static_cast<size_t>(g.slab.pixels + 1), 0.0);
  expect_everywhere(asp_system_set_topography(system, longer.data(), count), ASP_ERR_SIZE_MISMATCH,
                    "a wrong count on the last process");
  // The handles are still usable.
  require_ok(asp_system_set_topography(system, data_or_null(h), g.slab.pixels),
             "good heights after bad");

  // Different sizes on one process.
  asp_grid *odd = nullptr;
  const int status =
      asp_grid_create_mpi(MPI_COMM_WORLD, rank == last ? 33 : 32, 24, 32.0, 24.0, &odd);
  if (ranks > 1)
    expect_everywhere(status, ASP_ERR_INVALID_ARGUMENT, "different sizes on one process");
  asp_grid_destroy(odd);

  // Different scalar arguments or solver options on one process: every process fails,
  // before anything is computed, rather than solving different problems.
  if (ranks > 1) {
    expect_everywhere(asp_system_set_adhesion(system, 0.02, rank == last ? 0.4 : 0.3),
                      ASP_ERR_INVALID_ARGUMENT, "a different range on the last process");
    asp_solver *differing = nullptr;
    require_ok(asp_solver_create("pk", &differing), "solver");
    require_ok(asp_solver_set_tolerance(differing, rank == last ? 1e-9 : 1e-8), "tolerance");
    expect_everywhere(asp_solver_solve(differing, system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
                      ASP_ERR_INVALID_ARGUMENT, "a different tolerance on the last process");
    expect_everywhere(
        asp_solver_solve(differing, system, ASP_CONTROL_MEAN_PRESSURE, rank == last ? 0.02 : 0.01),
        ASP_ERR_INVALID_ARGUMENT, "a different load on the last process");
    asp_solver_destroy(differing);
    // Another algorithm (with another number of options), history on one process only, and
    // another scalar asked for.
    asp_solver *other = nullptr;
    require_ok(asp_solver_create(rank == last ? "lbfgsb" : "pk", &other), "solver");
    expect_everywhere(asp_solver_solve(other, system, ASP_CONTROL_PENETRATION, 0.1),
                      ASP_ERR_INVALID_ARGUMENT, "another algorithm on the last process");
    asp_solver_destroy(other);
    require_ok(asp_solver_create("pk", &other), "solver");
    require_ok(asp_solver_set_history(other, rank == 0 ? 1 : 0), "history");
    expect_everywhere(asp_solver_solve(other, system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
                      ASP_ERR_INVALID_ARGUMENT, "history on the first process only");
    asp_solver_destroy(other);
    double value = 0.0;
    expect_everywhere(
        asp_system_get(system, rank == last ? ASP_ELASTIC_ENERGY : ASP_MEAN_PRESSURE, &value),
        ASP_ERR_INVALID_ARGUMENT, "another key on the last process");
  }

  // A different FFT planning on one process: the first transform is refused on every
  // process (FFTW-MPI plans together).
  if (ranks > 1) {
    asp_grid *planned = nullptr;
    require_ok(asp_grid_create_mpi(MPI_COMM_WORLD, 16, 12, 16.0, 12.0, &planned), "grid");
    require_ok(
        asp_grid_set_fft_planning(planned, rank == last ? ASP_FFT_ESTIMATE : ASP_FFT_MEASURE),
        "planning");
    const Slab s = slab_of(planned);
    std::vector<double> heights(static_cast<size_t>(s.pixels), 0.0);
    double height = 0.0;
    expect_everywhere(asp_topography_statistics(planned, data_or_null(heights), s.pixels, &height,
                                                nullptr, nullptr),
                      ASP_ERR_INVALID_STATE, "a different FFT planning on the last process");
    asp_grid_destroy(planned);
  }

  // A callback that fails on one process fails the solve on all.
  asp_solver *solver = nullptr;
  require_ok(asp_solver_create("lbfgs", &solver), "solver");
  require_ok(asp_system_set_potential(system, failing_callback, nullptr, 0), "potential");
  const int solved = asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.1);
  if (ranks > 1 && solved != ASP_ERR_CALLBACK)
    fail("a callback failing on one process: status " + std::to_string(solved));

  // A cancel asked on one process stops every process.
  require_ok(asp_system_set_soft_wall(system, 0.05, 0.3, 0.01, 0.3), "soft wall");
  require_ok(asp_solver_set_progress(solver, cancel_on_last, nullptr), "progress");
  require_ok(asp_solver_set_tolerance(solver, 1e-14), "tolerance");
  require_ok(asp_solver_solve(solver, system, ASP_CONTROL_PENETRATION, 0.1), "cancelled solve");
  int reason = 0;
  require_ok(asp_solver_termination(solver, &reason), "termination");
  if (reason != ASP_TERMINATION_CANCELLED)
    fail("a cancel on one process did not stop every process");
  asp_solver_destroy(solver);
  asp_system_destroy(system);
}

}  // namespace

// A distributed grid's default thread count is `expected` on every process (the tests
// mpi.default_threads* run the program with --default-threads N under various environments).
int default_threads_are(int expected) {
  asp_grid *grid = nullptr;
  require_ok(asp_grid_create_mpi(MPI_COMM_WORLD, 32, 32, 1.0, 1.0, &grid), "asp_grid_create_mpi");
  int threads = 0;
  require_ok(asp_grid_get_threads(grid, &threads), "asp_grid_get_threads");
  if (threads != expected)
    fail("the default thread count of a distributed grid is " + std::to_string(threads) +
         ", not " + std::to_string(expected));
  asp_grid_destroy(grid);
  return failures;
}

// ---- nested grids --------------------------------------------------------------------------
// A distributed grid is coarsened like a serial one (its coarse grids are distributed over the
// same processes, and restriction and prolongation move rows and spectral columns between
// their slabs); a count the grid cannot take (an odd size) is refused on every process alike,
// naming the option and why, and "auto" then takes none, solving as without levels.
void nested_levels_are_refused_where_the_grid_cannot_be_halved() {
  Grids g(45, 37);
  std::vector<double> h = rough(g.distributed, g.slab.pixels, 5);
  asp_system *system = nullptr;
  asp_solver *solver = nullptr;
  require_ok(asp_system_create(g.distributed, 1.0, &system), "system");
  require_ok(asp_system_set_topography(system, data_or_null(h), g.slab.pixels), "topography");
  require_ok(asp_solver_create("pk", &solver), "solver");
  require_ok(asp_solver_set_option(solver, "levels", 1.0), "levels 1");
  const int supports = asp_solver_supports(solver, system, ASP_CONTROL_MEAN_PRESSURE);
  const std::string message = asp_last_error_message();
  if (supports != ASP_ERR_UNSUPPORTED || message.find("option 'levels'") == std::string::npos ||
      message.find("odd") == std::string::npos)
    fail("levels 1 on a distributed grid of odd size: status " + std::to_string(supports) +
         ", '" + message + "'");
  const int solved = asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01);
  if (solved != ASP_ERR_UNSUPPORTED)
    fail("a solve with levels 1 on a distributed grid of odd size: status " +
         std::to_string(solved));
  require_ok(asp_solver_set_option_string(solver, "levels", "auto"), "levels auto");
  require_ok(asp_solver_solve(solver, system, ASP_CONTROL_MEAN_PRESSURE, 0.01),
             "a solve with levels auto on a distributed grid of odd size");
  int converged = 0;
  require_ok(asp_solver_converged(solver, &converged), "converged");
  if (!converged) fail("levels auto on a distributed grid of odd size: not converged");
  asp_solver_destroy(solver);
  asp_system_destroy(system);
}

// ---- the range continuation ---------------------------------------------------------------
// On the unresolved adhesive scene bugnicourt's first stage with the range times F (explicit,
// and "auto": sqrt(2 / zone), decided alike on every process) is solved distributed as it is
// serially (solver_gives_the_serial_result: the fields to 1e-10, the transforms of both
// stages), on an even and an odd grid, and with a coarse level before it. And the stage ran:
// the serial solve with it differs in its transforms from the one without.
void range_continuation_gives_the_serial_result() {
  const Case cases[] = {
      {"bugnicourt", "gap", Wall::unresolved, ASP_CONTROL_PENETRATION, false,
       " range_continuation=4"},
      {"bugnicourt", "gap", Wall::unresolved, ASP_CONTROL_PENETRATION, false,
       " range_continuation=auto"},
      {"bugnicourt", "gap", Wall::unresolved, ASP_CONTROL_PENETRATION, false,
       " range_continuation=0"},
  };
  for (const Case &c : cases) {
    solver_gives_the_serial_result(c, 64, 64);
    solver_gives_the_serial_result(c, 45, 37);
  }
  Case nested = cases[0];
  nested.options = " range_continuation=4 levels=1";
  solver_gives_the_serial_result(nested, 64, 64);

  Grids g(64, 64);
  const std::vector<double> whole = rough(g.serial, 64 * 64, 7);
  const double range =
      *std::max_element(whole.begin(), whole.end()) - *std::min_element(whole.begin(), whole.end());
  const Outcome continued = solve(g.serial, 64 * 64, whole, cases[1], 0.15 * range);
  const Outcome plain = solve(g.serial, 64 * 64, whole, cases[2], 0.15 * range);
  if (continued.transforms == plain.transforms && continued.iterations == plain.iterations)
    fail("range_continuation auto did nothing on the unresolved scene");
}

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (argc == 3 && std::strcmp(argv[1], "--default-threads") == 0) {
    const int failed = default_threads_are(std::atoi(argv[2]));
    MPI_Finalize();
    return failed == 0 ? 0 : 1;
  }

  slabs_cover_the_grid(64, 64);
  slabs_cover_the_grid(45, 37);
  slabs_cover_the_grid(16, 2);  // fewer rows than three processes
  slabs_cover_the_grid(2, 45);  // fewer spectral columns (2) than three processes
  generators_give_the_serial_surface(64, 48);
  generators_give_the_serial_surface(45, 37);
  generators_give_the_serial_surface(16, 2);
  generators_give_the_serial_surface(2, 45);
  bad_input_on_one_process_fails_on_all();
  nested_levels_are_refused_where_the_grid_cannot_be_halved();
  range_continuation_gives_the_serial_result();

  const Case cases[] = {
      {"pk", "", Wall::hard, ASP_CONTROL_MEAN_PRESSURE},
      {"bugnicourt", "pressure", Wall::hard, ASP_CONTROL_MEAN_PRESSURE},
      {"bugnicourt", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION},
      {"lbfgsb", "pressure", Wall::hard, ASP_CONTROL_PENETRATION},
      {"lbfgsb", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION},
      {"lbfgs", "", Wall::soft, ASP_CONTROL_PENETRATION},
      {"lbfgs_fourier", "", Wall::soft, ASP_CONTROL_MEAN_PRESSURE},
      {"fire", "", Wall::soft, ASP_CONTROL_PENETRATION},
      {"fire_mass_weighted", "", Wall::soft, ASP_CONTROL_PENETRATION},
      {"gfmd", "", Wall::soft, ASP_CONTROL_PENETRATION},
      {"bugnicourt", "gap", Wall::hard, ASP_CONTROL_MEAN_GAP},
  };
  for (const Case &c : cases) {
    solver_gives_the_serial_result(c, 64, 64);
    solver_gives_the_serial_result(c, 45, 37);
  }
  // The options of the iterations against the grid: pk's defaults (the Fourier
  // preconditioner, Powell's restarts, levels auto, which takes none on these grids) are
  // the cases above; here pk as published, and the preconditioner where it is not the
  // default, and "auto" levels on the other solvers (none on a grid of 64 a side or of odd
  // size, serial or distributed; nested grids below).
  const Case option_cases[] = {
      {"pk", "", Wall::hard, ASP_CONTROL_MEAN_PRESSURE, false,
       " preconditioner=none restart=entry levels=0"},
      {"pk", "", Wall::hard, ASP_CONTROL_PENETRATION, false, " restart=entry"},
      {"bugnicourt", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION, false,
       " preconditioner=fourier levels=auto"},
      {"bugnicourt", "pressure", Wall::hard, ASP_CONTROL_MEAN_PRESSURE, true,
       " preconditioner=none"},
      {"lbfgsb", "pressure", Wall::hard, ASP_CONTROL_PENETRATION, false, " levels=auto"},
  };
  for (const Case &c : option_cases) {
    solver_gives_the_serial_result(c, 64, 64);
    solver_gives_the_serial_result(c, 45, 37);
  }
  solver_gives_the_serial_result(cases[0], 16, 2);
  solver_gives_the_serial_result(cases[5], 16, 2);
  solver_gives_the_serial_result(cases[0], 2, 45);
  solver_gives_the_serial_result(cases[6], 2, 45);
  // Nested grids: every formulation and substrate, the adhesive continuation, and slabs of
  // the coarse grids that do not line up with halves of the fine ones (64 rows over three
  // processes are 22, 21 and 21; their 32 coarse rows 11, 11 and 10; the 8 rows of a 32 x 16
  // grid's coarse level leave some processes' fine rows on other processes' coarse rows).
  const Case nested_cases[] = {
      {"pk", "", Wall::hard, ASP_CONTROL_MEAN_PRESSURE, false, " levels=2"},
      {"pk", "", Wall::hard, ASP_CONTROL_PENETRATION, true, " levels=2"},
      {"bugnicourt", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION, false,
       " preconditioner=fourier levels=2"},
      {"bugnicourt", "pressure", Wall::hard, ASP_CONTROL_MEAN_PRESSURE, true, " levels=2"},
      {"lbfgsb", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION, false, " levels=2"},
      {"lbfgs", "", Wall::soft, ASP_CONTROL_PENETRATION, false, " levels=2"},
      {"fire", "", Wall::soft, ASP_CONTROL_PENETRATION, true, " levels=2"},
  };
  for (const Case &c : nested_cases) solver_gives_the_serial_result(c, 64, 64);
  for (Case c : {nested_cases[0], nested_cases[2]}) {
    c.options = " levels=1";  // 16 x 8 pixels: a smaller coarse grid would be refused
    solver_gives_the_serial_result(c, 32, 16);
  }
  // One row: every process but one holds none, and the gap's unknowns are only its pixels.
  solver_gives_the_serial_result(cases[5], 64, 1);
  solver_gives_the_serial_result(cases[10], 64, 1);

  // The free (non-periodic) substrate: its padded grid is distributed too. Every solver that
  // takes it (not lbfgs_fourier, gfmd and fire_mass_weighted, whose Fourier masses and
  // preconditioner need a periodic one), on an even and an odd grid, on one with fewer rows
  // than three processes, and on grids with few spectral columns.
  const Case free_cases[] = {
      {"pk", "", Wall::hard, ASP_CONTROL_MEAN_PRESSURE, true},
      {"bugnicourt", "pressure", Wall::hard, ASP_CONTROL_MEAN_PRESSURE, true},
      {"bugnicourt", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION, true},
      {"lbfgsb", "pressure", Wall::hard, ASP_CONTROL_PENETRATION, true},
      {"lbfgsb", "gap", Wall::adhesive, ASP_CONTROL_PENETRATION, true},
      {"lbfgs", "", Wall::soft, ASP_CONTROL_PENETRATION, true},
      {"fire", "", Wall::soft, ASP_CONTROL_PENETRATION, true},
  };
  for (const Case &c : free_cases) {
    solver_gives_the_serial_result(c, 32, 32);
    solver_gives_the_serial_result(c, 27, 19);
  }
  solver_gives_the_serial_result(free_cases[0], 16, 2);
  solver_gives_the_serial_result(free_cases[4], 16, 2);
  solver_gives_the_serial_result(free_cases[5], 16, 2);
  // Fewer spectral columns of the padded grid (nx + 1) than three processes hold, and as many.
  solver_gives_the_serial_result(free_cases[0], 1, 24);
  solver_gives_the_serial_result(free_cases[2], 2, 45);

  int total = failures;
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf("%s: %d failed checks on %d processes\n", total ? "FAILED" : "passed", total,
                ranks);
  MPI_Finalize();
  return total == 0 ? 0 : 1;
}
