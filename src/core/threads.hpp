// SPDX-License-Identifier: GPL-2.0-or-later
// How many threads the library's element-wise loops use. Each grid has a thread count (its
// FFTs are planned with it); a solve runs its loops with its grid's count through a
// ThreadScope, and every loop of core/loops.hpp asks loop_threads(). Outside a scope the
// loops run on the calling thread alone.
//
// The default count, in one place: ASPERITY_NUM_THREADS, then OMP_NUM_THREADS, when it holds
// a positive whole number (the first entry of a list such as "4,2"); otherwise the processors
// this process may run on (its CPU affinity, which taskset, cgroups' cpusets and MPI
// launchers' binding narrow) for a grid of one process, and one thread for a distributed
// grid, whose processes usually have a core each.
#pragma once

namespace asp {

// The count the environment asks for (ASPERITY_NUM_THREADS, then OMP_NUM_THREADS), or 0.
int environment_threads();
// The default of a grid of one process: environment_threads(), else the processors this
// process may run on (at least 1).
int default_threads();
// The default of a distributed grid: environment_threads(), else 1.
int default_distributed_threads();

// The thread count of this calling thread's loops (1 outside a ThreadScope, and always 1 in
// a build without threads).
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
