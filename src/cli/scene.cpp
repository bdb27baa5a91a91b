// SPDX-License-Identifier: GPL-2.0-or-later
// The scene file's keys, their defaults and their checks (docs/command.md lists them).
#include "scene.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <toml++/toml.h>

#include "asperity/asperity.h"
#include "exit_status.hpp"
#include "io/height_map.hpp"
#include "scene_reader.hpp"

namespace cli {
namespace {

// ---- overrides (--set key.path=value) ---------------------------------------------------------

// Sets one dotted key of the document to the override's value, creating tables on the way.
void apply_override(toml::table &document, const Override &override) {
  const std::string &setting = override.setting;
  const std::string origin = override.origin;
  if (override.remove) {
    toml::node *node = document.at_path(setting).node();
    const size_t dot = setting.find_last_of('.');
    toml::node *parent =
        dot == std::string::npos ? &document : document.at_path(setting.substr(0, dot)).node();
    if (node != nullptr && parent != nullptr && parent->is_table())
      parent->as_table()->erase(setting.substr(dot == std::string::npos ? 0 : dot + 1));
    return;
  }
  const size_t equals = setting.find('=');
  if (equals == std::string::npos || equals == 0)
    throw usage_error(origin + ": expected KEY=VALUE, such as solver.tolerance=1e-10");
  // Messages about the value name the argument: where() shows a source path starting with
  // "--" as it is.
  const std::string path = setting.substr(0, equals);
  const std::string text = setting.substr(equals + 1);

  // The value as TOML (numbers, booleans, strings, arrays, inline tables); a bare word is a
  // string, so that --set solver.algorithm=lbfgs needs no quotes.
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + text, origin);
  } catch (const toml::parse_error &) {
    std::string quoted = "\"";
    for (char c : text) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    try {
      parsed = toml::parse("value = " + quoted + "\"", origin);
    } catch (const toml::parse_error &e) {
      throw usage_error(origin + ": cannot read the value: " + std::string(e.description()));
    }
  }
  toml::node &value = *parsed.get("value");

  toml::table *table = &document;
  size_t start = 0;
  for (;;) {
    const size_t dot = path.find('.', start);
    const std::string key = path.substr(start, dot == std::string::npos ? dot : dot - start);
    if (key.empty()) throw usage_error(origin + ": the key '" + path + "' has an empty part");
    if (dot == std::string::npos) {
      table->insert_or_assign(key, std::move(value));  // keeps its origin for messages
      return;
    }
    toml::node *next = table->get(key);
    if (next == nullptr) next = &table->insert_or_assign(key, toml::table{}).first->second;
    if (!next->is_table())
      throw usage_error(origin + ": '" + path.substr(0, dot) + "' is not a table in the scene");
    table = next->as_table();
    start = dot + 1;
  }
}

// ---- the tables -----------------------------------------------------------------------------

// A length unit ("" when absent), refused unless unit_in_metres knows it.
std::string length_unit(SceneTable &t, const std::string &key) {
  const std::string unit = t.text(key, "");
  if (!unit.empty()) {
    try {
      asp::io::unit_in_metres(unit);
    } catch (const std::invalid_argument &e) {
      t.refuse(key, e.what());
    }
  }
  return unit;
}

// The memory of this machine in bytes (0 when the system does not say).
double machine_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

// "1.1e+12 bytes" as "1.1 TB".
std::string bytes_text(double bytes) {
  const char *const units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB", "ZB", "YB"};
  int k = 0;
  while (bytes >= 1000.0 && k < 8) bytes /= 1000.0, ++k;
  std::ostringstream text;
  text.precision(3);
  text << bytes << " " << units[k];
  return text.str();
}

// A grid whose heights alone (one double a pixel; a solve holds several such arrays) would
// not fit this machine's memory is refused at its larger side, as the scene's mistake it
// is, before anything is allocated.
void check_grid_fits(SceneTable &t, const GridSpec &grid) {
  const double pixels = static_cast<double>(grid.nx) * static_cast<double>(grid.ny);
  const double bytes = pixels * sizeof(double), memory = machine_memory();
  if (!(memory > 0.0) || bytes <= memory) return;
  const bool along_x = grid.nx >= grid.ny;
  std::ostringstream problem;
  problem.precision(3);
  if (grid.ny > 1) problem << grid.nx << " x " << grid.ny << " = ";
  problem << pixels << " pixels, whose heights alone need " << bytes_text(bytes)
          << ", more than this machine's memory (" << bytes_text(memory) << ")";
  t.refuse(along_x ? "nx" : "ny", problem.str());
}

