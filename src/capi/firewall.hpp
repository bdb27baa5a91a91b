// SPDX-License-Identifier: GPL-2.0-or-later
// The exception firewall of the C API: every entry point runs its body through guarded(),
// which turns any C++ exception into a status code and a thread-local message naming the
// function. Nothing escapes into C.
#pragma once

#include <new>
#include <stdexcept>
#include <string>

#include "asperity/asperity.h"
#include "core/error.hpp"

namespace asp {
namespace capi {

void clear_last_error() noexcept;
int record_error(int status, const char *function, const char *message) noexcept;

template <class Body>
int guarded(const char *function, Body &&body) noexcept {
  try {
    clear_last_error();
    body();
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

}  // namespace capi
}  // namespace asp
