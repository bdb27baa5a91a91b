// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/substrate.hpp"

#include <complex>

namespace asp {

const char *substrate_name(SubstrateKind kind) {
  switch (kind) {
    case SubstrateKind::periodic: return "periodic half-space";
    case SubstrateKind::free: return "free half-space";
  }
  return "unknown";
}

double kernel_times_summing(const Reductions &reductions, const SpectralLayout &layout,
                            Complex *s, const double *kernel, double factor) {
  const auto energy = [&](std::int64_t q) { return kernel[q] * std::norm(s[q]); };
  double singles = layout.single_entries_sum(energy);
  reductions.combine_sums(&singles, 1);
  const double all = loops::sums<1>(reductions, layout.size(), [&](std::int64_t q, double *sum) {
                       sum[0] += energy(q);
                       s[q] *= factor * kernel[q];
                     })[0];
  return factor * (2.0 * all - singles);
}

}  // namespace asp
