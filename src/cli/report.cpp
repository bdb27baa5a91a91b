// SPDX-License-Identifier: GPL-2.0-or-later
#include "report.hpp"

#include "outputs.hpp"
#include "resolution.hpp"

namespace cli {
namespace {

std::string interaction_text(const InteractionSpec &i, const std::string &unit) {
  // A length with the scene's unit, if it has one.
  auto length = [&](double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%g%s%s", value, unit.empty() ? "" : " ", unit.c_str());
    return std::string(text);
  };
  char text[256];
  switch (i.kind) {
    case InteractionKind::hard_wall: return "hard wall, no adhesion";
    case InteractionKind::adhesive_hard_wall:
      std::snprintf(text, sizeof text, "hard wall with exponential adhesion: w = %g, range %s",
                    i.work_of_adhesion, length(i.range).c_str());
      return text;
    case InteractionKind::soft_wall:
      std::snprintf(text, sizeof text,
                    "soft wall: gamma_r = %g, rho_r = %s, gamma_a = %g, rho_a = %s", i.gamma_r,
                    length(i.rho_r).c_str(), i.gamma_a, length(i.rho_a).c_str());
      return text;
    case InteractionKind::lennard_jones:
      std::snprintf(text, sizeof text, "Lennard-Jones 9-3 wall: w = %g, z0 = %s",
                    i.work_of_adhesion, length(i.equilibrium_distance).c_str());
      return text;
  }
  return "";
}

}  // namespace

const char *control_name(int control) {
  switch (control) {
    case ASP_CONTROL_MEAN_PRESSURE: return "mean pressure";
    case ASP_CONTROL_PENETRATION: return "penetration";
    default: return "mean gap";
  }
}

std::string control_unit(int control, const Surface &surface) {
  if (control == ASP_CONTROL_MEAN_PRESSURE) return pressure_unit_text(surface);
  return surface.unit.empty() ? "scene length unit" : surface.unit;
}

void print_scene(std::FILE *out, const Scene &scene, const Contact &contact) {
  std::fprintf(out, "asperity %s: %s%s%s\n", asp_version_string(), scene.source.c_str(),
               scene.title.empty() ? "" : ": ", scene.title.c_str());
  std::fprintf(out, "surface           %s\n", contact.surface.description.c_str());
  if (scene.substrate.layer)
    std::fprintf(out,
                 "substrate         periodic elastic layer on a rigid base, E* = %g, "
                 "thickness %g, Poisson's ratio %g\n",
                 scene.substrate.contact_modulus, scene.substrate.thickness,
                 scene.substrate.poisson_ratio);
  else
    std::fprintf(out, "substrate         %s, E* = %g\n",
                 contact.periodic ? "periodic" : "free (non-periodic)",
                 scene.substrate.contact_modulus);
  std::fprintf(out, "interaction       %s\n",
               interaction_text(scene.interaction, contact.surface.unit).c_str());
  for (const std::string &note : contact.surface.notes)
    std::fprintf(out, "note              %s\n", note.c_str());
  print_resolution(out, contact);
}

void print_solve(std::FILE *out, const SolveReport &r, const Surface &s) {
  const std::string u = s.unit.empty() ? "" : " " + s.unit;
  std::fprintf(out, "termination       %s after %lld iterations (%.3f s)\n",
               termination_name(r.termination), static_cast<long long>(r.iterations), r.seconds);
  // What a solve stopped short of the tolerance leaves (asp_solver_solve in asperity.h).
  if (!r.converged() && r.termination != ASP_TERMINATION_BREAKDOWN)
    std::fprintf(out, "                  the state is the last iterate (with a hard wall, "
                      "its gap projected onto g >= 0)\n");
  std::fprintf(out, "error             %.3e (tolerance %.3g)\n", r.error, r.tolerance);
  std::fprintf(out, "contact fraction  %.6f\n", r.contact_fraction);
  std::fprintf(out, "mean pressure     %.6g (%s)\n", r.mean_pressure,
               pressure_unit_text(s).c_str());
  std::fprintf(out, "penetration       %.6g%s\n", r.penetration, u.c_str());
  std::fprintf(out, "mean gap          %.6g%s\n", r.mean_gap, u.c_str());
}

void write_summary(const std::string &path, const Scene &scene, const SolveReport &r,
                   const Surface &s) {
  CsvTable table({"quantity", "value", "unit"});
  table.add_row({"algorithm", r.algorithm, ""});
  table.add_row({"termination", termination_name(r.termination), ""});
  table.add_row({"iterations", cell(r.iterations), ""});
  table.add_row({"evaluations", cell(r.evaluations), ""});
  table.add_row({"transforms", cell(r.transforms), ""});
  table.add_row({"seconds", cell(r.seconds), "s"});
  table.add_row({"error", cell(r.error), ""});
  table.add_row({"tolerance", cell(r.tolerance), ""});
  table.add_row({"contact_fraction", cell(r.contact_fraction), ""});
  table.add_row({"compressive_fraction", cell(r.compressive_fraction), ""});
  table.add_row({"mean_pressure", cell(r.mean_pressure), pressure_unit_of(s)});
  table.add_row({"penetration", cell(r.penetration), s.unit});
  table.add_row({"mean_gap", cell(r.mean_gap), s.unit});
  table.add_row({"total_force", cell(r.total_force), force_unit_of(s)});
  table.add_row({"contact_modulus", cell(scene.substrate.contact_modulus), pressure_unit_of(s)});
  table.write(path);
}

void write_history(const std::string &path, const SolveReport &r) {
  std::vector<std::string> header;
  for (const HistoryColumn &c : history_columns)
    header.push_back(column(c.name, std::string(c.name) == "seconds" ? "s" : ""));
  CsvTable table(header);
  const size_t rows = r.history.empty() ? 0 : r.history[0].size();
  for (size_t i = 0; i < rows; ++i) {
    std::vector<std::string> cells;
    for (size_t c = 0; c < r.history.size(); ++c) {
      const double v = r.history[c][i];
      const bool count = c <= 2;  // iteration, evaluations, transforms
      cells.push_back(count ? cell(static_cast<int64_t>(v)) : cell(v));
    }
    table.add_row(std::move(cells));
  }
  table.write(path);
}

}  // namespace cli
