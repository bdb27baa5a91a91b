// SPDX-License-Identifier: GPL-2.0-or-later
#include "library.hpp"

#include <sstream>
#include <vector>

namespace cli {

std::string library_message(int status, const std::string &what) {
  return what + ": " + asp_status_string(status) + " (" + asp_last_error_message() + ")";
}

std::string refusal_message() {
  std::string message = asp_last_error_message();
  const size_t colon = message.find(": ");
  if (message.rfind("asp_", 0) == 0 && colon != std::string::npos &&
      message.find_first_not_of("abcdefghijklmnopqrstuvwxyz_0123456789") == colon)
    message.erase(0, colon + 2);
  return message;
}

void check(int status, const std::string &what) {
  if (status != ASP_OK) throw failure(library_message(status, what));
}

void check_given(int status, const std::string &where) {
  if (status == ASP_OK) return;
  if (status == ASP_ERR_INVALID_ARGUMENT || status == ASP_ERR_UNSUPPORTED ||
      status == ASP_ERR_SIZE_MISMATCH)
    throw usage_error(where + ": " + refusal_message());
  throw failure(library_message(status, where));
}

double observable(const asp_system *system, int key) {
  double value = 0.0;
  check(asp_system_get(system, key, &value), "reading an observable of the system");
  return value;
}

const char *termination_name(int reason) {
  switch (reason) {
    case ASP_TERMINATION_CONVERGED: return "converged";
    case ASP_TERMINATION_ITERATION_LIMIT: return "iteration limit";
    case ASP_TERMINATION_CANCELLED: return "cancelled";
    case ASP_TERMINATION_STALLED: return "stalled";
    case ASP_TERMINATION_BREAKDOWN: return "breakdown";
    case ASP_TERMINATION_SEPARATED: return "separated";
    default: return "unknown";
  }
}

std::string algorithm_names() {
  int64_t length = 0;
  check(asp_algorithms(nullptr, 0, &length), "listing the algorithms");
  std::vector<char> text(static_cast<size_t>(length) + 1);
  check(asp_algorithms(text.data(), length + 1, nullptr), "listing the algorithms");
  return std::string(text.data());
}

std::string description(const asp_solver *solver) {
  int64_t length = 0;
  check(asp_solver_describe(solver, nullptr, 0, &length), "describing the algorithm");
  std::vector<char> text(static_cast<size_t>(length) + 1);
  check(asp_solver_describe(solver, text.data(), length + 1, nullptr),
        "describing the algorithm");
  return text.data();
}

namespace {

// The description's option lines, "  NAME (TYPE...): MEANING", as (NAME, TYPE...).
std::vector<std::pair<std::string, std::string>> option_lines(const asp_solver *solver) {
  std::istringstream lines(description(solver));
  std::vector<std::pair<std::string, std::string>> options;
  std::string line;
  bool in_options = false;
  while (std::getline(lines, line)) {
    if (line == "options:") {
      in_options = true;
      continue;
    }
    const size_t open = line.find(" (");
    if (!in_options || line.rfind("  ", 0) != 0 || open == std::string::npos) continue;
    options.emplace_back(line.substr(2, open - 2), line.substr(open + 2));
  }
  return options;
}

}  // namespace

std::vector<std::string> option_names(const asp_solver *solver) {
  std::vector<std::string> names;
  for (const auto &[name, kind] : option_lines(solver)) names.push_back(name);
  return names;
}

std::vector<std::string> variables(const asp_solver *solver) {
  // "variable (one of pressure, gap; default pressure)"
  const std::string one_of = "one of ";
  for (const auto &[name, kind] : option_lines(solver)) {
    if (name != "variable" || kind.rfind(one_of, 0) != 0) continue;
    std::istringstream list(kind.substr(one_of.size(), kind.find(';') - one_of.size()));
    std::vector<std::string> values;
    std::string value;
    while (std::getline(list, value, ',')) {
      const size_t first = value.find_first_not_of(' ');
      if (first != std::string::npos) values.push_back(value.substr(first));
    }
    return values;
  }
  return {};
}

}  // namespace cli
