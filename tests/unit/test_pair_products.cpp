// SPDX-License-Identifier: GPL-2.0-or-later
// The products that enter a new pair into L-BFGS-B's compact matrix, in each variant this
// CPU runs (baseline SSE2; AVX2 with FMA): against sums in long double, and s and y exact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "solvers/pair_products.hpp"

namespace {

using asp::KernelVariant;

struct Fields {
  std::vector<double> x, x_old, g, g_old;
  std::vector<std::vector<double>> s, y;
};

// Entries in [0.5, 1.5] (steps) and [-1.5, -0.5] (old values), so that every product is
// positive and a sum's rounding is at most n epsilon times the sum.
Fields random_fields(std::int64_t n, int stored) {
  asp::Random random(7);
  const auto field = [&](double offset) {
    std::vector<double> f(static_cast<std::size_t>(n));
    for (double &v : f) v = offset + random.uniform();
    return f;
  };
  Fields f{field(0.5), field(-1.5), field(0.5), field(-1.5), {}, {}};
  for (int j = 0; j < stored; ++j) {
    f.s.push_back(field(0.5));
    f.y.push_back(field(0.5));
  }
  return f;
}

void expect_products(KernelVariant variant, const std::string &name) {
  // An odd length, so that the vector loops' remainders are summed too; two blocks.
  constexpr std::int64_t n = 4099, middle = 2050;
  constexpr int stored = 3;
  Fields f = random_fields(n, stored);
  const Fields before = f;
  std::vector<const double *> stored_s, stored_y;
  for (int j = 0; j < stored; ++j) {
    stored_s.push_back(f.s[j].data());
    stored_y.push_back(f.y[j].data());
  }
  const asp::PairBlock block{f.x.data(),      f.g.data(),      f.x_old.data(), f.g_old.data(),
                             stored_s.data(), stored_y.data(), stored};
  std::vector<double> sum(6 * stored + 5, 0.0);
  const asp::PairProducts products = asp::pair_products(variant);
  products(block, 0, middle, sum.data());
  products(block, middle, n, sum.data());

  std::vector<long double> expected(sum.size(), 0.0L);
  for (std::int64_t i = 0; i < n; ++i) {
    const long double s = static_cast<long double>(before.x[i]) - before.x_old[i];
    const long double y = static_cast<long double>(before.g[i]) - before.g_old[i];
    const long double g = before.g[i];
    // x - x_old is exact in either variant (both subtract the same doubles).
    ASSERT_EQ(f.x_old[i], before.x[i] - before.x_old[i]) << name << " s at " << i;
    ASSERT_EQ(f.g_old[i], before.g[i] - before.g_old[i]) << name << " y at " << i;
    for (int j = 0; j < stored; ++j) {
      long double *out = &expected[6 * j];
      out[0] += s * before.s[j][i];
      out[1] += s * before.y[j][i];
      out[2] += y * before.s[j][i];
      out[3] += y * before.y[j][i];
      out[4] += g * before.s[j][i];
      out[5] += g * before.y[j][i];
    }
    long double *own = &expected[6 * stored];
    own[0] += s * s;
    own[1] += s * y;
    own[2] += y * y;
    own[3] += g * s;
    own[4] += g * y;
  }
  // Every term is positive, so the relative error of a sum is at most that of its worst
  // term: one subtraction (s or y), one product and n - 1 additions, (n + 1) epsilon to
  // first order.
  const double bound = (n + 2) * std::numeric_limits<double>::epsilon();
  for (std::size_t e = 0; e < sum.size(); ++e) {
    const double exact = static_cast<double>(expected[e]);
    EXPECT_NEAR(sum[e], exact, bound * exact) << name << " sum " << e;
  }
}

TEST(PairProducts, BaselineKernelMatchesSumsInLongDouble) {
  expect_products(KernelVariant::baseline, "baseline");
}

TEST(PairProducts, Avx2FmaKernelMatchesSumsInLongDouble) {
  if (!asp::cpu_runs(KernelVariant::avx2_fma)) GTEST_SKIP() << "this CPU has no AVX2 and FMA";
  expect_products(KernelVariant::avx2_fma, "avx2_fma");
}

TEST(PairProducts, TheBestVariantIsOneThisCpuRuns) {
  EXPECT_TRUE(asp::cpu_runs(asp::best_kernel_variant()));
  EXPECT_TRUE(asp::cpu_runs(KernelVariant::baseline));
}

}  // namespace
