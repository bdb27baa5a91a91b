// SPDX-License-Identifier: GPL-2.0-or-later
// What the opaque C handles hold. The C API never exposes these types.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/checks.hpp"
#include "core/error.hpp"

#include "core/grid.hpp"
#include "physics/system.hpp"
#include "solvers/solver.hpp"

// The caller's reference to a grid; systems hold their own.
struct asp_grid {
  std::shared_ptr<asp::Grid> grid;
};

// `busy` is set while a call runs the user's callbacks with the handle in use (a solve, or
// asp_system_get evaluating a potential), so that a callback calling back into the library
// with that handle is refused instead of changing or freeing what the call is working on.
struct asp_system {
  std::unique_ptr<asp::System> system;
  mutable bool busy = false;
  bool has_topography = false;  // asp_system_set_topography succeeded once
};

// solved_revision: the revision (asp::System::revision) of the system its last solve left,
// 0 for none, so that asp_solver_normal_stiffness can tell whether a system is still that
// solve's state.
struct asp_solver {
  std::unique_ptr<asp::Solver> solver;
  mutable bool busy = false;
  std::uint64_t solved_revision = 0;
};

namespace asp::capi {

// A system or solver argument: Error(null_pointer) naming it if NULL, Error(invalid_state)
// if a call that is running has it in use (a callback of that call is calling back with it).
template <class Handle>
void require_handle(const Handle *handle, const char *name) {
  require_not_null(handle, name);
  if (handle->busy)
    throw Error(Status::invalid_state,
                std::string("argument '") + name + "' is in use by the call that is running "
                "this callback (asp_solver_solve, or asp_system_get evaluating a potential): "
                "a callback must not use the system or solver being solved");
}

// A system to be solved: Error(invalid_state) unless its topography was set (a solve on the
// zeros it starts with would report a flat surface as converged).
void require_topography(const asp_system *system);

// n heights of the grid (this process's rows), all finite: else Error(invalid_argument)
// naming the first that is not by its pixel (x, y) and its index in the array.
void require_finite_heights(const Grid &grid, const double *heights, std::int64_t n);

// Marks handles busy for its lifetime (null handles are skipped).
class BusyScope {
 public:
  BusyScope(const asp_system *system, const asp_solver *solver = nullptr)
      : system_(system), solver_(solver) {
    if (system_ != nullptr) system_->busy = true;
    if (solver_ != nullptr) solver_->busy = true;
  }
  ~BusyScope() {
    if (system_ != nullptr) system_->busy = false;
    if (solver_ != nullptr) solver_->busy = false;
  }
  BusyScope(const BusyScope &) = delete;
  BusyScope &operator=(const BusyScope &) = delete;

 private:
  const asp_system *system_;
  const asp_solver *solver_;
};

}  // namespace asp::capi
