// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/threads.hpp"

#include <cerrno>
#include <cstdlib>
#include <thread>

namespace asp {
namespace {

thread_local int current_threads = 1;

}  // namespace

int environment_threads() {
  if (const char *text = std::getenv("OMP_NUM_THREADS")) {
    char *end = nullptr;
    errno = 0;
    const long value = std::strtol(text, &end, 10);
    // "4" or "4,2" (nested levels: the first is ours).
    if (end != text && errno == 0 && value > 0 && value <= 4096 && (*end == '\0' || *end == ','))
      return static_cast<int>(value);
  }
  return 0;
}

int default_threads() {
  if (const int threads = environment_threads()) return threads;
  const unsigned processors = std::thread::hardware_concurrency();
  return processors > 0 ? static_cast<int>(processors) : 1;
}

int loop_threads() { return current_threads; }

ThreadScope::ThreadScope(int threads) : previous_(current_threads) {
  current_threads = threads > 0 ? threads : 1;
}

ThreadScope::~ThreadScope() { current_threads = previous_; }

}  // namespace asp
