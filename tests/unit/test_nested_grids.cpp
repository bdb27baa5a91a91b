// SPDX-License-Identifier: GPL-2.0-or-later
// Nested grids (option "levels"): the restriction of a system to a coarser grid, the
// prolongation of its state, and solves that start from coarser levels reaching the state
// that plain solves reach, on the closed-form scenes (Westergaard, Hertz) and an adhesive one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/spectral_layout.hpp"
#include "physics/coarse_system.hpp"
#include "physics/stiffness_law.hpp"
#include "scene.hpp"
#include "solvers/nested_grids.hpp"

namespace {

using asp::Control;
using asp_test::pi;

struct Outcome {
  asp::SolveReport report;
  std::vector<double> pressure;
  std::vector<double> gap;
  double penetration = 0.0;
  double contact = 0.0;
  double energy = 0.0;
};

// Solves a fresh copy of the scene with the given levels (levels_auto: "auto") and
// variable, if any.
Outcome solve_scene(const std::shared_ptr<asp::Grid> &grid, const std::vector<double> &h,
                    asp::SubstrateKind substrate, double work, double range,
                    const char *algorithm, const char *variable, Control control, double value,
                    double levels, double tolerance) {
  asp::System system(grid, 1.0, substrate);
  system.set_topography(h.data());
  if (work > 0.0) system.set_adhesion(work, range);
  asp::Solver solver(algorithm);
  solver.set_option("tolerance", tolerance);
  if (variable != nullptr) solver.set_option("variable", std::string(variable));
  if (levels == asp::levels_auto)
    solver.set_option("levels", std::string("auto"));
  else
    solver.set_option("levels", levels);
  solver.solve(system, control, value);
  Outcome o;
  o.report = solver.report();
  o.pressure = asp_test::field_vector(system.state().pressure);
  o.gap = asp_test::field_vector(system.state().gap);
  o.penetration = system.state().penetration;
  o.contact = system.contact_fraction();
  o.energy = system.elastic_energy() + system.mean_mode_energy() + system.interaction_energy();
  return o;
}

// ---- restriction and prolongation ----------------------------------------------------------

// The integer wavevectors that restriction reads spectra by: every stored entry visited once,
// in storage order, with kx in [0, nx/2] and ky signed in (-ny/2, ny/2], and entry() its
// inverse; by rows (a serial grid's spectrum) and by a slab of columns (a distributed one's),
// on odd and even sizes.
TEST(NestedGrids, SpectralLayoutWavevectorsAndEntriesAgree) {
  for (const auto &shape : {std::pair<std::int64_t, std::int64_t>{7, 6}, {8, 5}}) {
    const std::int64_t nx = shape.first, ny = shape.second, half = nx / 2 + 1;
    const asp::SpectralLayout rows(asp::Packing::half_spectrum, nx, ny, 1.0, 1.0);
    const asp::SpectralLayout slab(asp::Packing::transposed_half_spectrum, nx, ny, 1.0, 1.0, 2,
                                   1);
    for (const asp::SpectralLayout *layout : {&rows, &slab}) {
      const bool by_columns = layout == &slab;
      std::int64_t expected = 0;
      layout->for_each_wavevector([&](std::int64_t k, std::int64_t kx, std::int64_t ky) {
        EXPECT_EQ(k, expected);
        // The entry's own indices: by rows k = kx + half * row; by columns of the slab from
        // column 1, k = row + ny * (kx - 1).
        const std::int64_t row = by_columns ? k % ny : k / half;
        EXPECT_EQ(kx, by_columns ? 1 + k / ny : k % half);
        EXPECT_EQ(ky, 2 * row <= ny ? row : row - ny);
        EXPECT_EQ(layout->entry(kx, ky), k);
        ++expected;
      });
      EXPECT_EQ(expected, layout->size());
    }
  }
}

// A surface whose spectrum lies below the coarse grid's Nyquist wavevector restricts exactly:
// coarse pixel (i, j) holds the fine height at (2i, 2j), to rounding (1e-15 of the heights,
// a few FFT passes). A mode at the coarse Nyquist wavevector is dropped (see coarse_system.hpp).
TEST(NestedGrids, RestrictionIsExactForBandLimitedHeightsAndDropsTheCoarseNyquist) {
  const std::int64_t n = 32;
  auto grid = asp_test::grid_2d(n, n, 1.0, 2.0);
  std::vector<double> h(n * n), nyquist(n * n);
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t i = 0; i < n; ++i) {
      const double x = 2 * pi * i / n, y = 2 * pi * j / n;
      h[i + n * j] = 0.3 * std::cos(3 * x + 1.0) + 0.2 * std::sin(5 * x - 7 * y) +
                     0.1 * std::cos(7 * y) + 0.05;
      nyquist[i + n * j] = std::cos(8 * x);  // kx = 8 = (n/2)/2, the coarse Nyquist
    }
  asp::System fine(grid, 1.0);
  fine.set_topography(h.data());
  auto coarse = asp::coarse_system(fine);
  ASSERT_EQ(coarse->grid().nx(), n / 2);
  ASSERT_EQ(coarse->grid().ny(), n / 2);
  EXPECT_EQ(coarse->grid().lx(), 1.0);
  EXPECT_EQ(coarse->grid().ly(), 2.0);
  EXPECT_EQ(coarse->substrate().k0(), fine.substrate().k0());
  double worst = 0.0;
  for (std::int64_t j = 0; j < n / 2; ++j)
    for (std::int64_t i = 0; i < n / 2; ++i)
      worst = std::max(worst, std::fabs(coarse->heights()[i + n / 2 * j] -
                                        h[2 * i + n * 2 * j]));
  EXPECT_LT(worst, 1e-14);

