// SPDX-License-Identifier: GPL-2.0-or-later
#include "session.hpp"

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

Session open_session(const std::string &scene_path, const std::vector<Override> &overrides,
                     const ComputeOptions &compute, bool with_solver) {
  Session s;
  s.scene = read_scene(scene_path, overrides);
  s.compute = compute;
  read_wisdom(compute);
  s.contact = make_contact(s.scene, compute);
  if (with_solver) {
    s.solver = make_solver(s.scene.solver.algorithm, s.scene.solver.where, s.scene.solver.options);
    const std::string refused = refusal(s.solver.get(), s.contact, s.scene.control.control);
    if (!refused.empty()) throw usage_error(s.scene.solver.where + ": " + refused);
  }
  if (with_solver) make_directory(s);
  return s;
}

void make_directory(Session &session) {
  session.directory = prepare_directory(session.scene.output.directory,
                                        session.scene.source + ": output.directory");
}

}  // namespace cli
