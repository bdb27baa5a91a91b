// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/bugnicourt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "solvers/bugnicourt_passes.hpp"
#include "formulations/dual_formulation.hpp"
#include "formulations/primal_formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/nested_grids.hpp"
#include "solvers/range_continuation.hpp"

namespace asp {
namespace {

// Gradients followed from Hessian products between two evaluations: rounding grows with
// their number, and an evaluation costs one FFT pair.
constexpr int updates_between_evaluations = 32;

// Halvings of a step of the objective that is not quadratic that still raises it; 2^-30 of
// the step is far below what would still change the iterate.
constexpr int max_halvings = 30;

// The preconditioned step along a direction of negative curvature, in multiples of the safe
// step (below): inside the interval (0, 2) of multiples over which the quadratic bound
// guarantees descent, and past the bound's minimum at 1, since along negative curvature the
// objective falls the faster the longer the step (docs/algorithms.md, "The step along
// negative curvature").
constexpr double negative_curvature_step = 1.5;

// Alg. 4: exact step along d (the objective is quadratic), projection onto the bound, the
// mean restored, then the conjugate direction with beta = r.Hd / d.Hd. The gradient g of a
// step the bound did not cut follows from the Hessian product already made for the step
// length, in the pass that moves the iterate; it is evaluated after a cut, every few steps,
// and before convergence is declared. An iteration is then one Hessian product (whose pass
// over the spectrum also gives the curvature d.Hd) and two passes over the unknowns; under a
// mean constraint two more: the sum that gives the factor restoring the mean, and beta's sums
// once the multiplier is known.
// Preconditioned (option preconditioner = fourier), the direction is d = -z + beta d_old with
// z = M r, M the inverse of the elastic operator whose Hessian the objective is (diagonal in
// Fourier space), made mean-free on N under a mean constraint, and beta = z.H d_old /
// d_old.H d_old; the projection, the step and the restarts are the same. Since M cancels the
// |q| of the half-space's operator, the condition number left is the active set's, not the
// grid's (Vollebregt, J. Comput. Phys. 257 (2014) 333). It costs a transform pair and three
// passes per iteration.
void bugnicourt(Formulation &f, Monitor &monitor, bool preconditioned) {
  const BugnicourtPasses passes(f);
  const auto n = static_cast<std::size_t>(f.size());
  double *x = f.variable().data();
  // The gradient at zero takes the formulation's spare array if it lends one.
  double *spare = f.spare_array();
  Field g(n), c_field(spare != nullptr ? 0 : n), d(n), h(n), z(preconditioned ? n : 0);
  double *c = spare != nullptr ? spare : c_field.data();
  // The gradient at zero is needed from the first step on: a start that is already
  // converged (a warm start from a solved state) ends after its one evaluation.
  double value_at_zero = 0.0;
  // f(x) = x.(g + c)/2 + f(0) for the history, without an evaluation.
  const auto value_of = [&]() {
    return monitor.wants_objective()
               ? 0.5 * (f.dot(x, g.data()) + f.dot(x, c)) + value_at_zero
               : 0.0;
  };
  // The gradient at x, with the value only for the history.
  const auto evaluate = [&]() {
    if (monitor.wants_objective()) return f.value_and_gradient(x, g.data());
    f.gradient(x, g.data());
    return 0.0;
  };
  const auto gradient = [&](std::int64_t i) { return g[i]; };
  const auto product = [&](std::int64_t i) { return h[i]; };
  const auto nothing = [](std::int64_t, double) { return 0.0; };
  const auto no_correction = [](std::int64_t) { return 0.0; };
  // The new direction and the descent along it: conjugate to the last direction d_old (h
  // holds H d_old, last_curvature d_old.H d_old), or steepest where that is not positive.
  // Preconditioned, beta comes from the preconditioned gradient; otherwise gather gave it.
  const auto direct = [&](const Projection &p, double last_curvature) {
    return preconditioned ? passes.direct_preconditioned(x, gradient, p, product,
                                                         last_curvature, z.data(), d.data(),
                                                         nothing, no_correction)[0]
                          : passes.direct(x, gradient, p, d.data(), nothing)[0];
  };

  double value = evaluate();
  Projection p = passes.gather(x, gradient, product, 0.0, 0.0);
  if (monitor.should_stop(0, observe(f, x, g.data(), p.error, value, monitor))) return;
  value_at_zero = f.gradient_at_zero(c);
  double descent = direct(p, 0.0);

  int followed = 0;
  for (std::int64_t iteration = 1;; ++iteration) {
    double curvature = f.quadratic_part_product(d.data(), h.data());
    if (!(descent < 0.0 && curvature > 0.0)) {
      // Not a descent direction after the projection changed the free set: restart from
      // the projected steepest descent, which is one unless the iterate is stationary.
      Projection steepest = p;
      steepest.beta = 0.0;
      descent = direct(steepest, 0.0);
      curvature = f.quadratic_part_product(d.data(), h.data());
      if (!(curvature > 0.0)) {
        monitor.declare_stalled();
        return;
      }
    }
    const double alpha = -descent / curvature;
    const Step step = passes.step(x, d.data(), alpha, g.data(), h.data(), c,
                                  followed < updates_between_evaluations, p.shift, curvature);
    // The gradient is evaluated after a cut, when the followed one is due for a refresh, and
    // before the monitor may call the iterate converged (or see a non-finite error).
    if (step.followed) {
      ++followed;
      p = step.projection;
      value = value_of();
    }
    if (!step.followed || !(p.error > monitor.tolerance())) {
      followed = 0;
      value = evaluate();
      p = passes.gather(x, gradient, product, curvature, p.shift);
    }
    if (monitor.should_stop(iteration, observe(f, x, g.data(), p.error, value, monitor))) return;
    descent = direct(p, curvature);
  }
}

// Alg. 4 for a separable objective f(x) = Q(x) + sum_i psi(x_i) with Q quadratic (the gap
// with adhesion, psi the adhesive energy), with a safeguarded step. OUT-LIN's step is the
// minimiser of the second-order model along d, -r.d / d.H d with the Hessian H = Q + psi'' at
// the iterate (Bugnicourt et al. linearise the adhesive term's residual within the step); it
// is taken when that curvature is positive and the step lowers the objective. Otherwise (the
// curvature of strong adhesion can be negative, or the model can overshoot where psi'' grows
// along the step) the step is -r.d / d.Q d: for the hard wall with adhesion, whose adhesive
// energy is concave, Q bounds the curvature along the whole line, so that the objective lies
// below its quadratic model and this step lowers it for certain (before the bound cuts it,
// as for the quadratic); should a cut make it rise, it is halved. Preconditioned, where the
// curvature along d is not positive, the objective lies below that model by more the longer
// the step, and the step taken is 1.5 times the safe one, which the model still guarantees
// to descend (it descends for every multiple below 2); should a cut make it rise, the safe
// step is taken instead. On the contact-mechanics challenge's scene at 1024^2 to 4096^2 this
// cut the iterations 1.5 to 2.6 times. Along the plain gradient it changed little on nested
// grids and led one cold solve to a state of much higher energy (docs/performance.md), so
// there the step stays the safe one. Preconditioned, two things treat the pixels near the
// wall, which a step along d would settle only over many iterations (docs/algorithms.md,
// "The pixels near the wall"): the first trial of a step makes them jump across the
// adhesion's instability, onto the wall and off it (BugnicourtPasses::trial; which pixels,
// and after which steps, LocalTerm::eager says), and after a step that was not cut (by the
// bound or by jumps) the preconditioner is corrected for the free pixels' own curvature
// (own_correction, below). The conjugate direction uses
// beta = r.Hd / d.Hd (H at the iterate the step started from), restarting where that
// curvature is not positive.
// Q's gradient q is followed from Q's Hessian product as in the quadratic case, and the local
// term is evaluated element by element (one exponential per unknown, its state, gives psi,
// psi' and psi''), so that the objective at a trial point needs no transform unless the bound
// cut the step: a trial is one pass, writing the trial point, q there and the states into
// trial arrays that become the iterate's when the step is taken.
void bugnicourt_separable(Formulation &f, const LocalTerm &psi, Monitor &monitor,
                          bool preconditioned) {
  const BugnicourtPasses passes(f);
  const auto n = static_cast<std::size_t>(f.size());
  Field &variable = f.variable();
  // The trial point takes the formulation's spare array if it lends one.
  double *spare = f.spare_array();
  Field y_field(spare != nullptr ? 0 : n), q_field(n), qy_field(n), d(n), k(n), e_field(n),
      ey_field(n), z(preconditioned ? n : 0);
  // Q's gradient at 0, which a trial point rescaled to the mean needs; none without a mean
  // constraint.
  Field c(f.constrains_mean() ? n : 0);
  // The iterate, q and the states there, and the trial arrays (after a step, the previous
  // iterate's), exchanged when a step is taken.
  double *x = variable.data(), *y = spare != nullptr ? spare : y_field.data();
  double *q = q_field.data(), *qy = qy_field.data();
  double *e = e_field.data(), *ey = ey_field.data();
  const double value_per_state = psi.value_per_state(), slope = psi.slope_per_state(),
               bend = psi.curvature_per_state(), lower = f.lower_bound();
  if (f.constrains_mean()) f.quadratic_part_at_zero(c.data());

  const auto gradient = [&](std::int64_t i) { return q[i] + slope * e[i]; };
  // (H d)_i at the iterate the last step started from, whose states ey then holds.
  const auto product = [&](std::int64_t i) { return k[i] + bend * ey[i] * d[i]; };
  const auto none = [](std::int64_t) { return 0.0; };
  // psi''(x_i) d_i^2: the local term's part of the curvature along the new direction.
  const auto local_curvature = [&](std::int64_t i, double di) { return bend * e[i] * di * di; };
  // Whether the last step was cut (by the bound or by jumps); until a step that was not, the
  // preconditioner is the plain one and, unless the local term is eager, the trials make no
  // jumps.
  bool cut_before = true;
  // The preconditioner's correction for the free pixels' own curvature (docs/algorithms.md,
  // "The pixels near the wall"; LocalTerm::preconditioner_correction): longer moves along
  // their own residuals for the pixels that the adhesion softens, short of the instability.
  // The unstable ones jump instead (BugnicourtPasses::trial). Only after a step that was not
  // cut: while the contact set still moves, pixels cross the adhesive zone in a few steps,
  // and the correction would only lengthen their moves.
  const auto own_correction = [&](std::int64_t i) {
    return !cut_before && x[i] > lower ? psi.preconditioner_correction(e[i]) : 0.0;
  };
  // The new direction, the descent along it and the local term's curvature there: conjugate
  // to the last direction (product() is H d_old at the iterate it started from,
  // last_curvature d_old.H d_old), or steepest where that is not positive. Preconditioned,
  // with the correction for the pixels' own curvature.
  const auto direct = [&](const Projection &p, double last_curvature) {
    return preconditioned
               ? passes.direct_preconditioned(x, gradient, p, product, last_curvature, z.data(),
                                              d.data(), local_curvature, own_correction)
               : passes.direct(x, gradient, p, d.data(), local_curvature);
  };
  // The history's objective needs the gradient: written into the trial array qy, free until
  // the next trial.
  const auto state_at = [&](double error, double value) {
    if (monitor.wants_objective())
      loops::for_each(static_cast<std::int64_t>(n), [&](std::int64_t i) { qy[i] = gradient(i); });
    return observe(f, x, qy, error, value, monitor);
  };
  // Every way out leaves the iterate in the formulation's variable.
  const auto settle = [&]() {
    if (x != variable.data()) std::copy(x, x + n, variable.data());
  };

  double value = f.quadratic_part(x, q) + value_per_state * passes.local_states(x, psi, e);
  double states = 0.0;
  Projection p = passes.gather(x, gradient, none, 0.0, 0.0);
  if (monitor.should_stop(0, state_at(p.error, value))) return settle();
  auto along = direct(p, 0.0);

  int followed = 0;
  for (std::int64_t iteration = 1;; ++iteration) {
    double bound = f.quadratic_part_product(d.data(), k.data());
    if (!(along[0] < 0.0 && bound > 0.0)) {
      // Not a descent direction after the projection changed the free set: restart from
      // the projected steepest descent, which is one unless the iterate is stationary.
      Projection steepest = p;
      steepest.beta = 0.0;
      along = direct(steepest, 0.0);
      bound = f.quadratic_part_product(d.data(), k.data());
      if (!(along[0] < 0.0 && bound > 0.0)) {
        monitor.declare_stalled();
        return settle();
      }
    }
    const double descent = along[0], curvature = bound + along[1];
    const double safe = -descent / bound;
    const bool newton = curvature > 0.0 && curvature < bound;

    // The change of the objective from x to the trial point x + alpha d (cut and rescaled),
    // which goes into the trial arrays.
    bool cut = false;
    // Preconditioned, the first trial also makes the pixels near the adhesion's instability
    // jump across it, onto the wall or off it (BugnicourtPasses::trial): after a step that
    // was not cut, and where the local term is eager after a cut one too, since while the
    // bound cuts every step the contact lines would otherwise move a pixel or so per
    // iteration. A retry moves along d alone. A trial with jumps counts as cut, so that the
    // step after it has no correction of the preconditioner and, unless eager, no jumps.
    bool jumps = preconditioned && (psi.eager() || !cut_before);
    const auto trial = [&](double alpha) {
      const Trial t =
          passes.trial(x, d.data(), alpha, q, k.data(), c.data(), e, psi, y, qy, ey, jumps);
      jumps = false;
      cut = t.cut;
      states = t.states;
      double quadratic_change = t.quadratic_change;
      if (t.cut) {
        f.quadratic_part(y, qy);
        quadratic_change = passes.quadratic_change(x, y, q, qy);
      }
      return quadratic_change + value_per_state * t.state_change;
    };
    const bool concave = preconditioned && !(curvature > 0.0);
    double change = trial(newton    ? -descent / curvature
                          : concave ? negative_curvature_step * safe
                                    : safe);
    // A rise within 1e-12 of the value is taken for rounding, and the step kept. Where the
    // elastic and adhesive energies cancel, rounding can exceed that; a good step is then
    // replaced by the safe one, which costs a pass but never the descent. So is the longer
    // step along negative curvature that a cut made rise.
    const double slack = 1e-12 * std::fabs(value);
    if ((newton || concave) && !(change <= slack)) change = trial(safe);
    // The safe step descends before the bound cuts it; a cut can spoil that, but not for
    // short steps (the cut then only drops components along which r.d >= 0). So it is
    // halved while it raises the objective, a few times at most.
    double alpha = safe;
    for (int halving = 0; halving < max_halvings && !(change <= slack); ++halving) {
      alpha *= 0.5;
      change = trial(alpha);
    }
    std::swap(x, y);
    std::swap(q, qy);
    std::swap(e, ey);
    value += change;

    // q is evaluated after a cut (the trial did), when the followed one is due for a
    // refresh, and before the monitor may call the iterate converged.
    const auto refresh = [&]() {
      followed = 0;
      value = f.quadratic_part(x, q) + value_per_state * states;
    };
    cut_before = cut;
    followed = cut ? 0 : followed + 1;
    if (followed >= updates_between_evaluations) refresh();
    const double beta_curvature = curvature > 0.0 ? curvature : 0.0;
    p = passes.gather(x, gradient, product, beta_curvature, p.shift);
    if (followed > 0 && !(p.error > monitor.tolerance())) {
      refresh();
      p = passes.gather(x, gradient, product, beta_curvature, p.shift);
    }
    if (monitor.should_stop(iteration, state_at(p.error, value))) return settle();
    along = direct(p, beta_curvature);
  }
}

bool on_the_gap(const OptionValues &options) { return options.text("variable") == "gap"; }

// On a free substrate the gap formulation takes penetration and load control.
constexpr const char *mean_gap_on_free =
    "mean-gap control of the gap formulation is offered on a periodic substrate only; on a "
    "free one the mean displacement is not a free mode whose energy can be left out";

Offer offer_for(const OptionValues &options) {
  if (on_the_gap(options))
    // The separable step knows the exponential adhesion, not a user's callback.
    return {{Control::mean_gap, Control::penetration, Control::mean_pressure},
            false,
            {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential},
            false,
            "variable = gap",
            {Control::penetration, Control::mean_pressure},
            mean_gap_on_free,
            {},
            false,
            ""};
  return {{Control::mean_pressure, Control::penetration},
          false,
          {InteractionFamily::hard_wall},
          false,
          "variable = pressure",
          {},
          "",
          {},
          false,
          ""};
}

// The preconditioner's choices: "auto" takes it, with or without adhesion. Without adhesion
// the problem is convex, with one solution, reached in fewer iterations and less time from
// 64^2 on. With adhesion the problem has several stable states, and the preconditioned path,
// whose directions move large parts of the surface at once, can settle in another one than
// the plain path; on nested grids (the default from 128 pixels a side) it reached states
// within 1 % of the plain path's energy on the contact-mechanics challenge's scene, in 5.5
// to 7.3 times fewer iterations (docs/performance.md, "The step along negative curvature").
bool preconditioned(const OptionValues &options) {
  const std::string &choice = options.text("preconditioner");
  return choice == "fourier" || choice == "auto";
}

template <class Variable>
void run_on(System &system, Control control, double value, const OptionValues &options,
            Monitor &monitor) {
  Variable formulation(system, control, value);
  // Every objective the offer admits is quadratic, or separable (the gap with adhesion).
  if (formulation.quadratic())
    bugnicourt(formulation, monitor, preconditioned(options));
  else
    bugnicourt_separable(formulation, *formulation.local_term(), monitor,
                         preconditioned(options));
  conclude(formulation, system, monitor);
}

void run(System &system, Control control, double value, const OptionValues &options,
         Monitor &monitor) {
  if (on_the_gap(options))
    run_on<PrimalFormulation>(system, control, value, options, monitor);
  else
    run_on<DualFormulation>(system, control, value, options, monitor);
}

}  // namespace

AlgorithmSpec bugnicourt_algorithm() {
  AlgorithmSpec spec;
  spec.name = "bugnicourt";
  spec.summary =
      "Bugnicourt et al.'s constrained conjugate gradient (OUT-LIN, Tribol. Lett. 2018; "
      "thesis section 3.1.2, Alg. 4) on the pressure (the objective is the complementary "
      "energy, as for pk; no adhesion) or on the gap (the elastic energy plus the interaction "
      "energy; with or without adhesion)";
  spec.controls = {Control::mean_pressure, Control::mean_gap, Control::penetration};
  spec.offer_for = offer_for;
  spec.interactions = {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential};
  spec.options = {{"variable", OptionType::choice, 0.0, 0.0, 0.0, false, {"pressure", "gap"},
                   "the unknown: pressure (the dual problem; mean-pressure or penetration "
                   "control; no adhesion) or gap (the primal; mean-pressure, mean-gap or "
                   "penetration control, not mean-gap on a free substrate; with or without "
                   "adhesion, tensile loads included)"},
                  {"preconditioner", OptionType::choice, 0.0, 0.0, 0.0, false,
                   {"auto", "fourier", "none"},
                   "fourier: preconditioned by the inverse of the elastic operator of the "
                   "objective (the compliance on the gap, the stiffness on the pressure) "
                   "applied to the projected gradient, one more transform pair per iteration "
                   "and 12 more bytes per pixel (its vector, and the substrate's inverse "
                   "operator on the half spectrum; 24 on a free substrate) for iterations "
                   "that grow far less with the grid; none: the conjugate gradient as "
                   "published; auto: fourier, with or without adhesion (the adhesive problem "
                   "has several stable states, and the two paths can reach different ones)"}};
  // Nested grids by default: on the bench scene to 1e-8 they take 0.74 to 0.99 times the
  // time of a plain solve from 512^2 to 2048^2 (docs/performance.md, "Nested grids with
  // bugnicourt and lbfgsb"). With adhesion the coarse levels solve the non-adhesive contact
  // (nested_grids.cpp); below 128 pixels a side, and from a warm start, none are taken.
  spec.default_levels = levels_auto;
  // With exponential adhesion on a grid that does not resolve the cohesive zone, a first
  // solve with a longer range (range_continuation.hpp): on the challenge's scene at 1024^2
  // to 4096^2 it cut the iterations at 4096^2 by a third and their growth per doubling to
  // about 1.4, in states of lower energy than the cold solve's there (docs/performance.md).
  spec.default_range_continuation = continuation_auto;
  spec.run = run;
  return spec;
}

}  // namespace asp
