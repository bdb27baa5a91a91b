#include "solvers/bugnicourt.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "solvers/bound_residual.hpp"
#include "solvers/dual_formulation.hpp"
#include "solvers/primal_formulation.hpp"
#include "solvers/solver.hpp"

namespace asp {
namespace {

// Gradients followed from Hessian products between two evaluations: rounding grows with
// their number, and an evaluation costs one FFT pair.
constexpr int updates_between_evaluations = 32;

// Halvings of a step of the objective that is not quadratic that still raises it; 2^-30 of
// the step is far below what would still change the iterate.
constexpr int max_halvings = 30;

// What a step did to the iterate: the factor that restored the mean (1 without a mean
// constraint), and whether the bound cut it (then the gradient must be evaluated).
struct Move {
  double scale;
  bool cut;
};

// The passes over the unknowns that the algorithm's steps need; x >= lower is the bound on
// the first `bounded` unknowns, the others are free. The unknowns are pixels (real space),
// whose inner product is the plain sum.
class Steps {
 public:
  explicit Steps(Formulation &f)
      : f_(f),
        n_(f.size()),
        bounded_(f.bounded_size()),
        lower_(f.lower_bound()),
        reductions_(f.reductions()) {
    // The mean is restored by scaling every unknown, which keeps the followed gradient exact;
    // it is the mean of the bounded ones that the constraint fixes.
    if (f.constrains_mean() && bounded_ != n_)
      throw Error(Status::internal,
                  "bugnicourt: a mean constraint on some unknowns only is not supported");
  }

  // x <- max(from + alpha d, lower), then the mean restored by a common factor (a uniform
  // iterate if nothing is left above the bound). from may be x.
  Move move(const double *from, double *x, const double *d, double alpha) const {
    const double lower = lower_;
    const std::int64_t bounded = bounded_;
    const auto s = loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
      const double moved = from[i] + alpha * d[i];
      const bool cut = (i < bounded) & !(moved > lower);
      x[i] = cut ? lower : moved;
      sum[0] += x[i];
      sum[1] += cut & (moved < lower) ? 1.0 : 0.0;
    });
    Move m{1.0, s[1] > 0.0};
    if (!f_.constrains_mean()) return m;
    const double target = f_.mean_target() * static_cast<double>(n_);
    if (s[0] > 0.0) {
      m.scale = target / s[0];
      const double factor = m.scale;
      loops::for_each(n_, [&](std::int64_t i) { x[i] *= factor; });
    } else {
      const double uniform = f_.mean_target();
      loops::for_each(n_, [&](std::int64_t i) { x[i] = uniform; });
      m.cut = true;
    }
    return m;
  }

  // The gradient g made a direction of the feasible set, into r: its mean over the free
  // unknowns removed (the multiplier of the mean constraint), zero where x sits on the bound
  // and g pushes it out of the feasible set, and its mean over the entries left removed again
  // so that a step along it keeps the mean. Then the new direction d <- -r + beta d (0 where
  // the bound rule zeroed r), with beta = r.h / curvature (h = H d_old), or 0 for the first
  // or a restarted direction (curvature 0). Three passes: the second also sums what beta
  // needs, so that the last writes r and d together.
  void project_and_direct(const double *x, const double *g, const double *h, double curvature,
                          double *r, double *d) const {
    const double lower = lower_;
    const std::int64_t bounded = bounded_;
    const bool mean = f_.constrains_mean();
    const double shift = mean ? mean_over_free(reductions_, n_, x, g, lower) : 0.0;
    const bool conjugate = curvature > 0.0;
    const auto s = loops::sums<4>(reductions_, n_, [&](std::int64_t i, double *sum) {
      const double ri = g[i] - shift;
      const bool blocked = (i < bounded) & (x[i] <= lower) & (ri > 0.0);
      r[i] = blocked ? 0.0 : ri;
      const double nonzero = r[i] != 0.0 ? 1.0 : 0.0;
      sum[0] += r[i];
      sum[1] += nonzero;
      sum[2] += conjugate ? r[i] * h[i] : 0.0;
      sum[3] += conjugate ? nonzero * h[i] : 0.0;
    });
    const double again = mean && s[1] > 0.0 ? s[0] / s[1] : 0.0;
    const double beta = conjugate ? (s[2] - again * s[3]) / curvature : 0.0;
    loops::for_each(n_, [&](std::int64_t i) {
      const bool zero = r[i] == 0.0;
      r[i] = zero ? 0.0 : r[i] - again;
      d[i] = (i < bounded) & (x[i] <= lower) & zero ? 0.0 : -r[i] + beta * d[i];
    });
  }

