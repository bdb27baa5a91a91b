// SPDX-License-Identifier: GPL-2.0-or-later
// The registry of algorithms: each one's name, what it serves (controls, and what it needs of
// substrates and interactions), its options with defaults and ranges, and how to run it. Requests an
// algorithm cannot serve are refused here, the same way for every algorithm, before a solve
// touches the system.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "solvers/algorithm.hpp"

namespace asp {

// Every algorithm of this build, in a fixed order.
const std::vector<AlgorithmSpec> &algorithms();
// Throws Error(unsupported) naming the known algorithms if there is no such algorithm.
const AlgorithmSpec &find_algorithm(const std::string &name);
// Every refusal of a request before a solve, in one place. Throws Error(unsupported) with a
// message naming what the algorithm does not serve; then, with a value (null: the request
// without one, asp_solver_supports), Error(invalid_argument) naming 'value' when it is not
// finite, a negative mean pressure on the non-adhesive hard wall, or a negative mean gap.
// What only the scene's units can tell (whether doubles represent it) is refused when they
// are made (scene_units).
void check_request(const AlgorithmSpec &algorithm, const OptionValues &options,
                   const System &system, Control control, const double *value = nullptr);
// The algorithm, what it serves and its options, as text (asp_solver_describe).
std::string describe(const AlgorithmSpec &algorithm);

// Words a real or integer option also takes, each standing for a number outside its range
// ("levels": "auto" for -1): set with asp_solver_set_option_string, read back by either
// getter. Empty for the other options.
const std::vector<std::pair<std::string, double>> &option_words(const std::string &name);

}  // namespace asp
