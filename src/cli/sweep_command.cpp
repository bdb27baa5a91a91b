// SPDX-License-Identifier: GPL-2.0-or-later
// asperity sweep [SCENE]: loading then unloading steps of the control, each warm-started from
// the step before, so that jumps into and out of contact and the hysteresis between loading
// and unloading show (thesis section 4.3).
#include <algorithm>
#include <cmath>
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
    "\n"
    "Pull-off: under mean-pressure control with adhesion the unloading goes on past the\n"
    "first value into tension, by the smallest loading step, until a load separates the\n"
    "surfaces (termination 'separated': no stable state under that load); the bracket\n"
    "between the most tensile stable load and that one is then halved 4 times (phase\n"
    "'pull-off', each trial started again from the stable branch), and the pull-off\n"
    "force is reported as the most tensile load with a stable state.\n"
    "\n"
    "Jumps: a solve under mean-pressure control returns only stable states, so that where\n"
    "the branch the previous step was on ends (snap-in, partial detachment) it lands on\n"
    "another. A converged step that follows a converged one is said to have jumped when\n"
    "both have a stiffness (> 0) and the secant (change of mean pressure over change of\n"
    "penetration) is below half the smaller of the two: a line 'note: the contact jumped\n"
    "...' follows the step's, and sweep.csv's column 'jump' says 'yes' on that step.\n"
    "\n";

// d(mean pressure)/d(penetration) of a step's state (asp_solver_normal_stiffness), or NaN
// where it has none: the solve did not converge, or the state is not a stable equilibrium.
double stiffness_of(asp_solver *solver, asp_system *system, bool converged) {
  double stiffness = 0.0;
  if (!converged || asp_solver_normal_stiffness(solver, system, &stiffness) != ASP_OK)
    return std::nan("");
  return stiffness;
}

// A converged step of a load-controlled sweep, as the jump test below compares it with the
// next one.
struct BranchPoint {
  double target = 0.0;  // the load asked for
  double mean_pressure = 0.0;
  double penetration = 0.0;
  double stiffness = 0.0;  // the tangent d(mean pressure)/d(penetration); NaN where none
};

// The secant below which two successive load-controlled steps are taken to lie on different
// branches, as a fraction of the smaller of their tangents. On one continuous stable branch the
// secant (p1 - p0)/(d1 - d0) is the tangent at some point of the step (mean value theorem),
// and so lies between the two end tangents where the tangent varies monotonically along the
// step. On a grid it does not quite: the contact grows by whole pixels and the tangents of
// one branch scatter about a smooth curve, so that the secant of a step of the adhesive
// sphere's sweep (tests/cli/scenes/adhesive_sphere.toml) falls to 0.86 of the smaller tangent,
// and one of the wavy surface's partial contact (wavy_snap_in.toml) to 0.90. Half the smaller
// tangent leaves room for that, while a jump, which moves the penetration at almost constant
// load, puts the secant far below both tangents (0.29 of the smaller at the wavy surface's
// snap-in). The price: a step whose penetration moves by less than 2 |dp| / min(k) is never
// called a jump, so a small jump, or one from a branch whose tangent has already fallen
// towards zero near its end, can be missed; finer steps near it make its secant smaller.
constexpr double jump_secant_fraction = 0.5;

// Whether the step from `before` to `after` jumped between stable branches, and its secant.
// Both tangents must exist and be positive (stable states); a penetration that moved against
// the load (a secant <= 0) is a jump too. Steps at one load, or with no move in penetration,
// are not compared: a repeated load leaves a converged state where it is, and the secant
// between two solves of it is round-off.
bool jumped(const BranchPoint &before, const BranchPoint &after, double *secant) {
  const double dp = after.mean_pressure - before.mean_pressure;
  const double dd = after.penetration - before.penetration;
  if (!(before.stiffness > 0.0) || !(after.stiffness > 0.0) || after.target == before.target ||
      dp == 0.0 || dd == 0.0)
    return false;
  *secant = dp / dd;
  return *secant < jump_secant_fraction * std::min(before.stiffness, after.stiffness);
}

}  // namespace

// The pull-off search of a load-controlled sweep with adhesion: the solve at each load either
// converges on a stable state or ends separated (no stable state under that load), so that
// the most tensile load with a stable state and the first load found to separate bracket the
// pull-off force.
struct PullOff {
  double stable = 0.0;     // the most tensile load (mean pressure) with a stable state
  double separated = 0.0;  // the least tensile load found to separate
  bool has_stable = false;
  bool has_separated = false;
};

// Halvings of the bracket after the unloading steps have found it: 1/16 of a step.
constexpr int pull_off_halvings = 4;
// Unloading steps into tension past the last scheduled value before giving up the search.
constexpr int pull_off_extra_steps = 200;

