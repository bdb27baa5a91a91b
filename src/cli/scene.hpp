// SPDX-License-Identifier: GPL-2.0-or-later
// A scene: everything one solve or sweep needs, as a scene file (TOML) describes it. Reading a
// scene checks every key and value before anything is built, so that an invalid scene is
// refused with the file, line and key, and nothing runs half-configured; docs/command.md lists
// the keys.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace cli {

struct GridSpec {
  int64_t nx = 0;  // 0: taken from the topography file
  int64_t ny = 0;  // 0: from the file; 1 with one_dimensional
  bool one_dimensional = false;
  double lx = 0.0;  // 0: from the file (or its pixel count times pixel_size)
  double ly = 0.0;
  std::string unit;  // the scene's length unit ("" dimensionless), see asp::io::unit_in_metres
};

struct SubstrateSpec {
  bool periodic = true;
  bool type_given = false;  // the scene chose periodic or free (else the default for its kind)
  double contact_modulus = 1.0;  // E*
  std::string pressure_unit;     // the unit of E* and every pressure, shown only ("" none)
  double k0 = 0.0;               // 0: the library's default
  // An elastic layer of this thickness and Poisson's ratio on a rigid base (periodic).
  bool layer = false;
  double thickness = 0.0;
  double poisson_ratio = 0.0;
};

enum class TopographyKind { flat, sphere, paraboloid, sinusoid, double_sinewave, self_affine, file };

struct TopographySpec {
  TopographyKind kind = TopographyKind::self_affine;
  // sphere, paraboloid
  double radius = 0.0;
  // sinusoid, double_sinewave
  double amplitude = 0.0;
  int64_t periods_x = 1;
  int64_t periods_y = 0;
  double ripple_amplitude = 0.0;
  int64_t ripple_periods = 0;
  // self_affine
  double hurst = 0.8;
  double long_cutoff = 0.0;   // 0: the box's longer side
  double rolloff = 0.0;       // 0: the long cutoff
  double short_cutoff = 0.0;  // required
  bool rms_slope_given = false;
  double rms = 0.0;  // rms slope or rms height
  int64_t seed = 1;
  // file
  std::string path;      // resolved against the scene file's directory
  std::string format;    // "auto", "text", "npy", "x3p"
  std::string height_unit;  // overrides/declares the file's height unit ("" none given)
  double pixel_size = 0.0;  // declares the file's pixel size in the scene unit (0 none)
  bool fill_missing = false;
  bool pixels_when_size_unknown = false;  // asperity info: lengths in pixels for want of a size
  bool from_options = false;  // asperity info FILE: the settings above are its options, which
                              // messages name (--missing, not topography.missing)
  // every kind
  int detrend = 0;  // 0 none, else ASP_DETREND_*
};

enum class InteractionKind { hard_wall, adhesive_hard_wall, soft_wall, lennard_jones };

struct InteractionSpec {
  InteractionKind kind = InteractionKind::hard_wall;
  double work_of_adhesion = 0.0;
  double range = 0.0;                 // adhesive hard wall
  double equilibrium_distance = 0.0;  // Lennard-Jones
  double gamma_r = 0.0, rho_r = 0.0, gamma_a = 0.0, rho_a = 0.0;  // soft wall
};

struct SweepSpec {
  std::vector<double> loading;  // the values of the loading steps, in order
  bool unload = true;           // then the same values back, warm-started
};

struct ControlSpec {
  int control = 0;  // ASP_CONTROL_*
  std::string quantity;  // "mean_pressure", "penetration", "mean_gap"
  double value = 0.0;
  bool has_value = false;
  SweepSpec sweep;
  bool has_sweep = false;
  // Where the value or the sweep was given ("scene.toml:24:9: control.value"), for a value
  // the solve refuses.
  std::string where;
};

// A solver option as the scene gives it: a number or a text.
struct OptionSetting {
  std::string name;
  bool is_number = true;
  double number = 0.0;
  std::string text;
  std::string where;  // "scene.toml:12:1: solver.options.memory", for messages
};

struct SolverSpec {
  std::string algorithm = "pk";
  std::string where;  // where the algorithm was named, for messages
  std::vector<OptionSetting> options;  // tolerance and max_iterations first, then [solver.options]
};

struct CompareSpec {
  std::vector<std::string> solvers;  // empty: every algorithm that serves the scene
  std::map<std::string, std::vector<OptionSetting>> options;  // per algorithm
};

struct OutputSpec {
  std::string directory = "asperity-output";
  std::vector<std::string> fields = {"pressure", "gap", "contact"};
  bool history = true;
  bool plots = true;
};

struct Scene {
  std::string source;  // the file name, or "built-in scene"
  std::string directory;  // where relative paths in the scene are taken from
  std::string title;
  GridSpec grid;
  SubstrateSpec substrate;
  TopographySpec topography;
  InteractionSpec interaction;
  ControlSpec control;
  SolverSpec solver;
  CompareSpec compare;
  OutputSpec output;
};

// One key of the scene set on the command line: "solver.tolerance=1e-10", and the argument
// it came from ("--tolerance 1e-10"), which messages about it name.
// With remove set, setting is a key that is taken out of the scene if it is there (the sweep
// options take out control.value).
struct Override {
  std::string setting;
  std::string origin;
  bool remove = false;
};

// The built-in scene's text (a TOML scene file; `asperity --print-scene` shows it).
extern const char *const default_scene_text;

// Reads a scene file. Each override replaces or adds one key before the scene is checked,
// its value read as a TOML value (a bare word as a string).
// Throws CommandError(exit_usage) naming the file, line and key of the first problem.
Scene read_scene_file(const std::string &path, const std::vector<Override> &overrides);
Scene read_scene_text(const std::string &text, const std::string &name,
                      const std::vector<Override> &overrides);

}  // namespace cli