GridSpec read_grid(SceneTable t, bool from_file) {
  GridSpec grid;
  t.accepts({"nx", "ny", "lx", "ly", "unit"});
  grid.unit = length_unit(t, "unit");
  if (from_file) {
    // The file gives the pixels; the scene may state them only to check them.
    grid.nx = t.integer("nx", 1, 0);
    grid.ny = t.integer("ny", 1, 0);
    grid.lx = t.positive("lx", 0.0);
    grid.ly = t.positive("ly", 0.0);
  } else {
    grid.nx = t.integer("nx", 2);
    grid.ny = t.integer("ny", 1, grid.nx);
    grid.lx = t.positive("lx", 1.0);
    grid.one_dimensional = grid.ny == 1;
    if (grid.one_dimensional && t.has("ly"))
      t.refuse("ly", "a one-dimensional grid (ny = 1) has no ly");
    grid.ly = t.positive("ly", grid.lx * static_cast<double>(grid.ny) /
                                   static_cast<double>(grid.nx));
    check_grid_fits(t, grid);
  }
  t.finish();
  return grid;
}

SubstrateSpec read_substrate(SceneTable t, bool measured) {
  SubstrateSpec substrate;
  t.accepts({"type", "contact_modulus", "k0", "pressure_unit", "thickness", "poisson_ratio"});
  // Measured surfaces are not periodic: their default is the free half-space.
  substrate.type_given = t.has("type");
  const std::string type =
      t.choice("type", {"periodic", "free", "layer"}, measured ? "free" : "periodic");
  substrate.periodic = type != "free";
  substrate.layer = type == "layer";
  if (substrate.layer) {
    substrate.thickness = t.positive("thickness");
    substrate.poisson_ratio = t.real("poisson_ratio");
    if (!(substrate.poisson_ratio >= 0.0 && substrate.poisson_ratio < 0.5))
      t.refuse("poisson_ratio",
               "must be at least 0 and below 0.5 (at 0.5 the bonded, incompressible layer "
               "cannot be compressed)");
    if (t.has("k0"))
      t.refuse("k0", "the layer's stiffness under a uniform pressure, M/thickness, is its own");
  } else {
    for (const char *key : {"thickness", "poisson_ratio"})
      if (t.has(key)) t.refuse(key, "belongs to type = \"layer\" only");
  }
  substrate.contact_modulus = t.positive("contact_modulus");
  // A name to show with pressures ("MPa"): nothing is converted.
  substrate.pressure_unit = t.text("pressure_unit", "");
  if (t.has("pressure_unit") &&
      substrate.pressure_unit.find_first_not_of(" \t") == std::string::npos)
    t.refuse("pressure_unit", "is empty: leave it out for pressures in the units of E*");
  substrate.k0 = t.positive("k0", 0.0);
  if (!substrate.periodic && t.has("k0"))
    t.refuse("k0", "the free half-space has no q = 0 mode to set");
  t.finish();
  return substrate;
}

int detrend_mode(SceneTable &t) {
  const std::string mode =
      t.choice("detrend", {"none", "mean", "plane", "curvature"}, "none");
  if (mode == "mean") return ASP_DETREND_MEAN;
  if (mode == "plane") return ASP_DETREND_PLANE;
  if (mode == "curvature") return ASP_DETREND_CURVATURE;
  return 0;
}

