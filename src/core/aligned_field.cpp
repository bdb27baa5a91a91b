// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/aligned_field.hpp"

#include <fftw3.h>

#include <atomic>
#include <cstdint>
#include <cstring>
#include <new>

#include "core/loops.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace asp {
namespace {
std::atomic<std::int64_t> bytes_in_use{0};
std::atomic<std::int64_t> bytes_peak{0};
std::atomic<std::int64_t> bytes_limit{0};

void raise_peak(std::int64_t now) {
  std::int64_t peak = bytes_peak.load(std::memory_order_relaxed);
  while (now > peak && !bytes_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}

// Large fields ask the kernel for transparent huge pages (where it grants them on request,
// Linux's default "madvise" mode): a pass or a transform over a field of gigabytes then takes
// one TLB entry and one page fault per 2 MiB instead of per 4 KiB. Fresh pages are faulted in
// when the field is first written, which on a virtual machine dominated setting up a grid of
// 16384^2 (130 s, most of it in the kernel). Only advice: where it is refused, nothing changes.
constexpr std::size_t huge_page_advice_bytes = std::size_t{1} << 24;  // 16 MiB

void advise_huge_pages(void *p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes < huge_page_advice_bytes) return;
  constexpr std::uintptr_t page = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
  if (end > begin) madvise(reinterpret_cast<void *>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

// Fresh pages are faulted in, and cleared by the kernel, where they are first written. When
// std::vector zeroed a solve's work arrays on one thread, that clearing (a fifth of the time
// of a 20-iteration lbfgs_fourier thread-scaling run at 2048^2) ran on one core whatever the
// solve's threads; written in parallel parts, it is shared by them.
void zero_on_loop_threads(void *p, std::size_t bytes) {
  auto *bytes_of = static_cast<unsigned char *>(p);
  constexpr std::int64_t part = std::int64_t{1} << 16;  // 64 KiB
  const auto n = static_cast<std::int64_t>(bytes);
  const std::int64_t parts = (n + part - 1) / part;
  loops::in_pieces(parts, 8, loops::threads_for(n / 8), [&](std::int64_t begin, std::int64_t end) {
    const std::int64_t first = begin * part, last = std::min(n, end * part);
    if (last > first) std::memset(bytes_of + first, 0, static_cast<std::size_t>(last - first));
  });
}
}  // namespace

std::int64_t field_bytes_in_use() { return bytes_in_use.load(); }
std::int64_t field_bytes_peak() { return bytes_peak.load(); }
void reset_field_bytes_peak() { bytes_peak.store(bytes_in_use.load()); }
void set_field_bytes_limit(std::int64_t bytes) { bytes_limit.store(bytes > 0 ? bytes : 0); }

void *allocate_field_bytes(std::size_t bytes) {
  const std::int64_t limit = bytes_limit.load(std::memory_order_relaxed);
  if (limit > 0 && bytes_in_use.load() + static_cast<std::int64_t>(bytes) > limit)
    throw std::bad_alloc();
  void *p = fftw_malloc(bytes == 0 ? 1 : bytes);
  if (p == nullptr) throw std::bad_alloc();
  advise_huge_pages(p, bytes);
  zero_on_loop_threads(p, bytes);
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