  std::vector<double> restricted(n * n / 4);
  asp::resample_field(*grid, coarse->grid(), nyquist.data(), restricted.data());
  EXPECT_LT(asp_test::max_abs(restricted), 1e-14);
}

// Linear interpolation keeps the sign and, on a periodic grid, the mean of the pressure.
TEST(NestedGrids, ProlongedPressureKeepsSignAndMean) {
  const std::int64_t n = 16;
  auto fine = asp_test::grid_2d(n, n, 1.0, 1.0);
  auto coarse = asp_test::grid_2d(n / 2, n / 2, 1.0, 1.0);
  std::vector<double> c(n * n / 4), f(n * n);
  double mean = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i] = (i * 7919) % 5 == 0 ? 0.0 : static_cast<double>((i * 104729) % 13);
    mean += c[i] / c.size();
  }
  asp::prolong_pressure(*coarse, *fine, true, c.data(), f.data());
  double fine_mean = 0.0;
  for (double p : f) {
    EXPECT_GE(p, 0.0);
    fine_mean += p / f.size();
  }
  EXPECT_NEAR(fine_mean, mean, 1e-14 * mean);
  EXPECT_EQ(f[2 + n * 4], c[1 + n / 2 * 2]);  // the fine pixel at a coarse one's corner
}

// ---- nested solves reach the plain solve's state -------------------------------------------

// Westergaard's sinusoid in 1D (the scene of test_contact_oracles.cpp) with pk and bugnicourt
// under load control, two levels below 512 pixels.
TEST(NestedGrids, WestergaardNestedEqualsPlain) {
  const std::int64_t n = 512;
  const double h0 = 0.02;
  auto grid = asp_test::grid_1d(n, 1.0);
  std::vector<double> h(n);
  asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
  const double mean = 0.3 * pi * h0;
  for (const char *algorithm : {"pk", "bugnicourt"}) {
    const Outcome plain = solve_scene(grid, h, asp::SubstrateKind::periodic, 0, 0, algorithm,
                                      nullptr, Control::mean_pressure, mean, 0, 1e-10);
    const Outcome nested = solve_scene(grid, h, asp::SubstrateKind::periodic, 0, 0, algorithm,
                                       nullptr, Control::mean_pressure, mean, 2, 1e-10);
    ASSERT_TRUE(plain.report.converged());
    ASSERT_TRUE(nested.report.converged()) << algorithm;
    const double peak = asp_test::max_abs(plain.pressure);
    std::printf("Westergaard %s: %lld then %lld iterations, max dp/p %.1e\n", algorithm,
                (long long)plain.report.iterations, (long long)nested.report.iterations,
                asp_test::max_abs_difference(plain.pressure, nested.pressure) / peak);
    // Both meet the tolerance 1e-10 (a residual relative to the reference pressure); their
    // pressures differ by that residual through the inverse of the contact set's operator,
    // measured below 1e-10 of the peak: 100 times that leaves room for rounding elsewhere.
    EXPECT_EQ(nested.contact, plain.contact) << algorithm;
    EXPECT_LT(asp_test::max_abs_difference(plain.pressure, nested.pressure), 1e-8 * peak)
        << algorithm;
    // The coarse levels ran and gave a start closer than the cold one (measured 22 then 12
    // and 20 then 13 iterations): a nested solve that ignored them would equal the plain one.
    EXPECT_LT(nested.report.iterations, plain.report.iterations) << algorithm;
  }
}

