// SPDX-License-Identifier: GPL-2.0-or-later
#include "plots.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include "outputs.hpp"

namespace cli {
namespace {

// The program on PATH, or "".
std::string find_on_path(const std::string &name) {
  const char *path = std::getenv("PATH");
  std::istringstream directories(path != nullptr ? path : "/usr/bin:/bin");
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    const std::string candidate = (directory.empty() ? "." : directory) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

// A single-quoted shell word.
std::string quoted(const std::string &text) {
  std::string word = "'";
  for (char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

// A gnuplot string literal (single quotes; a quote is doubled).
std::string literal(const std::string &text) {
  std::string word = "'";
  for (char c : text) word += c == '\'' ? std::string("''") : std::string(1, c);
  return word + "'";
}

// Viridis (van der Walt and Smith, matplotlib's default), sampled at 11 points: gnuplot has
// no built-in perceptually uniform map, and its rgb 33,13,10 rainbow makes bands of equal
// values look like edges.
const char *const viridis =
    "set palette defined (0 '#440154', 0.1 '#482475', 0.2 '#414487', 0.3 '#355f8d', "
    "0.4 '#2a788e', 0.5 '#21918c', 0.6 '#22a884', 0.7 '#44bf70', 0.8 '#7ad151', "
    "0.9 '#bddf26', 1 '#fde725')\n";

}  // namespace

const char *const error_label =
    "error (largest force-balance residual over the free set / reference pressure)";

Plotter::Plotter() {
  const char *chosen = std::getenv("ASPERITY_GNUPLOT");
  if (chosen != nullptr) {
    if (*chosen == '\0') {
      missing_ = "pictures turned off (ASPERITY_GNUPLOT is empty)";
    } else if (access(chosen, X_OK) == 0) {
      program_ = chosen;
    } else {
      missing_ = std::string("ASPERITY_GNUPLOT names no program: ") + chosen;
    }
    return;
  }
  program_ = find_on_path("gnuplot");
  if (program_.empty())
    missing_ = "gnuplot is not installed (Debian: apt-get install gnuplot-nox)";
}

std::string Plotter::run(const std::string &png, const std::string &script) const {
  if (program_.empty()) return "skipped " + png + ": " + missing_;
  // gnuplot writes the picture to a fresh file of the directory, which then replaces the
  // PNG's name (a symbolic link there is replaced, not written through); its script and
  // messages are fresh files too, removed at the end.
  try {
    OutputFile picture(png), script_file(png + ".gnuplot"), errors(png + ".errors");
    // Enhanced text draws the tick labels 10^{%L} as powers; every text of the scene or the
    // user is drawn as it is (noenhanced), so that "lbfgs_fourier" keeps its underscore.
    script_file.write("set terminal pngcairo size 900,700 enhanced\nset output " +
                      literal(picture.fresh()) + "\n" + script);
    const std::string command = quoted(program_) + " " + quoted(script_file.fresh()) + " 2> " +
                                quoted(errors.fresh());
    if (std::system(command.c_str()) != 0) {
      std::ifstream messages(errors.fresh());
      std::string first;
      std::getline(messages, first);
      unlink(png.c_str());  // no picture of an earlier run is left to be taken for this one's
      return "skipped " + png + ": gnuplot failed" + (first.empty() ? "" : ": " + first);
    }
    picture.commit();
  } catch (const CommandError &e) {
    return "skipped " + png + ": " + e.what();
  }
  return "";
}

std::string Plotter::lines(const std::string &png, const LinePlot &plot) const {
  if (program_.empty()) return "skipped " + png + ": " + missing_;
  std::ostringstream script;
  script.precision(17);
  script << "set title " << literal(plot.title) << " noenhanced\n"
         << "set xlabel " << literal(plot.x_label) << " noenhanced\n"
         << "set ylabel " << literal(plot.y_label) << " noenhanced\n"
         << "set grid\nset key outside right top\n";
  if (plot.log_x) script << "set logscale x\nset format x '10^{%L}'\n";
  if (plot.log_y) script << "set logscale y\nset format y '10^{%L}'\n";
  if (plot.y_max > 0.0) script << "set yrange [:" << plot.y_max << "]\n";
  // Inline data blocks keep the picture to one file and one run.
  for (size_t k = 0; k < plot.series.size(); ++k) {
    script << "$data" << k << " << EOD\n";
    const Series &s = plot.series[k];
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (!(plot.log_y && s.y[i] <= 0.0) && !(plot.log_x && s.x[i] <= 0.0))
        script << s.x[i] << " " << s.y[i] << "\n";
    script << "EOD\n";
  }
  script << "plot ";
  for (size_t k = 0; k < plot.series.size(); ++k)
    script << (k ? ", " : "") << "$data" << k << " using 1:2 with "
           << (plot.points ? "linespoints" : "lines") << " lw 2 title "
           << literal(plot.series[k].title) << " noenhanced";
  if (plot.tolerance > 0.0) {
    std::ostringstream title;
    title << "tolerance " << plot.tolerance;
    script << (plot.series.empty() ? "" : ", ") << plot.tolerance
           << " with lines dt 2 lw 2 lc 'black' title " << literal(title.str()) << " noenhanced";
  }
  script << "\n";
  return run(png, script.str());
}

std::string Plotter::map(const std::string &png, const std::vector<double> &values, int64_t nx,
                         int64_t ny, double lx, double ly, const std::string &title,
                         const std::string &label, const std::string &length_label,
                         Colours colours) const {
  if (program_.empty()) return "skipped " + png + ": " + missing_;
  if (ny == 1) {
    LinePlot plot;
    plot.title = title;
    plot.x_label = length_label;
    plot.y_label = label;
    Series s;
    s.title = label;
    for (int64_t i = 0; i < nx; ++i) {
      s.x.push_back(lx * static_cast<double>(i) / static_cast<double>(nx));
      s.y.push_back(values[static_cast<size_t>(i)]);
    }
    plot.series.push_back(std::move(s));
    return lines(png, plot);
  }
  // The values as raw doubles, x fastest, read by gnuplot's binary array format from a fresh
  // file, removed at the end.
  std::unique_ptr<OutputFile> data;
  try {
    data = std::make_unique<OutputFile>(png + ".bin");
    data->write(std::string(reinterpret_cast<const char *>(values.data()),
                            values.size() * sizeof(double)));
  } catch (const CommandError &e) {
    return "skipped " + png + ": " + e.what();
  }
  std::ostringstream script;
  script.precision(17);
  const double dx = lx / static_cast<double>(nx), dy = ly / static_cast<double>(ny);
  script << "set title " << literal(title) << " noenhanced\n"
         << "set xlabel " << literal(length_label) << " noenhanced\nset ylabel "
         << literal(length_label) << " noenhanced\nset cblabel " << literal(label)
         << " noenhanced\nset size ratio -1\n";
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  if (colours == Colours::signed_values && *lowest < 0.0 && *highest > 0.0) {
    // Zero is white whatever the two extremes are (compression is larger than tension),
    // each sign running to its full colour at its own extreme.
    script << "set cbrange [" << *lowest << ":" << *highest << "]\n"
           << "set palette defined (" << *lowest << " '#2166ac', " << *lowest / 2
           << " '#92c5de', 0 '#f7f7f7', " << *highest / 2 << " '#f4a582', " << *highest
           << " '#b2182b')\n";
  } else {
    script << viridis;
  }
  script << "set xrange [0:" << lx << "]\nset yrange [0:" << ly << "]\n"
         << "plot " << literal(data->fresh()) << " binary array=(" << nx << "," << ny
         << ") format='%float64' dx=" << dx << " dy=" << dy << " origin=(" << dx / 2 << ","
         << dy / 2 << ") with image notitle\n";
  return run(png, script.str());
}

}  // namespace cli
