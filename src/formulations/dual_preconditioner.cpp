// SPDX-License-Identifier: GPL-2.0-or-later
// The Fourier preconditioner of Polonsky & Keer's iteration (see dual_formulation.hpp).
#include "core/loops.hpp"
#include "formulations/dual_formulation.hpp"

namespace asp {

double DualFormulation::precondition() {
  double *z = preconditioned_.data();
  const double *g = state_.gap.data();
  const double *p = state_.pressure.data();
  const double shift = shift_;
  // r = g - shift on the contact set, 0 elsewhere (and outside the box on a free substrate,
  // which the transform pads with zeros).
  loops::for_each(n_, [&](std::int64_t i) { z[i] = p[i] > 0.0 ? g[i] - shift : 0.0; });
  // The work spectrum that precondition() takes is free here: the gap's transform is done,
  // and curvature() transforms the new direction into it afterwards.
  precondition(z);

  // z restricted to the contact set: its sum there (for its mean) and r.z. Off the contact
  // set z is left as it came; update_preconditioned_direction reads it only on the set.
  const auto sums = loops::sums<3>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
    const bool in = p[i] > 0.0;
    const double r = in ? g[i] - shift : 0.0;
    const double zi = in ? z[i] : 0.0;
    sum[0] += zi;
    sum[1] += r * zi;
    sum[2] += r;
  });
  preconditioned_mean_ =
      control_ == Control::mean_pressure && contacts_ > 0.0 ? sums[0] / contacts_ : 0.0;
  // r.(z - mean) exactly, although sum r vanishes only up to rounding.
  return sums[1] - preconditioned_mean_ * sums[2];
}

bool DualFormulation::precondition(double *z) {
  // The scaled Hessian is k K^-1 (k the compliance factor); its inverse is K/k.
  linear_update_ready_ = false;  // the work spectrum is overwritten, as in hessian_product
  substrate_.grid_stiffness(z, z, spectrum_.data(),
                            Substrate::KernelTimes{1.0 / compliance_factor_});
  counters_.transforms += 2;
  return true;
}

}  // namespace asp
