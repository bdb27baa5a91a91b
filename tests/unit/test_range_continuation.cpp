// SPDX-License-Identifier: GPL-2.0-or-later
// Continuation in the range of the exponential adhesion (option "range_continuation",
// solvers/range_continuation.hpp): what it refuses, where "auto" leaves a solve as it was,
// that a continued solve is the two solves it stands for (its iterations, work, history and
// state, against the same two done by hand), that the system's interaction comes back however
// the solve ends, the state it reaches, and threads.
//
// The scenes are StrongAdhesionOnRoughSurfacesEndsFiniteAndHonest's (test_adhesion.cpp): a
// rough surface of rms slope 0.1, E* = 1, pressed to 0.3 of its height range on the gap with
// bugnicourt, the range rho given in l = P/k (P = 0.05, about E* h'_rms/2, k the stiffness of
// one pixel) and the largest tension w/rho in P. The cohesive zone (pi/4) E* rho^2/w is then
// 0.65 (rho/l)/(w/rho / P) pixels: at 1 P, rho = 0.1 l gives 0.065 pixel and rho = l 0.65
// (unresolved), rho = 10 l 6.5 pixels (resolved).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/error.hpp"
#include "physics/interaction.hpp"
#include "physics/resolution.hpp"
#include "scene.hpp"
#include "solvers/range_continuation.hpp"