TopographySpec read_topography(SceneTable t, const std::string &directory) {
  TopographySpec s;
  const std::string type = t.choice("type", {"self_affine", "flat", "sphere", "paraboloid",
                                             "sinusoid", "double_sinewave", "file"});
  t.accepts({"detrend"});
  if (type == "flat") {
    s.kind = TopographyKind::flat;
  } else if (type == "sphere" || type == "paraboloid") {
    s.kind = type == "sphere" ? TopographyKind::sphere : TopographyKind::paraboloid;
    t.accepts({"radius"});
    s.radius = t.positive("radius");
  } else if (type == "sinusoid") {
    s.kind = TopographyKind::sinusoid;
    t.accepts({"amplitude", "periods_x", "periods_y"});
    s.amplitude = t.positive("amplitude");
    s.periods_x = t.integer("periods_x", 1, 1);
    s.periods_y = t.integer("periods_y", 0, 0);
  } else if (type == "double_sinewave") {
    s.kind = TopographyKind::double_sinewave;
    t.accepts({"amplitude", "ripple_amplitude", "ripple_periods"});
    s.amplitude = t.positive("amplitude");
    s.ripple_amplitude = t.non_negative("ripple_amplitude", 0.0);
    s.ripple_periods = t.integer("ripple_periods", 1);
  } else if (type == "self_affine") {
    s.kind = TopographyKind::self_affine;
    t.accepts({"hurst", "long_cutoff", "rolloff", "short_cutoff", "rms_slope", "rms_height",
               "seed"});
    s.hurst = t.real("hurst", 0.8);
    if (!(s.hurst > 0.0 && s.hurst < 1.0)) t.refuse("hurst", "must lie in (0, 1)");
    s.long_cutoff = t.positive("long_cutoff", 0.0);
    s.rolloff = t.positive("rolloff", 0.0);
    s.short_cutoff = t.positive("short_cutoff");
    t.one_of("rms_slope", "rms_height", true);
    s.rms_slope_given = t.has("rms_slope");
    s.rms = s.rms_slope_given ? t.positive("rms_slope") : t.positive("rms_height");
    s.seed = t.integer("seed", INT64_MIN, 1);
  } else {
    s.kind = TopographyKind::file;
    t.accepts({"path", "format", "height_unit", "pixel_size", "missing"});
    const std::string path = t.text("path");
    if (path.empty()) t.refuse("path", "is empty");
    s.path = path[0] == '/' || directory.empty() ? path : directory + "/" + path;
    s.format = t.choice("format", {"auto", "text", "npy", "x3p"}, "auto");
    s.height_unit = length_unit(t, "height_unit");
    s.pixel_size = t.positive("pixel_size", 0.0);
    s.fill_missing = t.choice("missing", {"refuse", "interpolate"}, "refuse") == "interpolate";
  }
  s.detrend = detrend_mode(t);
  t.finish();
  return s;
}

InteractionSpec read_interaction(SceneTable t) {
  InteractionSpec s;
  const std::string type =
      t.choice("type", {"hard_wall", "adhesive_hard_wall", "soft_wall", "lennard_jones"},
               "hard_wall");
  if (type == "adhesive_hard_wall") {
    s.kind = InteractionKind::adhesive_hard_wall;
    t.accepts({"work_of_adhesion", "range"});
    s.work_of_adhesion = t.positive("work_of_adhesion");
    s.range = t.positive("range");
  } else if (type == "soft_wall") {
    s.kind = InteractionKind::soft_wall;
    t.accepts({"gamma_r", "gamma_a", "range", "rho_r", "rho_a"});
    s.gamma_r = t.positive("gamma_r");
    s.gamma_a = t.non_negative("gamma_a", 0.0);
    // One range for both exponentials unless each is given.
    t.one_of("range", "rho_r", false);
    if (t.has("range")) {
      if (t.has("rho_a")) t.refuse("rho_a", "give either 'range' or 'rho_r' and 'rho_a'");
      s.rho_r = s.rho_a = t.positive("range");
    } else {
      s.rho_r = t.positive("rho_r");
      s.rho_a = t.positive("rho_a");
    }
  } else if (type == "lennard_jones") {
    s.kind = InteractionKind::lennard_jones;
    t.accepts({"work_of_adhesion", "equilibrium_distance"});
    s.work_of_adhesion = t.positive("work_of_adhesion");
    s.equilibrium_distance = t.positive("equilibrium_distance");
  }
  t.finish();
  return s;
}

SweepSpec read_sweep(SceneTable t) {
  SweepSpec s;
  t.accepts({"values", "from", "to", "steps", "unload"});
  if (t.has("values")) {
    for (const char *key : {"from", "to", "steps"})
      if (t.has(key)) t.refuse(key, "give either 'values' or 'from', 'to' and 'steps'");
    s.loading = t.reals("values");
    if (s.loading.empty()) t.refuse("values", "is empty");
  } else {
    const double from = t.real("from"), to = t.real("to");
    const int64_t steps = t.integer("steps", 1);
    if (steps > 1000000) t.refuse("steps", "more than a million steps");
    for (int64_t k = 0; k <= steps; ++k)
      s.loading.push_back(from + (to - from) * static_cast<double>(k) /
                                     static_cast<double>(steps));
  }
  s.unload = t.boolean("unload", true);
  t.finish();
  return s;
}

