// SPDX-License-Identifier: GPL-2.0-or-later
// What the opaque C handles hold. The C API never exposes these types.
#pragma once

#include <memory>

#include "core/grid.hpp"
#include "physics/system.hpp"
#include "solvers/solver.hpp"

// The caller's reference to a grid; systems hold their own.
struct asp_grid {
  std::shared_ptr<asp::Grid> grid;
};

struct asp_system {
  std::unique_ptr<asp::System> system;
};

struct asp_solver {
  std::unique_ptr<asp::Solver> solver;
};
