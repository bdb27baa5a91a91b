// SPDX-License-Identifier: GPL-2.0-or-later
// The fields' allocator: it counts what it holds, asks for transparent huge pages for large
// fields (on Linux, where the kernel's per-mapping flags show the request), and hands out
// zeroed memory, written on the loop threads, so that a Field(n) is zero without a second,
// serial pass.
#include <gtest/gtest.h>

#include <complex>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "core/aligned_field.hpp"
#include "core/threads.hpp"
#include "scene.hpp"
#include "sanitizer.hpp"

#if defined(__linux__)
#include <sys/resource.h>
#endif

namespace {

// The VmFlags of the mapping of this process that holds `address` (/proc/self/smaps), or
// "none" if no mapping does, or "" where the file cannot be read.
std::string mapping_flags(const void *address) {
  std::ifstream smaps("/proc/self/smaps");
  if (!smaps) return "";
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  std::string line;
  while (std::getline(smaps, line)) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "none";
}

TEST(FieldAllocator, CountsTheBytesItHolds) {
  const std::int64_t before = asp::field_bytes_in_use();
  {
    const asp::Field f(1000);
    EXPECT_EQ(asp::field_bytes_in_use() - before, 8000);
    EXPECT_GE(asp::field_bytes_peak() - before, 8000);
  }
  EXPECT_EQ(asp::field_bytes_in_use(), before);
}

// A field of 64 MiB is advised for huge pages ("hg" among the flags of the mapping that holds
// its middle: the advice starts at the first whole page of the field); one of 64 KiB is not
// (it shares the heap with small allocations, whose pages are not the field's).
TEST(FieldAllocator, AsksForHugePagesForLargeFields) {
  const asp::Field large(std::size_t{8} << 20);
  const std::string flags = mapping_flags(large.data() + large.size() / 2);
  if (flags.empty() || flags == "none") GTEST_SKIP() << "no /proc/self/smaps on this system";
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  const asp::Field small(std::size_t{8} << 10);
  const std::string small_flags = mapping_flags(small.data());
  EXPECT_EQ(small_flags.find(" hg"), std::string::npos) << small_flags;
}

// Value-initialised elements are zero, on one thread or several, small or large, also where
// the memory held other values before (a freed field's); elements given a value have it.
TEST(FieldAllocator, ValueInitialisedFieldsAreZero) {
  for (int threads : {1, 2}) {
    const asp::ThreadScope scope(threads);
    for (std::size_t n : {std::size_t{1}, std::size_t{1000}, std::size_t{3} << 20}) {
      for (int round = 0; round < 2; ++round) {
        asp::Field f(n);
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(f[i], 0.0) << threads << " " << n << " " << i;
        for (std::size_t i = 0; i < n; ++i) f[i] = -1.5;  // what the next round's memory may hold
      }
      const asp::Field filled(n, 2.5);
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(filled[i], 2.5) << i;
      const asp::Spectrum spectrum(n);
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(spectrum[i], std::complex<double>(0.0)) << i;
    }
  }
}

// Many small solves, as a finite-element code makes them, fault no fresh pages once the first
// has run: the work arrays a solve frees are kept by its thread for the next one. Without
// that, each warm lbfgs_fourier solve of this 64^2 scene after a small change of the
// penetration made and gave back close to 1 MiB of arrays (its memory's pairs among them),
// which glibc returned to the kernel and the next solve faulted in again: about 6700 page
// faults in 100 solves. The bound, one fault per solve on average, leaves room for the odd
// page of the process's other allocations. Linux only (RUSAGE_THREAD).
TEST(FieldAllocator, WarmSmallSolvesFaultNoFreshPages) {
#ifdef ASPERITY_TEST_UNDER_ASAN
  GTEST_SKIP() << "under AddressSanitizer no freed field is kept (a use after free stays caught)";
#endif
#if defined(__linux__) && defined(RUSAGE_THREAD)
  auto grid = asp_test::grid_2d(64, 64, 64.0, 64.0);
  grid->set_threads(1);
  asp::System system(grid, 1.0);
  const std::vector<double> h = asp_test::rough_surface(*grid, 3, 0.1, 0.5, 2.0);
  system.set_topography(h.data());
  system.set_soft_wall(0.05, 0.3, 0.01, 0.3);
  asp::Solver solver("lbfgs_fourier");
  solver.solve(system, asp::Control::penetration, -0.45);
  ASSERT_TRUE(solver.report().converged());
  const auto faults = [] {
    rusage usage{};
    getrusage(RUSAGE_THREAD, &usage);
    return usage.ru_minflt + usage.ru_majflt;
  };
  const int solves = 100;
  const long before = faults();
  for (int k = 0; k < solves; ++k)
    solver.solve(system, asp::Control::penetration, k % 2 == 0 ? -0.4505 : -0.45);
  const long after = faults();
  EXPECT_LT(after - before, solves);
#else
  GTEST_SKIP() << "no per-thread fault counts on this system";
#endif
}

}  // namespace
