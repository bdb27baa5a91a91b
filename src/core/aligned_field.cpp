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

// The blocks of small fields that a thread freed, kept for its next fields of the same size. A
// finite-element code solves a small system at each of thousands of integration points, and
// every solve makes and frees the same work arrays: through malloc each time, glibc gave the
// top of its heap back to the kernel once 128 KiB were free, and the next solve faulted the
// pages in again (a warm lbfgs_fourier solve of a 64^2 grid that starts converged spent 40 %
// of its time making its arrays, most of it in the kernel). Blocks of at most
// cached_block_bytes (a field of 362^2, a spectrum of 256^2) are kept, at most
// cached_bytes_per_thread in all per thread, and freed when the thread ends; larger fields
// go straight back, as before. Under AddressSanitizer nothing is kept, so that a field used
// after it was freed is still caught.
#if defined(__SANITIZE_ADDRESS__)
#define ASPERITY_KEEP_FREED_FIELDS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ASPERITY_KEEP_FREED_FIELDS 0
#endif
#endif
#ifndef ASPERITY_KEEP_FREED_FIELDS
#define ASPERITY_KEEP_FREED_FIELDS 1
#endif
#if ASPERITY_KEEP_FREED_FIELDS
constexpr std::size_t cached_block_bytes = std::size_t{1} << 20;        // 1 MiB
constexpr std::size_t cached_bytes_per_thread = std::size_t{8} << 20;   // 8 MiB
constexpr int cached_blocks_per_thread = 64;

// Trivially destructible, so that it can be used until its thread has ended: a field freed
// after the thread's blocks were given back (by a destructor that runs as the thread ends, or
// as the process exits) goes straight back.
struct FreedBlocks {
  struct Block {
    void *pointer;
    std::size_t bytes;
  };
  Block blocks[cached_blocks_per_thread];
  int count;
  std::size_t kept_bytes;
  bool closed;

  // A kept block of exactly this size, or null.
  void *take(std::size_t bytes) {
    for (int k = count - 1; k >= 0; --k) {
      if (blocks[k].bytes != bytes) continue;
      void *p = blocks[k].pointer;
      blocks[k] = blocks[--count];
      kept_bytes -= bytes;
      return p;
    }
    return nullptr;
  }
  // Whether the block is kept (else the caller frees it).
  bool keep(void *pointer, std::size_t bytes);
  void give_back() {
    for (int k = 0; k < count; ++k) fftw_free(blocks[k].pointer);
    count = 0;
    kept_bytes = 0;
    closed = true;
  }
};

thread_local FreedBlocks freed_blocks = {};
// Gives the thread's blocks back when it ends; made on the thread's first kept block.
struct FreedBlocksOwner {
  bool armed = false;
  ~FreedBlocksOwner() { freed_blocks.give_back(); }
};
thread_local FreedBlocksOwner freed_blocks_owner;

bool FreedBlocks::keep(void *pointer, std::size_t bytes) {
  if (closed || bytes > cached_block_bytes || count == cached_blocks_per_thread ||
      kept_bytes + bytes > cached_bytes_per_thread)
    return false;
  freed_blocks_owner.armed = true;
  blocks[count++] = {pointer, bytes};
  kept_bytes += bytes;
  return true;
}
#endif
}  // namespace

std::int64_t field_bytes_in_use() { return bytes_in_use.load(); }
std::int64_t field_bytes_peak() { return bytes_peak.load(); }
void reset_field_bytes_peak() { bytes_peak.store(bytes_in_use.load()); }
void set_field_bytes_limit(std::int64_t bytes) { bytes_limit.store(bytes > 0 ? bytes : 0); }

void *allocate_field_bytes(std::size_t bytes) {
  const std::int64_t limit = bytes_limit.load(std::memory_order_relaxed);
  if (limit > 0 && bytes_in_use.load() + static_cast<std::int64_t>(bytes) > limit)
    throw std::bad_alloc();
  void *p = nullptr;
#if ASPERITY_KEEP_FREED_FIELDS
  if (bytes <= cached_block_bytes) p = freed_blocks.take(bytes == 0 ? 1 : bytes);
#endif
  if (p != nullptr) {
    std::memset(p, 0, bytes);  // at most 1 MiB, whose pages are in memory already: one thread
  } else {
    p = fftw_malloc(bytes == 0 ? 1 : bytes);
    if (p == nullptr) throw std::bad_alloc();
    advise_huge_pages(p, bytes);
    zero_on_loop_threads(p, bytes);
  }
  raise_peak(bytes_in_use.fetch_add(static_cast<std::int64_t>(bytes)) +
             static_cast<std::int64_t>(bytes));
  return p;
}

void free_field_bytes(void *pointer, std::size_t bytes) noexcept {
  if (pointer == nullptr) return;
  bytes_in_use.fetch_sub(static_cast<std::int64_t>(bytes));
#if ASPERITY_KEEP_FREED_FIELDS
  if (freed_blocks.keep(pointer, bytes == 0 ? 1 : bytes)) return;
#endif
  fftw_free(pointer);
}

}  // namespace asp