namespace {

using asp::Control;

struct Scene {
  std::shared_ptr<asp::Grid> grid;
  std::vector<double> heights;
  double work = 0.0, range = 0.0;  // work 0: the plain hard wall
  double penetration = 0.0;        // 0.3 of the height range
};

// The scene on an n x n grid of the unit square (nx x n with lx = nx/n: square pixels).
Scene adhesive_scene(std::int64_t n, double range_over_l, double stress_over_p,
                     std::int64_t nx = 0) {
  Scene s;
  if (nx == 0) nx = n;
  s.grid = asp_test::grid_2d(nx, n, static_cast<double>(nx) / static_cast<double>(n), 1.0);
  s.heights = asp_test::rough_surface(*s.grid, 9, 0.1);
  asp::System probe(s.grid, 1.0);
  probe.set_topography(s.heights.data());
  const double P = 0.05, l = P / probe.substrate().pixel_stiffness();
  s.range = range_over_l * l;
  s.work = stress_over_p * P * s.range;
  s.penetration = 0.3 * probe.height_range();
  return s;
}

std::unique_ptr<asp::System> system_of(const Scene &s) {
  auto system = std::make_unique<asp::System>(s.grid, 1.0);
  system->set_topography(s.heights.data());
  if (s.work > 0.0) system->set_adhesion(s.work, s.range);
  return system;
}

// bugnicourt on the gap, as the scenes are solved, with the continuation set to a factor or
// to "auto" (a negative argument).
asp::Solver gap_solver(double continuation, double tolerance = 1e-8) {
  asp::Solver solver("bugnicourt");
  solver.set_option("variable", std::string("gap"));
  solver.set_option("tolerance", tolerance);
  solver.set_option("max_iterations", 3000.0);
  if (continuation < 0.0)
    solver.set_option("range_continuation", std::string("auto"));
  else
    solver.set_option("range_continuation", continuation);
  return solver;
}

struct Outcome {
  asp::SolveReport report;
  asp::History history;
  std::vector<double> pressure, gap;
  double penetration = 0.0;
  double energy = 0.0;  // elastic + interaction: what the solve minimises at fixed penetration
};

Outcome outcome_of(const asp::Solver &solver, const asp::System &system) {
  Outcome o;
  o.report = solver.report();
  o.history = solver.history();
  o.pressure = asp_test::field_vector(system.state().pressure);
  o.gap = asp_test::field_vector(system.state().gap);
  o.penetration = system.state().penetration;
  o.energy = system.elastic_energy() + system.mean_mode_energy() + system.interaction_energy();
  return o;
}

Outcome solve(const Scene &s, asp::Solver solver, Control control, double value) {
  auto system = system_of(s);
  solver.solve(*system, control, value);
  return outcome_of(solver, *system);
}

Outcome solve(const Scene &s, double continuation, double tolerance = 1e-8) {
  return solve(s, gap_solver(continuation, tolerance), Control::penetration, s.penetration);
}

// The same iterations and termination, and the state bit for bit.
void expect_identical(const Outcome &a, const Outcome &b, const std::string &what) {
  EXPECT_EQ(a.report.iterations, b.report.iterations) << what;
  EXPECT_EQ(a.report.evaluations, b.report.evaluations) << what;
  EXPECT_EQ(a.report.transforms, b.report.transforms) << what;
  EXPECT_EQ(a.report.termination, b.report.termination) << what;
  EXPECT_TRUE(a.pressure == b.pressure) << what;
  EXPECT_TRUE(a.gap == b.gap) << what;
  EXPECT_EQ(a.penetration, b.penetration) << what;
}

// ---- what is refused, and the option's values ----------------------------------------------

// The interactions other than the exponential adhesion, each with a solver that takes it, on
// a 32^2 rough surface.
enum class Wall { hard, soft, user_hard, user_soft };
struct OtherInteraction {
  Wall wall;
  const char *algorithm;
  const char *name;
};
const OtherInteraction other_interactions[] = {
    {Wall::hard, "bugnicourt", "hard wall"},
    {Wall::hard, "pk", "hard wall (pk)"},
    {Wall::soft, "lbfgs", "soft wall"},
    {Wall::user_hard, "lbfgsb", "user potential, hard wall"},
    {Wall::user_soft, "lbfgs", "user potential"}};

struct Request {
  std::unique_ptr<asp::System> system;
  std::unique_ptr<asp::Solver> solver;  // range_continuation 4
  Control control = Control::mean_pressure;
  double value = 0.0;
};

Request request_on(const OtherInteraction &r) {
  const auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  const auto h = asp_test::rough_surface(*grid, 3);
  Request q;
  q.system = std::make_unique<asp::System>(grid, 1.0);
  q.system->set_topography(h.data());
  if (r.wall == Wall::soft) q.system->set_soft_wall(1e-2, 2.0 / 32, 1e-4, 2.0 / 32);
  if (r.wall == Wall::user_hard)
    q.system->set_user_potential(asp_test::zero_potential, nullptr, true);
  // Without the wall a zero potential has no equilibrium: only the refusal is checked there
  // (it comes before the potential is ever called).
  if (r.wall == Wall::user_soft)
    q.system->set_user_potential(asp_test::zero_potential, nullptr, false);
  q.solver = std::make_unique<asp::Solver>(r.algorithm);
  if (std::string(r.algorithm) == "bugnicourt" || std::string(r.algorithm) == "lbfgsb")
    q.solver->set_option("variable", std::string("gap"));
  q.solver->set_option("range_continuation", 4.0);
  q.control = r.wall == Wall::hard ? Control::mean_pressure : Control::penetration;
  q.value = r.wall == Wall::hard ? 0.01 : 0.3 * q.system->height_range();
  return q;
}

// An explicit factor on an interaction other than the exponential adhesion is refused with
// Error(unsupported) naming the option, before anything changes: no report, the state as it
// was, and the same solver with the option 0, or "auto" (which does nothing there), then
// solves the system. A factor in (0, 1) is refused with Error(invalid_argument), on the
// adhesion too, and the system then solves with F = 4; explicit 1 is none.
TEST(RangeContinuation, ExplicitFactorsAreRefusedWhereTheyCannotApply) {
  for (const OtherInteraction &r : other_interactions) {
    Request q = request_on(r);
    const auto before = asp_test::field_vector(q.system->state().gap);
    try {
      q.solver->solve(*q.system, q.control, q.value);
      ADD_FAILURE() << r.name << ": solved with range_continuation 4";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported) << r.name << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("'range_continuation'"), std::string::npos)
          << r.name << ": " << e.what();
    }
    EXPECT_FALSE(q.solver->report().available) << r.name;
    EXPECT_EQ(asp_test::field_vector(q.system->state().gap), before) << r.name;
    if (r.wall == Wall::user_soft) continue;  // the zero callback has no equilibrium to find
    q.solver->set_option("range_continuation", 0.0);
    q.solver->solve(*q.system, q.control, q.value);
    EXPECT_TRUE(q.solver->report().converged()) << r.name;
    q.system->reset_state();
    q.solver->set_option("range_continuation", std::string("auto"));
    q.solver->solve(*q.system, q.control, q.value);
    EXPECT_TRUE(q.solver->report().converged()) << r.name;
  }

  // A factor below 1 is no factor of a longer range.
  const Scene s = adhesive_scene(32, 0.1, 1.0);
  auto system = system_of(s);
  for (double bad : {0.5, 1e-300}) {
    asp::Solver solver = gap_solver(bad);
    try {
      solver.solve(*system, Control::penetration, s.penetration);
      ADD_FAILURE() << "solved with range_continuation " << bad;
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::invalid_argument) << e.what();
      EXPECT_NE(std::string(e.what()).find("'range_continuation'"), std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(solver.report().available);
    solver.set_option("range_continuation", 4.0);
    solver.solve(*system, Control::penetration, s.penetration);
    EXPECT_TRUE(solver.report().converged()) << "after " << bad;
    system->reset_state();
  }
  // Explicit 1 is none: the plain solve, bit for bit.
  expect_identical(solve(s, 1.0), solve(s, 0.0), "range_continuation 1");
}

// Solver::check_supported (asp_solver_supports) throws Error(unsupported) "as solve() would"
// for options the system cannot take: for a count of levels the grid cannot take, and for an
// explicit factor on an interaction other than the exponential adhesion (which it once took,
// and solve() then refused).
TEST(RangeContinuation, CheckSupportedRefusesWhatSolveRefuses) {
  for (const OtherInteraction &r : other_interactions) {
    Request q = request_on(r);
    try {
      q.solver->check_supported(*q.system, q.control);
      ADD_FAILURE() << r.name << ": check_supported took range_continuation 4";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::unsupported) << r.name;
      EXPECT_NE(std::string(e.what()).find("'range_continuation'"), std::string::npos)
          << r.name << ": " << e.what();
    }
    // "auto" is taken everywhere.
    q.solver->set_option("range_continuation", std::string("auto"));
    EXPECT_NO_THROW(q.solver->check_supported(*q.system, q.control)) << r.name;
  }
}

