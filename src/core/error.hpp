// SPDX-License-Identifier: GPL-2.0-or-later
// The one exception type the library throws internally. The C API turns it into a status
// code and a message; nothing else crosses the ABI.
#pragma once

#include <stdexcept>
#include <string>

namespace asp {

// Mirrors the ASP_ERR_* codes of the public header (kept numerically equal on purpose, so
// that the C layer can pass them through).
enum class Status : int {
  ok = 0,
  null_pointer = 1,
  invalid_argument = 2,
  size_mismatch = 3,
  out_of_memory = 4,
  unsupported = 5,
  invalid_state = 6,
  fft = 7,
  callback = 8,
  internal = 9,
  io = 10,
};

class Error : public std::runtime_error {
 public:
  Error(Status status, const std::string &message) : std::runtime_error(message), status_(status) {}
  Status status() const noexcept { return status_; }

 private:
  Status status_;
};

}  // namespace asp
