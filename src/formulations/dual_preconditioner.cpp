// SPDX-License-Identifier: GPL-2.0-or-later
// The Fourier preconditioner of Polonsky & Keer's iteration (see dual_formulation.hpp).
#include "core/loops.hpp"
#include "formulations/dual_formulation.hpp"

namespace asp {

double DualFormulation::precondition() {
  double *z = preconditioned_.data();
  const double *g = state_.gap.data();
  const double *p = state_.pressure.data();
  const double *t = direction_.data();
  const double shift = shift_;
  // r = g - shift on the free set N (the contact set and the pixels off it whose gap is
  // negative), 0 elsewhere (and outside the box on a free substrate, which the transform pads
  // with zeros).
  loops::for_each(n_, [&](std::int64_t i) {
    const double gi = g[i] - shift;
    z[i] = in_free_set(p[i], gi) ? gi : 0.0;
  });
  // The work spectrum that precondition() takes is free here: the gap's transform is done,
  // and curvature() transforms the new direction into it afterwards.
  precondition(z);

  // z restricted to N: its sum there (for its mean), r.z, the old direction's sum there, and
  // the size of N. Off N z is left as it came; update_preconditioned_direction reads it only
  // on N.
  const auto sums = loops::sums<5>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
    const double gi = g[i] - shift;
    const bool in = in_free_set(p[i], gi);
    const double r = in ? gi : 0.0;
    const double zi = in ? z[i] : 0.0;
    sum[0] += zi;
    sum[1] += r * zi;
    sum[2] += r;
    sum[3] += in ? t[i] : 0.0;
    sum[4] += in ? 1.0 : 0.0;
  });
  const bool centred = control_ == Control::mean_pressure && sums[4] > 0.0;
  preconditioned_mean_ = centred ? sums[0] / sums[4] : 0.0;
  free_direction_mean_ = centred ? sums[3] / sums[4] : 0.0;
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
