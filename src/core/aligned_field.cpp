// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/aligned_field.hpp"

#include <fftw3.h>

#include <atomic>
#include <new>

namespace asp {
namespace {
std::atomic<std::int64_t> bytes_in_use{0};
std::atomic<std::int64_t> bytes_peak{0};

void raise_peak(std::int64_t now) {
  std::int64_t peak = bytes_peak.load(std::memory_order_relaxed);
  while (now > peak && !bytes_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}
}  // namespace

std::int64_t field_bytes_in_use() { return bytes_in_use.load(); }
std::int64_t field_bytes_peak() { return bytes_peak.load(); }
void reset_field_bytes_peak() { bytes_peak.store(bytes_in_use.load()); }

void *allocate_field_bytes(std::size_t bytes) {
  void *p = fftw_malloc(bytes == 0 ? 1 : bytes);
  if (p == nullptr) throw std::bad_alloc();
  raise_peak(bytes_in_use.fetch_add(static_cast<std::int64_t>(bytes)) +
             static_cast<std::int64_t>(bytes));
  return p;
}

void free_field_bytes(void *pointer, std::size_t bytes) noexcept {
  if (pointer == nullptr) return;
  fftw_free(pointer);
  bytes_in_use.fetch_sub(static_cast<std::int64_t>(bytes));
}

}  // namespace asp
