// SPDX-License-Identifier: GPL-2.0-or-later
// Reading a command's arguments: options with a value after '=' or as the next argument, and
// positional arguments. Refusals name the argument and end with a pointer to --help.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contact.hpp"
#include "scene.hpp"

namespace cli {

class Arguments {
 public:
  // command: "asperity run", for messages.
  Arguments(std::vector<std::string> arguments, std::string command);

  // Moves to the next argument; false when there is none.
  bool next();
  const std::string &current() const { return arguments_[index_]; }
  // The current argument is this option (--name, or --name=VALUE for options with a value).
  bool is(const char *name);
  bool is_flag(const char *name);  // an option without a value (refuses --name=VALUE)
  // The value of the option matched by is(): after '=' or the next argument.
  std::string value();
  // The value as a whole number >= 1 (refused otherwise).
  int count();
  bool positional() const;  // does not start with '-' (or is "-")
  [[noreturn]] void refuse(const std::string &problem) const;
  // Refuses the current argument as an unknown option, with the closest of the options that
  // `help` names (every "--name" in it) as a suggestion.
  [[noreturn]] void refuse_unknown(const std::string &help) const;

  // The scene overrides shared by run, compare and sweep: --set KEY=VALUE, --algorithm NAME,
  // --tolerance T, --option NAME=VALUE, --output DIR, --no-plots. True if the current
  // argument was one of them (and adds its override).
  bool scene_option(std::vector<Override> &overrides);

  // The computing options shared by run, compare, sweep and info: --threads N,
  // --planning estimate|measure|patient, --wisdom PATH, --no-wisdom. True if the current
  // argument was one of them (and sets it).
  bool compute_option(ComputeOptions &compute);

 private:
  std::vector<std::string> arguments_;
  std::string command_;
  size_t index_ = 0;
  bool started_ = false;
  std::string matched_;  // the option name is() matched
  std::string inline_value_;
  bool has_inline_value_ = false;
  bool value_is_next_ = false;  // value() took the next argument: it is current()
};

// The help text of the scene overrides, for each command's --help.
extern const char *const scene_options_help;

// The help text of the computing options; `planning` is the command's default planning and
// why, as shown after "default: ".
std::string compute_options_help(const char *planning);

// What run, compare and sweep share on their command lines: the scene's overrides, the
// computing options and one SCENE (empty: the built-in scene).
struct SceneArguments {
  std::vector<Override> overrides;
  ComputeOptions compute;
  std::string scene_path;
};

// Reads a scene command's arguments: --help (prints help, the scene overrides' and computing
// options' help and the exit statuses, and returns false), the scene overrides, the
// computing options, one SCENE, and the command's own options through `own`, which returns
// true when it took the current argument. Anything else is refused.
bool read_scene_arguments(Arguments &args, const char *help, SceneArguments &out,
                          const std::function<bool(Arguments &)> &own);

}  // namespace cli
