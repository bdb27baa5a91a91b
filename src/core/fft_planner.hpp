// SPDX-License-Identifier: GPL-2.0-or-later
// What every FFTW plan of the library is made under: one lock (FFTW's planner is not
// thread-safe), FFTW's threads set up once, and the thread count of new plans. Shared by the
// serial transforms (core/fft_engine.cpp) and the distributed ones (core/mpi_partition.cpp).
#pragma once

#include <fftw3.h>

#include <cstdint>
#include <mutex>

#include "core/fft_engine.hpp"

namespace asp {
namespace fft_planner {

// Every plan creation and destruction and every wisdom operation holds this lock. Executing
// existing plans is thread-safe.
std::mutex &mutex();

// FFTW's planner flags for a planning choice.
unsigned flags_of(FftPlanning planning);

// How the plans of the serial transforms were made since the process started: from the
// process's wisdom alone (no candidate timed: a shape planned before, or imported with
// import_fft_wisdom), or by FFTW's planner (estimated, or measured candidates).
struct PlanCounts {
  std::int64_t from_wisdom = 0;
  std::int64_t planned = 0;
};
PlanCounts plan_counts();  // takes the lock

// The plan make(flags) returns, from wisdom alone when the process's wisdom holds the
// transform for these flags, else planned with them; counted in plan_counts(). Call under the
// lock. Estimated plans are planned as asked (they time nothing).
void count_plan(bool from_wisdom);
template <class Make>
fftw_plan plan(unsigned flags, Make &&make) {
  if ((flags & FFTW_ESTIMATE) == 0) {
    if (fftw_plan known = make(flags | FFTW_WISDOM_ONLY)) {
      count_plan(true);
      return known;
    }
  }
  count_plan(false);
  return make(flags);
}

// The most time FFTW may spend planning one transform (fftw_set_timelimit), in seconds:
// measured plans of a grid shape then cost at most a few seconds however busy the machine
// is (FFTW times its candidates by the wall clock, and on a busy machine each takes longer),
// patient ones a minute. Estimated plans take no time to speak of.
constexpr double measure_seconds = 1.0;
constexpr double patient_seconds = 15.0;

// Plans of a serial transform made while it lives are bounded so. FFTW's time limit is
// process-wide state without a getter: it is set under the lock and put back to FFTW's
// default, none, afterwards. Distributed plans are made without it: FFTW-MPI plans together,
// and processes whose clocks stopped their search at different candidates would disagree.
class PlanningTimeLimit {
 public:
  explicit PlanningTimeLimit(FftPlanning planning);
  ~PlanningTimeLimit();
  PlanningTimeLimit(const PlanningTimeLimit &) = delete;
  PlanningTimeLimit &operator=(const PlanningTimeLimit &) = delete;
};

// FFTW's threads, set up once (call under the lock) before the first threaded plan or the
// first wisdom import or export: wisdom may hold threaded plans, which FFTW reads only once
// its threads are set up. FFTW's threaded transforms then run their jobs on the library's
// pool (fftw_threads_set_callback; process-wide, so that other FFTW users of the process run
// theirs there too). False if the build has none or FFTW could not set them up.
bool threads_ready();

// Plans made while it lives, of transforms of `points` points, run on `threads` threads
// (FFTW's threads, when the build has them), or on one below loops::parallel_entries
// points, where waking threads costs more than the work they would share. FFTW's thread count
// for new plans is process-wide state: it is set under the lock and put back afterwards, so
// that other FFTW users in the process keep theirs.
class PlannerThreads {
 public:
  PlannerThreads(int threads, std::int64_t points);
  ~PlannerThreads();
  PlannerThreads(const PlannerThreads &) = delete;
  PlannerThreads &operator=(const PlannerThreads &) = delete;

 private:
  int previous_ = 0;
};

}  // namespace fft_planner
}  // namespace asp
