// SPDX-License-Identifier: GPL-2.0-or-later
// The Fourier preconditioner of the gap formulation (see primal_formulation.hpp).
#include "formulations/primal_formulation.hpp"

namespace asp {

bool PrimalFormulation::precondition(double *z) {
  // The scaled Hessian is K/k; its inverse k K^-1 is the compliance times the pixel
  // stiffness k.
  substrate_.surface_compliance(z, z, spectrum_.data(),
                                Substrate::KernelTimes{substrate_.pixel_stiffness()});
  counters_.transforms += 2;
  return true;
}

}  // namespace asp
