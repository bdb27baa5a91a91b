// SPDX-License-Identifier: GPL-2.0-or-later
// Every solver gives on two threads what it gives on one: the pressure and the gap agree to
// 1e-12 of their largest magnitude. Threads change only the order in which the pixels' sums
// are added (core/loops.hpp), and FFTW's threaded transforms round differently; a solve to
// 1e-10 amplifies those rounding differences (1e-16) by less than four orders of magnitude.
// The grids (256 x 256, and the free substrate's 512 x 512 transforms) are above the size at
// which loops and FFTs start using threads. The same count twice gives the same bits. pk's
// defaults (the Fourier preconditioner, Powell's restarts, nested grids) are covered as they
// are, its published iteration and the other solvers' nested grids and preconditioner by
// options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "../option_list.hpp"
#include "scene.hpp"

using namespace asp;

namespace {

enum class Wall { hard, adhesive, soft };

struct Case {
  const char *algorithm;
  const char *variable;  // "" for algorithms without the option
  Wall wall;
  bool free;
  Control control;
  const char *options = "";  // more options, "name=value" separated by spaces
};

// The options of a case, set on the solver.
void set_options(Solver &solver, const std::string &options) {
  for (const asp_test::OptionWord &o : asp_test::option_list(options)) {
    if (o.numeric)
      solver.set_option(o.name, o.number);
    else
      solver.set_option(o.name, o.text);
  }
}

struct Result {
  std::vector<double> pressure, gap;
  SolveReport report;
};

// A rough surface on a 256 x 256 grid of the given thread count; penetration control presses
// it to about 5 % contact.
Result solve(const Case &c, int threads) {
  auto grid = asp_test::grid_2d(256, 256, 256.0, 256.0);
  grid->set_threads(threads);
  const std::vector<double> h = asp_test::rough_surface(*grid, 7, 0.1, 0.25, 4.0);
  System system(grid, 1.0, c.free ? SubstrateKind::free : SubstrateKind::periodic);
  system.set_topography(h.data());
  double value = 0.005;  // mean pressure, in units of E*
  if (c.control == Control::penetration) value = 0.5 * system.height_range() * 0.15;
  if (c.wall == Wall::adhesive) system.set_adhesion(0.02, 0.3);
  if (c.wall == Wall::soft) system.set_soft_wall(0.05, 0.3, 0.01, 0.3);
  Solver solver(c.algorithm);
  solver.set_option("tolerance", 1e-10);
  solver.set_option("max_iterations", 20000.0);
  if (*c.variable != '\0') solver.set_option("variable", std::string(c.variable));
  set_options(solver, c.options);
  solver.solve(system, c.control, value);
  Result r;
  r.pressure = asp_test::field_vector(system.state().pressure);
  r.gap = asp_test::field_vector(system.state().gap);
  r.report = solver.report();
  return r;
}

double largest(const std::vector<double> &v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

std::string name_of(const Case &c) {
  std::string name = c.algorithm;
  if (*c.variable != '\0') name += std::string("_") + c.variable;
  name += c.wall == Wall::hard ? "_hard" : c.wall == Wall::adhesive ? "_adhesive" : "_soft";
  if (c.free) name += "_free";
  for (const char *o = c.options; *o != '\0'; ++o)
    name += std::isalnum(static_cast<unsigned char>(*o)) ? *o : '_';
  return name;
}

// How GoogleTest shows a case (instead of its bytes).
void PrintTo(const Case &c, std::ostream *out) { *out << name_of(c); }

class ThreadCounts : public ::testing::TestWithParam<Case> {};

TEST_P(ThreadCounts, TwoThreadsGiveWhatOneGives) {
  const Case &c = GetParam();
  const Result one = solve(c, 1), two = solve(c, 2), again = solve(c, 2);
  ASSERT_TRUE(one.report.converged()) << termination_name(one.report.termination);
  ASSERT_TRUE(two.report.converged()) << termination_name(two.report.termination);
  EXPECT_LE(asp_test::max_abs_difference(one.pressure, two.pressure),
            1e-12 * largest(one.pressure));
  EXPECT_LE(asp_test::max_abs_difference(one.gap, two.gap), 1e-12 * largest(one.gap));
  EXPECT_EQ(two.pressure, again.pressure);  // the same count: the same bits
}

std::string param_name(const ::testing::TestParamInfo<Case> &info) { return name_of(info.param); }

INSTANTIATE_TEST_SUITE_P(
    Solvers, ThreadCounts,
    ::testing::Values(Case{"pk", "", Wall::hard, false, Control::mean_pressure},
                      Case{"pk", "", Wall::hard, true, Control::mean_pressure},
                      Case{"pk", "", Wall::hard, false, Control::mean_pressure,
                           " preconditioner=none restart=entry levels=0"},
                      Case{"bugnicourt", "pressure", Wall::hard, false,
                           Control::mean_pressure, " levels=auto"},
                      Case{"bugnicourt", "gap", Wall::adhesive, false, Control::penetration,
                           " preconditioner=fourier levels=auto"},
                      Case{"lbfgsb", "pressure", Wall::hard, false, Control::penetration,
                           " levels=auto"},
                      Case{"bugnicourt", "pressure", Wall::hard, false, Control::mean_pressure},
                      Case{"bugnicourt", "gap", Wall::adhesive, false, Control::penetration},
                      Case{"lbfgsb", "pressure", Wall::hard, false, Control::penetration},
                      Case{"lbfgsb", "gap", Wall::adhesive, false, Control::penetration},
                      Case{"lbfgs", "", Wall::soft, false, Control::penetration},
                      Case{"lbfgs_fourier", "", Wall::soft, false, Control::mean_pressure},
                      Case{"fire", "", Wall::soft, false, Control::penetration},
                      Case{"fire_mass_weighted", "", Wall::soft, false, Control::penetration},
                      Case{"gfmd", "", Wall::soft, false, Control::penetration}),
    param_name);

}  // namespace
