// SPDX-License-Identifier: GPL-2.0-or-later
// asperity compare [SCENE]: several solvers on one scene, each from rest to the same
// tolerance, with error against wall time and against iteration for each, so that a user can
// see which solver is fastest on their own scene.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "outputs.hpp"
#include "report.hpp"
#include "solve.hpp"
#include "wisdom.hpp"

namespace cli {
namespace {

const char *const compare_help =
    "usage: asperity compare [SCENE] [OPTION]...\n"
    "\n"
    "Solves the scene (without SCENE, the built-in scene) with several solvers, each\n"
    "from rest to the same tolerance (solver.tolerance), and shows for each how the\n"
    "solve ended, its iterations, time, FFTs, results, and how far its pressure field\n"
    "lies from that of the first solver that converged. By default every algorithm that\n"
    "serves the scene (its substrate, interaction and control) runs; the others are\n"
    "listed as skipped, with the reason. An algorithm with a choice of unknown (its\n"
    "option variable: pressure or gap) runs once for each that serves the scene, named\n"
    "NAME:VARIABLE (lbfgsb:gap), unless the scene sets its variable. The error of each\n"
    "solver is its own measure of the force balance (docs/algorithms.md): all are\n"
    "pressures relative to the same reference pressure, so their tolerances mean the\n"
    "same. Each solver runs one untimed iteration first, so that no time includes the\n"
    "FFT planning that the first solve on a grid does, then solves from rest as many\n"
    "times as --repeats says. Its time is the wall-clock time of the fastest of these\n"
    "solves, shown with the processor time of that solve (summed over its threads, so\n"
    "above its time when they worked in parallel) and the spread of the times (slowest\n"
    "less fastest). The fastest solver is named unless the two fastest differ by less\n"
    "than the larger of their spreads: that is noise of a busy machine, and no winner\n"
    "is named. Writes to the output directory:\n"
    "  compare.csv           one row per iteration of each solver's fastest solve:\n"
    "                        algorithm, iteration, evaluations, transforms, seconds,\n"
    "                        error, objective, contact_fraction\n"
    "  compare_summary.csv   one row per solver, with its repeats, cpu_seconds and\n"
    "                        seconds_spread\n"
    "  error_vs_time.png     error against wall-clock time, one line per solver\n"
    "  error_vs_iteration.png  error against iteration (when gnuplot is installed)\n"
    "\n"
    "Solvers:\n"
    "  --solvers A,B,...  these algorithms, in this order (compare.solvers): NAME for\n"
    "                     each of its variants that serves the scene (one must), or\n"
    "                     NAME:VARIABLE for one (lbfgsb:gap, which must serve it)\n"
    "  --repeats K        solves of each solver, K >= 1 (default: 3 when its first\n"
    "                     solve takes under 10 s, else 1)\n"
    "Options of one algorithm come from [compare.options.NAME] tables of the scene;\n"
    "the scene's [solver.options] apply to solver.algorithm; tolerance, max_iterations\n"
    "and stall_window of [solver] to every solver.\n"
    "\n";

std::vector<std::string> split_names(const std::string &text, char separator) {
  std::vector<std::string> names;
  std::istringstream in(text);
  std::string name;
  while (std::getline(in, name, separator))
    if (!name.empty()) names.push_back(name);
  return names;
}

struct Entry {
  std::string algorithm;
  Solver solver;
};

// The largest difference between two pressure fields relative to the largest |pressure| of
// the reference.
double relative_difference(const std::vector<double> &p, const std::vector<double> &reference) {
  double difference = 0.0, scale = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    difference = std::max(difference, std::fabs(p[i] - reference[i]));
    scale = std::max(scale, std::fabs(reference[i]));
  }
  return scale > 0.0 ? difference / scale : difference;
}

// One untimed iteration of the solver, so that the FFT plans and the tables made on a first
// solve (stiffness, compliance) exist before its timed solve: otherwise the first solver's
// time would include what the others then reuse.
// A value the solve refuses is refused here, naming `where`.
void warm_up(asp_solver *solver, Contact &contact, int control, double value,
             const std::string &where) {
  double max_iterations = 0.0;
  check(asp_solver_get_option(solver, "max_iterations", &max_iterations), "reading an option");
  check(asp_solver_set_option(solver, "max_iterations", 1.0), "setting an option");
  check(asp_system_reset(contact.system.get()), "resetting the system");
  // The refusal's message is read before the next call empties it.
  check_given(asp_solver_solve(solver, contact.system.get(), control, value), where);
  check(asp_solver_set_option(solver, "max_iterations", max_iterations), "setting an option");
}

// What a solver's timed solves gave: the report and pressure field of the fastest, how many
// solves there were and the spread of their wall-clock times (slowest less fastest).
struct Timing {
  SolveReport report;
  std::vector<double> pressure;
  int repeats = 0;
  double spread = 0.0;
};

// The solver's timed solves, each from rest: `repeats` of them, or when that is 0, three
// when the first took under 10 s and one otherwise. A cancelled solve ends them; it is the
// result only when it was the first.
Timing timed_solves(Entry &e, Contact &contact, int control, double value, int repeats,
                    ProgressLine &progress, const std::string &where) {
  Timing t;
  double slowest = 0.0;
  for (int k = 0; k == 0 || k < repeats; ++k) {
    check(asp_system_reset(contact.system.get()), "resetting the system");
    SolveReport r = solve(e.solver.get(), e.algorithm, contact, control, value, progress, true,
                          where);
    if (repeats == 0) repeats = r.seconds < 10.0 ? 3 : 1;
    const bool cancelled = r.termination == ASP_TERMINATION_CANCELLED;
    if (cancelled && k > 0) break;
    ++t.repeats;
    slowest = std::max(slowest, r.seconds);
    if (k == 0 || r.seconds < t.report.seconds) {
      t.pressure = read_field(contact, ASP_FIELD_PRESSURE);
      t.report = std::move(r);
    }
    if (cancelled) break;
  }
  t.spread = slowest - t.report.seconds;
  return t;
}

}  // namespace