TEST(RangeContinuation, TakesAFactorOrAutoAndReadsBack) {
  // bugnicourt continues by default; the other solvers do not.
  EXPECT_EQ(asp::Solver("bugnicourt").option_text("range_continuation"), "auto");
  EXPECT_EQ(asp::Solver("bugnicourt").option("range_continuation"), asp::continuation_auto);
  for (const char *algorithm : {"pk", "lbfgsb", "fire", "lbfgs"})
    EXPECT_EQ(asp::Solver(algorithm).option("range_continuation"), 0.0) << algorithm;
  asp::Solver solver("lbfgsb");
  solver.set_option("range_continuation", std::string("auto"));
  EXPECT_EQ(solver.option("range_continuation"), asp::continuation_auto);
  EXPECT_EQ(solver.option_text("range_continuation"), "auto");
  solver.set_option("range_continuation", 4.0);
  EXPECT_EQ(solver.option("range_continuation"), 4.0);
  // A number does not read as a string; the setter takes no other word and no negative value.
  EXPECT_THROW(solver.option_text("range_continuation"), asp::Error);
  for (double bad : {-1.0, -0.5, std::nan("")})
    asp_test::expect_error(asp::Status::invalid_argument,
                           [&] { solver.set_option("range_continuation", bad); },
                           std::to_string(bad));
  const std::string message = asp_test::expect_error(
      asp::Status::invalid_argument,
      [&] { solver.set_option("range_continuation", std::string("long")); });
  EXPECT_NE(message.find("'auto'"), std::string::npos) << message;
  EXPECT_EQ(solver.option("range_continuation"), 4.0);  // a refused value changes nothing
}

// ---- where auto does nothing ---------------------------------------------------------------

// "auto" leaves a solve as it was (the same iterations, work and state, bit for bit, as with
// the option 0) on a non-adhesive scene, on an adhesive one whose grid resolves the zone, from
// a warm start, and under a mean pressure <= 0. Where the grid does not resolve the zone it
// is the explicit factor sqrt(2 / zone), bit for bit, and changes the solve (the check that
// the comparisons above could fail).
TEST(RangeContinuation, AutoActsOnlyOnAColdUnresolvedAdhesiveSolve) {
  // The plain hard wall, at 128^2 (levels auto takes one), on the gap and on the pressure.
  {
    Scene s = adhesive_scene(128, 1.0, 1.0);
    s.work = 0.0;
    expect_identical(solve(s, -1.0), solve(s, 0.0), "hard wall, gap");
    asp::Solver pressure_auto("bugnicourt"), pressure_none("bugnicourt");
    pressure_none.set_option("range_continuation", 0.0);
    expect_identical(solve(s, pressure_auto, Control::mean_pressure, 0.01),
                     solve(s, pressure_none, Control::mean_pressure, 0.01),
                     "hard wall, pressure");
  }
  // A resolved adhesive scene: 6.5 pixels of zone.
  {
    const Scene s = adhesive_scene(64, 10.0, 1.0);
    ASSERT_TRUE(asp::resolution(*system_of(s)).resolved);
    const Outcome automatic = solve(s, -1.0), none = solve(s, 0.0);
    EXPECT_TRUE(none.report.converged());
    expect_identical(automatic, none, "resolved adhesion");
  }
  const Scene s = adhesive_scene(64, 0.1, 1.0);
  const asp::Resolution r = asp::resolution(*system_of(s));
  ASSERT_FALSE(r.resolved);
  std::printf("unresolved scene: zone %.3f pixels, auto factor %.3f\n", r.ratio,
              std::sqrt(asp::continuation_zone / r.ratio));
  // A warm start: both systems solved alike (the option 0), then pressed further.
  {
    Outcome warm[2];
    for (int k = 0; k < 2; ++k) {
      auto system = system_of(s);
      asp::Solver first = gap_solver(0.0);
      first.solve(*system, Control::penetration, s.penetration);
      asp::Solver second = gap_solver(k == 0 ? -1.0 : 0.0);
      second.solve(*system, Control::penetration, 1.1 * s.penetration);
      warm[k] = outcome_of(second, *system);
    }
    EXPECT_GT(warm[1].report.iterations, 0);
    expect_identical(warm[0], warm[1], "warm start");
  }
  // Mean pressure 0 and tensile, from a cold start: whatever the ending (the surfaces may
  // separate), the same as without the option.
  for (double load : {0.0, -1e-4}) {
    const Outcome automatic = solve(s, gap_solver(-1.0), Control::mean_pressure, load);
    const Outcome none = solve(s, gap_solver(0.0), Control::mean_pressure, load);
    std::printf("mean pressure %g: %s after %lld iterations\n", load,
                asp::termination_name(none.report.termination),
                static_cast<long long>(none.report.iterations));
    expect_identical(automatic, none, "mean pressure " + std::to_string(load));
  }
  // A zone above continuation_largest_zone, still unresolved (0.65 pixel): auto leaves it.
  {
    const Scene near = adhesive_scene(64, 1.0, 1.0);
    const asp::Resolution nr = asp::resolution(*system_of(near));
    ASSERT_FALSE(nr.resolved);
    ASSERT_GT(nr.ratio, asp::continuation_largest_zone);
    expect_identical(solve(near, -1.0), solve(near, 0.0), "zone of 0.65 pixel");
  }
  // Where it acts: the explicit sqrt(2 / zone).
  const Outcome automatic = solve(s, -1.0);
  const Outcome explicit_factor = solve(s, std::sqrt(asp::continuation_zone / r.ratio));
  const Outcome none = solve(s, 0.0);
  expect_identical(automatic, explicit_factor, "auto against its explicit factor");
  EXPECT_FALSE(automatic.pressure == none.pressure &&
               automatic.report.iterations == none.report.iterations)
      << "auto did nothing on an unresolved scene";
}

