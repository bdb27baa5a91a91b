// SPDX-License-Identifier: GPL-2.0-or-later
// Continuation in the range of the exponential adhesion: before the solve of an adhesive
// scene whose grid does not resolve the cohesive zone, the same scene is solved on the same
// grid with the range F rho (the work of adhesion kept), to a loose tolerance, and the solve
// with the scene's own range starts from that state.
//
// Why: below about one pixel of cohesive zone ((pi/4) E* rho^2/w, physics/resolution.hpp) a
// pixel next to a contact is unstable on its own, and the contact lines settle a pixel at a
// time on the finest grid, so that the iterations grow with the grid. With the range F rho
// the zone is F^2 times longer; where it spans a couple of pixels the contact lines move
// together, and the iterations do not grow with the grid (docs/performance.md, "The growth
// and the cohesive zone"). From that state the scene's own range only has the short way back
// to go. The option "range_continuation" says F (0: none; "auto", the default of bugnicourt:
// the F that makes the zone continuation_zone pixels long, where the zone is at most
// continuation_largest_zone pixels, and none where it is longer).
#pragma once

#include "physics/resolution.hpp"
#include "physics/system.hpp"
#include "solvers/algorithm.hpp"
#include "solvers/monitor.hpp"

namespace asp {

// The option's value that stands for "auto".
constexpr double continuation_auto = -1.0;
// The cohesive zone, in pixels, that auto gives the first stage. On the challenge's scene
// (docs/algorithms.md) zones of 1.5, 2 and 3 pixels took about as many iterations at 1024^2
// and 2048^2 (41 / 41 / 39 and 53 / 54 / 54), and at 4096^2 zones of 1.5 to 4.4 pixels
// took from 71 to 99 with no trend: 2 pixels is the middle of that range, not a sharp
// optimum.
constexpr double continuation_zone = 2.0;
// Auto acts where the zone is at most this many pixels (a factor of at least 2). Nearer to
// resolved, a factor below 2 changes the scene too little to save iterations (a 64^2 test
// scene with a zone of 0.65 pixels: 65 iterations against 55) and led one 128^2 test scene
// to another metastable state, 1.5e-3 higher in energy (test_range_continuation.cpp).
constexpr double continuation_largest_zone = far_from_resolved;
// The first stage's tolerance (or the solve's own if looser): its state is a start, and one
// tighter than this spent iterations the second stage did not get back on that scene.
constexpr double continuation_tolerance = 1e-2;
// The first stage's tolerance in a solve to `tolerance`.
inline double first_stage_tolerance(double tolerance) {
  return tolerance > continuation_tolerance ? tolerance : continuation_tolerance;
}

// The settings for the coarse levels of nested grids in a solve with the continuation's
// factor (0: none) and the solve's settings: with a continuation the coarse levels start its
// first stage, and are solved to that stage's tolerance (every level to 1e-2, as
// nested_grids.hpp derives a level's tolerance from the solve's), not to the final one's.
// On the challenge's scene at 4096^2 that took 57 / 83 / 88 iterations at 1 / 1.5 / 2 um
// against 60 / 82 / 103 with the levels to the final tolerance's, and fewer transforms.
MonitorSettings coarse_level_settings(const MonitorSettings &settings, double factor);

// Refuses an option's value that a solve of the system cannot take: an explicit F >= 1 where
// the interaction is not the exponential adhesion, with Error(unsupported) naming the
// option; a value in (0, 1), with Error(invalid_argument). Changes nothing.
void check_range_continuation(const System &system, double option);

// The factor F of the range for the first stage of a solve of the system under the control,
// from the option's value (checked as above): 0 for none. An explicit F >= 1 is taken as it
// is (1: none). Auto gives sqrt(continuation_zone / zone) where the zone is at most
// continuation_largest_zone pixels, and 0 where it is longer or where the interaction is
// another. Under a mean pressure <= 0 there is none, whatever the option: a tensile load
// that the longer range, with its weaker largest tension w/(F rho), might not hold, and a
// first stage that separates the surfaces is no start. A state that carries pressure (a warm
// start) takes none either: the continuation, like the nested grids, is for a cold solve.
// Collective on a distributed grid.
double continuation_factor(const System &system, Control control, double value, double option);

// Runs the algorithm on the system with the range F rho, to first_stage_tolerance, counting
// its work in the monitor, and leaves the monitor ready for the solve with the scene's own
// range (Monitor::continue_with_next_stage, to `tolerance`) unless the stage was cancelled or
// reached the iteration limit (then the solve is over, in the first stage's state, its
// error that of the range F rho: returns false). A first stage that broke down or separated
// the surfaces leaves the state reset, and the second stage starts cold. The system's
// interaction is its own again on every path, exceptions included, and its revision() is
// unchanged. Does nothing and returns true when F <= 1.
bool solve_with_longer_range(const AlgorithmSpec &algorithm, const OptionValues &options,
                             System &system, Control control, double value, double factor,
                             double tolerance, Monitor &monitor);

}  // namespace asp
