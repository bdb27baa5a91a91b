// SPDX-License-Identifier: GPL-2.0-or-later
// What every solver shares: the monitor's termination reasons, history and progress, the
// registry's refusals and descriptions, and options by name.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <new>
#include <string>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/error.hpp"
#include "scene.hpp"
#include "formulations/dual_formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/registry.hpp"

namespace {
using asp_test::rough_surface;

asp::IterationState at_error(double error) {
  asp::IterationState s;
  s.error = error;
  return s;
}

TEST(Monitor, ConvergedWhenTheErrorMeetsTheTolerance) {
  asp::MonitorSettings settings;
  settings.tolerance = 1e-3;
  asp::Monitor monitor(settings);
  EXPECT_FALSE(monitor.should_stop(0, at_error(1.0)));
  EXPECT_TRUE(monitor.should_stop(1, at_error(1e-3)));
  EXPECT_EQ(monitor.termination(), asp::Termination::converged);
  EXPECT_EQ(monitor.iterations(), 1);
}

TEST(Monitor, IterationLimit) {
  asp::MonitorSettings settings;
  settings.max_iterations = 2;
  asp::Monitor monitor(settings);
  EXPECT_FALSE(monitor.should_stop(0, at_error(1.0)));
  EXPECT_FALSE(monitor.should_stop(1, at_error(0.5)));
  EXPECT_TRUE(monitor.should_stop(2, at_error(0.25)));
  EXPECT_EQ(monitor.termination(), asp::Termination::iteration_limit);
}

TEST(Monitor, StalledWhenTheBestErrorStopsFalling) {
  asp::MonitorSettings settings;
  settings.stall_window = 5;
  asp::Monitor monitor(settings);
  // Falls for a while, then only by 0.1 % per iteration: below the 1 % the window asks for.
  double error = 1.0;
  std::int64_t k = 0;
  for (; k < 10; ++k, error *= 0.5) ASSERT_FALSE(monitor.should_stop(k, at_error(error)));
  // Iteration 10 still improves by half; 11 to 14 do not count.
  for (int extra = 0; extra < 5; ++extra, ++k, error *= 0.999)
    ASSERT_FALSE(monitor.should_stop(k, at_error(error)));
  EXPECT_TRUE(monitor.should_stop(k, at_error(error)));
  EXPECT_EQ(monitor.termination(), asp::Termination::stalled);
  // A window of 0 never stalls.
  settings.stall_window = 0;
  asp::Monitor patient(settings);
  for (std::int64_t i = 0; i < 100; ++i) ASSERT_FALSE(patient.should_stop(i, at_error(1.0)));
}

TEST(Monitor, BreakdownOnANonFiniteErrorKeepsTheLastFiniteOne) {
  asp::Monitor monitor(asp::MonitorSettings{});
  EXPECT_FALSE(monitor.should_stop(0, at_error(0.5)));
  EXPECT_TRUE(monitor.should_stop(1, at_error(NAN)));
  EXPECT_EQ(monitor.termination(), asp::Termination::breakdown);
  EXPECT_EQ(monitor.error(), 0.5);
  // A start that is not finite leaves no finite error: the report says DBL_MAX, which no
  // tolerance accepts (and never 0, which every tolerance would).
  asp::Monitor at_start(asp::MonitorSettings{});
  EXPECT_TRUE(at_start.should_stop(0, at_error(INFINITY)));
  EXPECT_EQ(at_start.termination(), asp::Termination::breakdown);
  EXPECT_EQ(at_start.error(), DBL_MAX);
}

// The iteration that breaks down counts, so it has its history row: iterations + 1 rows
// however a solve ends. Its counters and time are its own; its error, objective and contact
// fraction, not numbers, are those of the last finite state (the error the report gives),
// or DBL_MAX, 0 and 0 when the starting point broke down.
TEST(Monitor, TheIterationThatBreaksDownHasItsHistoryRow) {
  using C = asp::HistoryColumn;
  asp::MonitorSettings settings;
  settings.record_history = true;
  asp::Monitor monitor(settings);
  asp::IterationState start = at_error(0.5);
  start.objective = -2.0;
  start.contact_fraction = 0.25;
  start.evaluations = 1;
  start.transforms = 2;
  EXPECT_FALSE(monitor.should_stop(0, start));
  asp::IterationState broken = at_error(NAN);
  broken.objective = INFINITY;
  broken.contact_fraction = NAN;
  broken.evaluations = 3;
  broken.transforms = 6;
  EXPECT_TRUE(monitor.should_stop(1, broken));
  EXPECT_EQ(monitor.termination(), asp::Termination::breakdown);
  ASSERT_EQ(static_cast<std::int64_t>(monitor.history().size()), monitor.iterations() + 1);
  const auto &row = monitor.history().back();
  EXPECT_EQ(row[static_cast<int>(C::iteration)], 1.0);
  EXPECT_EQ(row[static_cast<int>(C::evaluations)], 3.0);
  EXPECT_EQ(row[static_cast<int>(C::transforms)], 6.0);
  EXPECT_GE(row[static_cast<int>(C::seconds)], monitor.history()[0][static_cast<int>(C::seconds)]);
  EXPECT_EQ(row[static_cast<int>(C::error)], monitor.error());
  EXPECT_EQ(row[static_cast<int>(C::error)], 0.5);
  EXPECT_EQ(row[static_cast<int>(C::objective)], -2.0);
  EXPECT_EQ(row[static_cast<int>(C::contact_fraction)], 0.25);
  // A finite error with an objective that is not finite breaks down the same way.
  asp::Monitor objective(settings);
  EXPECT_FALSE(objective.should_stop(0, start));
  asp::IterationState no_objective = at_error(0.25);
  no_objective.objective = NAN;
  EXPECT_TRUE(objective.should_stop(1, no_objective));
  EXPECT_EQ(objective.history().size(), 2u);

  asp::Monitor at_start(settings);
  EXPECT_TRUE(at_start.should_stop(0, broken));
  ASSERT_EQ(at_start.history().size(), 1u);
  const auto &first = at_start.history()[0];
  EXPECT_EQ(first[static_cast<int>(C::iteration)], 0.0);
  EXPECT_EQ(first[static_cast<int>(C::evaluations)], 3.0);
  EXPECT_EQ(first[static_cast<int>(C::error)], DBL_MAX);
  EXPECT_EQ(first[static_cast<int>(C::objective)], 0.0);
  EXPECT_EQ(first[static_cast<int>(C::contact_fraction)], 0.0);
}

int cancel_at_three(std::int64_t iteration, double, double, void *calls) {
  ++*static_cast<int *>(calls);
  return iteration == 3 ? 1 : 0;
}

TEST(Monitor, ProgressIsCalledEveryIterationAndCancels) {
  int calls = 0;
  asp::MonitorSettings settings;
  settings.progress = cancel_at_three;
  settings.progress_data = &calls;
  settings.record_history = true;
  asp::Monitor monitor(settings);
  std::int64_t k = 0;
  while (!monitor.should_stop(k, at_error(1.0 / (k + 1)))) ++k;
  EXPECT_EQ(k, 3);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(monitor.termination(), asp::Termination::cancelled);
  ASSERT_EQ(monitor.history().size(), 4u);
  EXPECT_EQ(monitor.history()[3][static_cast<int>(asp::HistoryColumn::iteration)], 3.0);
  EXPECT_EQ(monitor.history()[3][static_cast<int>(asp::HistoryColumn::error)], 0.25);
}

// ---- the registry and options -------------------------------------------------------------

TEST(Registry, RefusesUnknownAlgorithmsNamingTheKnownOnes) {
  try {
    asp::Solver solver("no-such-solver");
    FAIL() << "accepted an unknown algorithm";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::unsupported);
    EXPECT_NE(std::string(e.what()).find("pk"), std::string::npos) << e.what();
  }
}

