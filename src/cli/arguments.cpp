// SPDX-License-Identifier: GPL-2.0-or-later
#include "arguments.hpp"

#include <cstdio>

#include "commands.hpp"
#include "exit_status.hpp"

namespace cli {

const char *const scene_options_help =
    "Scene overrides (each sets one key of the scene before it is checked):\n"
    "  --set KEY=VALUE      any key, such as grid.nx=256 or control.value=0.01; VALUE is\n"
    "                       read as TOML (a bare word as a string); repeatable\n"
    "  --algorithm NAME     the same as --set solver.algorithm=NAME\n"
    "  --tolerance T        the same as --set solver.tolerance=T\n"
    "  --option NAME=VALUE  the same as --set solver.options.NAME=VALUE\n"
    "  --output DIR         the same as --set output.directory=DIR\n"
    "  --no-plots           the same as --set output.plots=false\n";

Arguments::Arguments(std::vector<std::string> arguments, std::string command)
    : arguments_(std::move(arguments)), command_(std::move(command)) {}

bool Arguments::next() {
  if (started_) ++index_;
  started_ = true;
  return index_ < arguments_.size();
}

bool Arguments::is(const char *name) {
  const std::string &a = current();
  const std::string n = name;
  if (a == n) {
    matched_ = n;
    has_inline_value_ = false;
    return true;
  }
  if (a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=') {
    matched_ = n;
    has_inline_value_ = true;
    inline_value_ = a.substr(n.size() + 1);
    return true;
  }
  return false;
}

bool Arguments::is_flag(const char *name) {
  const std::string &a = current();
  const std::string n = name;
  if (a == n) return true;
  if (a.size() > n.size() && a.compare(0, n.size(), n) == 0 && a[n.size()] == '=')
    refuse("takes no value");
  return false;
}

std::string Arguments::value() {
  if (has_inline_value_) return inline_value_;
  if (index_ + 1 >= arguments_.size() || arguments_[index_ + 1].rfind("--", 0) == 0)
    throw usage_error(command_ + ": " + matched_ + ": needs a value\nRun '" + command_ +
                      " --help' for the options.");
  return arguments_[++index_];
}

bool Arguments::positional() const {
  const std::string &a = current();
  return a.empty() || a[0] != '-' || a == "-";
}

void Arguments::refuse(const std::string &problem) const {
  throw usage_error(command_ + ": " + current() + ": " + problem + "\nRun '" + command_ +
                    " --help' for the options.");
}

bool Arguments::scene_option(std::vector<Override> &overrides) {
  auto add = [&](const std::string &key, const std::string &value, const std::string &shown) {
    overrides.push_back({key + "=" + value, shown});
  };
  if (is("--set")) {
    const std::string v = value();
    overrides.push_back({v, "--set " + v});
  } else if (is("--algorithm")) {
    const std::string v = value();
    add("solver.algorithm", v, "--algorithm " + v);
  } else if (is("--tolerance")) {
    const std::string v = value();
    add("solver.tolerance", v, "--tolerance " + v);
  } else if (is("--option")) {
    const std::string v = value();
    if (v.find('=') == std::string::npos || v[0] == '=')
      throw usage_error(command_ + ": --option " + v + ": expected NAME=VALUE");
    overrides.push_back({"solver.options." + v, "--option " + v});
  } else if (is("--output")) {
    const std::string v = value();
    // A directory is a string whatever it looks like: quote it for the TOML reader.
    std::string quoted = "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    add("output.directory", quoted + "\"", "--output " + v);
  } else if (is_flag("--no-plots")) {
    add("output.plots", "false", "--no-plots");
  } else {
    return false;
  }
  return true;
}

bool read_scene_arguments(Arguments &args, const char *help, SceneArguments &out,
                          const std::function<bool(Arguments &)> &own) {
  while (args.next()) {
    if (args.is_flag("--help") || args.is_flag("-h")) {
      std::printf("%s%s\n%s", help, scene_options_help, exit_status_help);
      return false;
    }
    if (args.scene_option(out.overrides) || own(args)) continue;
    if (args.positional() && out.scene_path.empty()) {
      out.scene_path = args.current();
      continue;
    }
    args.refuse(args.positional() ? "a second scene: the command takes one" : "unknown option");
  }
  return true;
}

}  // namespace cli
