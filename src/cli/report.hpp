// SPDX-License-Identifier: GPL-2.0-or-later
// What the commands print: the scene in a few lines, and the results of a solve.
#pragma once

#include <cstdio>
#include <string>

#include "contact.hpp"
#include "scene.hpp"
#include "solve.hpp"

namespace cli {

// "mean pressure", "penetration" or "mean gap" for an ASP_CONTROL_*.
const char *control_name(int control);

// The unit of a control's value: the pressure unit or the scene's length unit.
std::string control_unit(int control, const Surface &surface);

// The scene: its surface, substrate, interaction, control and the notes made building it,
// and a warning when its grid does not resolve its interaction (resolution.hpp).
void print_scene(std::FILE *out, const Scene &scene, const Contact &contact);

// How a solve ended and the contact's main results.
void print_solve(std::FILE *out, const SolveReport &report, const Surface &surface);

// The scalars of a solve as CSV rows "quantity,value,unit".
void write_summary(const std::string &path, const Scene &scene, const SolveReport &report,
                   const Surface &surface);

// The history of a solve as CSV, one row per iteration.
void write_history(const std::string &path, const SolveReport &report);

}  // namespace cli
