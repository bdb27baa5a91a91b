// SPDX-License-Identifier: GPL-2.0-or-later
// The scene of the scaling benchmarks (asperity_thread_scaling, asperity_mpi_scaling): a
// self-affine surface (Hurst 0.8, rms slope 0.1, roll-off a quarter of the box, short cutoff
// 4 pixels, seed 1) on a periodic substrate, E* = 1; pk and bugnicourt under a mean pressure
// of 0.005 E* (a few percent of contact), lbfgs_fourier with the exponential soft wall of the
// soft-wall benchmark's rough scene (range 0.5 pixels) under penetration control. Solved for a
// fixed number of iterations, the tolerance out of reach.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "physics/surface_statistics.hpp"
#include "physics/system.hpp"
#include "physics/topography.hpp"
#include "solvers/solver.hpp"

namespace bench {

struct ScalingScene {
  std::unique_ptr<asp::System> system;
  asp::Control control = asp::Control::mean_pressure;
  double value = 0.005;
};

// The scene for `algorithm` on `grid` (this process's rows of it, if distributed), on a
// periodic half-space or a free one.
inline ScalingScene scaling_scene(const std::shared_ptr<asp::Grid> &grid, const char *algorithm,
                                  asp::SubstrateKind substrate = asp::SubstrateKind::periodic) {
  asp::SelfAffineParameters p;
  p.hurst = 0.8;
  p.long_cutoff = grid->lx();
  p.rolloff = 0.25 * grid->lx();
  p.short_cutoff = 4.0;
  p.norm = asp::RoughnessNorm::rms_slope;
  p.target = 0.1;
  p.seed = 1;
  std::vector<double> h(static_cast<std::size_t>(grid->local_pixels()));
  asp::self_affine_topography(*grid, p, h.data());
  ScalingScene scene;
  scene.system = std::make_unique<asp::System>(grid, 1.0, substrate);
  scene.system->set_topography(h.data());
  if (std::strcmp(algorithm, "lbfgs_fourier") == 0) {
    const double rc = 1.0 / asp::surface_statistics(*grid, h.data()).rms_curvature;
    scene.system->set_soft_wall(2.10e3 * rc, 0.5, 2.05 * rc, 0.5);
    scene.control = asp::Control::penetration;
    scene.value = 0.05 * scene.system->height_range();
  }
  return scene;
}

// Readies `solver` for a timed solve of `iterations` iterations of the scene: a first short
// solve, untimed, makes the plans and the substrate's tables; the state goes back to rest.
// The iterations are those of the grid itself: no nested grids (pk's default takes them).
inline void warm_up(asp::Solver &solver, ScalingScene &scene, int iterations) {
  solver.set_option("levels", 0.0);
  solver.set_option("tolerance", 1e-300);
  solver.set_option("stall_window", 0.0);
  solver.set_option("max_iterations", 2.0);
  solver.solve(*scene.system, scene.control, scene.value);
  scene.system->reset_state();
  solver.set_option("max_iterations", static_cast<double>(iterations));
}

// A timed solve of a scene readied by warm_up: the seconds before its first iteration (the
// formulation, the solver's arrays, whose fresh pages the kernel clears, and the first
// evaluation), per iteration after it, and in all, from the solve's own clock as its
// progress callback sees it.
struct SolveTimes {
  double setup = 0.0;
  double per_iteration = 0.0;
  double total = 0.0;
};

// A solve's clock as its progress callback sees it: the seconds at its first and last
// iterations. watch() sets it as the solver's progress callback.
struct IterationClock {
  std::int64_t first_iteration = -1, last_iteration = -1;
  double first = 0.0, last = 0.0;

  void watch(asp::Solver &solver) {
    solver.set_progress(
        [](std::int64_t iteration, double seconds, double, void *data) {
          auto *c = static_cast<IterationClock *>(data);
          if (c->first_iteration < 0) {
            c->first_iteration = iteration;
            c->first = seconds;
          }
          c->last_iteration = iteration;
          c->last = seconds;
          return 0;
        },
        this);
  }

  // Seconds per iteration after the first; `none` when there was none.
  double per_iteration(double none) const {
    const std::int64_t iterations = last_iteration - first_iteration;
    return iterations > 0 ? (last - first) / static_cast<double>(iterations) : none;
  }
};

inline SolveTimes timed_solve(asp::Solver &solver, ScalingScene &scene) {
  IterationClock clock;
  clock.watch(solver);
  solver.solve(*scene.system, scene.control, scene.value);
  solver.set_progress(nullptr, nullptr);
  SolveTimes t;
  t.setup = clock.first;
  t.total = solver.report().seconds;
  t.per_iteration = clock.per_iteration(t.total);
  return t;
}

}  // namespace bench
