// SPDX-License-Identifier: GPL-2.0-or-later
// The Fourier preconditioner of the gap formulation (see primal_formulation.hpp).
#include "core/loops.hpp"
#include "formulations/primal_formulation.hpp"

namespace asp {

bool PrimalFormulation::precondition(double *z) {
  // The scaled Hessian is K/k; its inverse k K^-1 is the normalised compliance (which
  // carries the transform's 1/N) times the pixel stiffness k.
  substrate_.surface_forward(z, spectrum_.data());
  Complex *s = spectrum_.data();
  const double *c = substrate_.normalised_compliance().data();
  const double factor = substrate_.pixel_stiffness();
  loops::for_each(static_cast<std::int64_t>(spectrum_.size()),
                  [&](std::int64_t q) { s[q] *= factor * c[q]; });
  substrate_.surface_backward(spectrum_.data(), z);
  counters_.transforms += 2;
  return true;
}

}  // namespace asp
