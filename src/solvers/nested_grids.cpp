// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/nested_grids.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "formulations/scene_units.hpp"
#include "physics/coarse_system.hpp"

namespace asp {

std::int64_t nested_levels(const System &system, double levels) {
  if (levels == 0.0) return 0;
  const bool automatic = levels == levels_auto;
  // A coarse grid calls a user's potential with its own pixels, fewer than the system's: a
  // callback that holds data per pixel would misread them. An explicit count is the user's
  // say that it does not.
  if (automatic && system.interaction().potential_from_callback()) return 0;
  const std::int64_t smallest = automatic ? auto_smallest_side : smallest_side;
  const std::int64_t wanted = automatic ? 64 : static_cast<std::int64_t>(levels);
  std::int64_t nx = system.grid().nx(), ny = system.grid().ny();
  const bool two_d = system.grid().dimension() == 2;
  std::int64_t found = 0;
  std::string obstacle = coarsening_obstacle(system.grid(), smallest);
  while (found < wanted && obstacle.empty()) {
    ++found;
    nx /= 2;
    ny = two_d ? ny / 2 : 1;
    // The sizes alone decide the next halving; a grid of them is made only to solve on it.
    if (nx % 2 != 0 || (two_d && ny % 2 != 0))
      obstacle = "a grid of " + std::to_string(nx) +
                 (two_d ? " x " + std::to_string(ny) : std::string()) +
                 " pixels cannot be halved per axis (odd size)";
    else if (nx / 2 < smallest || (two_d && ny / 2 < smallest))
      obstacle = "halving a grid of " + std::to_string(nx) +
                 (two_d ? " x " + std::to_string(ny) : std::string()) +
                 " pixels would leave fewer than " + std::to_string(smallest) + " a side";
  }
  if (automatic || found == wanted) return found;
  throw Error(Status::unsupported,
              "option 'levels' is " + std::to_string(wanted) + ", but the grid can be halved " +
                  std::to_string(found) + " time" + (found == 1 ? "" : "s") + " only: " +
                  obstacle);
}

namespace {

// Solves `fine`'s problem on `levels` coarser grids, the coarsest first, and prolongs the
// result onto `fine`'s state. `depth` is the level of `fine` (0 the system's own grid).
void cascade(const AlgorithmSpec &algorithm, const OptionValues &options, System &fine,
             Control control, double value, std::int64_t levels, std::int64_t depth,
             double reference_pressure, double finest_pixels, const MonitorSettings &settings,
             CoarseWork &work) {
  if (levels == 0) return;
  std::unique_ptr<System> coarse = coarse_system(fine);
  // One reference pressure for every level: their errors are in the same units, and their
  // tolerances mean the same thing.
  coarse->set_reference_pressure(reference_pressure);
  // Adhesion by continuation: the coarse levels solve the non-adhesive contact, and the
  // adhesive solve on the system's grid starts from it, as a cold solve starts from the
  // surfaces touching at their highest point. Adhesive contact has several stable states;
  // a coarse adhesive state holds contact that its coarse pixels made and the adhesion keeps
  // (a state of higher energy than the cold solve's, on some scenes), where the contact
  // grown from the non-adhesive one reached the cold solve's state or a lower energy on
  // every scene measured (test_nested_grids.cpp, docs/algorithms.md). A tensile or zero
  // load has no non-adhesive solution to start from: there the levels keep the adhesion.
  if (exponential_adhesion(coarse->interaction()) != nullptr &&
      !(control == Control::mean_pressure && value <= 0.0))
    coarse->set_hard_wall();
  // Under penetration control the rigid body stays where it is: the penetration counts from
  // the highest height, which the truncation lowered.
  const double coarse_value = control == Control::penetration
                                  ? value + (coarse->max_height() - fine.max_height())
                                  : value;
  cascade(algorithm, options, *coarse, control, coarse_value, levels - 1, depth + 1,
          reference_pressure, finest_pixels, settings, work);

  MonitorSettings level = settings;
  level.tolerance = std::max(settings.tolerance,
                             std::min(largest_level_tolerance,
                                      settings.tolerance *
                                          std::pow(level_tolerance_factor,
                                                   static_cast<double>(depth + 1))));
  level.record_history = false;
  level.progress = nullptr;
  level.progress_data = nullptr;
  level.reductions = &coarse->grid().reductions();
  Monitor monitor(level);
  {
    const ThreadScope threads(coarse->grid().threads());
    // A coarse level's solve is part of a cold solve, whatever its state (prolonged from the
    // level below, or the surfaces at rest): what the formulations ask of a cold start
    // (PrimalFormulation::snaps_eagerly) holds for it.
    coarse->set_state_held_by_solve(true);
    algorithm.run(*coarse, control, coarse_value, options, monitor);
  }
  coarse->set_state_held_by_solve(false);
  work.iterations += monitor.iterations();
  work.transforms += static_cast<double>(monitor.transforms()) *
                     static_cast<double>(coarse->grid().n_pixels()) / finest_pixels;
  // A breakdown leaves the coarse state reset, and a coarse grid that separated under a
  // tensile load leaves surfaces apart: nothing to start from (the finer grid then starts
  // cold, touching at its highest point, and finds its own stable state or its own
  // separation). So does a coarse state without pressure, the surfaces apart (a penetration
  // short of the highest point): prolonged, it would hold an adhesive finer grid apart, a
  // stable state of higher energy than the contact that a cold start, touching, grows.
  const Termination ended = monitor.termination();
  if (ended != Termination::breakdown && ended != Termination::separated &&
      coarse->carries_pressure()) {
    prolong_state(*coarse, fine);
    if (depth == 0) work.prolonged = true;
  }
}

}  // namespace

CoarseWork solve_coarse_levels(const AlgorithmSpec &algorithm, const OptionValues &options,
                               System &system, Control control, double value,
                               std::int64_t levels, const MonitorSettings &settings) {
  CoarseWork work;
  if (levels == 0 || system.carries_pressure()) return work;
  const double reference_pressure = scene_units(system, control, value).pressure;
  cascade(algorithm, options, system, control, value, levels, 0, reference_pressure,
          static_cast<double>(system.grid().n_pixels()), settings, work);
  return work;
}

}  // namespace asp
