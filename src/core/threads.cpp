// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/threads.hpp"

#include <cerrno>
#include <cstdlib>
#include <thread>

#if defined(__linux__)
#include <sched.h>
#endif

namespace asp {
namespace {

thread_local int current_threads = 1;

// A positive whole number of at most 4096 at the start of the variable's text ("4", or "4,2"
// for nested levels, of which the first is ours), else 0.
int threads_in(const char *variable) {
  const char *text = std::getenv(variable);
  if (text == nullptr) return 0;
  char *end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (end != text && errno == 0 && value > 0 && value <= 4096 && (*end == '\0' || *end == ','))
    return static_cast<int>(value);
  return 0;
}

// The processors this process may run on.
int usable_processors() {
#if defined(__linux__)
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int count = CPU_COUNT(&set);
    if (count > 0) return count;
  }
#endif
  const unsigned processors = std::thread::hardware_concurrency();
  return processors > 0 ? static_cast<int>(processors) : 1;
}

}  // namespace

int environment_threads() {
  if (const int threads = threads_in("ASPERITY_NUM_THREADS")) return threads;
  return threads_in("OMP_NUM_THREADS");
}

int default_threads() {
  if (const int threads = environment_threads()) return threads;
  return usable_processors();
}

int default_distributed_threads() {
  if (const int threads = environment_threads()) return threads;
  return 1;
}

int loop_threads() { return current_threads; }

ThreadScope::ThreadScope(int threads) : previous_(current_threads) {
#ifdef ASPERITY_THREADS
  current_threads = threads > 0 ? threads : 1;
#else
  (void)threads;
#endif
}

ThreadScope::~ThreadScope() { current_threads = previous_; }

}  // namespace asp
