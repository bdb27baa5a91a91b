// SPDX-License-Identifier: GPL-2.0-or-later
#include "session.hpp"

#include <sstream>

#include "outputs.hpp"
#include "wisdom.hpp"

namespace cli {

Scene read_scene(const std::string &scene_path, const std::vector<Override> &overrides) {
  return scene_path.empty() ? read_scene_text(default_scene_text, "built-in scene", overrides)
                            : read_scene_file(scene_path, overrides);
}

std::string refusal(asp_solver *solver, const Contact &contact, int control) {
  const int status = asp_solver_supports(solver, contact.system.get(), control);
  if (status == ASP_OK) return "";
  if (status != ASP_ERR_UNSUPPORTED) check(status, "asking what the solver serves");
  return refusal_message();
}

Solver make_variant(const std::string &algorithm, const std::string &variable,
                    const std::string &where, std::vector<OptionSetting> settings) {
  if (!variable.empty())
    settings.insert(settings.begin(), OptionSetting{"variable", false, 0.0, variable, where});
  return make_solver(algorithm, where, settings);
}

std::string variant_name(const std::string &algorithm, const std::string &variable) {
  return variable.empty() ? algorithm : algorithm + ":" + variable;
}

std::vector<std::string> serving_solvers(const Contact &contact, int control) {
  std::vector<std::string> serving;
  std::istringstream names(algorithm_names());
  for (std::string name; std::getline(names, name);) {
    Solver bare = make_solver(name, name, {});
    const std::vector<std::string> vs = variables(bare.get());
    if (vs.empty() && refusal(bare.get(), contact, control).empty()) serving.push_back(name);
    for (const std::string &v : vs) {
      Solver solver = make_variant(name, v, name, {});
      if (refusal(solver.get(), contact, control).empty())
        serving.push_back(variant_name(name, v));
    }
  }
  return serving;
}

Solver scene_solver(const Scene &scene, const Contact &contact) {
  const SolverSpec &spec = scene.solver;
  const int control = scene.control.control;
  Solver bare = make_solver(spec.algorithm, spec.where, {});
  std::string refused = refusal(bare.get(), contact, control);
  for (const std::string &v : variables(bare.get()))
    if (!refused.empty() &&
        refusal(make_variant(spec.algorithm, v, spec.where, {}).get(), contact, control).empty())
      refused.clear();
  if (refused.empty()) {
    Solver solver = make_solver(spec.algorithm, spec.where, spec.options);
    refused = refusal(solver.get(), contact, control);
    if (refused.empty()) return solver;
  }
  const std::vector<std::string> serving = serving_solvers(contact, control);
  std::string list;
  for (const std::string &name : serving) list += (list.empty() ? "" : ", ") + name;
  throw usage_error(spec.where + ": " + refused +
                    (serving.empty() ? "; no solver serves this scene"
                                     : "; the solvers that serve this scene: " + list));
}

Session open_session(const std::string &scene_path, const std::vector<Override> &overrides,
                     const ComputeOptions &compute, bool with_solver) {
  Session s;
  s.scene = read_scene(scene_path, overrides);
  s.compute = compute;
  read_wisdom(compute);
  s.contact = make_contact(s.scene, compute);
  if (with_solver) {
    s.solver = scene_solver(s.scene, s.contact);
    make_directory(s);
  }
  return s;
}

void make_directory(Session &session) {
  session.directory = prepare_directory(session.scene.output.directory,
                                        session.scene.source + ": output.directory");
}

}  // namespace cli
