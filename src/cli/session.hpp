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

}  // namespace cli
