// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "io/height_map.hpp"
#include "scene_reader.hpp"

namespace cli {
namespace {

std::string number(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

std::string with_unit(double value, const std::string &unit) {
  return number(value) + (unit.empty() ? "" : " " + unit);
}

// Generated surfaces: the scene's grid, heights from the library's generators.
Surface generated_surface(const Scene &scene, const ComputeOptions &compute) {
  const GridSpec &g = scene.grid;
  const TopographySpec &t = scene.topography;
  Surface s;
  s.nx = g.nx;
  s.ny = g.one_dimensional ? 1 : g.ny;
  s.one_dimensional = g.one_dimensional;
  s.lx = g.lx;
  s.ly = g.one_dimensional ? g.lx : g.ly;
  s.unit = g.unit;
  s.grid_where = scene.source + ": grid.nx = " + std::to_string(g.nx) +
                 (g.one_dimensional ? "" : ", grid.ny = " + std::to_string(g.ny));
  const std::string where = scene.source + ": [topography]";
  s.heights_where = where;
  // The grid first: the library refuses sizes it cannot transform before the heights are
  // made (the scene's reader refused those that do not fit this machine's memory).
  Grid grid = make_grid(s, compute);
  s.heights.assign(static_cast<size_t>(s.nx * s.ny), 0.0);
  const int64_t n = s.nx * s.ny;
  std::ostringstream what;
  what << s.nx;
  if (!s.one_dimensional) what << " x " << s.ny;
  what << " pixels, box " << with_unit(s.lx, s.unit);
  if (!s.one_dimensional) what << " x " << with_unit(s.ly, s.unit);
  double *h = s.heights.data();
  switch (t.kind) {
    case TopographyKind::flat:
      check_given(asp_topography_flat(grid.get(), h, n), where);
      s.description = "flat surface, " + what.str();
      break;
    case TopographyKind::sphere:
      check_given(asp_topography_sphere(grid.get(), t.radius, h, n), where);
      s.description = "sphere of radius " + with_unit(t.radius, s.unit) + ", " + what.str();
      break;
    case TopographyKind::paraboloid:
      check_given(asp_topography_paraboloid(grid.get(), t.radius, h, n), where);
      s.description = "paraboloid of radius " + with_unit(t.radius, s.unit) + ", " + what.str();
      break;
    case TopographyKind::sinusoid:
      check_given(
          asp_topography_sinusoid(grid.get(), t.amplitude, t.periods_x, t.periods_y, h, n),
          where);
      s.description = "sinusoid of amplitude " + with_unit(t.amplitude, s.unit) + ", " +
                      what.str();
      break;
    case TopographyKind::double_sinewave:
      check_given(asp_topography_double_sinewave(grid.get(), t.amplitude, t.ripple_amplitude,
                                                 t.ripple_periods, h, n),
                  where);
      s.description = "double sinewave of amplitude " + with_unit(t.amplitude, s.unit) + ", " +
                      what.str();
      break;
    case TopographyKind::self_affine: {
      const double long_cutoff = t.long_cutoff > 0.0 ? t.long_cutoff : std::max(s.lx, s.ly);
      const double rolloff = t.rolloff > 0.0 ? t.rolloff : long_cutoff;
      check_given(asp_topography_self_affine(grid.get(), t.hurst, long_cutoff, rolloff,
                                             t.short_cutoff,
                                             t.rms_slope_given ? ASP_RMS_SLOPE : ASP_RMS_HEIGHT,
                                             t.rms, t.seed, h, n),
                  where);
      s.description = "self-affine surface (Hurst " + number(t.hurst) + ", seed " +
                      std::to_string(t.seed) + "), " + what.str();
      break;
    }
    case TopographyKind::file: break;
  }
  return s;
}

double metres(const std::string &unit) { return asp::io::unit_in_metres(unit); }

// Measured surfaces: the file's pixels and sizes, in the scene's unit.
Surface measured_surface(const Scene &scene) {
  const TopographySpec &t = scene.topography;
  const GridSpec &g = scene.grid;
  const std::string where = scene.source + ": topography.path";
  asp::io::HeightMap map;
  try {
    map = asp::io::read_height_map(t.path, t.format == "auto"
                                               ? asp::io::FileFormat::automatic
                                               : asp::io::format_from_name(t.format));
  } catch (const std::exception &e) {
    throw usage_error(where + ": " + e.what());
  }

  Surface s;
  s.nx = map.nx;
  s.ny = map.ny;
  s.one_dimensional = map.ny == 1;
  s.grid_where = where + ": " + t.path;
  s.heights_where = where + ": " + t.path;
  if (map.nx * map.ny < 2)
    throw usage_error(where + ": " + t.path +
                      " has one point: a surface needs at least 2 (a profile, or rows of them)");
  // The units the file gives must be known ones: the conversions below take them as such.
  for (const auto &[unit, what] : {std::pair<const std::string &, const char *>{
                                       map.height_unit, "heights"},
                                   {map.length_unit, "lengths"}}) {
    if (unit.empty()) continue;
    try {
      metres(unit);
    } catch (const std::invalid_argument &e) {
      throw usage_error(where + ": " + t.path + " gives its " + what + " in an " + e.what());
    }
  }
  if (g.nx != 0 && g.nx != map.nx)
    throw usage_error(scene.source + ": grid.nx: is " + std::to_string(g.nx) + ", but " +
                      t.path + " has " + std::to_string(map.nx) + " points along x");
  if (g.ny != 0 && g.ny != map.ny)
    throw usage_error(scene.source + ": grid.ny: is " + std::to_string(g.ny) + ", but " +
                      t.path + " has " + std::to_string(map.ny) + " rows (y)");

  // Heights: the file's unit, or the one the scene declares for a file that gives none.
  std::string height_unit = map.height_unit;
  if (!t.height_unit.empty()) {
    if (!height_unit.empty() && metres(height_unit) != metres(t.height_unit))
      throw usage_error(scene.source + ": topography.height_unit: is \"" + t.height_unit +
                        "\", but " + t.path + " gives its heights in " + height_unit);
    height_unit = t.height_unit;
  }
  // The scene's unit: its own, else the file's lateral unit, else the heights' unit.
  s.unit = !g.unit.empty() ? g.unit : !map.length_unit.empty() ? map.length_unit : height_unit;
  if (!height_unit.empty()) {
    const double factor = metres(height_unit) / metres(s.unit);
    for (double &h : map.heights) h *= factor;
  } else if (!s.unit.empty()) {
    s.notes.push_back("heights taken in " + s.unit + ": " + t.path +
                      " does not give their unit (" +
                      (t.from_options ? "--height-unit" : "set topography.height_unit") + ")");
  }

  // The box: the scene's, else from the pixel size, else the file's.
  const bool file_has_size = std::isfinite(map.lx) && map.lx > 0.0;
  const double file_factor =
      file_has_size && !map.length_unit.empty() && !s.unit.empty()
          ? metres(map.length_unit) / metres(s.unit)
          : 1.0;
  if (g.lx > 0.0) {
    s.lx = g.lx;
    s.ly = g.ly > 0.0 ? g.ly : g.lx * static_cast<double>(map.ny) / static_cast<double>(map.nx);
  } else if (t.pixel_size > 0.0) {
    s.lx = t.pixel_size * static_cast<double>(map.nx);
    s.ly = t.pixel_size * static_cast<double>(map.ny);
  } else if (file_has_size) {
    if (map.length_unit.empty() && !s.unit.empty())
      s.notes.push_back("box taken in " + s.unit + ": " + t.path +
                        " does not give the unit of its size");
    s.lx = map.lx * file_factor;
    s.ly = std::isfinite(map.ly) && map.ly > 0.0
               ? map.ly * file_factor
               : s.lx * static_cast<double>(map.ny) / static_cast<double>(map.nx);
  } else if (t.pixels_when_size_unknown) {
    s.lx = static_cast<double>(map.nx);
    s.ly = static_cast<double>(map.ny);
    s.unit = "";
    s.lengths_in_pixels = true;
    s.notes.push_back(t.path + " does not give its physical size: lengths in pixels");
  } else {
    throw usage_error(where + ": " + t.path +
                      " does not give its physical size: set topography.pixel_size, or "
                      "grid.lx (and grid.ly)");
  }
  if (s.one_dimensional) s.ly = s.lx;

  if (map.missing > 0) {
    if (!t.fill_missing)
      throw usage_error(where + ": " + t.path + " has " + asp::io::describe_missing(map) +
                        (t.from_options ? "; use --missing interpolate to fill them"
                                        : "; set topography.missing = \"interpolate\" to "
                                          "fill them"));
    const std::string missing = asp::io::describe_missing(map);
    try {
      asp::io::fill_missing(map);
    } catch (const std::exception &e) {
      throw usage_error(where + ": " + e.what());
    }
    s.notes.push_back("filled " + missing + " by harmonic interpolation");
  }
  s.heights = std::move(map.heights);

  std::ostringstream what;
  what << "file " << t.path << " (" << asp::io::format_name(map.format) << ", " << map.layout
       << "), " << s.nx;
  if (!s.one_dimensional) what << " x " << s.ny;
  what << " pixels, box " << with_unit(s.lx, s.unit);
  if (!s.one_dimensional) what << " x " << with_unit(s.ly, s.unit);
  s.description = what.str();
  return s;
}

const char *detrend_name(int mode) {
  switch (mode) {
    case ASP_DETREND_MEAN: return "mean";
    case ASP_DETREND_PLANE: return "plane";
    default: return "curvature";
  }
}

}  // namespace

Grid make_grid(const Surface &s, const ComputeOptions &compute) {
  asp_grid *grid = nullptr;
  const int status = s.one_dimensional ? asp_grid_create_1d(s.nx, s.lx, &grid)
                                       : asp_grid_create_2d(s.nx, s.ny, s.lx, s.ly, &grid);
  check_given(status, s.grid_where);
  Grid owned(grid);
  // The plans are made at the first transform, with the threads and planning set by then.
  if (compute.threads > 0)
    check_given(asp_grid_set_threads(grid, compute.threads),
                "--threads " + std::to_string(compute.threads));
  check(asp_grid_set_fft_planning(grid, compute.planning), "setting the FFT planning");
  return owned;
}

Surface make_surface(const Scene &scene, const ComputeOptions &compute) {
  Surface s = scene.topography.kind == TopographyKind::file ? measured_surface(scene)
                                                             : generated_surface(scene, compute);
  if (scene.topography.detrend != 0) {
    Grid grid = make_grid(s, compute);
    check_given(asp_topography_detrend(grid.get(), scene.topography.detrend, s.heights.data(),
                                       static_cast<int64_t>(s.heights.size())),
                scene.source + ": topography.detrend");
    s.notes.push_back(std::string("detrended: ") + detrend_name(scene.topography.detrend) +
                      " removed");
  }
  return s;
}

Contact make_contact(const Scene &scene, const ComputeOptions &compute) {
  Contact c;
  c.surface = make_surface(scene, compute);
  c.surface.pressure_unit = scene.substrate.pressure_unit;
  c.grid = make_grid(c.surface, compute);
  const SubstrateSpec &sub = scene.substrate;
  c.periodic = sub.periodic;
  if (c.surface.one_dimensional && !sub.periodic) {
    if (sub.type_given)
      throw usage_error(scene.source +
                        ": substrate.type: the free half-space needs a 2D surface; this one "
                        "is a profile (one row)");
    c.periodic = true;
    c.surface.notes.push_back("a profile (one row): solved on the periodic substrate");
  } else if (sub.periodic && scene.topography.kind == TopographyKind::file) {
    c.surface.notes.push_back(
        "a measured surface on the periodic substrate, which repeats it and joins its edges; "
        "a measurement is not periodic: the free half-space (substrate.type = \"free\", the "
        "default for files) loads only the box");
  }
  asp_system *system = nullptr;
  const std::string where = scene.source + ": [substrate]";
  check_given(sub.layer    ? asp_system_create_layer(c.grid.get(), sub.contact_modulus,
                                                     sub.poisson_ratio, sub.thickness, &system)
              : c.periodic ? asp_system_create(c.grid.get(), sub.contact_modulus, &system)
                           : asp_system_create_free(c.grid.get(), sub.contact_modulus, &system),
              where);
  c.system.reset(system);
  check_given(asp_system_set_topography(system, c.surface.heights.data(),
                                        static_cast<int64_t>(c.surface.heights.size())),
              scene.source + ": [topography]");
  if (sub.k0 > 0.0) check_given(asp_system_set_k0(system, sub.k0), scene.source + ": substrate.k0");

  const InteractionSpec &i = scene.interaction;
  const std::string interaction = scene.source + ": [interaction]";
  switch (i.kind) {
    case InteractionKind::hard_wall: break;
    case InteractionKind::adhesive_hard_wall:
      check_given(asp_system_set_adhesion(system, i.work_of_adhesion, i.range), interaction);
      break;
    case InteractionKind::soft_wall:
      check_given(asp_system_set_soft_wall(system, i.gamma_r, i.rho_r, i.gamma_a, i.rho_a),
                  interaction);
      break;
    case InteractionKind::lennard_jones:
      check_given(asp_system_set_lennard_jones(system, i.work_of_adhesion, i.equilibrium_distance),
                  interaction);
      break;
  }
  return c;
}

Solver make_solver(const std::string &algorithm, const std::string &where,
                   const std::vector<OptionSetting> &settings) {
  asp_solver *solver = nullptr;
  const int created = asp_solver_create(algorithm.c_str(), &solver);
  if (created == ASP_ERR_UNSUPPORTED) {  // an unknown algorithm
    const std::string message = refusal_message();  // before the next call empties it
    std::vector<std::string> names;
    std::istringstream lines(algorithm_names());
    for (std::string name; std::getline(lines, name);) names.push_back(name);
    throw usage_error(where + ": " + message + did_you_mean(algorithm, names));
  }
  check_given(created, where);
  Solver owned(solver);
  // A name the algorithm does not know is refused here, with the closest of its options
  // (the library lists them but cannot guess what was meant).
  const std::vector<std::string> names = option_names(solver);
  for (const OptionSetting &o : settings) {
    if (std::find(names.begin(), names.end(), o.name) != names.end()) continue;
    std::string known;
    for (const std::string &n : names) known += (known.empty() ? "" : ", ") + n;
    throw usage_error(o.where + ": solver '" + algorithm + "' has no option '" + o.name + "'" +
                      did_you_mean(o.name, names) + " (its options: " + known + ")");
  }
  for (const OptionSetting &o : settings) {
    const int status = o.is_number
                           ? asp_solver_set_option(solver, o.name.c_str(), o.number)
                           : asp_solver_set_option_string(solver, o.name.c_str(), o.text.c_str());
    check_given(status, o.where);
  }
  return owned;
}

}  // namespace cli