ControlSpec read_control(SceneTable t) {
  ControlSpec s;
  t.accepts({"quantity", "value", "sweep"});
  s.quantity = t.choice("quantity", {"mean_pressure", "penetration", "mean_gap"});
  s.control = s.quantity == "mean_pressure" ? ASP_CONTROL_MEAN_PRESSURE
              : s.quantity == "penetration" ? ASP_CONTROL_PENETRATION
                                            : ASP_CONTROL_MEAN_GAP;
  t.one_of("value", "sweep", true);
  if (t.has("value")) {
    s.value = t.real("value");
    s.has_value = true;
    s.where = where(t.node("value")->source()) + ": " + t.key_name("value");
  } else {
    s.where = where(t.node("sweep")->source()) + ": " + t.key_name("sweep");
    s.sweep = read_sweep(SceneTable(*t.table("sweep"), t.key_name("sweep")));
    s.has_sweep = true;
  }
  t.finish();
  return s;
}

// One solver option: a number (integers too), a boolean (as 0 or 1) or a text.
OptionSetting read_option(SceneTable &t, const std::string &key) {
  OptionSetting o;
  o.name = key;
  const toml::node &value = *t.node(key);
  o.where = where(value.source()) + ": " + t.key_name(key);
  if (auto real = value.as_floating_point()) {
    o.number = real->get();
  } else if (auto integer = value.as_integer()) {
    o.number = static_cast<double>(integer->get());
  } else if (auto flag = value.as_boolean()) {
    o.number = flag->get() ? 1.0 : 0.0;
  } else if (auto string = value.as_string()) {
    o.is_number = false;
    o.text = string->get();
  } else {
    t.refuse(key, "expected a number, a boolean or a string");
  }
  if (o.is_number && !std::isfinite(o.number)) t.refuse(key, "expected a finite number");
  return o;
}

std::vector<OptionSetting> read_option_table(const toml::table &table, const std::string &name) {
  SceneTable t(table, name);
  std::vector<OptionSetting> options;
  for (auto &&[key, value] : table) {
    (void)value;
    options.push_back(read_option(t, std::string(key.str())));
  }
  return options;
}

SolverSpec read_solver(SceneTable t) {
  SolverSpec s;
  t.accepts({"algorithm", "tolerance", "max_iterations", "stall_window", "options"});
  s.algorithm = t.text("algorithm", s.algorithm);
  const toml::node *named = t.node("algorithm");
  s.where = (named != nullptr ? where(named->source()) : std::string("built-in default")) +
            ": solver.algorithm";
  // The options every algorithm has, checked here for their type and sign (the library
  // checks their ranges).
  auto common = [&](const std::string &key, double value) {
    const toml::node *node = t.node(key);
    s.options.push_back({key, true, value, "", where(node->source()) + ": " + t.key_name(key)});
  };
  if (t.has("tolerance")) common("tolerance", t.positive("tolerance"));
  if (t.has("max_iterations"))
    common("max_iterations", static_cast<double>(t.integer("max_iterations", 1)));
  if (t.has("stall_window"))
    common("stall_window", static_cast<double>(t.integer("stall_window", 0)));
  // "lbfgsb:gap" is lbfgsb with the option variable = "gap", as compare names it.
  const size_t colon = s.algorithm.find(':');
  std::string variable;
  if (colon != std::string::npos) {
    variable = s.algorithm.substr(colon + 1);
    s.algorithm.erase(colon);
    if (s.algorithm.empty() || variable.empty())
      t.refuse("algorithm", "expected NAME or NAME:VARIABLE, such as \"lbfgsb:gap\"");
    s.options.push_back({"variable", false, 0.0, variable, s.where});
  }
  if (const toml::table *options = t.table("options")) {
    for (const OptionSetting &o : read_option_table(*options, t.key_name("options"))) {
      if (o.name == "variable" && !variable.empty())
        throw usage_error(o.where + ": the variable is given twice: here and in " + s.where +
                          " (" + s.algorithm + ":" + variable + ")");
      s.options.push_back(o);
    }
  }
  t.finish();
  return s;
}

