// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer driver of the scene reader of the asperity command (src/cli/scene.cpp with
// scene_reader.cpp, on toml++): the input is the text of a scene file, read with
// cli::read_scene_text as `asperity run` reads one. A scene that is read is then built as the
// command builds it before solving (cli::make_contact: the grid, the generated surface, its
// detrending, the system and its interaction; cli::make_solver: the algorithm and its options),
// when its grid is small (at most 32 x 32 pixels, or 1024 in 1D: the command plans its FFTs
// with FFTW's measuring planner, which takes a while for every new size); scenes of measured surfaces are only read, because their files are not there
// (the topography readers have their own drivers).
//
// Scene files are written by hand, so any text must end in a refusal that names the problem:
// the contract (src/cli/scene.hpp, exit_status.hpp) is that reading and building throw
// cli::CommandError with the usage status (exit 2) and a message, and nothing else. Any other
// exception, a CommandError of another status (the library failed on a scene that passed every
// check), a crash, a leak or undefined behaviour is a finding.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "contact.hpp"
#include "exit_status.hpp"
#include "scene.hpp"

namespace {

[[noreturn]] void broken(const char *what, const char *detail) {
  std::fprintf(stderr, "scene reader contract broken: %s: %s\n", what, detail);
  __builtin_trap();
}

bool small_enough(const cli::Scene &scene) {
  if (scene.topography.kind == cli::TopographyKind::file) return false;
  const cli::GridSpec &g = scene.grid;
  if (g.one_dimensional) return g.nx >= 1 && g.nx <= 1024;
  return g.nx >= 1 && g.nx <= 32 && g.ny >= 1 && g.ny <= 32;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  const std::string text(reinterpret_cast<const char *>(data), size);
  try {
    const cli::Scene scene = cli::read_scene_text(text, "fuzz.toml", {});
    if (!small_enough(scene)) return 0;
    cli::Contact contact = cli::make_contact(scene);
    cli::Solver solver = cli::make_solver(scene.solver.algorithm, scene.solver.where,
                                          scene.solver.options);
    for (const auto &[algorithm, options] : scene.compare.options)
      (void)cli::make_solver(algorithm, "fuzz.toml: [compare]", options);
  } catch (const cli::CommandError &e) {
    if (e.status() != cli::exit_usage) broken("a failure, not a refusal", e.what());
    if (std::string(e.what()).empty()) broken("a refusal without a message", "");
  } catch (const std::exception &e) {
    broken("an exception other than CommandError", e.what());
  } catch (...) {
    broken("an exception other than CommandError", "(not a std::exception)");
  }
  return 0;
}
