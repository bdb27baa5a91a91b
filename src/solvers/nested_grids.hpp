// SPDX-License-Identifier: GPL-2.0-or-later
// Nested grids (cascadic coarse-to-fine): before a solve on the system's grid, the same
// problem is solved on grids coarser by 2, 4, ... per axis (physics/coarse_system.hpp), from
// the coarsest up, each from the prolonged solution of the one below it and to a looser
// tolerance, and the solve on the system's own grid starts from the prolonged solution of the
// finest of them. The option "levels" says how many coarser grids (0: none; "auto", the
// default of the constrained solvers: as many as leave both sides at least 64 pixels).
#pragma once

#include <cstdint>

#include "physics/system.hpp"
#include "solvers/algorithm.hpp"

namespace asp {

// The option's value that stands for "auto", and the smallest side auto leaves a grid.
constexpr double levels_auto = -1.0;
constexpr std::int64_t auto_smallest_side = 64;
// The smallest side an explicit number of levels may leave a grid.
constexpr std::int64_t smallest_side = 8;

// How many coarser levels a solve of the system takes with the option's value: an explicit
// number as it is, refused with Error(unsupported) naming the option and why where the grid
// cannot be halved that often (an odd size, or a side below smallest_side); auto: as many
// halvings as leave both sides at least auto_smallest_side, none on a grid of odd size or
// with a user's potential (the coarse grids would call it with their own pixels). A
// distributed grid's coarse grids are distributed over the same processes. A solve whose
// state carries no pressure (a fresh system, after a reset or a new topography) starts the
// cascade; one from a state with pressure warm-starts from it on its own grid, as without
// levels (see solve_coarse_levels).
std::int64_t nested_levels(const System &system, double levels);

// The coarse levels' work, for the report: their iterations, and their transforms weighted
// by their grid's pixels over the system's (the cost in transforms of the system's size).
struct CoarseWork {
  std::int64_t iterations = 0;
  double transforms = 0.0;
  bool prolonged = false;  // whether the system's state is now a prolonged coarse solution
};

// Solves `levels` coarser levels of the system under the control (at the same mean pressure
// or mean gap; at the same rigid-body position under penetration control) and leaves the
// prolonged solution of the finest of them as the system's state. Does nothing with
// levels = 0 or when the state carries pressure (a warm start, kept). `settings` are those
// of the stage they start on the system's grid (the solve's, or with a continuation in the
// range its first stage's tolerance: range_continuation.hpp); the coarse levels take its
// iteration limit and stall window, a tolerance loosened by level_tolerance_factor per
// level, and neither the history nor the progress callback. With exponential adhesion the coarse levels solve the
// non-adhesive hard wall (continuation; see nested_grids.cpp), except under a load <= 0.
CoarseWork solve_coarse_levels(const AlgorithmSpec &algorithm, const OptionValues &options,
                               System &system, Control control, double value,
                               std::int64_t levels, const MonitorSettings &settings);

// A coarse level's tolerance is the final one times this to the power of its level
// (1 the first coarser grid), at most largest_level_tolerance (and never below the final
// one). Its solution is a start, whose error on the finer grid is that of the prolongation
// (about 1 to 10 on the scenes of asperity_iteration_scaling): coarse tolerances from 10 to
// 1e5 times the final one left the finest level's iterations the same there (pk at 512^2
// and 1024^2 to 1e-8, bugnicourt on the challenge's scene at 512^2 to 1e-6) and saved a few
// percent of the transforms; 1e-4 keeps the coarse contact sets settled.
constexpr double level_tolerance_factor = 100.0;
constexpr double largest_level_tolerance = 1e-4;

}  // namespace asp