// Hertz's paraboloid (the scene of test_contact_oracles.cpp, 128^2 here) with each solver of
// the hard wall under the controls it takes: pk and bugnicourt under load, bugnicourt on the
// gap under mean-gap control and lbfgsb under penetration control (where the coarse levels
// must keep the rigid body where it is, their highest height being lower), on the periodic
// and the free substrate.
struct NestedCase {
  const char *algorithm;
  const char *variable;
  Control control;
  asp::SubstrateKind substrate;
};
class NestedHertz : public ::testing::TestWithParam<NestedCase> {};

TEST_P(NestedHertz, NestedEqualsPlain) {
  const NestedCase c = GetParam();
  const std::int64_t n = 128;
  const double a = 1.0 / 12, radius = 1.0;
  auto grid = asp_test::grid_2d(n, n, 1.0, 1.0);
  std::vector<double> h(n * n);
  asp::paraboloid_topography(*grid, radius, h.data());
  double value = 4 * a * a * a / (3 * radius);
  if (c.control != Control::mean_pressure) {
    asp::System system(grid, 1.0, c.substrate);
    system.set_topography(h.data());
    asp::Solver pk("pk");
    pk.set_option("tolerance", 1e-10);
    pk.solve(system, Control::mean_pressure, value);
    value = c.control == Control::penetration ? system.state().penetration : system.mean_gap();
  }
  const Outcome plain = solve_scene(grid, h, c.substrate, 0, 0, c.algorithm, c.variable,
                                    c.control, value, 0, 1e-10);
  const Outcome nested = solve_scene(grid, h, c.substrate, 0, 0, c.algorithm, c.variable,
                                     c.control, value, 2, 1e-10);
  ASSERT_TRUE(plain.report.converged());
  ASSERT_TRUE(nested.report.converged());
  const double peak = asp_test::max_abs(plain.pressure);
  std::printf("Hertz: %lld then %lld iterations, max dp/p %.1e, d penetration %.1e\n",
              (long long)plain.report.iterations, (long long)nested.report.iterations,
              asp_test::max_abs_difference(plain.pressure, nested.pressure) / peak,
              nested.penetration - plain.penetration);
  // As for Westergaard: both meet the tolerance 1e-10; measured differences up to 5e-10 of
  // the peak pressure and 1e-14 of the penetration (where it is not the one imposed).
  EXPECT_EQ(nested.contact, plain.contact);
  EXPECT_LT(asp_test::max_abs_difference(plain.pressure, nested.pressure), 1e-8 * peak);
  EXPECT_NEAR(nested.penetration, plain.penetration, 1e-8 * std::fabs(plain.penetration));
  // The coarse levels ran (measured 10 to 81 iterations on the grid against 16 to 109).
  EXPECT_LT(nested.report.iterations, plain.report.iterations);
}

