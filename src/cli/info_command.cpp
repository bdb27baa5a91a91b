// SPDX-License-Identifier: GPL-2.0-or-later
// asperity info TOPOGRAPHY: what a measured surface (or a scene's surface) is: its size,
// units and layout, its rms height, slope and curvature, and its power spectrum.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "arguments.hpp"
#include "commands.hpp"
#include "io/height_map.hpp"
#include "outputs.hpp"
#include "wisdom.hpp"

namespace cli {
namespace {

const char *const info_help =
    "usage: asperity info TOPOGRAPHY [OPTION]...\n"
    "\n"
    "Describes a surface: a height file (text matrix, .npy or .x3p) or the surface of a\n"
    "scene file (.toml). Prints its pixels, box, units and layout, the range of its\n"
    "heights, its rms height, rms slope and rms curvature, and writes its radially\n"
    "averaged power spectrum C(q) to the output directory (default: the file's name\n"
    "with -info): power_spectrum.csv, and power_spectrum.png when gnuplot is installed.\n"
    "\n"
    "Options for a height file:\n"
    "  --format F        text, npy or x3p (default: from the content)\n"
    "  --height-unit U   the unit of the heights, when the file does not say (m, mm, um,\n"
    "                    nm, pm, A)\n"
    "  --pixel-size S    the pixel size, in the heights' unit, when the file does not say\n"
    "                    (otherwise lengths are in pixels)\n"
    "  --unit U          show lengths in this unit (m, mm, um, nm, pm, A)\n"
    "  --missing M       refuse (default) or interpolate missing points (NaN)\n"
    "  --detrend D       none (default), mean, plane or curvature\n"
    "  --bins N          bins of the power spectrum (default: half the larger pixel count)\n"
    "  --output DIR      the output directory\n"
    "  --no-plots        no PNG\n"
    "For a scene file, --set KEY=VALUE overrides its keys as for 'asperity run'.\n"
    "\n";

// info's default planning, and why.
const char *const info_planning =
    "estimate (info transforms a surface once or a few times: measuring the plans would "
    "cost more than it saves)";

bool ends_with(const std::string &text, const std::string &end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string stem(const std::string &path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot != std::string::npos && dot > 0 ? name.substr(0, dot) : name;
}

}  // namespace

int info_command(const std::vector<std::string> &arguments) {
  Arguments args(arguments, "asperity info");
  std::vector<Override> overrides;
  std::string path, output, format = "auto", height_unit, unit, missing = "refuse",
                                                            detrend = "none";
  double pixel_size = 0.0;
  int64_t bins = 0;
  bool plots = true;
  ComputeOptions compute;
  compute.planning = ASP_FFT_ESTIMATE;
  auto number = [&](const std::string &text, bool whole) {
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > 0.0) ||
        (whole && value != std::floor(value)))
      args.refuse(whole ? "expected a whole number > 0" : "expected a number > 0");
    return value;
  };
  while (args.next()) {
    if (args.is_flag("--help") || args.is_flag("-h")) {
      std::printf("%s%s\n%s", info_help, compute_options_help(info_planning).c_str(),
                  exit_status_help);
      return exit_converged;
    }
    if (args.is("--set")) {
      const std::string v = args.value();
      overrides.push_back({v, "--set " + v});
    } else if (args.is("--format")) {
      format = args.value();
      if (format != "text" && format != "npy" && format != "x3p" && format != "auto")
        args.refuse("expected text, npy or x3p");
    } else if (args.is("--height-unit")) {
      height_unit = args.value();
    } else if (args.is("--unit")) {
      unit = args.value();
    } else if (args.is("--pixel-size")) {
      pixel_size = number(args.value(), false);
    } else if (args.is("--missing")) {
      missing = args.value();
      if (missing != "refuse" && missing != "interpolate")
        args.refuse("expected refuse or interpolate");
    } else if (args.is("--detrend")) {
      detrend = args.value();
      if (detrend != "none" && detrend != "mean" && detrend != "plane" && detrend != "curvature")
        args.refuse("expected none, mean, plane or curvature");
    } else if (args.is("--bins")) {
      bins = static_cast<int64_t>(number(args.value(), true));
    } else if (args.is("--output")) {
      output = args.value();
    } else if (args.is_flag("--no-plots")) {
      plots = false;
    } else if (args.compute_option(compute)) {
      continue;
    } else if (args.positional() && path.empty()) {
      path = args.current();
    } else {
      if (args.positional()) args.refuse("a second file: info takes one");
      args.refuse_unknown(std::string(info_help) + compute_options_help(info_planning));
    }
  }
  if (path.empty())
    throw usage_error("asperity info: needs a height file or a scene\nRun 'asperity info "
                      "--help' for the options.");

