// SPDX-License-Identifier: GPL-2.0-or-later
// The exception firewall of the C API: every entry point runs its body through guarded(),
// which turns any C++ exception into a status code and a thread-local message naming the
// function. Nothing escapes into C. A call that succeeds leaves the message empty, also when
// its body called back into the user's code and a call made there failed.
#pragma once

#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "asperity/asperity.h"
#include "core/error.hpp"
#include "core/grid.hpp"

namespace asp {
namespace capi {

void clear_last_error() noexcept;
int record_error(int status, const char *function, const char *message) noexcept;

template <class Body>
int guarded(const char *function, Body &&body) noexcept {
  try {
    clear_last_error();
    body();
    // A callback run by the body (a progress or potential callback) may have made a call of
    // its own that failed and left its message.
    clear_last_error();
    return ASP_OK;
  } catch (const Error &e) {
    return record_error(static_cast<int>(e.status()), function, e.what());
  } catch (const std::bad_alloc &) {
    return record_error(ASP_ERR_OUT_OF_MEMORY, function, "out of memory");
  } catch (const std::length_error &) {
    // A container asked for more elements than it can address: a size too large to hold.
    return record_error(ASP_ERR_OUT_OF_MEMORY, function,
                        "out of memory: an array of this size cannot be allocated");
  } catch (const std::exception &e) {
    return record_error(ASP_ERR_INTERNAL, function, e.what());
  } catch (...) {
    return record_error(ASP_ERR_INTERNAL, function, "unknown exception");
  }
}

// Calls on a distributed grid, or on a system or solver made on one, are collective, and a
// call that fails on any process fails on all, with the status and message of the first
// failing one (naming it). A body takes an Agreement: it checks its arguments, which may
// differ between processes (arrays, their counts, their values), then calls
// agreement.checks_passed(), where the processes wait for each other's checks, and only then
// does anything collective. What fails after that fails alike on every process, since it
// depends only on what they share. On a serial grid (or a null one) the agreement does
// nothing.
class Agreement {
 public:
  // An integer argument among the scalars checked below: its bits, not its value rounded to
  // a double.
  static double bits(std::int64_t value) {
    double d;
    std::memcpy(&d, &value, sizeof d);
    return d;
  }

  explicit Agreement(const Grid *grid) : partition_(grid ? grid->partition() : nullptr) {}
  void checks_passed() {
    if (partition_ == nullptr || done_) return;
    done_ = true;
    partition_->agree(nullptr);
  }
  // The same, and the call's scalar arguments (`what` names them) must be the same bits on
  // every process: processes given different loads, parameters or options would compute
  // different things and stop at different iterations, so every process fails instead,
  // naming the first one that differs.
  void checks_passed(const std::vector<double> &scalars, const char *what) {
    if (partition_ == nullptr || done_) return;
    checks_passed();
    std::vector<double> theirs(scalars.size());
    const int differing = partition_->first_differing(
        scalars.data(), static_cast<int>(scalars.size()), theirs.data());
    if (differing >= 0)
      throw Error(Status::invalid_argument,
                  "on process " + std::to_string(differing) + " of " +
                      std::to_string(partition_->ranks()) + ": " + what +
                      " differ from process 0's; a call on a distributed grid takes the same "
                      "scalar arguments on every process");
  }
  // This process failed before its checks passed: the others learn it at their agreement.
  void failed(const Error &error) {
    if (partition_ == nullptr || done_) return;
    done_ = true;
    partition_->agree(&error);
  }

 private:
  const Partition *partition_;
  bool done_ = false;
};

template <class Body>
int guarded_on(const char *function, const Grid *grid, Body &&body) noexcept {
  return guarded(function, [&] {
    Agreement agreement(grid);
    try {
      body(agreement);
    } catch (const Error &e) {
      agreement.failed(e);
      throw;
    } catch (const std::bad_alloc &) {
      agreement.failed(Error(Status::out_of_memory, "out of memory"));
      throw;
    } catch (const std::exception &e) {
      agreement.failed(Error(Status::internal, e.what()));
      throw;
    }
    agreement.checks_passed();
  });
}

}  // namespace capi
}  // namespace asp
