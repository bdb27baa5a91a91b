// Polonsky & Keer's constrained conjugate gradient (Wear 231, 1999; thesis section 3.1.1,
// Alg. 3) for the hard-wall, non-adhesive contact, on the pressure (the dual variable).
//
// It minimises the complementary energy (a/2) p.K^-1 p - a p.(h - max h + delta) over p >= 0,
// whose gradient is a times the gap. Under mean-pressure control the mean of p is fixed and
// the penetration delta is the Lagrange multiplier, found by centring the gap on the contact
// set each iteration. Conjugation is dropped (steepest descent) whenever a pixel enters the
// contact set.
#pragma once

#include "solvers/solver.hpp"

namespace asp {

class PolonskyKeer final : public Solver {
 public:
  const char *name() const override { return "pk"; }
  bool supports(Control control) const override {
    return control == Control::mean_pressure || control == Control::penetration;
  }

 protected:
  void run(System &system, Control control, double value, SolveReport &report) override;
  void check_target(Control control, double value) const override;
};

}  // namespace asp
