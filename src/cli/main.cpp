// SPDX-License-Identifier: GPL-2.0-or-later
// The asperity command: scenes from TOML files (or the built-in scene) solved, compared,
// swept and described, through the library's public C interface only, like any other program
// linked to asperity. Each subcommand lives in its own file; this one dispatches and is the
// one place where errors become messages and exit statuses.
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "library.hpp"

namespace cli {
namespace {

const char *const usage =
    "usage: asperity [run] [SCENE] [OPTION]...   solve a scene (the built-in one without\n"
    "                                            SCENE) and write its results\n"
    "       asperity compare [SCENE] [OPTION]...  several solvers on one scene: error\n"
    "                                            against time and iteration for each\n"
    "       asperity sweep [SCENE] [OPTION]...    loading and unloading steps, warm-started\n"
    "       asperity info TOPOGRAPHY [OPTION]...  size, units, statistics and power\n"
    "                                            spectrum of a height file or a scene\n"
    "       asperity --print-scene               the built-in scene, as a scene file to\n"
    "                                            start from\n"
    "       asperity --list-algorithms           the solvers of this build\n"
    "       asperity --describe NAME             what a solver does and its options\n"
    "       asperity --version\n"
    "\n"
    "SCENE is a TOML file (docs/command.md lists its keys; examples/scenes/ has the\n"
    "thesis's scenes). 'asperity COMMAND --help' shows a command's options.\n"
    "When standard error is a terminal, a progress line (iteration, error, seconds) is\n"
    "shown there during a solve. Ctrl-C stops the solve at its next iteration and\n"
    "reports it as cancelled (a sweep or comparison stops there); a second Ctrl-C quits.\n"
    "\n";

std::string describe(const std::string &algorithm) {
  Solver solver = make_solver(algorithm, "--describe " + algorithm, {});
  int64_t length = 0;
  check(asp_solver_describe(solver.get(), nullptr, 0, &length), "describing the algorithm");
  std::vector<char> text(static_cast<size_t>(length) + 1);
  check(asp_solver_describe(solver.get(), text.data(), length + 1, nullptr),
        "describing the algorithm");
  return text.data();
}

int dispatch(const std::vector<std::string> &arguments) {
  if (!arguments.empty()) {
    const std::string &first = arguments[0];
    const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
    if (first == "run") return run_command(rest);
    if (first == "compare") return compare_command(rest);
    if (first == "sweep") return sweep_command(rest);
    if (first == "info") return info_command(rest);
    if (first == "--help" || first == "-h" || first == "help") {
      std::printf("%s%s", usage, exit_status_help);
      return exit_converged;
    }
    if (first == "--version") {
      if (arguments.size() > 1) throw usage_error("--version takes no other argument");
      std::printf("asperity %s\n", asp_version_string());
      return exit_converged;
    }
    if (first == "--list-algorithms") {
      if (arguments.size() > 1) throw usage_error("--list-algorithms takes no other argument");
      std::printf("%s", algorithm_names().c_str());
      return exit_converged;
    }
    if (first == "--print-scene") {
      if (arguments.size() > 1) throw usage_error("--print-scene takes no other argument");
      std::printf("%s", default_scene_text);
      return exit_converged;
    }
    if (first == "--describe" || first.rfind("--describe=", 0) == 0) {
      std::string name = first.size() > 10 ? first.substr(11) : "";
      if (name.empty() && arguments.size() > 1) name = arguments[1];
      if (name.empty()) throw usage_error("--describe: needs an algorithm's name");
      std::printf("%s", describe(name).c_str());
      return exit_converged;
    }
    // asperity SCENE is asperity run SCENE; another word is a mistyped command.
    if ((first.empty() || first[0] != '-') && !std::ifstream(first))
      throw usage_error(first + ": not a command (run, compare, sweep, info), an option or a "
                        "scene file\nRun 'asperity --help' for the commands.");
  }
  // No command: run, on the built-in scene unless a scene comes first.
  return run_command(arguments);
}

}  // namespace
}  // namespace cli

int main(int argc, char **argv) {
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  try {
    return cli::dispatch(arguments);
  } catch (const cli::CommandError &e) {
    std::fflush(stdout);
    std::fprintf(stderr, "asperity: %s\n", e.what());
    return e.status();
  } catch (const std::bad_alloc &) {
    std::fflush(stdout);
    std::fprintf(stderr, "asperity: out of memory\n");
    return cli::exit_failure;
  } catch (const std::exception &e) {
    std::fflush(stdout);
    std::fprintf(stderr, "asperity: %s\n", e.what());
    return cli::exit_failure;
  }
}
