// SPDX-License-Identifier: GPL-2.0-or-later
// The asperity command's exit statuses, and the errors that carry one out of a command.
#pragma once

#include <stdexcept>
#include <string>

namespace cli {

// Exit statuses, documented in every command's --help.
enum ExitStatus {
  exit_converged = 0,      // every solve converged (or an informational request ran)
  exit_not_converged = 1,  // a solve ended without converging
  exit_usage = 2,          // a bad argument or scene, refused before any work
  exit_failure = 3,        // the library or the system failed
};

// A refusal or failure with the status the command exits with; the message is complete
// ("scene.toml:4:6: grid.nx: ...") and main prints it after "asperity: ".
class CommandError : public std::runtime_error {
 public:
  CommandError(ExitStatus status, const std::string &message)
      : std::runtime_error(message), status_(status) {}
  ExitStatus status() const { return status_; }

 private:
  ExitStatus status_;
};

// Shorthands for the two kinds.
inline CommandError usage_error(const std::string &message) {
  return CommandError(exit_usage, message);
}
inline CommandError failure(const std::string &message) {
  return CommandError(exit_failure, message);
}

}  // namespace cli
