// SPDX-License-Identifier: GPL-2.0-or-later
// How many threads the library's element-wise loops use. Each grid has a thread count (its
// FFTs are planned with it); a solve runs its loops with its grid's count through a
// ThreadScope, and every loop of core/loops.hpp asks loop_threads(). Outside a scope the
// loops run on the calling thread alone.
#pragma once

namespace asp {

// The default thread count of a new grid: OMP_NUM_THREADS when it holds a positive whole
// number (its first entry, for a list), else the number of processors.
int default_threads();
// OMP_NUM_THREADS when it holds a positive whole number (its first entry), else 0. The
// default of a distributed grid, whose processes usually have a core each, or 1.
int environment_threads();

// The thread count of this calling thread's loops (1 outside a ThreadScope).
int loop_threads();

// Sets loop_threads() for the calling thread while it lives.
class ThreadScope {
 public:
  explicit ThreadScope(int threads);
  ~ThreadScope();
  ThreadScope(const ThreadScope &) = delete;
  ThreadScope &operator=(const ThreadScope &) = delete;

 private:
  int previous_;
};

}  // namespace asp
