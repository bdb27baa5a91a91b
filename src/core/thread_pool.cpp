// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/thread_pool.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include <pthread.h>

namespace asp {
namespace thread_pool {
namespace {

using Clock = std::chrono::steady_clock;

// How long a helper looks for the next loop after its last job before it goes to sleep. A
// solve's loops follow each other within microseconds (what lies between them is a transform
// or a few scalar operations), so on an idle machine the helpers are awake for the next one;
// on a busy machine a helper that is not needed costs the other processes this much and then
// nothing.
constexpr auto spin_time = std::chrono::microseconds(50);

// A loop whose caller, done with its own jobs, waited longer than this and longer than it
// worked, waited for a helper that the system stopped running in the middle of a job: the
// machine's cores are busy with other processes. Loops then run on their callers alone for
// a while, first_solo_period, doubled at each such loop up to last_solo_period, and the
// helpers are tried again after it. On an idle machine a caller waits at most about one job.
constexpr auto stall = std::chrono::microseconds(200);
constexpr auto first_solo_period = std::chrono::milliseconds(20);
constexpr auto last_solo_period = std::chrono::milliseconds(1000);

// The most helpers the pool starts, whatever a grid asks for.
constexpr int most_helpers = 255;

// True in a child process forked after the pool started: the child has none of its helpers,
// and a lock a helper held at the fork stays taken there, so its loops run on its one thread.
std::atomic<bool> forked{false};

// True on the pool's helpers, and on a caller while it runs jobs: a loop started there runs
// on its thread alone.
thread_local bool inside_job = false;

class InsideJob {
 public:
  InsideJob() : previous_(inside_job) { inside_job = true; }
  ~InsideJob() { inside_job = previous_; }
  InsideJob(const InsideJob &) = delete;
  InsideJob &operator=(const InsideJob &) = delete;

 private:
  bool previous_;
};

void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// One parallel loop: its jobs, who takes the next one, how many have ended.
struct Loop {
  Loop(Job j, void *c, std::int64_t n) : job(j), context(c), jobs(n) {}

  // Takes jobs until none is left, and says so when it ended the last one.
  void take_jobs() {
    std::int64_t ended_here = 0;
    for (std::int64_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < jobs; ++ended_here) {
      try {
        job(context, i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
      }
    }
    if (ended_here > 0 &&
        ended.fetch_add(ended_here, std::memory_order_acq_rel) + ended_here == jobs) {
      std::lock_guard<std::mutex> lock(mutex);
      all_ended.notify_all();
    }
  }

  // Returns once every job has ended: a few microseconds looking, then asleep.
  void wait() {
    const auto until = Clock::now() + spin_time;
    while (ended.load(std::memory_order_acquire) < jobs)
      if (Clock::now() < until) {
        relax();
      } else {
        std::unique_lock<std::mutex> lock(mutex);
        all_ended.wait(lock, [&] { return ended.load(std::memory_order_acquire) == jobs; });
      }
  }

  const Job job;
  void *const context;
  const std::int64_t jobs;
  std::atomic<std::int64_t> next{0};
  std::atomic<std::int64_t> ended{0};
  std::mutex mutex;  // for error and the caller's sleep
  std::condition_variable all_ended;
  std::exception_ptr error;
};

class Pool {
 public:
  // Made on first use and never destroyed: a child forked while helpers waited holds copies
  // of their condition variables that can never be destroyed there. The helpers of the
  // process itself are stopped and joined at its exit (Stopper).
  static Pool &instance() {
    static Pool *const pool = new Pool;
    static const Stopper stopper(pool);
    return *pool;
  }

  // A child process forked after the pool started uses no helper. Its copies of the helpers'
  // handles name threads it does not have: they are set aside, never joined.
  static void after_fork_in_child() {
    forked.store(true);
    Pool &pool = instance();
    new std::vector<std::thread>(std::move(pool.helpers_));
    pool.helpers_.clear();
  }

  // Stops and joins the helpers at the process's exit (or when the library is unloaded), in
  // the process that started them only: a forked child has none, and a lock a helper held
  // at the fork is held there for ever.
  void stop() {
    if (forked.load()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread &helper : helpers_) helper.join();
    helpers_.clear();
  }

  struct Stopper {
    explicit Stopper(Pool *p) : pool(p) {}
    ~Stopper() { pool->stop(); }
    Pool *pool;
  };

