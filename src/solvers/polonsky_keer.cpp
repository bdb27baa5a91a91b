// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/polonsky_keer.hpp"

#include <cmath>

#include "formulations/dual_formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/nested_grids.hpp"

namespace asp {
namespace {

// Powell's bound on what the old direction may contribute to the descent before the
// direction restarts (M. J. D. Powell, Math. Programming 12 (1977) 241: 0.2).
constexpr double powell_bound = 0.2;

// The iteration of Polonsky & Keer, on the complementary energy over p >= 0:
//   gap g of p (the gradient); under load control the penetration closes its mean on the
//   contact set I_c; the error is the largest projected gap;
//   t = g + beta t_old on I_c, beta = |g|^2 / |g_old|^2 (g centred), or 0 (steepest
//   descent) where the restart rule asks for it (below), and wherever t would not descend
//   (g.t <= 0);
//   exact line minimum tau = g.t / t.K^-1 t;
//   p = max(p - tau t, 0) on I_c; pixels outside I_c with g < 0 enter with p = -tau g.
// When the direction vanishes although pixels interpenetrate (no contact yet, or a gap
// already uniform on I_c, as after a warm start from a one-pixel contact), those pixels are
// admitted with the pressure that closes their own gap, and descent starts again.
//
// Preconditioned, this is Vollebregt's CG with an FFT-based preconditioner (J. Comput. Phys.
// 257 (2014) 333) with Polonsky & Keer's projection: z = P K P g, the stiffness applied to g
// on the free set N (I_c and the pixels off it with g < 0), restricted to N again and made
// mean-free there under load control; t = z + beta t_old on N with beta = g.z / g_old.z_old,
// and the pixels off I_c enter along t.
//
// The restart rules. Polonsky & Keer restart after every step that let pixels enter I_c
// (restart = entry). On a rough surface the set changes in most early iterations and in many
// late ones, and each restart throws away the conjugate directions built so far. By default
// (restart = powell) the direction restarts only where the old one has lost its
// conjugacy: while I_c stands, the exact line search leaves g orthogonal to t_old, and a
// change of I_c shows as a slope along it; the test is Powell's, |beta g.t_old| > 0.2 g.z
// (z = g without the preconditioner). On the bench scene of docs/performance.md the plain
// counts fall 1.9 times at 1024^2 and 2.8 times at 2048^2, and grow about 1.25 times per
// doubling of the grid instead of 1.8 to 2.4.
void polonsky_keer(DualFormulation &f, Monitor &monitor, bool preconditioned,
                   bool restart_on_entry) {
  const double total = f.total_size();
  double norm_old = 1.0;
  bool conjugate = false;
  const auto direct = [&](double beta) {
    return preconditioned ? f.update_preconditioned_direction(beta) : f.update_direction(beta);
  };
  for (std::int64_t iteration = 0;; ++iteration) {
    const DualFormulation::Gap gap = f.evaluate_gap(monitor.wants_objective());
    const double norm = preconditioned ? f.precondition() : gap.norm;
    const double beta = conjugate ? norm / norm_old : 0.0;
    double error = direct(beta);
    if (beta != 0.0) {
      const double steepest = f.descent() - f.old_slope();  // g.z
      const bool lost =
          !restart_on_entry && std::fabs(f.old_slope()) > powell_bound * steepest;
      if (lost || !(f.descent() > 0.0)) error = direct(0.0);
    }

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
    const bool entered = f.step(f.descent() / curvature);
    conjugate = !(restart_on_entry && entered);
  }
}

void run(System &system, Control control, double value, const OptionValues &options,
         Monitor &monitor) {
  const bool fourier = options.text("preconditioner") != "none";
  DualFormulation formulation(
      system, control, value,
      fourier ? DualSteps::polonsky_keer_fourier : DualSteps::polonsky_keer);
  polonsky_keer(formulation, monitor, fourier, options.text("restart") == "entry");
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
                   "periodic half-space) applied to the gap on the contact set and on the "
                   "pixels off it whose gap is negative, which enter along it, one more "
                   "transform pair per iteration and 12 more bytes per pixel (24 on a free "
                   "substrate) for iterations that grow far less with the grid; none: "
                   "Polonsky & Keer's conjugate gradient, unpreconditioned as published; "
                   "auto: fourier (pk's problem is always the convex one of the hard wall; "
                   "the choice is there as for bugnicourt)"},
                  {"restart", OptionType::choice, 0.0, 0.0, 0.0, false, {"powell", "entry"},
                   "when the conjugate direction restarts from steepest descent: powell, "
                   "where the gap's slope along the old direction shows it no longer "
                   "conjugate (Powell's test, |beta g.t_old| > 0.2 g.z; far fewer iterations "
                   "on rough surfaces, whose contact set changes often); entry, after every "
                   "step that let pixels enter the contact set (Polonsky & Keer as "
                   "published); both restart where the direction would not descend"}};
  // Nested grids by default: pk's problem is the convex one of the hard wall, whose one
  // solution the cascade reaches as a cold solve does, in fewer iterations on the grid
  // itself (38 against 48 at 2048^2 on the bench scene) and less time (0.9 times); below
  // 128 pixels a side "auto" takes no level, and a warm start none either.
  spec.default_levels = levels_auto;
  spec.run = run;
  return spec;
}

}  // namespace asp
