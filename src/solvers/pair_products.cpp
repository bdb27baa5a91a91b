// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/pair_products.hpp"

namespace asp {
namespace {

// The kernel's one source. Each block of s and y is formed, then met by every stored pair
// while it is in cache, so that each field is read once from memory. The loops work on local
// copies of the pointers, so that GCC vectorises them as plain loads.
ASP_KERNEL_BODY void pair_products_body(const PairBlock &block, std::int64_t begin,
                                        std::int64_t end, double *sum) {
  const double *__restrict x = block.x;
  const double *__restrict g = block.g;
  double *__restrict s = block.s;
  double *__restrict y = block.y;
  const int own = 6 * block.stored;
  double ss = 0.0, sy = 0.0, yy = 0.0, gs = 0.0, gy = 0.0;
#pragma omp simd reduction(+ : ss, sy, yy, gs, gy)
  for (std::int64_t i = begin; i < end; ++i) {
    const double si = x[i] - s[i], yi = g[i] - y[i];
    s[i] = si;
    y[i] = yi;
    ss += si * si;
    sy += si * yi;
    yy += yi * yi;
    gs += g[i] * si;
    gy += g[i] * yi;
  }
  sum[own] += ss;
  sum[own + 1] += sy;
  sum[own + 2] += yy;
  sum[own + 3] += gs;
  sum[own + 4] += gy;
  for (int j = 0; j < block.stored; ++j) {
    const double *__restrict sj = block.stored_s[j];
    const double *__restrict yj = block.stored_y[j];
    double a = 0.0, b = 0.0, c = 0.0, d = 0.0, e = 0.0, f = 0.0;
#pragma omp simd reduction(+ : a, b, c, d, e, f)
    for (std::int64_t i = begin; i < end; ++i) {
      a += s[i] * sj[i];
      b += s[i] * yj[i];
      c += y[i] * sj[i];
      d += y[i] * yj[i];
      e += g[i] * sj[i];
      f += g[i] * yj[i];
    }
    double *out = sum + 6 * j;
    out[0] += a;
    out[1] += b;
    out[2] += c;
    out[3] += d;
    out[4] += e;
    out[5] += f;
  }
}

void pair_products_baseline(const PairBlock &block, std::int64_t begin, std::int64_t end,
                            double *sum) {
  pair_products_body(block, begin, end, sum);
}

#if ASP_KERNEL_VARIANTS
ASP_TARGET_AVX2_FMA void pair_products_avx2_fma(const PairBlock &block, std::int64_t begin,
                                                std::int64_t end, double *sum) {
  pair_products_body(block, begin, end, sum);
}
#endif

}  // namespace

PairProducts pair_products(KernelVariant variant) {
#if ASP_KERNEL_VARIANTS
  if (variant == KernelVariant::avx2_fma) return pair_products_avx2_fma;
#else
  (void)variant;
#endif
  return pair_products_baseline;
}

}  // namespace asp