INSTANTIATE_TEST_SUITE_P(
    Solvers, NestedHertz,
    ::testing::Values(
        NestedCase{"pk", nullptr, Control::mean_pressure, asp::SubstrateKind::periodic},
        NestedCase{"pk", nullptr, Control::penetration, asp::SubstrateKind::periodic},
        NestedCase{"bugnicourt", nullptr, Control::mean_pressure, asp::SubstrateKind::periodic},
        NestedCase{"bugnicourt", "gap", Control::mean_gap, asp::SubstrateKind::periodic},
        NestedCase{"lbfgsb", "gap", Control::penetration, asp::SubstrateKind::periodic},
        NestedCase{"pk", nullptr, Control::mean_pressure, asp::SubstrateKind::free},
        NestedCase{"bugnicourt", "gap", Control::penetration, asp::SubstrateKind::free}),
    [](const ::testing::TestParamInfo<NestedCase> &info) {
      return std::string(info.param.algorithm) +
             (info.param.variable ? std::string("_") + info.param.variable : std::string()) +
             "_" + asp::control_name(info.param.control) +
             (info.param.substrate == asp::SubstrateKind::free ? "_free" : "");
    });

// Every coarse level's solve is part of a cold solve: the system it runs on is held by the
// solve (System::state_held_by_solve), also where its state, prolonged from the level below,
// carries pressure, so that the formulations take it for the cold start it is
// (PrimalFormulation::snaps_eagerly). An algorithm that records the flag and presses the
// surface uniformly stands in for a solver, so that each level above the coarsest starts from
// a prolonged state with pressure. This failed before the coarse levels were held.
struct CoarseStart {
  bool held = false;
  bool carries_pressure = false;
};
std::vector<CoarseStart> coarse_starts;

void record_and_press(asp::System &system, Control, double, const asp::OptionValues &,
                      asp::Monitor &) {
  coarse_starts.push_back({system.state_held_by_solve(), system.carries_pressure()});
  for (double &p : system.state().pressure) p = 1e-3;
}

TEST(NestedGrids, EveryCoarseLevelIsSolvedAsAColdSolvesOwn) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const auto heights = asp_test::rough_surface(*grid, 9, 0.1);
  asp::System system(grid, 1.0);
  system.set_topography(heights.data());
  asp::AlgorithmSpec recorder;
  recorder.name = "recorder";
  recorder.run = record_and_press;
  coarse_starts.clear();
  const asp::CoarseWork work =
      asp::solve_coarse_levels(recorder, asp::OptionValues{}, system, Control::penetration,
                               0.3 * system.height_range(), 3, asp::MonitorSettings{});
  ASSERT_EQ(coarse_starts.size(), 3u);
  EXPECT_FALSE(coarse_starts[0].carries_pressure);  // the coarsest starts at rest
  for (std::size_t level = 0; level < coarse_starts.size(); ++level) {
    EXPECT_TRUE(coarse_starts[level].held) << "level " << level;
    if (level > 0) EXPECT_TRUE(coarse_starts[level].carries_pressure) << "level " << level;
  }
  EXPECT_TRUE(work.prolonged);
  EXPECT_TRUE(system.carries_pressure());
}