  // r.d and d.h in one pass: the descent along d and its curvature.
  std::array<double, 2> descent_and_curvature(const double *r, const double *d,
                                              const double *h) const {
    return loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
      sum[0] += r[i] * d[i];
      sum[1] += d[i] * h[i];
    });
  }

  // d <- -r + beta d where r is not zero by the bound rule, 0 there.
  void new_direction(const double *x, const double *r, double beta, double *d) const {
    const double lower = lower_;
    const std::int64_t bounded = bounded_;
    loops::for_each(n_, [&](std::int64_t i) {
      const bool blocked = (i < bounded) & (x[i] <= lower) & (r[i] == 0.0);
      d[i] = blocked ? 0.0 : -r[i] + beta * d[i];
    });
  }

  // g <- s (g + alpha h) + (1 - s) c: the gradient after a step the bound did not cut.
  void follow(double *g, const double *h, const double *c, double alpha, double scale) const {
    loops::for_each(n_, [&](std::int64_t i) {
      g[i] = scale * (g[i] + alpha * h[i]) + (1.0 - scale) * c[i];
    });
  }

 private:
  Formulation &f_;
  std::int64_t n_;
  std::int64_t bounded_;
  double lower_;
  const Reductions &reductions_;
};

// Alg. 4: exact step along d (the objective is quadratic), projection onto the bound, the
// mean restored, then the conjugate direction with beta = r.Hd / d.Hd. The gradient g of a
// step the bound did not cut follows from the Hessian product already made for the step
// length; it is evaluated after a cut, every few steps, and before convergence is declared.
void bugnicourt(Formulation &f, Monitor &monitor) {
  const Steps steps(f);
  const auto n = static_cast<std::size_t>(f.size());
  double *x = f.variable().data();
  Field g(n), c(n), r(n), d(n), h(n);
  const double value_at_zero = f.gradient_at_zero(c.data());
  // f(x) = x.(g + c)/2 + f(0) for the history, without an evaluation.
  const auto value_of = [&]() {
    return monitor.wants_objective()
               ? 0.5 * (f.dot(x, g.data()) + f.dot(x, c.data())) + value_at_zero
               : 0.0;
  };

  const double value = f.value_and_gradient(x, g.data());
  if (monitor.should_stop(0, observe(f, x, g.data(), value, monitor))) return;
  steps.project_and_direct(x, g.data(), h.data(), 0.0, r.data(), d.data());

  int followed = 0;
  for (std::int64_t iteration = 1;; ++iteration) {
    f.hessian_product(d.data(), h.data());
    std::array<double, 2> along = steps.descent_and_curvature(r.data(), d.data(), h.data());
    if (!(along[0] < 0.0 && along[1] > 0.0)) {
      // Not a descent direction after the projection changed the free set: restart from
      // the projected steepest descent, which is one unless the iterate is stationary.
      steps.new_direction(x, r.data(), 0.0, d.data());
      f.hessian_product(d.data(), h.data());
      along = steps.descent_and_curvature(r.data(), d.data(), h.data());
      if (!(along[1] > 0.0)) {
        monitor.declare_stalled();
        return;
      }
    }
    const double descent = along[0], curvature = along[1];
    const double alpha = -descent / curvature;
    const Move move = steps.move(x, x, d.data(), alpha);

    // The gradient is evaluated after a cut, when the followed one is due for a refresh, and
    // before the monitor may call the iterate converged (or see a non-finite error).
    IterationState state;
    const bool follow = !move.cut && followed < updates_between_evaluations;
    if (follow) {
      steps.follow(g.data(), h.data(), c.data(), alpha, move.scale);
      ++followed;
      state = observe(f, x, g.data(), value_of(), monitor);
    }
    if (!follow || !(state.error > monitor.tolerance())) {
      followed = 0;
      state = observe(f, x, g.data(), f.value_and_gradient(x, g.data()), monitor);
    }
    if (monitor.should_stop(iteration, state)) return;
    steps.project_and_direct(x, g.data(), h.data(), curvature, r.data(), d.data());
  }
}

