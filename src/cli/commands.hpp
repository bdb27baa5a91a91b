// SPDX-License-Identifier: GPL-2.0-or-later
// The asperity command's subcommands. Each takes its arguments (after the subcommand's name),
// prints its results on standard output and its notes and progress on standard error, and
// returns an exit status (exit_status.hpp); refusals and failures are thrown as CommandError.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "session.hpp"

namespace cli {

int run_command(const std::vector<std::string> &arguments);
int compare_command(const std::vector<std::string> &arguments);
int sweep_command(const std::vector<std::string> &arguments);
int info_command(const std::vector<std::string> &arguments);

// The loading and unloading steps of the session's sweep (shared by run and sweep).
int run_sweep(Session &session);

// The exit statuses, for every --help.
extern const char *const exit_status_help;

}  // namespace cli