// ---- adhesion -------------------------------------------------------------------------------
// The adhesive rough scenes of test_adhesion.cpp (64^2, ranges of 10 and 1 times the pixel's
// compliance length, largest tensile stress 1 and 100 times the pressure scale) under
// penetration control with bugnicourt on the gap. Adhesive problems can have several stable
// states, and a solve from another start may find another: the nested solve must find the
// plain one's (same contact set, pressures to the tolerance) or one of lower energy (elastic
// plus interaction, what the solve minimises at a given penetration), said in the output.
TEST(NestedGrids, AdhesiveRoughScenesReachThePlainStateOrALowerEnergy) {
  auto grid = asp_test::grid_2d(64, 64, 1.0, 1.0);
  const auto heights = asp_test::rough_surface(*grid, 9, 0.1);
  int same = 0, lower = 0;
  for (double range_over_l : {10.0, 1.0}) {
    for (double stress_over_p : {1.0, 100.0}) {
      for (double levels : {1.0, 2.0}) {
        asp::System probe(grid, 1.0);
        probe.set_topography(heights.data());
        const double P = 0.05, l = P / probe.substrate().pixel_stiffness();
        const double rho = range_over_l * l, work = stress_over_p * P * rho;
        const double delta = 0.3 * probe.height_range();
        const Outcome plain = solve_scene(grid, heights, asp::SubstrateKind::periodic, work, rho,
                                          "bugnicourt", "gap", Control::penetration, delta, 0,
                                          1e-8);
        const Outcome nested = solve_scene(grid, heights, asp::SubstrateKind::periodic, work,
                                           rho, "bugnicourt", "gap", Control::penetration,
                                           delta, levels, 1e-8);
        ASSERT_TRUE(plain.report.converged());
        ASSERT_TRUE(nested.report.converged());
        const double peak = asp_test::max_abs(plain.pressure);
        const double dp = asp_test::max_abs_difference(plain.pressure, nested.pressure) / peak;
        // The same state: the same contact set and pressures within 1e-6 of the peak (the
        // tolerance 1e-8 through the adhesive operator, less well conditioned than the
        // elastic one alone); otherwise an energy lower than the plain one's by more than
        // its rounding (1e-12 of it).
        const bool is_same = nested.contact == plain.contact && dp < 1e-6;
        const bool is_lower = nested.energy < plain.energy - 1e-12 * std::fabs(plain.energy);
        same += is_same;
        lower += !is_same && is_lower;
        std::printf("rho = %g l, w/rho = %g P, %g levels: %lld then %lld iterations, contact "
                    "%.4f then %.4f, energy %.8e then %.8e: %s\n",
                    range_over_l, stress_over_p, levels, (long long)plain.report.iterations,
                    (long long)nested.report.iterations, plain.contact, nested.contact,
                    plain.energy, nested.energy,
                    is_same ? "the same state" : is_lower ? "a state of lower energy"
                                                          : "A STATE OF HIGHER ENERGY");
        EXPECT_TRUE(is_same || is_lower);
      }
    }
  }
  std::printf("%d of 8 the same state, %d of lower energy\n", same, lower);
}

// Surfaces held apart (a penetration short of the highest point) on Johnson's adhesive
// sinusoid in the JKR limit (test_adhesion.cpp): the non-adhesive coarse levels find no
// contact, and their state, prolonged, held the adhesive grid apart (converged, no pixel on
// the wall), where the cold solve, touching at the crest, is pulled into the JKR contact of
// lower energy. A coarse state without pressure is now no start, and the nested solve
// reaches the cold solve's state: the same contact and pressures within 1e-6 of the peak
// (the tolerance 1e-10 through the adhesive operator).
TEST(NestedGrids, SurfacesHeldApartStartCold) {
  const std::int64_t n = 512;
  const double l = 1.0, h0 = 0.01, alpha = 0.2;
  const double w = alpha * alpha * pi * pi * h0 * h0 / (2 * l);
  const double rho = std::sqrt(2.0 * (l / n) * w);
  auto grid = asp_test::grid_1d(n, l);
  std::vector<double> h(static_cast<std::size_t>(n));
  asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
  for (const char *algorithm : {"bugnicourt", "lbfgsb"}) {
    for (double delta : {-0.3 * h0, -0.1 * h0}) {
      const Outcome plain = solve_scene(grid, h, asp::SubstrateKind::periodic, w, rho,
                                        algorithm, "gap", Control::penetration, delta, 0, 1e-10);
      const Outcome nested =
          solve_scene(grid, h, asp::SubstrateKind::periodic, w, rho, algorithm, "gap",
                      Control::penetration, delta, asp::levels_auto, 1e-10);
      ASSERT_TRUE(plain.report.converged()) << algorithm << " " << delta;
      ASSERT_TRUE(nested.report.converged()) << algorithm << " " << delta;
      ASSERT_GT(plain.contact, 0.04) << algorithm << " " << delta;
      EXPECT_EQ(nested.contact, plain.contact) << algorithm << " " << delta;
      EXPECT_LT(asp_test::max_abs_difference(plain.pressure, nested.pressure),
                1e-6 * asp_test::max_abs(plain.pressure))
          << algorithm << " " << delta;
    }
  }
}

