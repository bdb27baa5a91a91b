// SPDX-License-Identifier: GPL-2.0-or-later
// The library's handles owned by C++ objects, and its status codes turned into CommandError.
// The command uses only the public C interface, like any other program linked to asperity.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asperity/asperity.h"
#include "exit_status.hpp"

namespace cli {

struct GridDeleter {
  void operator()(asp_grid *grid) const { asp_grid_destroy(grid); }
};
struct SystemDeleter {
  void operator()(asp_system *system) const { asp_system_destroy(system); }
};
struct SolverDeleter {
  void operator()(asp_solver *solver) const { asp_solver_destroy(solver); }
};
using Grid = std::unique_ptr<asp_grid, GridDeleter>;
using System = std::unique_ptr<asp_system, SystemDeleter>;
using Solver = std::unique_ptr<asp_solver, SolverDeleter>;

// The library's message for the last failed call, prefixed by what was being done.
std::string library_message(int status, const std::string &what);

// The library's last error message without the name of the function that set it
// ("asp_solver_solve: "), which says nothing to a user of the command.
std::string refusal_message();

// Throws failure(...) unless status is ASP_OK: the library or the system failed.
void check(int status, const std::string &what);

// Throws usage_error(where + ": " + message) when the library refused a value the user gave
// (ASP_ERR_INVALID_ARGUMENT, ASP_ERR_UNSUPPORTED, ASP_ERR_SIZE_MISMATCH), failure otherwise.
void check_given(int status, const std::string &where);

// Reads one observable (ASP_MEAN_PRESSURE, ...) of the system.
double observable(const asp_system *system, int key);

// "converged", "iteration limit", ... for an ASP_TERMINATION_* reason.
const char *termination_name(int reason);

// The text of asp_algorithms: one name per line.
std::string algorithm_names();

// What asp_solver_describe says of the solver's algorithm.
std::string description(const asp_solver *solver);

// The names of the solver's options, in the order its description lists them.
std::vector<std::string> option_names(const asp_solver *solver);

// The values of the solver's option "variable" (the unknown it solves for: "pressure",
// "gap"), its default first; empty when the algorithm has one formulation only.
std::vector<std::string> variables(const asp_solver *solver);

}  // namespace cli
