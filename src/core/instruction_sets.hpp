// SPDX-License-Identifier: GPL-2.0-or-later
// Kernels compiled for more than the build's instruction set, chosen when the library runs.
//
// The library is built for the x86-64 baseline (SSE2), as a Debian package must be. A pass
// whose arithmetic, not its memory traffic, sets its time can carry a second variant compiled
// for AVX2 with fused multiply-adds: the same source, inlined into a function with GCC's and
// Clang's `target` attribute, and called only where the CPU reports both. Such a variant rounds
// differently (fused products, wider partial sums), so its results depend on the CPU, as
// FFTW's do (it picks its codelets by the CPU too); never on the thread count.
//
// Only a few kernels need this: the element-wise passes of the solvers stream their fields
// from memory at any width (a build with -march=native is no faster there).
#pragma once

// ASP_KERNEL_VARIANTS is 1 where variants are compiled (GCC or Clang on x86-64), 0 elsewhere.
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(_M_X64))
#define ASP_KERNEL_VARIANTS 1
// A function compiled for AVX2 and FMA.
#define ASP_TARGET_AVX2_FMA __attribute__((target("avx2,fma")))
// A kernel's one source, inlined into each variant's function.
#define ASP_KERNEL_BODY inline __attribute__((always_inline))
#else
#define ASP_KERNEL_VARIANTS 0
#define ASP_KERNEL_BODY inline
#endif

namespace asp {

enum class KernelVariant { baseline, avx2_fma };

// Whether this CPU runs the variant (the baseline: always).
bool cpu_runs(KernelVariant variant);

// The fastest variant this CPU runs, asked once.
KernelVariant best_kernel_variant();

}  // namespace asp