// A soft wall (no hard wall: the prolonged gap is the pressure's own, unclipped) with the
// unconstrained solvers, under penetration control and, for lbfgs_fourier, load control.
TEST(NestedGrids, SoftWallNestedEqualsPlain) {
  const std::int64_t n = 128;
  auto grid = asp_test::grid_2d(n, n, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 13);
  struct SoftCase {
    const char *algorithm;
    Control control;
  };
  for (const SoftCase &c : {SoftCase{"lbfgs_fourier", Control::penetration},
                            SoftCase{"lbfgs_fourier", Control::mean_pressure},
                            SoftCase{"lbfgs", Control::penetration}}) {
    Outcome o[2];
    for (int nested = 0; nested < 2; ++nested) {
      asp::System system(grid, 1.0);
      system.set_topography(h.data());
      system.set_soft_wall(1e-2, 2.0 / n, 1e-4, 2.0 / n);
      asp::Solver solver(c.algorithm);
      solver.set_option("tolerance", 1e-10);
      solver.set_option("levels", nested ? 2.0 : 0.0);
      const double value =
          c.control == Control::penetration ? 0.3 * system.height_range() : 0.005;
      solver.solve(system, c.control, value);
      ASSERT_TRUE(solver.report().converged()) << c.algorithm << " nested " << nested;
      o[nested].pressure = asp_test::field_vector(system.state().pressure);
      o[nested].report = solver.report();
    }
    const double dp = asp_test::max_abs_difference(o[0].pressure, o[1].pressure) /
                      asp_test::max_abs(o[0].pressure);
    std::printf("soft wall, %s, %s: %lld then %lld iterations, max dp/p %.1e\n", c.algorithm,
                asp::control_name(c.control), (long long)o[0].report.iterations,
                (long long)o[1].report.iterations, dp);
    // As for the hard walls: both meet the tolerance 1e-10.
    EXPECT_LT(dp, 1e-8) << c.algorithm;
  }
}

// On a grid with threads, the coarse grids take the same threads, and a nested solve there
// reaches the plain serial one's state (to the tolerance, as above: the threads' sums run in
// another order).
TEST(NestedGrids, ThreadedNestedSolveEqualsSerialPlain) {
  auto serial = asp_test::grid_2d(128, 128, 1.0, 1.0);
  auto threaded = asp_test::grid_2d(128, 128, 1.0, 1.0);
  threaded->set_threads(2);
  const auto h = asp_test::rough_surface(*serial, 11);
  asp::System system(threaded, 1.0);
  system.set_topography(h.data());
  EXPECT_EQ(asp::coarse_system(system)->grid().threads(), 2);
  const Outcome plain = solve_scene(serial, h, asp::SubstrateKind::periodic, 0, 0, "bugnicourt",
                                    nullptr, Control::mean_pressure, 0.01, 0, 1e-10);
  const Outcome nested = solve_scene(threaded, h, asp::SubstrateKind::periodic, 0, 0,
                                     "bugnicourt", nullptr, Control::mean_pressure, 0.01,
                                     asp::levels_auto, 1e-10);
  ASSERT_TRUE(plain.report.converged());
  ASSERT_TRUE(nested.report.converged());
  EXPECT_EQ(nested.contact, plain.contact);
  EXPECT_LT(asp_test::max_abs_difference(plain.pressure, nested.pressure),
            1e-8 * asp_test::max_abs(plain.pressure));
}