TEST(Registry, RefusesAControlTheAlgorithmDoesNotServeBeforeTouchingTheSystem) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  asp::System system(grid, 1.0);
  auto h = rough_surface(*grid, 1);
  system.set_topography(h.data());
  system.state().pressure[3] = 0.25;  // a state that must survive the refusal
  asp::Solver solver("pk");
  try {
    solver.solve(system, asp::Control::mean_gap, 0.1);
    FAIL() << "pk accepted mean-gap control";
  } catch (const asp::Error &e) {
    EXPECT_EQ(e.status(), asp::Status::unsupported);
    EXPECT_NE(std::string(e.what()).find("mean_gap"), std::string::npos) << e.what();
  }
  EXPECT_EQ(system.state().pressure[3], 0.25);
  EXPECT_FALSE(solver.report().available);
}

// Every refusal before a solve is made by check_request: what the algorithm serves, and then,
// when the request has a value, the value (asp_solver_supports asks without one).
TEST(Registry, CheckRequestRefusesTheValueToo) {
  auto grid = asp_test::grid_2d(8, 8, 1.0, 1.0);
  asp::System system(grid, 1.0);
  asp::OptionValues gap;
  gap.texts["variable"] = "gap";
  const asp::AlgorithmSpec &bugnicourt = asp::find_algorithm("bugnicourt");
  const asp::AlgorithmSpec &pk = asp::find_algorithm("pk");
  struct Case {
    const asp::AlgorithmSpec &algorithm;
    asp::Control control;
    double value;
    const char *why;
  };
  const Case refused[] = {
      {bugnicourt, asp::Control::mean_gap, -1e-3, "a mean gap cannot be negative"},
      {pk, asp::Control::mean_pressure, -1e-3, "cannot carry a negative mean pressure"},
      {pk, asp::Control::penetration, std::nan(""), "'value'"},
  };
  for (const Case &c : refused) {
    EXPECT_NO_THROW(asp::check_request(c.algorithm, gap, system, c.control, nullptr)) << c.why;
    try {
      asp::check_request(c.algorithm, gap, system, c.control, &c.value);
      ADD_FAILURE() << c.why << ": accepted";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::invalid_argument);
      EXPECT_NE(std::string(e.what()).find(c.why), std::string::npos) << e.what();
    }
  }
  // With adhesion a tensile mean pressure is a request like any other.
  system.set_adhesion(1e-4, 1e-2);
  const double tensile = -1e-3;
  EXPECT_NO_THROW(
      asp::check_request(bugnicourt, gap, system, asp::Control::mean_pressure, &tensile));
}

