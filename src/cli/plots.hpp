// SPDX-License-Identifier: GPL-2.0-or-later
// Pictures as PNG, drawn by gnuplot (Debian's gnuplot-nox) when it is installed: the library
// has no plotting dependency, and a command never fails for want of a picture; a missing or
// failing gnuplot skips the PNG with a note. ASPERITY_GNUPLOT names another gnuplot program
// (an empty value turns the pictures off); it is called with one argument, the script, whose
// "set output" names the picture to draw, so that a program of one's own can keep a copy.
#pragma once

#include <string>
#include <vector>

namespace cli {

// One line of a line plot.
struct Series {
  std::string title;
  std::vector<double> x;
  std::vector<double> y;
};

struct LinePlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  bool points = false;  // mark each point (sweeps), not only the lines
  double y_max = 0.0;   // > 0: the top of the y axis (keeps a runaway solver from flattening
                        // the others' lines)
  double tolerance = 0.0;  // > 0: a dashed horizontal line at this y, titled with it
  std::vector<Series> series;
};

// The y label of error plots: what the error of every solver is (docs/command.md).
extern const char *const error_label;

// How a map colours its values.
enum class Colours {
  sequential,  // viridis, a perceptually uniform map, from the lowest value to the highest
  signed_values,  // the same when the values have one sign; when they have both (adhesive
                  // pressure), a diverging map with white at zero, blue below and red above
};

class Plotter {
 public:
  Plotter();
  // Each draws one PNG and returns "" when it was written, or a note saying why not.
  std::string lines(const std::string &png, const LinePlot &plot) const;
  // A field of nx x ny pixels on a box lx x ly (a line plot when ny == 1).
  std::string map(const std::string &png, const std::vector<double> &values, int64_t nx,
                  int64_t ny, double lx, double ly, const std::string &title,
                  const std::string &label, const std::string &length_label,
                  Colours colours = Colours::sequential) const;

 private:
  std::string run(const std::string &png, const std::string &script) const;

  std::string program_;  // empty: none found
  std::string missing_;  // why there is none
};

}  // namespace cli