int compare_command(const std::vector<std::string> &arguments) {
  Arguments args(arguments, "asperity compare");
  SceneArguments a;
  int repeats = 0;  // 0: by the first solve's time
  const bool proceed = read_scene_arguments(args, compare_help, a, [&](Arguments &args) {
    if (args.is("--repeats")) {
      repeats = args.count();
      return true;
    }
    if (!args.is("--solvers")) return false;
    const std::string v = args.value();
    std::string array = "[";
    for (const std::string &name : split_names(v, ','))
      array += (array.size() > 1 ? ", \"" : "\"") + name + "\"";
    a.overrides.push_back({"compare.solvers=" + array + "]", "--solvers " + v});
    return true;
  });
  if (!proceed) return exit_converged;
  const std::vector<Override> &overrides = a.overrides;
  const std::string &scene_path = a.scene_path;

  Session session = open_session(scene_path, overrides, a.compute, false);
  const Scene &scene = session.scene;
  Contact &contact = session.contact;
  const int control = scene.control.control;
  if (scene.control.has_sweep)
    throw usage_error(scene.source + ": control: compare solves one value; this scene sweeps");

  // The solvers: made, configured and checked against the scene before any solve. An
  // algorithm with a choice of variable (pk's pressure, bugnicourt's and lbfgsb's pressure or
  // gap) runs once for each one that serves the scene, named "lbfgsb:gap", unless the scene
  // fixes its variable (in its options, or by naming "lbfgsb:gap" in compare.solvers).
  const bool chosen = !scene.compare.solvers.empty();
  const std::vector<std::string> names =
      chosen ? scene.compare.solvers : split_names(algorithm_names(), '\n');
  std::vector<OptionSetting> common;
  for (const OptionSetting &o : scene.solver.options)
    if (o.name == "tolerance" || o.name == "max_iterations" || o.name == "stall_window")
      common.push_back(o);
  std::vector<Entry> entries;
  std::vector<std::string> skipped;
  std::set<std::string> algorithms, labels;
  for (const std::string &name : names) {
    const size_t colon = name.find(':');
    const std::string algorithm = name.substr(0, colon);
    const std::string named_variable = colon == std::string::npos ? "" : name.substr(colon + 1);
    const std::string where = scene.source + ": compare.solvers: " + name;
    if (algorithm.empty() || (colon != std::string::npos && named_variable.empty()))
      throw usage_error(where + ": expected NAME or NAME:VARIABLE, such as lbfgsb:gap");
    algorithms.insert(algorithm);
    std::vector<OptionSetting> settings =
        algorithm == scene.solver.algorithm ? scene.solver.options : common;
    const auto own = scene.compare.options.find(algorithm);
    if (own != scene.compare.options.end())
      settings.insert(settings.end(), own->second.begin(), own->second.end());
    // The variants: the one named or set, else every value of the algorithm's variable.
    std::vector<std::string> variants = {named_variable};
    if (named_variable.empty()) {
      for (const OptionSetting &o : settings)
        if (o.name == "variable" && !o.is_number) variants = {o.text};
      if (variants.front().empty()) {
        const std::vector<std::string> all = variables(make_solver(algorithm, where, {}).get());
        if (!all.empty()) variants = all;
      }
    }
    std::vector<std::string> refusals;
    size_t served = 0;
    for (const std::string &variable : variants) {
      const std::string label = variant_name(algorithm, variable);
      if (!labels.insert(label).second)
        throw usage_error(where + ": " + label + " is compared twice");
      // A variable set in the settings is applied after the variant's own, and is the same.
      Solver solver = make_variant(algorithm, variable, where, settings);
      const std::string refused = refusal(solver.get(), contact, control);
      if (refused.empty()) {
        entries.push_back({label, std::move(solver)});
        ++served;
      } else {
        refusals.push_back(label + ": " + refused);
        if (chosen && variants.size() == 1) refusals.back() = refused;  // named already
      }
    }
    // A solver the scene names must serve it, in one of its variants at least.
    if (chosen && served == 0) {
      std::string text;
      for (const std::string &r : refusals) text += (text.empty() ? "" : "; ") + r;
      throw usage_error(where + ": " + text);
    }
    skipped.insert(skipped.end(), refusals.begin(), refusals.end());
  }
  for (const auto &[name, options] : scene.compare.options)
    if (!algorithms.count(name))
      throw usage_error(scene.source + ": compare.options." + name +
                        ": options for an algorithm that is not compared");
  if (entries.empty())
    throw usage_error(scene.source + ": no algorithm serves this scene:\n  " +
                      [&] {
                        std::string text;
                        for (const std::string &s : skipped) text += s + "\n  ";
                        return text;
                      }());

  make_directory(session);
  print_scene(stdout, scene, contact);
  std::printf("control           %s %g (%s)\n", control_name(control), scene.control.value,
              control_unit(control, contact.surface).c_str());
  for (const std::string &s : skipped) std::printf("skipped           %s\n", s.c_str());
  std::printf("\n%-20s %-16s %10s %10s %10s %10s %7s %10s %11s %14s %14s %9s %10s\n",
              "algorithm", "termination", "iterations", "time [s]", "cpu [s]", "spread [s]",
              "repeats", "error", "transforms", "mean pressure", "penetration", "contact",
              "vs first");
  std::fflush(stdout);

  InterruptGuard interrupts;
  ProgressLine progress(stderr);
  std::vector<Timing> timings;
  std::vector<double> reference;
  std::string reference_name;
  for (Entry &e : entries) {
    if (InterruptGuard::interrupted()) break;
    const std::string where = scene.control.where + " (" + e.algorithm + ")";
    warm_up(e.solver.get(), contact, control, scene.control.value, where);
    progress.set_label(e.algorithm);
    Timing t = timed_solves(e, contact, control, scene.control.value, repeats, progress, where);
    const SolveReport &r = t.report;
    std::string versus = "-";
    if (!reference.empty()) {
      char text[32];
      std::snprintf(text, sizeof text, "%.2e", relative_difference(t.pressure, reference));
      versus = text;
    } else if (r.converged()) {
      reference = std::move(t.pressure);
      reference_name = e.algorithm;
      versus = "reference";
    }
    t.pressure = std::vector<double>();  // not needed any more
    std::printf("%-20s %-16s %10lld %10.3f %10.3f %10.3f %7d %10.2e %11lld %14.6g %14.6g %9.5f "
                "%10s\n",
                e.algorithm.c_str(), termination_name(r.termination),
                static_cast<long long>(r.iterations), r.seconds, r.cpu_seconds, t.spread,
                t.repeats, r.error, static_cast<long long>(r.transforms), r.mean_pressure,
                r.penetration, r.contact_fraction, versus.c_str());
    std::fflush(stdout);
    timings.push_back(std::move(t));
  }

  // The files.
  const Surface &s = contact.surface;
  std::vector<std::string> header = {"algorithm"};
  for (const HistoryColumn &c : history_columns)
    header.push_back(column(c.name, std::string(c.name) == "seconds" ? "s" : ""));
  CsvTable histories(header);
  CsvTable summary({"algorithm", "termination", "iterations", "evaluations", "transforms",
                    column("seconds", "s"), "error", "tolerance", "contact_fraction",
                    column("mean_pressure", pressure_unit_of(s)), column("penetration", s.unit),
                    column("mean_gap", s.unit), "repeats", column("cpu_seconds", "s"),
                    column("seconds_spread", "s")});
  LinePlot by_time, by_iteration;
  const std::string scene_name = file_name(scene.source);
  by_time.title = "error against time (" + scene_name + ")";
  by_time.x_label = "wall-clock time [s]";
  by_iteration.title = "error against iteration (" + scene_name + ")";
  by_iteration.x_label = "iteration";
  by_time.y_label = by_iteration.y_label = error_label;
  // One tolerance line when every solver had the same (compare.options may differ).
  for (const Timing &t : timings) {
    const double tolerance = t.report.tolerance;
    if (&t == &timings.front()) by_time.tolerance = tolerance;
    else if (tolerance != by_time.tolerance) by_time.tolerance = 0.0;
  }
  by_iteration.tolerance = by_time.tolerance;
  by_time.log_y = by_iteration.log_y = true;
  std::vector<const Timing *> converged;  // fastest first
  for (const Timing &t : timings) {
    const SolveReport &r = t.report;
    for (size_t i = 0; i < r.history[0].size(); ++i) {
      std::vector<std::string> row = {r.algorithm};
      for (size_t c = 0; c < r.history.size(); ++c)
        row.push_back(c <= 2 ? cell(static_cast<int64_t>(r.history[c][i])) : cell(r.history[c][i]));
      histories.add_row(std::move(row));
    }
    summary.add_row({r.algorithm, termination_name(r.termination), cell(r.iterations),
                     cell(r.evaluations), cell(r.transforms), cell(r.seconds), cell(r.error),
                     cell(r.tolerance), cell(r.contact_fraction), cell(r.mean_pressure),
                     cell(r.penetration), cell(r.mean_gap), cell(static_cast<int64_t>(t.repeats)),
                     cell(r.cpu_seconds), cell(t.spread)});
    if (!r.history[4].empty())
      by_time.y_max = by_iteration.y_max = std::max(by_time.y_max, 100.0 * r.history[4][0]);
    by_time.series.push_back({r.algorithm, r.history[3], r.history[4]});
    by_iteration.series.push_back({r.algorithm, r.history[0], r.history[4]});
    if (r.converged()) converged.push_back(&t);
  }
  std::stable_sort(converged.begin(), converged.end(), [](const Timing *a, const Timing *b) {
    return a->report.seconds < b->report.seconds;
  });
  const std::string &dir = session.directory;
  histories.write(dir + "/compare.csv");
  summary.write(dir + "/compare_summary.csv");
  std::string files = "compare.csv, compare_summary.csv";
  if (scene.output.plots) {
    for (const auto &[plot, name] : {std::pair<const LinePlot *, const char *>{&by_time, "error_vs_time"},
                                     {&by_iteration, "error_vs_iteration"}}) {
      const std::string note = session.plotter.lines(dir + "/" + name + ".png", *plot);
      if (note.empty()) files += std::string(", ") + name + ".png";
      else std::fprintf(stderr, "asperity: note: %s\n", note.c_str());
    }
  }
  std::printf("\n");
  if (converged.size() >= 2 &&
      converged[1]->report.seconds - converged[0]->report.seconds <
          std::max(converged[0]->spread, converged[1]->spread)) {
    const Timing &a = *converged[0], &b = *converged[1];
    std::printf("fastest           no winner: %s (%.3f s) and %s (%.3f s) differ by less than "
                "the spread of their repeats (%.3f s)\n",
                a.report.algorithm.c_str(), a.report.seconds, b.report.algorithm.c_str(),
                b.report.seconds, std::max(a.spread, b.spread));
  } else if (!converged.empty()) {
    const Timing &a = *converged[0];
    std::printf("fastest           %s: converged in %.3f s", a.report.algorithm.c_str(),
                a.report.seconds);
    if (a.repeats > 1) std::printf(" (the fastest of %d solves)", a.repeats);
    std::printf("\n");
  }
  if (!reference_name.empty())
    std::printf("vs first          largest pressure difference from %s's, relative to its "
                "largest pressure\n", reference_name.c_str());
  std::printf("outputs           %s/: %s\n", dir.c_str(), files.c_str());
  write_wisdom(session.compute);
  bool all = timings.size() == entries.size();
  for (const Timing &t : timings) all = all && t.report.converged();
  return all ? exit_converged : exit_not_converged;
}

}  // namespace cli