// A coarse level keeps the substrate's stiffness law: on an elastic layer (thickness a tenth
// of the box, so that its K~(q) differs from the half-space's at every wavevector the surface
// holds) the coarse system has the layer's own K~(0) and law, and the nested solve reaches
// the plain one's state (to the tolerance, as above). A coarse half-space would start the fine
// solve from another body's contact; the state would still agree, so the law is checked too.
TEST(NestedGrids, ALayerKeepsItsLawOnTheCoarseLevels) {
  auto grid = asp_test::grid_2d(128, 128, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 11);
  const auto layer = [&]() {
    auto system = std::make_unique<asp::System>(
        grid, std::make_unique<asp::LayerLaw>(1.0, 0.3, 0.1));
    system->set_topography(h.data());
    return system;
  };
  auto fine = layer();
  auto coarse = asp::coarse_system(*fine);
  EXPECT_EQ(coarse->substrate().mean_stiffness(), asp::MeanStiffness::physical);
  EXPECT_EQ(coarse->substrate().k0(), fine->substrate().k0());
  EXPECT_EQ(std::string(coarse->substrate().name()), std::string(fine->substrate().name()));
  auto plain = layer(), nested = layer();
  asp::Solver solver("bugnicourt");
  solver.set_option("tolerance", 1e-10);
  solver.set_option("levels", 0.0);
  solver.solve(*plain, Control::mean_pressure, 0.01);
  ASSERT_TRUE(solver.report().converged());
  const std::int64_t plain_iterations = solver.report().iterations;
  solver.set_option("levels", std::string("auto"));
  solver.solve(*nested, Control::mean_pressure, 0.01);
  ASSERT_TRUE(solver.report().converged());
  EXPECT_LT(solver.report().iterations, plain_iterations);  // the coarse levels ran
  const auto p_plain = asp_test::field_vector(plain->state().pressure);
  const auto p_nested = asp_test::field_vector(nested->state().pressure);
  EXPECT_EQ(nested->contact_fraction(), plain->contact_fraction());
  EXPECT_LT(asp_test::max_abs_difference(p_plain, p_nested), 1e-8 * asp_test::max_abs(p_plain));
}

// ---- what levels do and refuse -------------------------------------------------------------

TEST(NestedGrids, AutoHalvesWhileBothSidesStayAt64) {
  auto system_of = [](std::int64_t nx, std::int64_t ny) {
    return asp::System(asp_test::grid_2d(nx, ny, 1.0, 1.0), 1.0);
  };
  EXPECT_EQ(asp::nested_levels(system_of(64, 64), asp::levels_auto), 0);
  EXPECT_EQ(asp::nested_levels(system_of(128, 128), asp::levels_auto), 1);
  EXPECT_EQ(asp::nested_levels(system_of(512, 256), asp::levels_auto), 2);
  EXPECT_EQ(asp::nested_levels(system_of(384, 384), asp::levels_auto), 2);  // 96: odd halves
  EXPECT_EQ(asp::nested_levels(system_of(130, 130), asp::levels_auto), 1);  // 65, odd
  EXPECT_EQ(asp::nested_levels(system_of(126, 126), asp::levels_auto), 0);  // 63 < 64
  EXPECT_EQ(asp::nested_levels(asp::System(asp_test::grid_1d(1024, 1.0), 1.0),
                               asp::levels_auto),
            4);
}

// A coarse grid calls a user's potential with its own pixels, which a callback holding data
// per pixel would misread: "auto" takes no level there, and an explicit count still does.
TEST(NestedGrids, AutoTakesNoLevelWithAUsersPotential) {
  asp::System system(asp_test::grid_2d(256, 256, 1.0, 1.0), 1.0);
  EXPECT_EQ(asp::nested_levels(system, asp::levels_auto), 2);
  system.set_user_potential(asp_test::zero_potential, nullptr, true);
  EXPECT_EQ(asp::nested_levels(system, asp::levels_auto), 0);
  EXPECT_EQ(asp::nested_levels(system, 2.0), 2);
  system.set_hard_wall();
  EXPECT_EQ(asp::nested_levels(system, asp::levels_auto), 2);
}

// An explicit count the grid cannot take is refused before anything changes, naming the
// option and why; the same request is refused by check_supported (asp_solver_supports).
TEST(NestedGrids, LevelsTheGridCannotTakeAreRefusedNamingTheOption) {
  struct Refusal {
    std::int64_t nx, ny;
    double levels;
    const char *why;
  };
  for (const Refusal &r : {Refusal{30, 32, 2, "odd size"}, Refusal{36, 36, 3, "odd size"},
                           Refusal{32, 32, 3, "fewer than 8 a side"}}) {
    auto grid = asp_test::grid_2d(r.nx, r.ny, 1.0, 1.0);
    asp::System system(grid, 1.0);
    const auto h = asp_test::rough_surface(*grid, 3);
    system.set_topography(h.data());
    const auto before = asp_test::field_vector(system.state().gap);
    asp::Solver solver("pk");
    solver.set_option("levels", r.levels);
    try {
      solver.check_supported(system, Control::mean_pressure);
      ADD_FAILURE() << "check_supported took " << r.levels << " levels on " << r.nx;
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported);
    }
    try {
      solver.solve(system, Control::mean_pressure, 0.01);
      ADD_FAILURE() << "solved with " << r.levels << " levels on " << r.nx << " x " << r.ny;
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported);
      const std::string m = e.what();
      EXPECT_NE(m.find("option 'levels'"), std::string::npos) << m;
      EXPECT_NE(m.find(r.why), std::string::npos) << m;
    }
    EXPECT_FALSE(solver.report().available);
    EXPECT_EQ(asp_test::field_vector(system.state().gap), before);
  }
}