// ---- a continued solve is the two solves it stands for -------------------------------------

// The stages done by hand: with the range F rho, a plain solve (range_continuation 0) to
// max(tolerance, 1e-2), its coarse levels (if any) solved on the way, their tolerance derived
// from that one as the continued solve derives theirs from its first stage's; then the range
// rho and a second solve from that state to the solve's tolerance, marked as the cold
// solve's own (as the continued solve holds it). The continued solve must do exactly this:
// the same iterations, evaluations and transforms (the sums; the coarse levels' transforms
// are in the first solve's), the same state bit for bit (the same operations in the same
// order: nothing may differ but the bookkeeping), and a history that is the first solve's
// rows up to its last, whose row the second solve's first takes, then the second's, its
// counts offset by the first's.
struct ByHand {
  Outcome first, second;
};

ByHand solve_by_hand(const Scene &s, double factor, double tolerance, bool levels) {
  ByHand out;
  auto system = system_of(s);
  system->set_adhesion(s.work, factor * s.range);
  asp::Solver first = gap_solver(0.0, asp::first_stage_tolerance(tolerance));
  if (!levels) first.set_option("levels", 0.0);
  first.set_history(true);
  first.solve(*system, Control::penetration, s.penetration);
  out.first = outcome_of(first, *system);
  system->set_adhesion(s.work, s.range);
  asp::Solver second = gap_solver(0.0, tolerance);
  second.set_history(true);
  // The second stage is part of a cold solve: the state the first stage left is the solve's
  // (as the continued solve marks it), so that its pixels near the wall jump as a cold
  // solve's do (LocalTerm::eager), not as a warm start's.
  system->set_state_held_by_solve(true);
  second.solve(*system, Control::penetration, s.penetration);
  out.second = outcome_of(second, *system);
  return out;
}

TEST(RangeContinuation, AContinuedSolveIsItsTwoStagesDoneByHand) {
  // 128^2, the zone 0.065 and 0.65 pixel; F = 4; with the default levels (auto: one coarse
  // level on a cold start, before the first stage) and without.
  for (const bool levels : {true, false}) {
    for (double range_over_l : {0.1, 1.0}) {
      const Scene s = adhesive_scene(128, range_over_l, 1.0);
      ASSERT_FALSE(asp::resolution(*system_of(s)).resolved);
      const double factor = 4.0, tolerance = 1e-8;
      const ByHand hand = solve_by_hand(s, factor, tolerance, levels);
      asp::Solver solver = gap_solver(factor, tolerance);
      if (!levels) solver.set_option("levels", 0.0);
      solver.set_history(true);
      const Outcome continued = solve(s, solver, Control::penetration, s.penetration);
      const std::string what = "rho = " + std::to_string(range_over_l) + " l, levels " +
                               (levels ? "auto" : "0");
      std::printf("%s: by hand %lld + %lld iterations, %lld + %lld transforms (%s); "
                  "continued %lld iterations, %lld transforms (%s)\n",
                  what.c_str(), static_cast<long long>(hand.first.report.iterations),
                  static_cast<long long>(hand.second.report.iterations),
                  static_cast<long long>(hand.first.report.transforms),
                  static_cast<long long>(hand.second.report.transforms),
                  asp::termination_name(hand.second.report.termination),
                  static_cast<long long>(continued.report.iterations),
                  static_cast<long long>(continued.report.transforms),
                  asp::termination_name(continued.report.termination));
      // The first stage converged to its tolerance after some iterations: a stage that did
      // nothing would make the sums trivial.
      ASSERT_TRUE(hand.first.report.converged()) << what;
      ASSERT_GT(hand.first.report.iterations, 0) << what;
      EXPECT_TRUE(continued.report.converged()) << what;
      EXPECT_EQ(continued.report.termination, hand.second.report.termination) << what;
      EXPECT_EQ(continued.report.iterations,
                hand.first.report.iterations + hand.second.report.iterations)
          << what;
      EXPECT_EQ(continued.report.evaluations,
                hand.first.report.evaluations + hand.second.report.evaluations)
          << what;
      EXPECT_EQ(continued.report.transforms,
                hand.first.report.transforms + hand.second.report.transforms)
          << what;
      EXPECT_EQ(continued.report.error, hand.second.report.error) << what;
      EXPECT_TRUE(continued.pressure == hand.second.pressure) << what;
      EXPECT_TRUE(continued.gap == hand.second.gap) << what;
      EXPECT_EQ(continued.penetration, hand.second.penetration) << what;

      // The history: the first solve's rows but its last, then the second's, offset.
      const asp::History &h = continued.history;
      const std::size_t boundary = static_cast<std::size_t>(hand.first.report.iterations);
      ASSERT_EQ(h.size(), boundary + hand.second.history.size()) << what;
      const int columns[] = {static_cast<int>(asp::HistoryColumn::iteration),
                             static_cast<int>(asp::HistoryColumn::evaluations),
                             static_cast<int>(asp::HistoryColumn::transforms),
                             static_cast<int>(asp::HistoryColumn::error),
                             static_cast<int>(asp::HistoryColumn::objective),
                             static_cast<int>(asp::HistoryColumn::contact_fraction)};
      const double second_offsets[] = {
          static_cast<double>(hand.first.report.iterations),
          static_cast<double>(hand.first.report.evaluations),
          static_cast<double>(hand.first.report.transforms), 0.0, 0.0, 0.0};
      int differing = 0;
      for (std::size_t k = 0; k < h.size(); ++k) {
        const bool first = k < boundary;
        const auto &expected =
            first ? hand.first.history[k] : hand.second.history[k - boundary];
        for (int c = 0; c < 6; ++c)
          differing += h[k][columns[c]] !=
                       expected[columns[c]] + (first ? 0.0 : second_offsets[c]);
      }
      EXPECT_EQ(differing, 0) << what;
    }
  }
}