  Scene scene;
  if (ends_with(path, ".toml")) {
    scene = read_scene_file(path, overrides);
  } else {
    if (!overrides.empty())
      throw usage_error("asperity info: --set applies to scene files only");
    scene.source = path;
    TopographySpec &t = scene.topography;
    t.kind = TopographyKind::file;
    t.path = path;
    t.format = format;
    for (const auto &[option, value] : {std::pair<const char *, const std::string *>{
                                             "--height-unit", &height_unit},
                                         {"--unit", &unit}}) {
      if (value->empty()) continue;
      try {
        asp::io::unit_in_metres(*value);
      } catch (const std::invalid_argument &e) {
        throw usage_error(std::string("asperity info: ") + option + " " + *value + ": " +
                          e.what());
      }
    }
    scene.grid.unit = unit;
    t.height_unit = height_unit;
    t.pixel_size = pixel_size;
    t.fill_missing = missing == "interpolate";
    t.pixels_when_size_unknown = true;
    t.from_options = true;
    t.detrend = detrend == "mean"    ? ASP_DETREND_MEAN
                : detrend == "plane" ? ASP_DETREND_PLANE
                : detrend == "curvature" ? ASP_DETREND_CURVATURE
                                         : 0;
  }
  read_wisdom(compute);
  const Surface s = make_surface(scene, compute);
  const int64_t n = static_cast<int64_t>(s.heights.size());
  if (bins > n)
    throw usage_error("--bins " + std::to_string(bins) + ": more bins than the surface's " +
                      std::to_string(n) + " pixels");

  // Everything the library computes comes before any output: heights it refuses (a range or
  // a spectrum that overflows) are a bad surface, refused before the directory is made.
  Grid grid = make_grid(s, compute);
  double rms_height = 0.0, rms_slope = 0.0, rms_curvature = 0.0;
  check_given(asp_topography_statistics(grid.get(), s.heights.data(), n, &rms_height,
                                        &rms_slope, &rms_curvature),
              s.heights_where);
  if (bins == 0) bins = std::min(n, std::max<int64_t>(2, std::max(s.nx, s.ny) / 2));
  std::vector<double> q(static_cast<size_t>(bins)), c(static_cast<size_t>(bins));
  check_given(
      asp_topography_power_spectrum(grid.get(), s.heights.data(), n, bins, q.data(), c.data()),
      s.heights_where);
  const std::string directory =
      prepare_directory(output.empty() ? stem(path) + "-info" : output, "--output");

  const auto [lowest, highest] = std::minmax_element(s.heights.begin(), s.heights.end());
  double mean = 0.0;
  for (double h : s.heights) mean += h;
  mean /= static_cast<double>(n);
  // Without a unit, heights are the file's own numbers (not pixels), and lengths count
  // pixels when the file gives no size, else are the file's numbers too.
  const std::string u = s.unit.empty() ? "" : " " + s.unit;
  const std::string length_unit = !s.unit.empty()       ? u
                                  : s.lengths_in_pixels ? " pixels"
                                                        : " (no unit: the file's numbers)";
  const std::string heights_unit = s.unit.empty() ? " (no unit: the file's numbers)" : u;

  std::printf("surface           %s\n", s.description.c_str());
  for (const std::string &note : s.notes) std::printf("note              %s\n", note.c_str());
  std::printf("pixel size        %.6g", s.lx / static_cast<double>(s.nx));
  if (!s.one_dimensional) std::printf(" x %.6g", s.ly / static_cast<double>(s.ny));
  std::printf("%s\nheights           min %.6g, max %.6g, mean %.6g%s\n", length_unit.c_str(),
              *lowest, *highest, mean, heights_unit.c_str());
  std::printf("rms height        %.6g%s\n", rms_height, heights_unit.c_str());
  std::printf("rms slope         %.6g%s\n", rms_slope,
              s.lengths_in_pixels ? " (height per pixel)" : "");
  std::printf("rms curvature     %.6g%s\n", rms_curvature,
              !s.unit.empty()       ? (" 1/" + s.unit).c_str()
              : s.lengths_in_pixels ? " (height per pixel^2)"
                                    : "");

  const std::string length = s.unit.empty() ? "pixel" : s.unit;
  const std::string c_unit = length + (s.one_dimensional ? "^3" : "^4");
  CsvTable table({column("q", "1/" + length), column("C", c_unit)});
  Series spectrum{"C(q)", {}, {}};
  for (size_t k = 0; k < q.size(); ++k) {
    if (!(c[k] > 0.0)) continue;  // empty bins
    table.add_row({cell(q[k]), cell(c[k])});
    spectrum.x.push_back(q[k]);
    spectrum.y.push_back(c[k]);
  }
  table.write(directory + "/power_spectrum.csv");
  std::string files = "power_spectrum.csv";
  if (plots) {
    LinePlot plot;
    plot.title = "power spectrum (" + path.substr(path.find_last_of('/') + 1) + ")";
    plot.x_label = "q [1/" + length + "]";
    plot.y_label = "C(q) [" + c_unit + "]";
    plot.log_x = plot.log_y = true;
    plot.points = true;
    plot.series.push_back(spectrum);
    const std::string note = Plotter().lines(directory + "/power_spectrum.png", plot);
    if (note.empty()) files += ", power_spectrum.png";
    else std::fprintf(stderr, "asperity: note: %s\n", note.c_str());
  }
  std::printf("outputs           %s/: %s\n", directory.c_str(), files.c_str());
  write_wisdom(compute);
  return exit_converged;
}

}  // namespace cli