TEST(Registry, DescribesEveryOptionWithItsDefault) {
  const std::string text = asp::describe(asp::find_algorithm("pk"));
  for (const char *word : {"pk:", "mean_pressure", "penetration", "tolerance", "1e-08",
                           "max_iterations", "10000", "stall_window", "1000"})
    EXPECT_NE(text.find(word), std::string::npos) << word << " missing from:\n" << text;
}

TEST(Options, DefaultsRangesAndTypes) {
  asp::Solver solver("pk");
  EXPECT_EQ(solver.option("tolerance"), 1e-8);
  EXPECT_EQ(solver.option("max_iterations"), 10000);
  EXPECT_EQ(solver.option("stall_window"), 1000);
  solver.set_option("tolerance", 1e-6);
  EXPECT_EQ(solver.option("tolerance"), 1e-6);
  for (double bad : {0.0, -1.0, std::nan(""), HUGE_VAL})
    EXPECT_THROW(solver.set_option("tolerance", bad), asp::Error) << bad;
  EXPECT_THROW(solver.set_option("max_iterations", 2.5), asp::Error);
  EXPECT_THROW(solver.set_option("max_iterations", 0.0), asp::Error);
  EXPECT_THROW(solver.set_option("stall_window", -1.0), asp::Error);
  EXPECT_THROW(solver.set_option("tolerance", std::string("small")), asp::Error);
  try {
    solver.set_option("tolerence", 1e-6);
    FAIL();
  } catch (const asp::Error &e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'tolerence'"), std::string::npos) << message;
    EXPECT_NE(message.find("tolerance"), std::string::npos) << message;  // lists valid names
  }
  EXPECT_EQ(solver.option("tolerance"), 1e-6);  // refusals change nothing
}

