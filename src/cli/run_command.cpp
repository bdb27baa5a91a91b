// SPDX-License-Identifier: GPL-2.0-or-later
// asperity run [SCENE]: one solve (or the scene's sweep), its report and its files.
#include <cstdio>

#include "arguments.hpp"
#include "commands.hpp"
#include "outputs.hpp"
#include "report.hpp"
#include "solve.hpp"
#include "wisdom.hpp"

namespace cli {
namespace {

const char *const run_help =
    "usage: asperity run [SCENE] [OPTION]...\n"
    "       asperity [OPTION]...            (the same, on the built-in scene)\n"
    "\n"
    "Solves the scene file SCENE (TOML; docs/command.md lists its keys), or without SCENE\n"
    "the built-in scene (a 512 x 512 adhesive rough contact; 'asperity --print-scene'\n"
    "shows it), prints how the solve ended and the contact's main results, and writes to\n"
    "the output directory (default: the scene file's name with -output, in the current\n"
    "directory):\n"
    "  summary.csv       the scalars of the solve: quantity,value,unit\n"
    "  history.csv       one row per iteration: iteration, evaluations, transforms,\n"
    "                    seconds, error, objective, contact_fraction\n"
    "  NAME.npy          the fields of output.fields (pressure, gap, contact by default;\n"
    "                    also displacement, topography), shape (ny, nx), for numpy.load\n"
    "  NAME.png          a map of each field, and convergence.png (error against\n"
    "                    iteration), when gnuplot is installed\n"
    "A scene whose control is a sweep runs the sweep (see 'asperity sweep --help').\n"
    "\n"
    "  --check            reads and builds the scene and checks that its solver serves\n"
    "                     it, prints the scene, and exits (0) without solving or writing\n"
    "\n";

}  // namespace

const char *const exit_status_help =
    "Exit status:\n"
    "  0  every solve converged (or an information option ran)\n"
    "  1  a solve ended without converging: iteration limit, stalled, cancelled or\n"
    "     breakdown (the report says which; the files show the state it left)\n"
    "  2  a bad argument or scene, refused before any work: unknown option or key, bad\n"
    "     value, unreadable or malformed file, a solver that does not serve the scene,\n"
    "     an output directory that cannot be made\n"
    "  3  the library or the system failed: out of memory, FFT planning, writing a file\n";

int run_command(const std::vector<std::string> &arguments) {
  Arguments args(arguments, "asperity run");
  SceneArguments a;
  bool check_only = false;
  const bool proceed = read_scene_arguments(args, run_help, a, [&](Arguments &args) {
    return args.is_flag("--check") ? (check_only = true) : false;
  });
  if (!proceed) return exit_converged;
  const std::vector<Override> &overrides = a.overrides;
  const std::string &scene_path = a.scene_path;

  if (check_only) {
    Session session = open_session(scene_path, overrides, a.compute, false);
    scene_solver(session.scene, session.contact);
    print_scene(stdout, session.scene, session.contact);
    std::printf("solver            %s serves the scene\n", session.scene.solver.algorithm.c_str());
    return exit_converged;
  }
  // From here on, a Ctrl-C cancels: one that comes while the scene is still being set up
  // (a large surface, FFT planning) cancels the solve at its first iteration, so that the
  // run ends the same way (exit 1, "cancelled", the files of the state) whenever it came.
  InterruptGuard interrupts;
  Session session = open_session(scene_path, overrides, a.compute, true);
  if (session.scene.control.has_sweep) return run_sweep(session);

  const Scene &scene = session.scene;
  Contact &contact = session.contact;
  print_scene(stdout, scene, contact);
  std::printf("control           %s %g (%s)\n", control_name(scene.control.control),
              scene.control.value, control_unit(scene.control.control, contact.surface).c_str());
  std::printf("solver            %s\n", scene.solver.algorithm.c_str());
  std::fflush(stdout);

  ProgressLine progress(stderr);
  const SolveReport report =
      solve(session.solver.get(), scene.solver.algorithm, contact, scene.control.control,
            scene.control.value, progress, scene.output.history, scene.control.where);
  print_solve(stdout, report, contact.surface);
  write_wisdom(session.compute);

  // The files.
  const std::string &dir = session.directory;
  std::vector<std::string> written;
  write_summary(dir + "/summary.csv", scene, report, contact.surface);
  written.push_back("summary.csv");
  if (scene.output.history) {
    write_history(dir + "/history.csv", report);
    written.push_back("history.csv");
  }
  for (const std::string &path : write_fields(contact, scene.output.fields, dir))
    written.push_back(path.substr(dir.size() + 1));

  std::vector<std::string> notes;
  if (scene.output.plots) {
    const Surface &s = contact.surface;
    const std::string length = s.unit.empty() ? "length" : "length [" + s.unit + "]";
    const std::string scene_name = file_name(scene.source);
    auto draw = [&](const std::string &name, const std::vector<double> &values,
                    const std::string &label, Colours colours = Colours::sequential) {
      const std::string png = dir + "/" + name + ".png";
      const std::string note =
          session.plotter.map(png, values, s.nx, s.ny, s.lx, s.ly,
                              name + " (" + scene_name + ")", label, length, colours);
      if (note.empty()) written.push_back(name + ".png");
      else notes.push_back(note);
    };
    for (const std::string &field : scene.output.fields) {
      if (field == "pressure")
        draw(field, read_field(contact, ASP_FIELD_PRESSURE),
             s.pressure_unit.empty() ? "pressure (in the units of E*)"
                                     : "pressure [" + s.pressure_unit + "]",
             Colours::signed_values);
      else if (field == "gap")
        draw(field, read_field(contact, ASP_FIELD_GAP), s.unit.empty() ? "gap" : "gap [" + s.unit + "]");
      else if (field == "contact")
        draw(field, contact_map(contact), "in contact (1) or not (0)");
      else if (field == "displacement")
        draw(field, read_field(contact, ASP_FIELD_DISPLACEMENT), "displacement");
      else
        draw(field, read_field(contact, ASP_FIELD_TOPOGRAPHY), "height");
    }
    if (scene.output.history && !report.history.empty()) {
      LinePlot plot;
      plot.title = "convergence of " + report.algorithm + " (" + scene_name + ")";
      plot.x_label = "iteration";
      plot.y_label = error_label;
      plot.tolerance = report.tolerance;
      plot.log_y = true;
      plot.series.push_back({report.algorithm, report.history[0], report.history[4]});
      const std::string note = session.plotter.lines(dir + "/convergence.png", plot);
      if (note.empty()) written.push_back("convergence.png");
      else notes.push_back(note);
    }
  }
  std::string files;
  for (const std::string &w : written) files += (files.empty() ? "" : ", ") + w;
  std::printf("outputs           %s/: %s\n", dir.c_str(), files.c_str());
  for (const std::string &note : notes) std::fprintf(stderr, "asperity: note: %s\n", note.c_str());
  return report.converged() ? exit_converged : exit_not_converged;
}

}  // namespace cli
