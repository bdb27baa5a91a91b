// SPDX-License-Identifier: GPL-2.0-or-later
// asperity sweep [SCENE]: loading then unloading steps of the control, each warm-started from
// the step before, so that jumps into and out of contact and the hysteresis between loading
// and unloading show (thesis section 4.3).
#include <cstdio>

#include "arguments.hpp"
#include "commands.hpp"
#include "outputs.hpp"
#include "report.hpp"
#include "solve.hpp"
#include "wisdom.hpp"

namespace cli {
namespace {

const char *const sweep_help =
    "usage: asperity sweep [SCENE] [OPTION]...\n"
    "\n"
    "Steps the scene's control (control.quantity) through a loading sweep and back,\n"
    "each step warm-started from the one before, and reports per step the control,\n"
    "mean pressure, penetration, mean gap, contact fraction, iterations and how the\n"
    "solve ended. The steps come from the scene's control.sweep table (from, to, steps\n"
    "or values; unload) or from the options below. Without SCENE, the built-in scene.\n"
    "Writes to the output directory:\n"
    "  sweep.csv         one row per step\n"
    "  sweep.png         mean pressure against penetration, loading and unloading\n"
    "                    (when gnuplot is installed)\n"
    "\n"
    "Sweep:\n"
    "  --quantity Q      mean_pressure, penetration or mean_gap (control.quantity)\n"
    "  --from A          first value (control.sweep.from)\n"
    "  --to B            last loading value (control.sweep.to)\n"
    "  --steps N         N equal steps from A to B (control.sweep.steps)\n"
    "  --no-unload       only the loading steps (control.sweep.unload = false)\n"
    "\n";

// d(mean pressure)/d(penetration) of a step's state (asp_solver_normal_stiffness), or an empty
// cell where it has none: the solve did not converge, or the state is not a stable
// equilibrium.
std::string stiffness_cell(asp_solver *solver, asp_system *system, bool converged) {
  double stiffness = 0.0;
  if (!converged || asp_solver_normal_stiffness(solver, system, &stiffness) != ASP_OK) return "";
  return cell(stiffness);
}

}  // namespace

int run_sweep(Session &session) {
  const Scene &scene = session.scene;
  Contact &contact = session.contact;
  const Surface &s = contact.surface;
  const int control = scene.control.control;

  std::vector<double> values = scene.control.sweep.loading;
  const size_t loading = values.size();
  if (scene.control.sweep.unload)
    for (size_t k = loading - 1; k-- > 0;) values.push_back(values[k]);

  print_scene(stdout, scene, contact);
  std::printf("sweep             %s from %g to %g in %zu loading steps%s, solver %s\n",
              control_name(control), values.front(), values[loading - 1], loading,
              scene.control.sweep.unload ? " and back" : "", scene.solver.algorithm.c_str());
  const std::string length = s.unit.empty() ? "" : " [" + s.unit + "]";
  std::printf("%5s %-9s %14s %14s %14s %14s %10s %6s  %s\n", "step", "phase",
              ("penetration" + length).c_str(), "mean pressure", ("mean gap" + length).c_str(),
              "contact", "iterations", "time", "termination");
  std::fflush(stdout);

  const std::string control_column_unit = control == ASP_CONTROL_MEAN_PRESSURE ? pressure_unit : s.unit;
  CsvTable table({"step", "phase", column("target_" + scene.control.quantity, control_column_unit),
                  column("mean_pressure", pressure_unit), column("penetration", s.unit),
                  column("mean_gap", s.unit), "contact_fraction",
                  column("total_force", pressure_unit), "iterations", column("seconds", "s"),
                  "error", "termination",
                  column("stiffness", s.unit.empty() ? std::string(pressure_unit) + "/length"
                                                     : std::string(pressure_unit) + "/" + s.unit)});
  Series up{"loading", {}, {}}, down{"unloading", {}, {}};
  InterruptGuard interrupts;
  ProgressLine progress(stderr);
  bool all_converged = true;
  for (size_t k = 0; k < values.size(); ++k) {
    const bool unloading = k >= loading;
    progress.set_label("step " + std::to_string(k) + "/" + std::to_string(values.size() - 1));
    const SolveReport r = solve(session.solver.get(), scene.solver.algorithm, contact, control,
                                values[k], progress, false,
                                scene.control.where + ": step " + std::to_string(k));
    all_converged = all_converged && r.converged();
    std::printf("%5zu %-9s %14.6g %14.6g %14.6g %14.6f %10lld %6.2f  %s\n", k,
                unloading ? "unloading" : "loading", r.penetration, r.mean_pressure, r.mean_gap,
                r.contact_fraction, static_cast<long long>(r.iterations), r.seconds,
                termination_name(r.termination));
    std::fflush(stdout);
    table.add_row({cell(static_cast<int64_t>(k)), unloading ? "unloading" : "loading",
                   cell(values[k]), cell(r.mean_pressure), cell(r.penetration),
                   cell(r.mean_gap), cell(r.contact_fraction), cell(r.total_force),
                   cell(r.iterations), cell(r.seconds), cell(r.error),
                   termination_name(r.termination),
                   stiffness_cell(session.solver.get(), contact.system.get(), r.converged())});
    Series &series = unloading ? down : up;
    series.x.push_back(r.penetration);
    series.y.push_back(r.mean_pressure);
    if (r.termination == ASP_TERMINATION_CANCELLED) {
      std::fprintf(stderr, "asperity: the sweep was cancelled at step %zu\n", k);
      break;
    }
  }
  write_wisdom(session.compute);
  // The unloading line starts where loading turned.
  if (!down.x.empty()) {
    down.x.insert(down.x.begin(), up.x.back());
    down.y.insert(down.y.begin(), up.y.back());
  }

  const std::string &dir = session.directory;
  table.write(dir + "/sweep.csv");
  std::string files = "sweep.csv";
  if (scene.output.plots) {
    LinePlot plot;
    plot.title = "force against penetration (" + scene.source + ")";
    plot.x_label = "penetration" + length;
    plot.y_label = "mean pressure [E* unit]";
    plot.points = true;
    plot.series.push_back(up);
    if (!down.x.empty()) plot.series.push_back(down);
    const std::string note = session.plotter.lines(dir + "/sweep.png", plot);
    if (note.empty()) files += ", sweep.png";
    else std::fprintf(stderr, "asperity: note: %s\n", note.c_str());
  }
  std::printf("outputs           %s/: %s\n", dir.c_str(), files.c_str());
  return all_converged ? exit_converged : exit_not_converged;
}

int sweep_command(const std::vector<std::string> &arguments) {
  Arguments args(arguments, "asperity sweep");
  SceneArguments a;
  bool sweep_given = false;
  const bool proceed = read_scene_arguments(args, sweep_help, a, [&](Arguments &args) {
    const struct {
      const char *option;
      const char *key;
    } sweep_options[] = {{"--quantity", "control.quantity"},
                         {"--from", "control.sweep.from"},
                         {"--to", "control.sweep.to"},
                         {"--steps", "control.sweep.steps"}};
    for (const auto &o : sweep_options) {
      if (!args.is(o.option)) continue;
      const std::string v = args.value();
      a.overrides.push_back({std::string(o.key) + "=" + v, std::string(o.option) + " " + v});
      sweep_given = sweep_given || std::string(o.option) != "--quantity";
      return true;
    }
    if (!args.is_flag("--no-unload")) return false;
    a.overrides.push_back({"control.sweep.unload=false", "--no-unload"});
    sweep_given = true;
    return true;
  });
  if (!proceed) return exit_converged;
  std::vector<Override> &overrides = a.overrides;
  const std::string &scene_path = a.scene_path;
  // Sweep options replace the scene's single value.
  if (sweep_given) overrides.insert(overrides.begin(), Override{"control.value", "", true});
  // Checked before the session makes anything (reading a scene builds nothing).
  const Scene scene = read_scene(scene_path, overrides);
  if (!scene.control.has_sweep)
    throw usage_error(scene.source +
                      ": control: a sweep needs control.sweep in the scene, or --from, --to and "
                      "--steps");
  Session session = open_session(scene_path, overrides, a.compute, true);
  return run_sweep(session);
}

}  // namespace cli