// Alg. 4 for an objective that is not quadratic (the gap with adhesion): the gradient is
// evaluated after every step, and the step length is safeguarded. OUT-LIN's step is the
// minimiser of the second-order model along d, -r.d / d.H d with the Hessian H at the
// iterate (Bugnicourt et al. linearise the adhesive term's residual within the step); it is
// taken when that curvature is positive and the step lowers the objective. Otherwise (the
// curvature of strong adhesion can be negative, or the model can overshoot where phi'' grows
// along the step) the step is -r.d / bound, with the formulation's upper bound on the
// curvature along the whole line: for the hard wall with adhesion, whose adhesive energy is
// concave, the elastic curvature d.K d, under which the objective lies below its quadratic
// model, so that this step lowers it for certain (before the bound cuts it, as for the
// quadratic). The conjugate direction uses beta = r.Hd / d.Hd as before, restarting where
// that curvature is not positive.
void bugnicourt_nonquadratic(Formulation &f, Monitor &monitor) {
  const Steps steps(f);
  const auto n = static_cast<std::size_t>(f.size());
  double *x = f.variable().data();
  Field g(n), start(n), r(n), d(n), h(n);

  double value = f.value_and_gradient(x, g.data());
  if (monitor.should_stop(0, observe(f, x, g.data(), value, monitor))) return;
  steps.project_and_direct(x, g.data(), h.data(), 0.0, r.data(), d.data());

  for (std::int64_t iteration = 1;; ++iteration) {
    f.hessian_product(d.data(), h.data());
    std::array<double, 2> along = steps.descent_and_curvature(r.data(), d.data(), h.data());
    double bound = f.curvature_bound(d.data(), h.data());
    if (!(along[0] < 0.0 && bound > 0.0)) {
      // Not a descent direction after the projection changed the free set: restart from
      // the projected steepest descent, which is one unless the iterate is stationary.
      steps.new_direction(x, r.data(), 0.0, d.data());
      f.hessian_product(d.data(), h.data());
      along = steps.descent_and_curvature(r.data(), d.data(), h.data());
      bound = f.curvature_bound(d.data(), h.data());
      if (!(along[0] < 0.0 && bound > 0.0)) {
        monitor.declare_stalled();
        return;
      }
    }
    const double descent = along[0], curvature = along[1];
    const double safe = -descent / bound;
    std::copy(x, x + n, start.data());
    const bool newton = curvature > 0.0 && curvature < bound;
    steps.move(start.data(), x, d.data(), newton ? -descent / curvature : safe);
    double trial = f.value_and_gradient(x, g.data());
    // A rise within 1e-12 of the values is taken for rounding, and the step kept. Where the
    // elastic and adhesive energies cancel, rounding can exceed that; a good step is then
    // replaced by the safe one, which costs an evaluation but never the descent.
    const double slack = 1e-12 * std::fabs(value);
    if (newton && !(trial <= value + slack)) {
      steps.move(start.data(), x, d.data(), safe);
      trial = f.value_and_gradient(x, g.data());
    }
    // The safe step descends before the bound cuts it; a cut can spoil that, but not for
    // short steps (the cut then only drops components along which r.d >= 0). So it is
    // halved while it raises the objective, a few times at most.
    double alpha = safe;
    for (int halving = 0; halving < max_halvings && !(trial <= value + slack); ++halving) {
      alpha *= 0.5;
      steps.move(start.data(), x, d.data(), alpha);
      trial = f.value_and_gradient(x, g.data());
    }
    value = trial;
    if (monitor.should_stop(iteration, observe(f, x, g.data(), value, monitor))) return;
    steps.project_and_direct(x, g.data(), h.data(), curvature > 0.0 ? curvature : 0.0,
                             r.data(), d.data());
  }
}

bool on_the_gap(const OptionValues &options) { return options.text("variable") == "gap"; }

// On a free substrate the gap formulation takes penetration control only (its constructor
// refuses the mean gap, naming the substrate).
Offer offer_for(const OptionValues &options) {
  if (on_the_gap(options))
    return {{Control::mean_gap, Control::penetration},
            {SubstrateKind::periodic, SubstrateKind::free},
            {InteractionKind::hard_wall, InteractionKind::adhesive_hard_wall},
            "variable = gap"};
  return {{Control::mean_pressure, Control::penetration},
          {SubstrateKind::periodic, SubstrateKind::free},
          {InteractionKind::hard_wall},
          "variable = pressure"};
}

template <class Variable>
void run_on(System &system, Control control, double value, Monitor &monitor) {
  Variable formulation(system, control, value);
  if (formulation.quadratic())
    bugnicourt(formulation, monitor);
  else
    bugnicourt_nonquadratic(formulation, monitor);
  conclude(formulation, system, monitor);
}

void run(System &system, Control control, double value, const OptionValues &options,
         Monitor &monitor) {
  if (on_the_gap(options))
    run_on<PrimalFormulation>(system, control, value, monitor);
  else
    run_on<DualFormulation>(system, control, value, monitor);
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
  spec.substrates = {SubstrateKind::periodic, SubstrateKind::free};
  spec.interactions = {InteractionKind::hard_wall, InteractionKind::adhesive_hard_wall};
  spec.options = {{"variable", OptionType::choice, 0.0, 0.0, 0.0, false, {"pressure", "gap"},
                   "the unknown: pressure (the dual problem; mean-pressure or penetration "
                   "control; no adhesion) or gap (the primal; mean-gap or penetration "
                   "control, penetration only on a free substrate; with or without "
                   "adhesion)"}};
  spec.run = run;
  return spec;
}

}  // namespace asp
