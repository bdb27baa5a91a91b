// SPDX-License-Identifier: GPL-2.0-or-later
// The live progress line on a terminal, and Ctrl-C: the first one cancels the solve under way
// (through the library's progress callback), a second one quits.
#pragma once

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <string>

namespace cli {

// Installs the Ctrl-C handler for the lifetime of the object (unless the command was started
// ignoring SIGINT) and restores the previous one afterwards.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard &) = delete;
  InterruptGuard &operator=(const InterruptGuard &) = delete;
  static bool interrupted();

 private:
  void (*previous_)(int);
};

// The progress callback's state: draws "LABEL  iteration N  error E  T s" on stream, at most
// ten times a second, when stream is a terminal; cancels the solve once Ctrl-C was pressed.
class ProgressLine {
 public:
  explicit ProgressLine(std::FILE *stream);
  void set_label(const std::string &label) { label_ = label; }
  void clear();  // erases the line, so that what follows starts on a clean line

  // An asp_progress_fn; user_data is the ProgressLine.
  static int callback(int64_t iteration, double seconds, double error, void *user_data);

 private:
  std::FILE *stream_;
  bool draw_;
  std::string label_;
  double last_drawn_ = -1.0;
  int width_ = 0;
};

}  // namespace cli