// The history of a continued solve: one row per iteration and the starting point, numbered
// 0..n, its work never decreasing, and from the second stage's starting point on (the row
// whose number is the first stage's iterations, found by hand as above) the objective of the
// scene's own range, which every step of bugnicourt on the gap descends: it never rises by
// more than rounding (1e-12 of it, as in test_adhesion.cpp). Before it, the first stage's
// objective of the longer range does the same; the row at the boundary is the jump between
// the two objectives, which may go either way. The progress callback sees every iteration
// once, in order (the boundary's with the first stage's error).
struct Seen {
  std::vector<std::int64_t> iterations;
};

int record_iteration(std::int64_t iteration, double, double, void *data) {
  static_cast<Seen *>(data)->iterations.push_back(iteration);
  return 0;
}

TEST(RangeContinuation, TheHistoryCountsBothStagesAndDescendsInEach) {
  int scenes = 0;
  for (double range_over_l : {0.1, 0.3, 1.0}) {
    for (double stress_over_p : {1.0, 100.0}) {
      const Scene s = adhesive_scene(64, range_over_l, stress_over_p);
      // Only where auto acts (the zone at most continuation_largest_zone pixels).
      if (asp::resolution(*system_of(s)).ratio > asp::continuation_largest_zone) continue;
      ++scenes;
      const std::string what = "rho = " + std::to_string(range_over_l) + " l, w/rho = " +
                               std::to_string(stress_over_p) + " P";
      asp::Solver solver = gap_solver(-1.0);
      solver.set_history(true);
      Seen seen;
      solver.set_progress(record_iteration, &seen);
      const Outcome o = solve(s, solver, Control::penetration, s.penetration);
      ASSERT_EQ(static_cast<std::int64_t>(seen.iterations.size()), o.report.iterations + 1)
          << what;
      for (std::size_t k = 0; k < seen.iterations.size(); ++k)
        EXPECT_EQ(seen.iterations[k], static_cast<std::int64_t>(k)) << what;
      const double factor =
          std::sqrt(asp::continuation_zone / asp::resolution(*system_of(s)).ratio);
      const std::int64_t boundary = solve_by_hand(s, factor, 1e-8, false).first.report.iterations;
      const asp::History &h = o.history;
      ASSERT_EQ(static_cast<std::int64_t>(h.size()), o.report.iterations + 1) << what;
      ASSERT_GT(boundary, 0) << what;
      ASSERT_LE(boundary, o.report.iterations) << what;
      const int iteration = static_cast<int>(asp::HistoryColumn::iteration);
      const int evaluations = static_cast<int>(asp::HistoryColumn::evaluations);
      const int transforms = static_cast<int>(asp::HistoryColumn::transforms);
      const int objective = static_cast<int>(asp::HistoryColumn::objective);
      int misnumbered = 0, less_work = 0, rises = 0;
      for (std::size_t k = 0; k < h.size(); ++k) {
        misnumbered += h[k][iteration] != static_cast<double>(k);
        if (k == 0) continue;
        less_work += h[k][evaluations] < h[k - 1][evaluations] ||
                     h[k][transforms] < h[k - 1][transforms];
        if (static_cast<std::int64_t>(k) != boundary)
          rises += h[k][objective] >
                   h[k - 1][objective] + 1e-12 * std::fabs(h[k - 1][objective]);
      }
      std::printf("%s: factor %.2f, %lld iterations, the second stage from %lld (%s)\n",
                  what.c_str(), factor, static_cast<long long>(o.report.iterations),
                  static_cast<long long>(boundary),
                  asp::termination_name(o.report.termination));
      EXPECT_EQ(misnumbered, 0) << what;
      EXPECT_EQ(less_work, 0) << what;
      EXPECT_EQ(rises, 0) << what;
      EXPECT_EQ(h.back()[transforms], static_cast<double>(o.report.transforms)) << what;
      EXPECT_EQ(h.back()[evaluations], static_cast<double>(o.report.evaluations)) << what;
    }
  }
  EXPECT_EQ(scenes, 5);  // all but rho = l at w/rho = P (0.65 pixel)
}

