// SPDX-License-Identifier: GPL-2.0-or-later
// Status strings, the thread-local error message and the version queries.
#include <string>

#include "capi/firewall.hpp"

namespace asp {
namespace capi {
namespace {
thread_local std::string last_error;
}

void clear_last_error() noexcept { last_error.clear(); }

int record_error(int status, const char *function, const char *message) noexcept {
  try {
    last_error = std::string(function) + ": " + message;
  } catch (...) {
    last_error.clear();  // out of memory while reporting: the status still says what failed
  }
  return status;
}

}  // namespace capi
}  // namespace asp

extern "C" {

const char *asp_status_string(int status) {
  switch (status) {
    case ASP_OK: return "success";
    case ASP_ERR_NULL_POINTER: return "a required pointer argument is NULL";
    case ASP_ERR_INVALID_ARGUMENT: return "invalid argument";
    case ASP_ERR_SIZE_MISMATCH: return "size or count does not match what the call needs";
    case ASP_ERR_OUT_OF_MEMORY: return "out of memory";
    case ASP_ERR_UNSUPPORTED: return "not supported";
    case ASP_ERR_INVALID_STATE: return "call not valid in the current state";
    case ASP_ERR_FFT: return "FFT planning failed";
    case ASP_ERR_CALLBACK: return "a user callback reported failure";
    case ASP_ERR_INTERNAL: return "internal error";
    case ASP_ERR_IO: return "a file could not be read or written";
    default: return "unknown status";
  }
}

const char *asp_last_error_message(void) { return asp::capi::last_error.c_str(); }

const char *asp_version_string(void) { return ASP_VERSION_STRING; }

int asp_abi_version(void) { return ASP_ABI_VERSION; }

}  // extern "C"
