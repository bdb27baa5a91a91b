// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/polonsky_keer.hpp"

#include "solvers/dual_formulation.hpp"
#include "solvers/solver.hpp"

namespace asp {
namespace {

// The iteration of Polonsky & Keer, on the complementary energy over p >= 0:
//   gap g of p (the gradient); under load control the penetration closes its mean on the
//   contact set I_c; the error is the largest projected gap;
//   t = g + beta t_old on I_c, beta = |g|^2/|g_old|^2, or 0 (steepest descent) right after
//   pixels entered I_c;
//   exact line minimum tau = g.t / t.K^-1 t;
//   p = max(p - tau t, 0) on I_c; pixels outside I_c with g < 0 enter with p = -tau g.
// When the direction vanishes although pixels interpenetrate (no contact yet, or a gap
// already uniform on I_c, as after a warm start from a one-pixel contact), those pixels are
// admitted with the pressure that closes their own gap, and descent starts again.
void polonsky_keer(DualFormulation &f, Monitor &monitor) {
  const double total = f.total_size();
  double gap_norm_old = 1.0;
  bool conjugate = false;
  for (std::int64_t iteration = 0;; ++iteration) {
    const DualFormulation::Gap gap = f.evaluate_gap(monitor.wants_objective());
    const double beta = conjugate ? gap.norm / gap_norm_old : 0.0;
    const double error = f.update_direction(beta);

    IterationState state;
    state.error = error;
    state.objective = gap.objective * f.energy_unit();
    state.contact_fraction = gap.contacts / total;
    state.evaluations = f.counters().evaluations;
    state.transforms = f.counters().transforms;
    if (monitor.should_stop(iteration, state)) return;
    gap_norm_old = gap.norm;

    const double curvature = gap.contacts > 0.0 ? f.curvature() : 0.0;
    if (!(curvature > 0.0)) {
      f.admit_interpenetrating_pixels();
      conjugate = false;
      continue;
    }
    conjugate = !f.step(f.descent() / curvature);
  }
}

void run(System &system, Control control, double value, const OptionValues &, Monitor &monitor) {
  DualFormulation formulation(system, control, value, DualSteps::polonsky_keer);
  polonsky_keer(formulation, monitor);
  conclude(formulation, system, monitor);
}

}  // namespace

AlgorithmSpec polonsky_keer_algorithm() {
  AlgorithmSpec spec;
  spec.name = "pk";
  spec.summary =
      "Polonsky & Keer's constrained conjugate gradient on the pressure (thesis section "
      "3.1.1, Alg. 3); the objective is the complementary energy, minus the elastic energy "
      "(q = 0 term included) at the solution";
  spec.controls = {Control::mean_pressure, Control::penetration};
  spec.substrates = {SubstrateKind::periodic, SubstrateKind::free};
  spec.interactions = {InteractionKind::hard_wall};
  spec.run = run;
  return spec;
}

}  // namespace asp
