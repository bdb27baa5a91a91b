// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/formulation.hpp"

#include "core/loops.hpp"

namespace asp {

void Formulation::project(double *x) const {
  const std::int64_t bounded = bounded_size();
  const double lower = lower_bound();
  // The bound, and the sum that the mean needs, in one pass.
  const double sum = loops::sum(reductions(), bounded, [&](std::int64_t i) {
    x[i] = x[i] > lower ? x[i] : lower;
    return x[i];
  });
  if (!constrains_mean()) return;
  const double target = mean_target();
  if (!(sum > 0.0)) {
    loops::for_each(bounded, [&](std::int64_t i) { x[i] = target; });
    return;
  }
  double total = static_cast<double>(bounded);
  reductions().combine_sums(&total, 1);
  const double scale = target * total / sum;
  loops::for_each(bounded, [&](std::int64_t i) { x[i] *= scale; });
}

}  // namespace asp