CompareSpec read_compare(SceneTable t) {
  CompareSpec s;
  s.solvers = t.texts("solvers", {});
  if (const toml::table *options = t.table("options")) {
    SceneTable by_algorithm(*options, t.key_name("options"));
    for (auto &&[key, value] : *options) {
      const std::string algorithm(key.str());
      const toml::table *table = by_algorithm.table(algorithm);
      s.options[algorithm] = read_option_table(*table, by_algorithm.key_name(algorithm));
    }
    by_algorithm.finish();
  }
  t.finish();
  return s;
}

OutputSpec read_output(SceneTable t, const std::string &default_directory) {
  OutputSpec s;
  s.directory = t.text("directory", default_directory);
  if (s.directory.empty()) t.refuse("directory", "is empty");
  const std::vector<std::string> known = {"pressure", "gap", "displacement", "topography",
                                          "contact"};
  s.fields = t.texts("fields", s.fields);
  for (const std::string &field : s.fields) {
    bool ok = false;
    for (const std::string &k : known) ok = ok || field == k;
    if (!ok)
      t.refuse("fields", "\"" + field +
                             "\" is not a field; the fields are pressure, gap, displacement, "
                             "topography and contact");
  }
  s.history = t.boolean("history", true);
  s.plots = t.boolean("plots", true);
  t.finish();
  return s;
}

std::string stem_of(const std::string &path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0) name = name.substr(0, dot);
  return name;
}

Scene read_document(toml::table &document, const std::string &source,
                    const std::string &directory, const std::string &default_output,
                    const std::vector<Override> &overrides) {
  for (const Override &o : overrides) apply_override(document, o);

  Scene scene;
  scene.source = source;
  scene.directory = directory;
  SceneTable top(document, "");
  top.accepts({"title", "grid", "substrate", "topography", "interaction", "control", "solver",
               "compare", "output"});
  scene.title = top.text("title", "");
  const toml::table empty;
  auto required = [&](const std::string &name) -> const toml::table & {
    const toml::table *table = top.table(name);
    if (table == nullptr) top.refuse_misspelling(name);
    if (table == nullptr)
      throw usage_error(source + ": [" + name + "]: missing: the scene needs a [" + name +
                        "] table");
    return *table;
  };
  auto optional = [&](const std::string &name) -> const toml::table & {
    const toml::table *table = top.table(name);
    return table != nullptr ? *table : empty;
  };

  // The topography first: whether it comes from a file decides the grid's and substrate's
  // defaults.
  scene.topography = read_topography(SceneTable(required("topography"), "topography"), directory);
  const bool measured = scene.topography.kind == TopographyKind::file;
  scene.grid = measured ? read_grid(SceneTable(optional("grid"), "grid"), true)
                        : read_grid(SceneTable(required("grid"), "grid"), false);
  scene.substrate = read_substrate(SceneTable(required("substrate"), "substrate"), measured);
  scene.interaction = read_interaction(SceneTable(optional("interaction"), "interaction"));
  scene.control = read_control(SceneTable(required("control"), "control"));
  scene.solver = read_solver(SceneTable(optional("solver"), "solver"));
  scene.compare = read_compare(SceneTable(optional("compare"), "compare"));
  scene.output = read_output(SceneTable(optional("output"), "output"), default_output);
  top.finish();

  if (!scene.substrate.periodic && scene.grid.one_dimensional)
    throw usage_error(source + ": substrate.type: the free half-space needs a 2D grid (ny > 1)");
  return scene;
}

}  // namespace

Scene read_scene_text(const std::string &text, const std::string &name,
                      const std::vector<Override> &overrides) {
  toml::table document;
  try {
    document = toml::parse(text, name);
  } catch (const toml::parse_error &e) {
    throw usage_error(where(e.source()) + ": not a valid TOML file: " +
                      std::string(e.description()));
  }
  return read_document(document, name, "", "asperity-output", overrides);
}

Scene read_scene_file(const std::string &path, const std::vector<Override> &overrides) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw usage_error(path + ": cannot open the scene file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw usage_error(path + ": cannot read the scene file");
  toml::table document;
  try {
    document = toml::parse(text.str(), path);
  } catch (const toml::parse_error &e) {
    throw usage_error(where(e.source()) + ": not a valid TOML file: " +
                      std::string(e.description()));
  }
  const size_t slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "" : path.substr(0, slash);
  return read_document(document, path, directory, stem_of(path) + "-output", overrides);
}

}  // namespace cli