// ---- the interaction comes back ------------------------------------------------------------

int cancel_at_two(std::int64_t iteration, double, double, void *) { return iteration >= 2; }

void expect_own_adhesion(const asp::System &system, const Scene &s, const std::string &what) {
  const asp::ExponentialAdhesion *adhesion = asp::exponential_adhesion(system.interaction());
  ASSERT_NE(adhesion, nullptr) << what;
  EXPECT_EQ(adhesion->work(), s.work) << what;
  EXPECT_EQ(adhesion->range(), s.range) << what;
}

// After a converged solve, after a cancel in the first stage and after the iteration limit
// met in the first stage, the system's adhesion is the one set, exactly; a solve stopped in
// the first stage reports it as it would any other (cancelled at iteration 2; the limit).
TEST(RangeContinuation, TheInteractionIsRestoredHoweverTheSolveEnds) {
  const Scene s = adhesive_scene(64, 0.1, 1.0);
  const double factor = 4.0;
  const std::int64_t first_stage = solve_by_hand(s, factor, 1e-8, false).first.report.iterations;
  ASSERT_GT(first_stage, 5);
  {
    auto system = system_of(s);
    asp::Solver solver = gap_solver(factor);
    solver.solve(*system, Control::penetration, s.penetration);
    EXPECT_TRUE(solver.report().converged());
    expect_own_adhesion(*system, s, "converged");
  }
  {
    auto system = system_of(s);
    asp::Solver solver = gap_solver(factor);
    solver.set_progress(cancel_at_two, nullptr);
    solver.solve(*system, Control::penetration, s.penetration);
    EXPECT_EQ(solver.report().termination, asp::Termination::cancelled);
    EXPECT_EQ(solver.report().iterations, 2);
    expect_own_adhesion(*system, s, "cancelled");
  }
  {
    auto system = system_of(s);
    asp::Solver solver = gap_solver(factor);
    solver.set_option("max_iterations", 5.0);
    solver.solve(*system, Control::penetration, s.penetration);
    EXPECT_EQ(solver.report().termination, asp::Termination::iteration_limit);
    EXPECT_EQ(solver.report().iterations, 5);
    expect_own_adhesion(*system, s, "iteration limit");
    // The system solves on from there, warm, with its own range (no stage: a warm start).
    solver.set_option("max_iterations", 3000.0);
    solver.solve(*system, Control::penetration, s.penetration);
    EXPECT_TRUE(solver.report().converged());
    expect_own_adhesion(*system, s, "after the iteration limit");
  }
}

// When memory runs out in the middle of a continued solve (the library's allocator limited to
// a little more each time, as in test_solver_framework.cpp), the solve throws, the system's
// adhesion is its own, exactly, and its state is the cold one it started from (the solve held
// it); some limit lets the solve through, which then converges.
TEST(RangeContinuation, TheInteractionIsRestoredWhenMemoryRunsOut) {
  const Scene s = adhesive_scene(64, 0.1, 1.0);
  auto system = system_of(s);
  const asp::ContactState cold = system->state();
  asp::Solver solver = gap_solver(4.0);
  const std::int64_t pixels = s.grid->n_pixels();
  int failures = 0;
  bool solved = false;
  for (int step = 0; step < 400 && !solved; ++step) {
    asp::set_field_bytes_limit(asp::field_bytes_in_use() + 4 * pixels * step + 1);
    try {
      solver.solve(*system, Control::penetration, s.penetration);
      solved = true;
    } catch (const std::bad_alloc &) {
      ++failures;
    }
    asp::set_field_bytes_limit(0);
    expect_own_adhesion(*system, s, "after step " + std::to_string(step));
    if (solved) break;
    EXPECT_TRUE(asp_test::field_vector(system->state().pressure) ==
                asp_test::field_vector(cold.pressure))
        << "step " << step;
    EXPECT_TRUE(asp_test::field_vector(system->state().gap) == asp_test::field_vector(cold.gap))
        << "step " << step;
  }
  std::printf("%d solves ran out of memory before one went through\n", failures);
  EXPECT_GT(failures, 0);
  ASSERT_TRUE(solved);
  EXPECT_TRUE(solver.report().converged());
}