  void run(int threads, std::int64_t jobs, Job job, void *context) {
    const int wanted = static_cast<int>(
        std::min<std::int64_t>({static_cast<std::int64_t>(threads) - 1, jobs - 1, most_helpers}));
    // On the heap and shared: a helper woken late may still look at it (to find no job left)
    // after this call has returned.
    const auto loop = std::make_shared<Loop>(job, context, jobs);
    const auto start = Clock::now();
    std::unique_lock<std::mutex> busy(busy_, std::defer_lock);
    const int helpers = wanted > 0 && !inside_job && !forked.load() &&
                                start.time_since_epoch().count() >= solo_until_.load() &&
                                busy.try_lock()
                            ? start_helpers(wanted)
                            : 0;
    if (helpers > 0) offer(loop, helpers);
    {
      const InsideJob mark;
      loop->take_jobs();
    }
    if (helpers > 0) {
      const auto worked = Clock::now();
      withdraw();
      loop->wait();
      judge_the_wait(start, worked, Clock::now());
    }
    if (loop->error) std::rethrow_exception(loop->error);
  }

  int started() {
    std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<int>(helpers_.size());
  }

 private:
  Pool() { pthread_atfork(nullptr, nullptr, &Pool::after_fork_in_child); }

  // Starts helpers until there are `wanted` (called by the one caller that holds busy_).
  // Returns how many there are: fewer when the system refuses a thread.
  int start_helpers(int wanted) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return 0;  // loops of other objects' destructors at exit run alone
    try {
      while (static_cast<int>(helpers_.size()) < wanted)
        helpers_.emplace_back([this] { helper_main(); });
    } catch (const std::system_error &) {
    }
    return std::min(wanted, static_cast<int>(helpers_.size()));
  }

  // After a loop with helpers (by the caller that holds busy_): a wait for a helper far
  // longer than the caller's own work starts a period of loops without helpers, longer each
  // time it happens again; a loop without such a wait makes the next period short again.
  void judge_the_wait(Clock::time_point start, Clock::time_point worked, Clock::time_point end) {
    const auto waited = end - worked;
    if (waited > stall && waited > worked - start) {
      solo_until_.store((end + solo_period_).time_since_epoch().count());
      solo_period_ = std::min<Clock::duration>(2 * solo_period_, last_solo_period);
    } else {
      solo_period_ = first_solo_period;
    }
  }

  // Makes the loop the one `helpers` helpers join, waking those asleep.
  void offer(const std::shared_ptr<Loop> &loop, int helpers) {
    int asleep;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      current_ = loop;
      wanted_ = helpers;
      generation_.fetch_add(1, std::memory_order_release);
      asleep = sleeping_;
    }
    for (int i = 0; i < std::min(helpers, asleep); ++i) wake_.notify_one();
  }

  // No helper joins the loop from now on (its jobs are all taken; those that joined finish
  // what they took).
  void withdraw() {
    std::lock_guard<std::mutex> lock(mutex_);
    current_ = nullptr;
    wanted_ = 0;
  }

  void helper_main() {
    inside_job = true;
    std::uint64_t seen = generation_.load(std::memory_order_acquire);
    for (;;) {
      const auto until = Clock::now() + spin_time;
      while (generation_.load(std::memory_order_acquire) == seen && Clock::now() < until) relax();
      std::shared_ptr<Loop> loop;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        if (generation_.load(std::memory_order_relaxed) == seen && !stopping_) {
          ++sleeping_;
          wake_.wait(lock, [&] {
            return stopping_ || generation_.load(std::memory_order_relaxed) != seen;
          });
          --sleeping_;
        }
        if (stopping_) return;
        seen = generation_.load(std::memory_order_relaxed);
        if (wanted_ > 0 && current_ != nullptr) {
          --wanted_;
          loop = current_;
        }
      }
      if (loop) loop->take_jobs();
    }
  }

  std::mutex busy_;  // held by the caller whose loop the helpers serve
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::thread> helpers_;
  std::atomic<std::uint64_t> generation_{0};
  // Until when loops run without helpers (Clock ticks), and the next such period (busy_).
  std::atomic<Clock::rep> solo_until_{0};
  Clock::duration solo_period_ = first_solo_period;
  std::shared_ptr<Loop> current_;
  int wanted_ = 0;
  int sleeping_ = 0;
  bool stopping_ = false;
};

}  // namespace

void run(int threads, std::int64_t jobs, Job job, void *context) {
  if (jobs <= 0) return;
  Pool::instance().run(threads, jobs, job, context);
}

int helpers_started() { return Pool::instance().started(); }

}  // namespace thread_pool
}  // namespace asp