int run_sweep(Session &session) {
  const Scene &scene = session.scene;
  Contact &contact = session.contact;
  const Surface &s = contact.surface;
  const int control = scene.control.control;

  std::vector<double> values = scene.control.sweep.loading;
  const size_t loading = values.size();
  if (scene.control.sweep.unload)
    for (size_t k = loading - 1; k-- > 0;) values.push_back(values[k]);
  // Under load control with adhesion the unloading goes on into tension until the surfaces
  // separate, and the pull-off force is bracketed.
  const bool search_pull_off = control == ASP_CONTROL_MEAN_PRESSURE &&
                               scene.control.sweep.unload &&
                               observable(contact.system.get(), ASP_WORK_OF_ADHESION) > 0.0;
  // The stride of the steps into tension: the loading steps' (a tenth of the largest load
  // for a single value).
  double stride = 0.0;
  for (size_t k = 1; k < loading; ++k) {
    const double d = std::fabs(values[k] - values[k - 1]);
    if (d > 0.0 && (stride == 0.0 || d < stride)) stride = d;
  }
  if (stride == 0.0) stride = 0.1 * std::fabs(values[0]);

  print_scene(stdout, scene, contact);
  std::printf("sweep             %s from %g to %g in %zu loading steps%s, solver %s\n",
              control_name(control), values.front(), values[loading - 1], loading,
              search_pull_off ? " and back into tension until the surfaces separate"
              : scene.control.sweep.unload ? " and back" : "",
              scene.solver.algorithm.c_str());
  const std::string length = s.unit.empty() ? "" : " [" + s.unit + "]";
  std::printf("%5s %-9s %14s %14s %14s %14s %10s %6s  %s\n", "step", "phase",
              ("penetration" + length).c_str(), "mean pressure", ("mean gap" + length).c_str(),
              "contact", "iterations", "time", "termination");
  std::fflush(stdout);

  const std::string pressure = pressure_unit_of(s);
  const std::string control_column_unit =
      control == ASP_CONTROL_MEAN_PRESSURE ? pressure : s.unit;
  CsvTable table({"step", "phase", column("target_" + scene.control.quantity, control_column_unit),
                  column("mean_pressure", pressure), column("penetration", s.unit),
                  column("mean_gap", s.unit), "contact_fraction",
                  column("total_force", force_unit_of(s)), "iterations", column("seconds", "s"),
                  "error", "termination",
                  column("stiffness", pressure + "/" + (s.unit.empty() ? "length" : s.unit)),
                  "jump"});
  Series up{"loading", {}, {}}, down{"unloading", {}, {}};
  InterruptGuard interrupts;
  ProgressLine progress(stderr);
  bool all_converged = true, cancelled = false;
  size_t step = 0;
  PullOff pull_off;
  // The step before, where it converged under load control and is to be compared with the
  // next: a load-controlled solve returns only stable states, and where the branch it was on
  // ends it follows the jump to another, which the secant between the two steps shows.
  BranchPoint previous;
  bool has_previous = false;
  // One step of the sweep: solved, printed, tabled. A step of the pull-off search that
  // separates is what the search looks for, not a failure; the search's trials each start
  // again from the stable branch, and are not compared with the step before.
  const auto solve_step = [&](double value, const char *phase, Series *series) {
    progress.set_label("step " + std::to_string(step));
    const SolveReport r = solve(session.solver.get(), scene.solver.algorithm, contact, control,
                                value, progress, false,
                                scene.control.where + ": step " + std::to_string(step));
    const bool separated = r.termination == ASP_TERMINATION_SEPARATED;
    all_converged = all_converged && (r.converged() || (search_pull_off && separated));
    std::printf("%5zu %-9s %14.6g %14.6g %14.6g %14.6f %10lld %6.2f  %s\n", step, phase,
                r.penetration, r.mean_pressure, r.mean_gap, r.contact_fraction,
                static_cast<long long>(r.iterations), r.seconds, termination_name(r.termination));
    const double stiffness =
        stiffness_of(session.solver.get(), contact.system.get(), r.converged());
    const bool compared = control == ASP_CONTROL_MEAN_PRESSURE && r.converged() &&
                          std::string(phase) != "pull-off";
    const BranchPoint here{value, r.mean_pressure, r.penetration, stiffness};
    double secant = 0.0;
    const bool jump = compared && has_previous && jumped(previous, here, &secant);
    if (jump)
      std::printf("note: the contact jumped to another stable branch between steps %zu and %zu "
                  "(penetration %.6g -> %.6g at mean pressure %.6g -> %.6g; secant %.6g, "
                  "tangents %.6g, %.6g)\n",
                  step - 1, step, previous.penetration, here.penetration,
                  previous.mean_pressure, here.mean_pressure, secant, previous.stiffness,
                  here.stiffness);
    previous = here;
    has_previous = compared;
    std::fflush(stdout);
    table.add_row({cell(static_cast<int64_t>(step)), phase, cell(value), cell(r.mean_pressure),
                   cell(r.penetration), cell(r.mean_gap), cell(r.contact_fraction),
                   cell(r.total_force), cell(r.iterations), cell(r.seconds), cell(r.error),
                   termination_name(r.termination),
                   std::isnan(stiffness) ? std::string() : cell(stiffness), jump ? "yes" : ""});
    if (series != nullptr && !separated) {
      series->x.push_back(r.penetration);
      series->y.push_back(r.mean_pressure);
    }
    if (r.termination == ASP_TERMINATION_CANCELLED) {
      std::fprintf(stderr, "asperity: the sweep was cancelled at step %zu\n", step);
      cancelled = true;
    }
    ++step;
    return r;
  };
  // What the unloading learns of the pull-off.
  const auto learn = [&](double value, const SolveReport &r) {
    if (r.converged() && (!pull_off.has_stable || value < pull_off.stable)) {
      pull_off.stable = value;
      pull_off.has_stable = true;
    }
    if (r.termination == ASP_TERMINATION_SEPARATED &&
        (!pull_off.has_separated || value > pull_off.separated)) {
      pull_off.separated = value;
      pull_off.has_separated = true;
    }
  };

  double turn_penetration = 0.0;
  for (size_t k = 0; k < values.size() && !cancelled && !pull_off.has_separated; ++k) {
    const bool unloading = k >= loading;
    const SolveReport r =
        solve_step(values[k], unloading ? "unloading" : "loading", unloading ? &down : &up);
    if (k + 1 == loading) turn_penetration = r.penetration;
    // The turning step counts: with a single loading value it is the only stable one.
    if (unloading || k + 1 == loading) learn(values[k], r);
  }
  if (search_pull_off && !cancelled) {
    // On into tension, step by step, until a load separates the surfaces.
    double value = values.back();
    for (int extra = 0; extra < pull_off_extra_steps && !cancelled && !pull_off.has_separated &&
                        pull_off.has_stable && stride > 0.0;
         ++extra) {
      value -= stride;
      learn(value, solve_step(value, "unloading", &down));
    }
    // Then the bracket halved: each trial starts again from the stable branch (the state a
    // separating solve leaves is far from it), reached from the loading's turning point
    // under penetration control and then at the most tensile stable load.
    for (int halving = 0; halving < pull_off_halvings && !cancelled && pull_off.has_stable &&
                          pull_off.has_separated;
         ++halving) {
      check(asp_system_reset(contact.system.get()), "resetting the state");
      progress.set_label("back to the stable branch");
      const SolveReport back =
          solve(session.solver.get(), scene.solver.algorithm, contact, ASP_CONTROL_PENETRATION,
                turn_penetration, progress, false, scene.control.where + ": pull-off search");
      const SolveReport again =
          back.converged()
              ? solve(session.solver.get(), scene.solver.algorithm, contact, control,
                      pull_off.stable, progress, false, scene.control.where + ": pull-off search")
              : back;
      if (!again.converged()) {
        std::fprintf(stderr,
                     "asperity: note: the pull-off search could not return to the stable "
                     "branch (%s); the bracket is left as it is\n",
                     termination_name(again.termination));
        break;
      }
      const double middle = 0.5 * (pull_off.stable + pull_off.separated);
      const SolveReport r = solve_step(middle, "pull-off", nullptr);
      if (!r.converged() && r.termination != ASP_TERMINATION_SEPARATED) break;
      learn(middle, r);
    }
  }
  write_wisdom(session.compute);
  // The unloading line starts where loading turned.
  if (!down.x.empty() && !up.x.empty()) {
    down.x.insert(down.x.begin(), up.x.back());
    down.y.insert(down.y.begin(), up.y.back());
  }
  if (search_pull_off) {
    const double area = s.one_dimensional ? s.lx : s.lx * s.ly;
    if (pull_off.has_stable && pull_off.has_separated)
      std::printf("pull-off          force %.6g (mean pressure %.6g): the most tensile load "
                  "with a stable state; the surfaces separate at %.6g (mean pressure %.6g), "
                  "so that the pull-off force lies between the two\n",
                  pull_off.stable * area, pull_off.stable, pull_off.separated * area,
                  pull_off.separated);
    else
      std::printf("pull-off          not found: %s\n",
                  !pull_off.has_stable ? "no unloading step reached a stable state"
                                       : "no load tried separated the surfaces");
  }

  const std::string &dir = session.directory;
  table.write(dir + "/sweep.csv");
  std::string files = "sweep.csv";
  if (scene.output.plots) {
    LinePlot plot;
    plot.title = "force against penetration (" + file_name(scene.source) + ")";
    plot.x_label = "penetration" + length;
    plot.y_label = "mean pressure [" + pressure + "]";
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
