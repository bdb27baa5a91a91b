// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/polonsky_keer.hpp"

#include "formulations/dual_formulation.hpp"
#include "solvers/monitor.hpp"

namespace asp {
namespace {

// The iteration of Polonsky & Keer, on the complementary energy over p >= 0:
//   gap g of p (the gradient); under load control the penetration closes its mean on the
//   contact set I_c; the error is the largest projected gap;
//   with the Fourier preconditioner, z = P K P g, the stiffness applied to g restricted to
//   I_c, restricted again (and made mean-free there under load control); without it z = g;
//   t = z + beta t_old on I_c, beta = g.z / g_old.z_old, or 0 (steepest descent) right after
//   pixels entered I_c;
//   exact line minimum tau = g.t / t.K^-1 t;
//   p = max(p - tau t, 0) on I_c; pixels outside I_c with g < 0 enter with p = -tau g.
// When the direction vanishes although pixels interpenetrate (no contact yet, or a gap
// already uniform on I_c, as after a warm start from a one-pixel contact), those pixels are
// admitted with the pressure that closes their own gap, and descent starts again.
// Preconditioned, this is Vollebregt's CG with an FFT-based preconditioner (J. Comput. Phys.
// 257 (2014) 333) with Polonsky & Keer's projection and restart.
void polonsky_keer(DualFormulation &f, Monitor &monitor, bool preconditioned) {
  const double total = f.total_size();
  double norm_old = 1.0;
  bool conjugate = false;
  for (std::int64_t iteration = 0;; ++iteration) {
    const DualFormulation::Gap gap = f.evaluate_gap(monitor.wants_objective());
    const double norm = preconditioned ? f.precondition() : gap.norm;
    const double beta = conjugate ? norm / norm_old : 0.0;
    const double error =
        preconditioned ? f.update_preconditioned_direction(beta) : f.update_direction(beta);

    IterationState state;
    state.error = error;
    state.objective = gap.objective * f.energy_unit();
    state.contact_fraction = gap.contacts / total;
    state.evaluations = f.counters().evaluations;
    state.transforms = f.counters().transforms;
    if (monitor.should_stop(iteration, state)) return;
    norm_old = norm;

    const double curvature = gap.contacts > 0.0 ? f.curvature() : 0.0;
    if (!(curvature > 0.0)) {
      f.admit_interpenetrating_pixels();
      conjugate = false;
      continue;
    }
    conjugate = !f.step(f.descent() / curvature);
  }
}

void run(System &system, Control control, double value, const OptionValues &options,
         Monitor &monitor) {
  const bool fourier = options.text("preconditioner") != "none";
  DualFormulation formulation(
      system, control, value,
      fourier ? DualSteps::polonsky_keer_fourier : DualSteps::polonsky_keer);
  polonsky_keer(formulation, monitor, fourier);
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
  spec.interactions = {InteractionFamily::hard_wall};
  spec.options = {{"preconditioner", OptionType::choice, 0.0, 0.0, 0.0, false,
                   {"auto", "fourier", "none"},
                   "fourier: preconditioned by the substrate's stiffness (E*|q|/2 on a "
                   "periodic half-space) applied to the gap on the contact set, one more "
                   "transform pair per iteration and 12 more bytes per pixel (24 on a free "
                   "substrate) for iterations "
                   "that grow far less with the grid; none: Polonsky & Keer's conjugate "
                   "gradient as published; auto: fourier (pk's problem is always the convex "
                   "one of the hard wall; the choice is there as for bugnicourt)"}};
  spec.run = run;
  return spec;
}

}  // namespace asp
