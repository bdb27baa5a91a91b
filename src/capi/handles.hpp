// What the opaque C handles hold. Each owns one C++ object; the C API never exposes them.
#pragma once

#include <memory>

#include "core/grid.hpp"
#include "physics/system.hpp"
#include "solvers/solver.hpp"

struct asp_grid {
  std::unique_ptr<asp::Grid> grid;
};

struct asp_system {
  std::unique_ptr<asp::System> system;
};

struct asp_solver {
  std::unique_ptr<asp::Solver> solver;
};