// Under a mean pressure <= 0 there is no continuation, whatever the option: an explicit
// factor solves as 0 does, bit for bit.
TEST(RangeContinuation, AnExplicitFactorDoesNothingUnderATensileOrZeroLoad) {
  const Scene s = adhesive_scene(64, 0.1, 1.0);
  for (double load : {0.0, -1e-4}) {
    const Outcome explicit_factor = solve(s, gap_solver(4.0), Control::mean_pressure, load);
    const Outcome none = solve(s, gap_solver(0.0), Control::mean_pressure, load);
    expect_identical(explicit_factor, none, "mean pressure " + std::to_string(load));
  }
  // A compressive load takes it.
  const Outcome pressed = solve(s, gap_solver(4.0), Control::mean_pressure, 1e-3);
  const Outcome plain = solve(s, gap_solver(0.0), Control::mean_pressure, 1e-3);
  EXPECT_TRUE(pressed.report.converged());
  EXPECT_FALSE(pressed.pressure == plain.pressure &&
               pressed.report.iterations == plain.report.iterations);
}

// A cancel asked at the first stage's last iteration stops the solve. A state that met the
// tolerance is reported converged rather than cancelled (asperity.h: "unless that
// iteration's error already met the tolerance"); in the first stage that tolerance is the
// stage's, 1e-2, and a cancel there once ended the stage as converged, the cancel dropped,
// and the second stage went on (a callback that asks once, a button pressed once, saw the
// solve run to its end: converged after 26 iterations). Expected: cancelled at that
// iteration (the solve's own tolerance, 1e-8, is not met there).
struct OneCancel {
  std::int64_t at = 0;
  int calls_at = 0;  // how often the callback was asked at iteration `at`
};

int cancel_once_at(std::int64_t iteration, double, double, void *data) {
  auto *c = static_cast<OneCancel *>(data);
  if (iteration != c->at) return 0;
  return c->calls_at++ == 0 ? 1 : 0;
}

TEST(RangeContinuation, ACancelAtTheFirstStagesLastIterationStopsTheSolve) {
  const Scene s = adhesive_scene(64, 0.1, 1.0);
  const double factor = 4.0;
  const ByHand hand = solve_by_hand(s, factor, 1e-8, false);
  ASSERT_GT(hand.first.report.iterations, 0);
  // The control: one iteration earlier, the cancel is honoured.
  for (const std::int64_t at : {hand.first.report.iterations - 1, hand.first.report.iterations}) {
    auto system = system_of(s);
    asp::Solver solver = gap_solver(factor);
    OneCancel cancel;
    cancel.at = at;
    solver.set_progress(cancel_once_at, &cancel);
    solver.solve(*system, Control::penetration, s.penetration);
    std::printf("cancel once at iteration %lld (the first stage's last is %lld): %s after %lld "
                "iterations, the callback asked %d times there\n",
                static_cast<long long>(at),
                static_cast<long long>(hand.first.report.iterations),
                asp::termination_name(solver.report().termination),
                static_cast<long long>(solver.report().iterations), cancel.calls_at);
    EXPECT_EQ(solver.report().termination, asp::Termination::cancelled)
        << "at " << at << ": " << asp::termination_name(solver.report().termination);
    EXPECT_EQ(solver.report().iterations, at) << "at " << at;
    expect_own_adhesion(*system, s, "cancelled at " + std::to_string(at));
  }
}

// ---- the state it reaches ------------------------------------------------------------------

// On unresolved scenes the continued solve (the default, auto) converges to its tolerance in
// a finite state whose energy is at most the plain cold solve's plus 1e-9 of it, as on the
// challenge's scene (docs/performance.md). 1e-9: two solves that end in the same state to
// the tolerance 1e-8 differ in energy by less (measured 7e-10 at 64^2, rho = l: the same
// contact set, pressures within 3e-8 of the peak; the elastic and adhesive energies cancel
// in part, so the total's relative error exceeds theirs), and a different metastable state
// by far more (1e-4 to 1e-1 of the energy on these scenes).
// Not every continuation does: at 128^2, rho = l, w/rho = P (zone 0.65 pixel) a factor of
// 1.75 (sqrt(2/zone)) reached a state with 1.5e-3 more energy than the plain cold solve's
// (one pixel in contact differs; with levels 0 too, and with F = 4: 1.4e-3). That is why auto
// leaves zones above continuation_largest_zone (0.5 pixel) alone: on that scene and on 64^2,
// rho = l, w/rho = P auto is the plain solve, and the other four scenes here are continued.
TEST(RangeContinuation, TheContinuedStateIsFiniteAndNoHigherInEnergy) {
  for (const std::int64_t n : {64, 128}) {
    for (double range_over_l : {0.1, 1.0}) {
      for (double stress_over_p : {1.0, 100.0}) {
        if (n == 128 && stress_over_p > 1.0) continue;
        const Scene s = adhesive_scene(n, range_over_l, stress_over_p);
        const std::string what = std::to_string(n) + "^2, rho = " +
                                 std::to_string(range_over_l) + " l, w/rho = " +
                                 std::to_string(stress_over_p) + " P";
        const Outcome plain = solve(s, 0.0), continued = solve(s, -1.0);
        int contact_differs = 0;
        for (std::size_t i = 0; i < plain.gap.size(); ++i)
          contact_differs += (plain.gap[i] == 0.0) != (continued.gap[i] == 0.0);
        std::printf("%s: plain %lld iterations (%s), energy %.10e; continued %lld (%s), "
                    "energy %.10e; %d pixels in or out of contact, max dp/p %.1e\n",
                    what.c_str(), static_cast<long long>(plain.report.iterations),
                    asp::termination_name(plain.report.termination), plain.energy,
                    static_cast<long long>(continued.report.iterations),
                    asp::termination_name(continued.report.termination), continued.energy,
                    contact_differs,
                    asp_test::max_abs_difference(plain.pressure, continued.pressure) /
                        asp_test::max_abs(plain.pressure));
        EXPECT_TRUE(continued.report.converged()) << what;
        EXPECT_LE(continued.report.error, 1e-8) << what;
        int not_finite = 0;
        for (std::size_t i = 0; i < continued.pressure.size(); ++i)
          not_finite +=
              !std::isfinite(continued.pressure[i]) || !std::isfinite(continued.gap[i]);
        EXPECT_EQ(not_finite, 0) << what;
        ASSERT_TRUE(std::isfinite(continued.energy)) << what;
        EXPECT_LE(continued.energy, plain.energy + 1e-9 * std::fabs(plain.energy)) << what;
      }
    }
  }
}

