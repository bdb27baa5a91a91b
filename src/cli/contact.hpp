// SPDX-License-Identifier: GPL-2.0-or-later
// The library objects a scene describes: the surface's heights on their grid, the grid, the
// system (substrate, topography, interaction) and configured solvers. Everything a scene asks
// for is built and checked here, before any solve, so that a scene the library refuses is
// reported as a bad scene (exit status 2) and nothing runs half-configured.
#pragma once

#include <string>
#include <vector>

#include "library.hpp"
#include "scene.hpp"

namespace cli {

// The heights of a scene on their grid, in the scene's length unit.
struct Surface {
  int64_t nx = 0;
  int64_t ny = 0;  // 1 for a one-dimensional grid
  bool one_dimensional = false;
  double lx = 0.0;
  double ly = 0.0;  // lx for a one-dimensional grid
  std::string unit;  // "" when the scene is dimensionless
  std::string pressure_unit;  // the scene's substrate.pressure_unit; "" when it gives none
  bool lengths_in_pixels = false;  // the file gives no size: lengths count pixels (info only)
  std::vector<double> heights;  // x fastest
  std::string description;      // one line: what the surface is and where it came from
  std::vector<std::string> notes;  // what was assumed or changed on the way (units, filling)
  // What a message about the grid or the heights names: "scene.toml: grid.nx = 64, grid.ny =
  // 64" for a generated surface, the file for a measured one.
  std::string grid_where;
  std::string heights_where;
};

// How every grid of a command computes, from its command line (--threads, --planning), and
// the FFTW wisdom file it keeps between runs (--wisdom, --no-wisdom; wisdom.hpp reads and
// writes it).
struct ComputeOptions {
  int threads = 0;                 // 0: the library's default
  int planning = ASP_FFT_MEASURE;  // ASP_FFT_*
  std::string wisdom;              // --wisdom PATH; "" for the default file
  bool no_wisdom = false;          // --no-wisdom
};

// The scene's grid, as the library makes it, with the threads and FFT planning of `compute`
// set before anything transforms on it. A grid the library refuses is a bad scene, named by
// surface.grid_where.
Grid make_grid(const Surface &surface, const ComputeOptions &compute);

// The surface a scene describes: generated or read from its file, converted to the scene's
// unit, missing points filled if the scene says so, detrended if it says so.
Surface make_surface(const Scene &scene, const ComputeOptions &compute = {});

struct Contact {
  Surface surface;
  Grid grid;
  System system;
  bool periodic = true;
};

// The grid and the system (substrate, topography, interaction) of a scene.
Contact make_contact(const Scene &scene, const ComputeOptions &compute = {});

// A solver of that algorithm with the settings applied in order. `where` names the place in
// the scene the algorithm came from, for messages.
Solver make_solver(const std::string &algorithm, const std::string &where,
                   const std::vector<OptionSetting> &settings);


}  // namespace cli
