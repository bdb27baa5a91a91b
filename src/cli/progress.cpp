// SPDX-License-Identifier: GPL-2.0-or-later
#include "progress.hpp"

#include <cmath>
#include <csignal>
#include <ctime>

#include <unistd.h>

namespace cli {
namespace {

volatile std::sig_atomic_t interrupt_count = 0;
// When the first interrupt came (CLOCK_MONOTONIC seconds; written before the count).
volatile double first_interrupt = 0.0;

double monotonic_seconds() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// One Ctrl-C may arrive twice: sent to the process and to its process group (as `timeout`
// does, and a shell's job control can), a moment apart. A second interrupt within this time
// of the first is the same one; a later one is a second Ctrl-C.
constexpr double same_interrupt_seconds = 0.5;

void on_interrupt(int signal_number) {
  if (interrupt_count == 0) {
    first_interrupt = monotonic_seconds();
    interrupt_count = 1;
    return;
  }
  if (monotonic_seconds() - first_interrupt < same_interrupt_seconds) return;
  std::signal(signal_number, SIG_DFL);  // a second Ctrl-C quits at once
  std::raise(signal_number);
}

// Redraw at most this often: small solves make thousands of iterations a second.
constexpr double redraw_interval = 0.1;

}  // namespace

InterruptGuard::InterruptGuard() : previous_(std::signal(SIGINT, on_interrupt)) {
  if (previous_ == SIG_IGN) std::signal(SIGINT, SIG_IGN);
}

InterruptGuard::~InterruptGuard() {
  if (previous_ != SIG_ERR) std::signal(SIGINT, previous_);
}

bool InterruptGuard::interrupted() { return interrupt_count != 0; }

ProgressLine::ProgressLine(std::FILE *stream)
    : stream_(stream), draw_(isatty(fileno(stream)) != 0) {}

int ProgressLine::callback(int64_t iteration, double seconds, double error, void *user_data) {
  auto *p = static_cast<ProgressLine *>(user_data);
  if (p->draw_ && (p->last_drawn_ < 0.0 || seconds - p->last_drawn_ >= redraw_interval)) {
    char line[160];
    int width =
        std::isfinite(error)
            ? std::snprintf(line, sizeof line, "%s%siteration %lld  error %.3e  %.1f s",
                            p->label_.c_str(), p->label_.empty() ? "" : "  ",
                            static_cast<long long>(iteration), error, seconds)
            : std::snprintf(line, sizeof line, "%s%siteration %lld  error not finite  %.1f s",
                            p->label_.c_str(), p->label_.empty() ? "" : "  ",
                            static_cast<long long>(iteration), seconds);
    if (width < 0) width = 0;
    if (width >= static_cast<int>(sizeof line)) width = static_cast<int>(sizeof line) - 1;
    // Spaces cover what is left of a longer previous line.
    std::fprintf(p->stream_, "\r%s%*s", line, p->width_ > width ? p->width_ - width : 0, "");
    std::fflush(p->stream_);
    if (width > p->width_) p->width_ = width;
    p->last_drawn_ = seconds;
  }
  return InterruptGuard::interrupted() ? 1 : 0;
}

void ProgressLine::clear() {
  if (draw_ && width_ > 0) {
    std::fprintf(stream_, "\r%*s\r", width_, "");
    std::fflush(stream_);
  }
  width_ = 0;
  last_drawn_ = -1.0;
}

}  // namespace cli