// ---- whole solves through the monitor -----------------------------------------------------

// A whole solve of "fire" that breaks down at its starting point (a corrupted warm start):
// its history has its one row, as the report counts iteration 0.
TEST(Solve, FireBreakingDownAtTheStartHasTheRowOfItsIteration) {
  auto grid = asp_test::grid_2d(32, 32, 32.0, 32.0);
  asp::System system(grid, 1.0);
  const std::vector<double> h = rough_surface(*grid, 5, 0.1, 0.5, 2.0);
  system.set_topography(h.data());
  system.set_soft_wall(0.05, 0.3, 0.01, 0.3);
  system.state().gap[5] = NAN;
  system.state().pressure[5] = NAN;
  asp::Solver solver("fire");
  solver.set_history(true);
  solver.solve(system, asp::Control::penetration, -0.45);
  EXPECT_EQ(solver.report().termination, asp::Termination::breakdown);
  ASSERT_EQ(static_cast<std::int64_t>(solver.history().size()), solver.report().iterations + 1);
  for (double v : solver.history().back()) EXPECT_TRUE(std::isfinite(v));
  EXPECT_EQ(solver.history().back()[static_cast<int>(asp::HistoryColumn::error)],
            solver.report().error);
}

TEST(Solve, BreakdownResetsTheStateAndSaysSo) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  asp::System system(grid, 1.0);
  auto h = rough_surface(*grid, 2);
  system.set_topography(h.data());
  system.state().pressure[5] = NAN;  // a corrupted warm start
  asp::Solver solver("pk");
  solver.solve(system, asp::Control::mean_pressure, 0.01);
  EXPECT_EQ(solver.report().termination, asp::Termination::breakdown);
  EXPECT_FALSE(solver.report().converged());
  EXPECT_TRUE(std::isfinite(solver.report().error));
  for (double p : system.state().pressure) ASSERT_EQ(p, 0.0);
  for (std::size_t i = 0; i < h.size(); ++i)
    ASSERT_EQ(system.state().gap[i], system.max_height() - h[i]);
  // The system is usable: the next solve converges.
  solver.solve(system, asp::Control::mean_pressure, 0.01);
  EXPECT_TRUE(solver.report().converged());
}

// Memory that runs out in the middle of a solve (a solver's work arrays, a quasi-Newton pair
// made on the way) leaves the system consistent: the state it had before the call, or, once
// the solve has begun to change it in place, the zero-pressure state a breakdown leaves. Each
// solver runs from a warm state under a ceiling on the fields' bytes raised in steps of 4
// bytes per pixel until the solve gets through.
TEST(Solve, MemoryRunningOutDuringASolveLeavesAConsistentState) {
  struct Case {
    const char *algorithm;
    const char *variable;  // "" for none
    bool soft_wall;
    asp::Control control;
    double value;
  };
  const Case cases[] = {
      {"pk", "", false, asp::Control::mean_pressure, 0.01},
      {"bugnicourt", "gap", false, asp::Control::penetration, 0.004},
      {"lbfgsb", "gap", false, asp::Control::penetration, 0.004},
      {"lbfgs", "", true, asp::Control::penetration, -0.45},
      {"fire_mass_weighted", "", true, asp::Control::penetration, -0.45},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.algorithm);
    auto grid = asp_test::grid_2d(32, 32, 32.0, 32.0);
    asp::System system(grid, 1.0);
    const std::vector<double> h = rough_surface(*grid, 5, 0.1, 0.5, 2.0);
    system.set_topography(h.data());
    if (c.soft_wall) {
      system.set_soft_wall(0.05, 0.3, 0.01, 0.3);
    } else if (std::string(c.variable) == "gap") {
      system.set_adhesion(1e-4, 0.3);
    }
    asp::Solver solver(c.algorithm);
    if (*c.variable != '\0') solver.set_option("variable", std::string(c.variable));
    solver.set_option("max_iterations", 5.0);
    solver.solve(system, c.control, 0.5 * c.value);  // a warm state to start from
    const asp::ContactState before = system.state();
    const std::int64_t pixels = grid->n_pixels();
    bool solved = false;
    int failures = 0;
    for (int step = 0; step < 200 && !solved; ++step) {
      asp::set_field_bytes_limit(asp::field_bytes_in_use() + 4 * pixels * step + 1);
      try {
        solver.solve(system, c.control, c.value);
        solved = true;
      } catch (const std::bad_alloc &) {
        ++failures;
      }
      asp::set_field_bytes_limit(0);
      if (solved) break;
      const asp::ContactState &now = system.state();
      bool unchanged = now.penetration == before.penetration;
      bool reset = now.penetration == 0.0;
      for (std::int64_t i = 0; i < pixels; ++i) {
        unchanged = unchanged && now.pressure[i] == before.pressure[i] &&
                    now.gap[i] == before.gap[i];
        reset = reset && now.pressure[i] == 0.0 && now.gap[i] == system.max_height() - h[i];
      }
      ASSERT_TRUE(unchanged || reset) << "after running out of memory at step " << step;
      system.state() = before;
    }
    EXPECT_TRUE(solved);
    EXPECT_GT(failures, 1);  // it ran out at more than one point
    // The system is usable afterwards.
    solver.set_option("max_iterations", 10000.0);
    solver.solve(system, c.control, c.value);
    EXPECT_TRUE(solver.report().converged()) << asp::termination_name(solver.report().termination);
  }
}

