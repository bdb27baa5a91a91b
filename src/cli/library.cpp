// SPDX-License-Identifier: GPL-2.0-or-later
#include "library.hpp"

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

}  // namespace cli
