// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/fft_planner.hpp"

#include <fftw3.h>

#include "core/loops.hpp"
#include "core/thread_pool.hpp"

namespace asp {
namespace fft_planner {

std::mutex &mutex() {
  static std::mutex m;
  return m;
}

unsigned flags_of(FftPlanning planning) {
  switch (planning) {
    case FftPlanning::patient:
      return FFTW_PATIENT;
    case FftPlanning::measure:
      return FFTW_MEASURE;
    case FftPlanning::estimate:
      break;
  }
  return FFTW_ESTIMATE;
}

namespace {
PlanCounts counts;  // under the lock
}  // namespace

void count_plan(bool from_wisdom) { ++(from_wisdom ? counts.from_wisdom : counts.planned); }

PlanCounts plan_counts() {
  std::lock_guard<std::mutex> lock(mutex());
  return counts;
}

PlanningTimeLimit::PlanningTimeLimit(FftPlanning planning) {
  if (planning == FftPlanning::measure) fftw_set_timelimit(measure_seconds);
  if (planning == FftPlanning::patient) fftw_set_timelimit(patient_seconds);
}

PlanningTimeLimit::~PlanningTimeLimit() { fftw_set_timelimit(FFTW_NO_TIMELIMIT); }

#ifdef ASPERITY_THREADS
namespace {
// FFTW's threaded transforms hand their jobs here, and so to the library's pool: the calling
// thread takes the jobs of helpers the system has not run yet, where FFTW's own workers would
// be waited for (core/thread_pool.hpp).
void run_fftw_jobs(void *(*work)(char *), char *jobs, std::size_t size, int count, void *) {
  thread_pool::run_jobs(count, count, [&](std::int64_t k) {
    work(jobs + size * static_cast<std::size_t>(k));
  });
}
}  // namespace
#endif

bool threads_ready() {
#ifdef ASPERITY_THREADS
  static const bool ready = [] {
    if (fftw_init_threads() == 0) return false;
    fftw_threads_set_callback(&run_fftw_jobs, nullptr);
    return true;
  }();
  return ready;
#else
  return false;
#endif
}

PlannerThreads::PlannerThreads(int threads, std::int64_t points) {
#ifdef ASPERITY_THREADS
  if (threads_ready()) {
    previous_ = fftw_planner_nthreads();
    fftw_plan_with_nthreads(threads > 1 && points >= loops::parallel_entries ? threads : 1);
  }
#else
  (void)threads;
  (void)points;
#endif
}

PlannerThreads::~PlannerThreads() {
#ifdef ASPERITY_THREADS
  if (previous_ > 0) fftw_plan_with_nthreads(previous_);
#endif
}

}  // namespace fft_planner
}  // namespace asp
