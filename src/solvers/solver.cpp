// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/solver.hpp"

#include "core/threads.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {

Solver::Solver(const std::string &algorithm) : algorithm_(find_algorithm(algorithm)) {
  for (const OptionSpec &o : algorithm_.options) {
    if (o.type == OptionType::choice)
      options_.texts[o.name] = o.choices.front();
    else
      options_.numbers[o.name] = o.default_value;
  }
}

namespace {
// "'auto'" or "'a' or 'b'": the words an option also takes, for messages.
std::string word_list(const OptionSpec &o) {
  std::string out;
  for (const auto &word : option_words(o.name))
    out += (out.empty() ? "'" : " or '") + word.first + "'";
  return out;
}
}  // namespace

const OptionSpec &Solver::spec_of(const std::string &name) const {
  std::string valid;
  for (const OptionSpec &o : algorithm_.options) {
    if (o.name == name) return o;
    valid += (valid.empty() ? "" : ", ") + o.name;
  }
  throw Error(Status::invalid_argument, "argument 'name': solver '" + algorithm_.name +
                                            "' has no option '" + name + "' (options: " +
                                            valid + ")");
}

void Solver::set_option(const std::string &name, double value) {
  const OptionSpec &o = spec_of(name);
  if (o.type == OptionType::choice)
    throw Error(Status::invalid_argument, "option '" + name +
                                              "' takes a string (set it with "
                                              "asp_solver_set_option_string), not a number");
  const bool above_minimum = o.minimum_excluded ? value > o.minimum : value >= o.minimum;
  if (!std::isfinite(value) || !above_minimum || value > o.maximum ||
      (o.type == OptionType::integer && value != std::floor(value)))
    throw Error(Status::invalid_argument,
                "option '" + name + "' must be " +
                    (o.type == OptionType::integer ? "a whole number" : "a real number") +
                    " in " + (o.minimum_excluded ? "(" : "[") + format_number(o.minimum) +
                    ", " + format_number(o.maximum) + "], got " + format_number(value));
  options_.numbers[name] = value;
}

void Solver::set_option(const std::string &name, const std::string &value) {
  const OptionSpec &o = spec_of(name);
  for (const auto &word : option_words(o.name)) {
    if (word.first == value) {
      options_.numbers[name] = word.second;
      return;
    }
  }
  if (o.type != OptionType::choice)
    throw Error(Status::invalid_argument,
                "option '" + name + "' takes a number (set it with asp_solver_set_option)" +
                    (option_words(o.name).empty()
                         ? std::string(", not a string")
                         : ", or " + word_list(o) + ", not '" + value + "'"));
  std::string valid;
  for (const std::string &c : o.choices) {
    if (c == value) {
      options_.texts[name] = value;
      return;
    }
    valid += (valid.empty() ? "" : ", ") + c;
  }
  throw Error(Status::invalid_argument,
              "option '" + name + "' must be one of " + valid + ", got '" + value + "'");
}

double Solver::option(const std::string &name) const {
  const OptionSpec &o = spec_of(name);
  if (o.type == OptionType::choice)
    throw Error(Status::invalid_argument,
                "option '" + name + "' is a string (read it with asp_solver_get_option_string)");
  return options_.number(name);
}

namespace {
// FNV-1a, fed byte by byte.
class Fnv1a {
 public:
  void add(const void *data, std::size_t size) {
    const auto *bytes = static_cast<const unsigned char *>(data);
    for (std::size_t k = 0; k < size; ++k) hash_ = (hash_ ^ bytes[k]) * 1099511628211ULL;
  }
  // A text with its end, so that "ab" + "c" and "a" + "bc" differ.
  void add(const std::string &text) { add(text.c_str(), text.size() + 1); }
  double bits() const {
    double d;
    std::memcpy(&d, &hash_, sizeof d);
    return d;
  }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};
}  // namespace

double Solver::fingerprint() const {
  Fnv1a hash;
  hash.add(algorithm_.name);
  for (const auto &number : options_.numbers) {
    hash.add(number.first);
    hash.add(&number.second, sizeof number.second);
  }
  for (const auto &text : options_.texts) {
    hash.add(text.first);
    hash.add(text.second);
  }
  return hash.bits();
}

