// SPDX-License-Identifier: GPL-2.0-or-later
#include "arguments.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>

#include "commands.hpp"
#include "exit_status.hpp"
#include "scene_reader.hpp"

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

std::string compute_options_help(const char *planning) {
  const std::pair<std::string, std::string> options[] = {
      {"--threads N",
       "threads of every solve and of its FFTs (default: ASPERITY_NUM_THREADS, else "
       "OMP_NUM_THREADS, else the processors the command may run on)"},
      {"--planning P",
       std::string("estimate, measure or patient: how hard FFTW looks for fast transforms "
                   "the first time it meets a grid's shape (docs/building.md); default: ") +
           planning},
      {"--wisdom PATH",
       "the FFTW wisdom file: what measured planning has learnt, read before the first grid "
       "and written after the solves when the planning is measure or patient (default: "
       "$XDG_CACHE_HOME/asperity/fftw-wisdom, else ~/.cache/asperity/fftw-wisdom)"},
      {"--no-wisdom", "neither read nor write a wisdom file"}};
  // Each description wrapped to the width of the other options' help, in a column.
  const size_t column = 23, width = 84;
  std::string text = "Threads and FFT planning:\n";
  for (const auto &[option, description] : options) {
    std::string line = "  " + option;
    line.resize(column - 1, ' ');
    std::istringstream words(description);
    std::string word;
    while (words >> word) {
      if (line.size() + 1 + word.size() > width) {
        text += line + "\n";
        line = std::string(column - 1, ' ');
      }
      line += " " + word;
    }
    text += line + "\n";
  }
  return text;
}

Arguments::Arguments(std::vector<std::string> arguments, std::string command)
    : arguments_(std::move(arguments)), command_(std::move(command)) {}

bool Arguments::next() {
  if (started_) ++index_;
  started_ = true;
  value_is_next_ = false;
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
  value_is_next_ = true;
  return arguments_[++index_];
}

int Arguments::count() {
  const std::string v = value();
  char *end = nullptr;
  errno = 0;
  const long long n = std::strtoll(v.c_str(), &end, 10);
  if (v.empty() || v[0] < '0' || v[0] > '9' || *end != '\0' || n < 1)
    refuse("expected a whole number >= 1");
  if (errno == ERANGE || n > INT_MAX) refuse("too large");
  return static_cast<int>(n);
}

bool Arguments::positional() const {
  const std::string &a = current();
  return a.empty() || a[0] != '-' || a == "-";
}

void Arguments::refuse(const std::string &problem) const {
  // A value given as the next argument is shown after its option: "--threads 0".
  const std::string shown = value_is_next_ ? matched_ + " " + current() : current();
  throw usage_error(command_ + ": " + shown + ": " + problem + "\nRun '" + command_ +
                    " --help' for the options.");
}

void Arguments::refuse_unknown(const std::string &help) const {
  std::vector<std::string> options;
  for (size_t at = help.find("--"); at != std::string::npos; at = help.find("--", at + 2)) {
    size_t end = at + 2;
    while (end < help.size() && (std::islower(static_cast<unsigned char>(help[end])) ||
                                 help[end] == '-'))
      ++end;
    if (end > at + 2) options.push_back(help.substr(at, end - at));
  }
  const std::string &a = current();
  refuse("unknown option" + did_you_mean(a.substr(0, a.find('=')), options));
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

bool Arguments::compute_option(ComputeOptions &compute) {
  if (is("--threads")) {
    compute.threads = count();
  } else if (is("--planning")) {
    const std::string v = value();
    if (v == "estimate") compute.planning = ASP_FFT_ESTIMATE;
    else if (v == "measure") compute.planning = ASP_FFT_MEASURE;
    else if (v == "patient") compute.planning = ASP_FFT_PATIENT;
    else refuse("expected estimate, measure or patient");
  } else if (is("--wisdom")) {
    compute.wisdom = value();
    if (compute.wisdom.empty()) refuse("expected the path of a file");
    compute.no_wisdom = false;
  } else if (is_flag("--no-wisdom")) {
    compute.wisdom.clear();
    compute.no_wisdom = true;
  } else {
    return false;
  }
  return true;
}

bool read_scene_arguments(Arguments &args, const char *help, SceneArguments &out,
                          const std::function<bool(Arguments &)> &own) {
  while (args.next()) {
    if (args.is_flag("--help") || args.is_flag("-h")) {
      std::printf("%s%s\n%s\n%s", help, scene_options_help,
                  compute_options_help("measure").c_str(), exit_status_help);
      return false;
    }
    if (args.scene_option(out.overrides) || args.compute_option(out.compute) || own(args))
      continue;
    if (args.positional() && out.scene_path.empty()) {
      out.scene_path = args.current();
      continue;
    }
    if (args.positional()) args.refuse("a second scene: the command takes one");
    args.refuse_unknown(std::string(help) + scene_options_help + compute_options_help(""));
  }
  return true;
}

}  // namespace cli
