// SPDX-License-Identifier: GPL-2.0-or-later
// A scene made ready to solve: read (with the command line's overrides), its contact built,
// its solver made and checked against the scene, and its output directory made. Everything
// that can be refused is refused here, before any solve.
#pragma once

#include <string>
#include <vector>

#include "contact.hpp"
#include "plots.hpp"
#include "scene.hpp"

namespace cli {

struct Session {
  Scene scene;
  ComputeOptions compute;  // the command line's threads, FFT planning and wisdom file
  Contact contact;
  Solver solver;          // the scene's solver (null when not asked for)
  std::string directory;  // the output directory, made
  Plotter plotter;
};

// scene_path "" reads the built-in scene.
Scene read_scene(const std::string &scene_path, const std::vector<Override> &overrides);

// with_solver: make the scene's solver and check that it serves the scene's control. The
// FFTW wisdom file is read once the scene is, before the first grid. The output directory is
// made last (make_directory; compare calls it after checking its solvers).
Session open_session(const std::string &scene_path, const std::vector<Override> &overrides,
                     const ComputeOptions &compute, bool with_solver);

// Makes the scene's output directory and sets session.directory.
void make_directory(Session &session);

// The solver's refusal of the scene, if any: "" when it serves it.
std::string refusal(asp_solver *solver, const Contact &contact, int control);

// A solver of `algorithm` with its option "variable" set to `variable` ("" leaves the default),
// then the settings.
Solver make_variant(const std::string &algorithm, const std::string &variable,
                    const std::string &where, std::vector<OptionSetting> settings);

// How compare names a variant: "lbfgsb:gap", or the algorithm's name when it has no variable.
std::string variant_name(const std::string &algorithm, const std::string &variable);

// Every algorithm, in each of its variants, that serves the contact under the control, by
// variant_name.
std::vector<std::string> serving_solvers(const Contact &contact, int control);

// The scene's solver with its options, checked against the scene. An algorithm that serves
// the scene in none of its variants is refused for that before its options are set (they may
// have been written for another algorithm: --algorithm pk on a scene written for bugnicourt
// on the gap); a refusal names the solvers that do serve the scene.
Solver scene_solver(const Scene &scene, const Contact &contact);

}  // namespace cli