// On a resolved scene (6.5 pixels of zone; one stable state expected) an explicit F = 4
// reaches the plain solve's state: the same contact set and pressures within 1e-6 of the
// peak (both meet the tolerance 1e-8, a residual that the adhesive operator, less well
// conditioned than the elastic one alone, amplifies by far less than 100; as in
// test_nested_grids.cpp), and energies within 1e-8 of each other (the energies of two states
// that meet the tolerance differ at most by about the residual times the state, relative:
// the tolerance). Measured: 2e-9 of the peak, 6e-11 in energy.
TEST(RangeContinuation, OnAResolvedSceneTheContinuedStateIsThePlainOne) {
  const Scene s = adhesive_scene(64, 10.0, 1.0);
  const Outcome plain = solve(s, 0.0), continued = solve(s, 4.0);
  ASSERT_TRUE(plain.report.converged());
  ASSERT_TRUE(continued.report.converged());
  const double peak = asp_test::max_abs(plain.pressure);
  const double dp = asp_test::max_abs_difference(plain.pressure, continued.pressure) / peak;
  std::printf("resolved: plain %lld iterations, continued %lld; max dp/p %.1e, energies "
              "%.12e and %.12e\n",
              static_cast<long long>(plain.report.iterations),
              static_cast<long long>(continued.report.iterations), dp, plain.energy,
              continued.energy);
  EXPECT_FALSE(plain.pressure == continued.pressure);  // the stage ran
  int contact_differs = 0;
  for (std::size_t i = 0; i < plain.gap.size(); ++i)
    contact_differs += (plain.gap[i] == 0.0) != (continued.gap[i] == 0.0);
  EXPECT_EQ(contact_differs, 0);
  EXPECT_LT(dp, 1e-6);
  EXPECT_NEAR(continued.energy, plain.energy, 1e-8 * std::fabs(plain.energy));
}

// ---- threads -------------------------------------------------------------------------------

// A 256 x 128 grid (32768 pixels, the size at which loops and FFTs take threads): the
// continued solve on two threads makes the iterations it makes on one, and its pressure and
// gap agree to 1e-12 of their largest (as in test_thread_counts.cpp: only the order of
// FFTW's sums differs, rounding of 1e-16 that the solve amplifies by less than 1e4).
TEST(RangeContinuation, TwoThreadsGiveWhatOneGives) {
  Outcome o[2];
  Scene s = adhesive_scene(128, 0.1, 1.0, 256);
  ASSERT_FALSE(asp::resolution(*system_of(s)).resolved);
  for (int threads = 1; threads <= 2; ++threads) {
    // The same heights on a grid of each thread count.
    s.grid = asp_test::grid_2d(256, 128, 2.0, 1.0);
    s.grid->set_threads(threads);
    ASSERT_EQ(s.grid->threads(), threads);
    o[threads - 1] = solve(s, -1.0);
    ASSERT_TRUE(o[threads - 1].report.converged()) << threads << " threads";
  }
  std::printf("%lld and %lld iterations, max dp %.1e, dg %.1e of the largest\n",
              static_cast<long long>(o[0].report.iterations),
              static_cast<long long>(o[1].report.iterations),
              asp_test::max_abs_difference(o[0].pressure, o[1].pressure) /
                  asp_test::max_abs(o[0].pressure),
              asp_test::max_abs_difference(o[0].gap, o[1].gap) / asp_test::max_abs(o[0].gap));
  EXPECT_EQ(o[1].report.iterations, o[0].report.iterations);
  EXPECT_LE(asp_test::max_abs_difference(o[0].pressure, o[1].pressure),
            1e-12 * asp_test::max_abs(o[0].pressure));
  EXPECT_LE(asp_test::max_abs_difference(o[0].gap, o[1].gap), 1e-12 * asp_test::max_abs(o[0].gap));
}

}  // namespace