TEST(NestedGrids, LevelsTakeACountOrAutoAndReadBack) {
  // The constrained solvers nest grids by default; the solvers of soft walls do not.
  for (const char *algorithm : {"pk", "bugnicourt", "lbfgsb"})
    EXPECT_EQ(asp::Solver(algorithm).option_text("levels"), "auto") << algorithm;
  for (const char *algorithm : {"lbfgs", "lbfgs_fourier", "fire", "fire_mass_weighted", "gfmd"})
    EXPECT_EQ(asp::Solver(algorithm).option("levels"), 0.0) << algorithm;
  asp::Solver solver("bugnicourt");
  solver.set_option("levels", 3.0);
  EXPECT_EQ(solver.option("levels"), 3.0);
  solver.set_option("levels", std::string("auto"));
  EXPECT_EQ(solver.option("levels"), asp::levels_auto);
  EXPECT_EQ(solver.option_text("levels"), "auto");
  for (double bad : {-1.0, 1.5, 17.0})
    asp_test::expect_error(asp::Status::invalid_argument,
                           [&] { solver.set_option("levels", bad); }, std::to_string(bad));
  const std::string message = asp_test::expect_error(
      asp::Status::invalid_argument, [&] { solver.set_option("levels", std::string("many")); });
  EXPECT_NE(message.find("'auto'"), std::string::npos) << message;
  solver.set_option("levels", 2.0);
  try {
    solver.option_text("levels");
    ADD_FAILURE();
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::invalid_argument);
  }
  // A choice option takes no word of a number's.
  try {
    solver.set_option("variable", std::string("auto"));
    ADD_FAILURE();
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::invalid_argument);
  }
}

// A state with pressure is a warm start, kept: a converged one is solved again in no
// iteration, with levels as without. The report counts the finest grid's iterations and the
// transforms of all levels, the coarse ones' weighted by their share of the pixels.
TEST(NestedGrids, WarmStartsAreKeptAndTheHistoryCountsTheCoarseWork) {
  auto grid = asp_test::grid_2d(128, 128, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 5);
  asp::System system(grid, 1.0);
  system.set_topography(h.data());
  asp::Solver solver("pk");
  solver.set_option("levels", std::string("auto"));
  solver.set_history(true);
  solver.solve(system, Control::mean_pressure, 0.01);
  ASSERT_TRUE(solver.report().converged());
  const asp::SolveReport nested = solver.report();
  EXPECT_EQ(static_cast<std::int64_t>(solver.history().size()), nested.iterations + 1);
  // The coarse levels' transforms are the solve's work from its first row on: a cold solve
  // of pk has made 3 at its iteration 0 (the heights' spectrum and the first gap's pair), the
  // nested one more; and the report's count is the last row's.
  const auto transforms_in_row = [&](std::size_t row) {
    return static_cast<std::int64_t>(
        solver.history()[row][static_cast<int>(asp::HistoryColumn::transforms)]);
  };
  EXPECT_GT(transforms_in_row(0), 3);
  EXPECT_EQ(nested.transforms, transforms_in_row(solver.history().size() - 1));
  solver.solve(system, Control::mean_pressure, 0.01);
  EXPECT_EQ(solver.report().iterations, 0);
  EXPECT_EQ(solver.report().termination, asp::Termination::converged);
}

}  // namespace