TEST(Solve, StallsWhenTheToleranceIsBelowRoundOff) {
  auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
  asp::System system(grid, 1.0);
  auto h = rough_surface(*grid, 3);
  system.set_topography(h.data());
  asp::Solver solver("pk");
  solver.set_option("tolerance", 1e-300);
  solver.set_option("stall_window", 20);
  solver.solve(system, asp::Control::mean_pressure, 0.01);
  EXPECT_EQ(solver.report().termination, asp::Termination::stalled);
  EXPECT_LT(solver.report().error, 1e-12);  // it got as far as rounding allows
  for (double p : system.state().pressure) ASSERT_TRUE(std::isfinite(p));
}

TEST(Solve, HistoryRecordsEveryIterationOnlyWhenAsked) {
  auto grid = asp_test::grid_2d(48, 48, 1.0, 1.0);
  asp::System system(grid, 1.0);
  auto h = rough_surface(*grid, 4);
  system.set_topography(h.data());
  asp::Solver solver("pk");
  solver.solve(system, asp::Control::mean_pressure, 0.01);
  EXPECT_TRUE(solver.history().empty());

  system.reset_state();
  solver.set_history(true);
  solver.solve(system, asp::Control::mean_pressure, 0.01);
  const asp::History &history = solver.history();
  ASSERT_EQ(static_cast<std::int64_t>(history.size()), solver.report().iterations + 1);
  using C = asp::HistoryColumn;
  for (std::size_t k = 0; k < history.size(); ++k) {
    EXPECT_EQ(history[k][static_cast<int>(C::iteration)], static_cast<double>(k));
    if (k > 0) {
      EXPECT_GE(history[k][static_cast<int>(C::transforms)],
                history[k - 1][static_cast<int>(C::transforms)] + 1);
      EXPECT_EQ(history[k][static_cast<int>(C::evaluations)],
                history[k - 1][static_cast<int>(C::evaluations)] + 1);
      EXPECT_GE(history[k][static_cast<int>(C::seconds)],
                history[k - 1][static_cast<int>(C::seconds)]);
    }
  }
  EXPECT_EQ(history.back()[static_cast<int>(C::error)], solver.report().error);
  EXPECT_EQ(history.back()[static_cast<int>(C::contact_fraction)], system.contact_fraction());
  // At the solution the dual objective is minus the elastic energy, q = 0 term included.
  const double objective = history.back()[static_cast<int>(C::objective)];
  const double energy = system.elastic_energy() + system.mean_mode_energy();
  EXPECT_NEAR(objective, -energy, 1e-6 * energy);
  // And it decreases from the start overall.
  EXPECT_LT(objective, history.front()[static_cast<int>(C::objective)]);
}

}  // namespace
