// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/instruction_sets.hpp"

namespace asp {

bool cpu_runs(KernelVariant variant) {
  switch (variant) {
    case KernelVariant::baseline:
      return true;
    case KernelVariant::avx2_fma:
#if ASP_KERNEL_VARIANTS
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
      return false;
#endif
  }
  return false;
}

KernelVariant best_kernel_variant() {
  static const KernelVariant best =
      cpu_runs(KernelVariant::avx2_fma) ? KernelVariant::avx2_fma : KernelVariant::baseline;
  return best;
}

}  // namespace asp