const std::string &Solver::option_text(const std::string &name) const {
  const OptionSpec &o = spec_of(name);
  for (const auto &word : option_words(o.name))
    if (options_.number(name) == word.second) return word.first;
  if (o.type != OptionType::choice)
    throw Error(Status::invalid_argument,
                "option '" + name + "' is a number (read it with asp_solver_get_option)" +
                    (option_words(o.name).empty()
                         ? std::string()
                         : "; it reads as a string only when it is " + word_list(o)));
  return options_.text(name);
}

void Solver::set_progress(ProgressFunction progress, void *user_data) {
  progress_ = progress;
  progress_data_ = user_data;
}

void Solver::forget_last_solve() {
  report_ = SolveReport();
  history_.clear();
}

void Solver::solve(System &system, Control control, double value) {
  forget_last_solve();
  check_request(algorithm_, options_, system, control, &value);

  MonitorSettings settings;
  settings.tolerance = options_.number("tolerance");
  settings.max_iterations = static_cast<std::int64_t>(options_.number("max_iterations"));
  settings.stall_window = static_cast<std::int64_t>(options_.number("stall_window"));
  settings.record_history = record_history_;
  settings.progress = progress_;
  settings.progress_data = progress_data_;
  settings.reductions = &system.grid().reductions();
  Monitor monitor(settings);
  // The solve's loops run on the grid's threads (its FFTs were planned with them).
  const ThreadScope threads(system.grid().threads());

  // A user's potential can fail in the middle of a solve (Error(callback)): the system then
  // goes back to the state the solve started from, which costs a copy of it only for them.
  // Any other error after a formulation began to work on the state in place (memory running
  // out for a solver's arrays or a quasi-Newton pair) resets the state, as a breakdown does,
  // rather than leave it in the solve's units.
  const bool keep_start = system.interaction().potential_from_callback();
  ContactState start;
  if (keep_start) start = system.state();
  const std::int64_t levels = nested_levels(system, options_.number("levels"));
  // Asked of the state before the coarse levels give it pressure: a cold start.
  const double range_factor =
      continuation_factor(system, control, value, options_.number("range_continuation"));
  CoarseWork coarse;
  try {
    coarse = solve_coarse_levels(algorithm_, options_, system, control, value, levels,
                                 coarse_level_settings(settings, range_factor));
    // A prolonged coarse state is the solve's, not the caller's: a failure from here on
    // resets it (a nested solve starts only from a state without pressure, a cold one).
    if (coarse.prolonged) system.set_state_held_by_solve(true);
    // The coarse levels' transforms, weighted by their share of the pixels, are the solve's
    // work: the history's rows and the report count them.
    monitor.count_prior_transforms(static_cast<std::int64_t>(std::ceil(coarse.transforms)));
    // The first stage of a continuation in the range, on the system's grid: its iterations
    // are the solve's, and so is its state (a cold start's, like the prolonged one).
    if (range_factor > 1.0) system.set_state_held_by_solve(true);
    if (solve_with_longer_range(algorithm_, options_, system, control, value, range_factor,
                                settings.tolerance, monitor))
      algorithm_.run(system, control, value, options_, monitor);
  } catch (...) {
    if (keep_start) {
      system.state() = start;
    } else if (system.state_held_by_solve()) {
      system.reset_state();
    }
    system.set_state_held_by_solve(false);
    throw;
  }
  system.set_state_held_by_solve(false);

  report_.iterations = monitor.iterations();
  report_.evaluations = monitor.evaluations();
  // With nested grids: the iterations and evaluations of the system's own grid, the
  // transforms of every level, a coarse one's weighted by its share of the pixels.
  report_.transforms = monitor.transforms();
  report_.error = monitor.error();
  report_.termination = monitor.termination();
  report_.seconds = monitor.seconds();
  report_.available = true;
  history_ = std::move(monitor.history());
}

}  // namespace asp
