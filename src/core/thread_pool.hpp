// SPDX-License-Identifier: GPL-2.0-or-later
// The library's own threads for its element-wise loops. A parallel loop is cut into jobs;
// the calling thread takes jobs one after another, and helper threads woken for the loop
// take them too when they get a core. A helper that the operating system does not run in
// time (the machine is busy with other processes) takes nothing, and the caller does its
// jobs itself: a loop never waits for a thread that has not started, only for jobs already
// under way. Helpers spin for a few microseconds after a loop, so that the next one finds them
// awake on an idle machine, and then sleep on a condition variable: they never spin against
// other processes for longer than that. A helper that the system stops in the middle of a
// job (its core is wanted by others) makes its caller wait; when a caller has waited longer
// than it worked, the loops of the next few milliseconds (doubling while it happens again,
// up to a second) run on their callers alone, and then the helpers are tried again. FFTW's
// threaded transforms hand their jobs to the pool too (core/fft_planner.cpp). This is what
// keeps a solve on a busy machine about as fast as on one thread, where OpenMP's fork-join teams, which wait for every thread and
// spin while they wait, were many times slower (docs/performance.md, "A busy machine").
//
// The pool serves one loop at a time. A loop started while another thread of the process
// runs one (several solves at once, a host program's own threads) runs on its caller alone,
// as does a loop started from inside a job: the process's cores are already at work.
#pragma once

#include <cstdint>
#include <type_traits>

namespace asp {
namespace thread_pool {

// job(context, i) for every i in [0, jobs), on the calling thread and on up to threads - 1
// helpers. The jobs must not depend on which thread runs them or in which order. An
// exception thrown by a job is rethrown here once every job has ended (the first one, if
// several throw); the other jobs still run.
using Job = void (*)(void *context, std::int64_t index);
void run(int threads, std::int64_t jobs, Job job, void *context);

// The same for a callable body(i).
template <class Body>
void run_jobs(int threads, std::int64_t jobs, Body &&body) {
  using Plain = typename std::remove_reference<Body>::type;
  run(
      threads, jobs,
      [](void *context, std::int64_t index) { (*static_cast<Plain *>(context))(index); },
      const_cast<void *>(static_cast<const void *>(&body)));
}

// Helper threads started so far (they are started on first need and kept for the process's
// life, asleep while there is no work).
int helpers_started();

}  // namespace thread_pool
}  // namespace asp
