// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/stiffness_law.hpp"

#include <cfloat>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {

LayerLaw::LayerLaw(double contact_modulus, double poisson_ratio, double thickness)
    : modulus_(contact_modulus), poisson_(poisson_ratio), thickness_(thickness) {
  require_positive(contact_modulus, "contact_modulus");
  require_positive(thickness, "thickness");
  require_finite(poisson_ratio, "poisson_ratio");
  if (!(poisson_ratio >= 0.0 && poisson_ratio < 0.5))
    throw Error(Status::invalid_argument,
                "argument 'poisson_ratio' is " + format_number(poisson_ratio) +
                    ": a layer on a rigid base takes 0 <= nu < 1/2 (at nu = 1/2 the bonded, "
                    "incompressible layer cannot be compressed: its K~(0) is infinite)");
  const double nu = poisson_ratio;
  const double young = contact_modulus * (1.0 - nu * nu);
  uniaxial_modulus_ = young * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double k0 = uniaxial_modulus_ / thickness;
  if (!std::isfinite(k0) || k0 < DBL_MIN)
    throw Error(Status::invalid_argument,
                "argument 'thickness' is " + format_number(thickness) +
                    ": the layer's stiffness M/t under a uniform pressure would be " +
                    format_number(k0) + ", not a finite, normal double; rescale the units");
}

double LayerLaw::at(double q) const {
  const double kappa = 3.0 - 4.0 * poisson_;
  const double c = 0.5 * (1.0 + kappa * kappa);
  const double s = q * thickness_;
  if (s < 0.5) {
    // K~ = E* N/(4t (kappa - 1 + kappa f)) with N = kappa cosh 2s + 2s^2 + c and
    // f = (sinh y - y)/y, y = 2s, from its series: sinh 2s - 2s would cancel, and
    // kappa - 1 = 2(1 - 2 nu) may itself be small. Twelve terms leave less than 1e-20 of f
    // for y < 1.
    const double y = 2.0 * s, y2 = y * y;
    double term = 1.0, f = 0.0;
    for (int k = 1; k <= 12; ++k) {
      term *= y2 / ((2.0 * k) * (2.0 * k + 1.0));
      f += term;
    }
    const double n = kappa * std::cosh(y) + 2.0 * s * s + c;
    return modulus_ * n / (4.0 * thickness_ * (kappa - 1.0 + kappa * f));
  }
  // The ratio with numerator and denominator multiplied by 2 exp(-2s), so that nothing
  // overflows: both are of order kappa for s >= 1/2, without cancellation there.
  const double x = std::exp(-2.0 * s);
  if (x == 0.0) return 0.5 * modulus_ * q;  // s^2 exp(-2s) below any rounding
  const double numerator = kappa * (1.0 + x * x) + 2.0 * (2.0 * s * s + c) * x;
  const double denominator = kappa * (1.0 - x * x) - 4.0 * s * x;
  return 0.5 * modulus_ * q * (numerator / denominator);
}

}  // namespace asp
