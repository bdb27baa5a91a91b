#include "solvers/bugnicourt.hpp"

#include <cstdint>

#include "core/loops.hpp"
#include "solvers/dual_formulation.hpp"
#include "solvers/primal_formulation.hpp"
#include "solvers/solver.hpp"

namespace asp {
namespace {

// The passes over the unknowns that the algorithm's steps need, on the formulation's
// unknowns; x >= lower is the bound.
class Steps {
 public:
  explicit Steps(Formulation &f)
      : f_(f), n_(f.size()), lower_(f.lower_bound()), reductions_(f.reductions()) {}

  // x <- max(x + alpha d, lower), then the mean restored by a common factor (a uniform
  // iterate if nothing is left above the bound).
  void move(double *x, const double *d, double alpha) const {
    const double lower = lower_;
    const double total = loops::sum(reductions_, n_, [&](std::int64_t i) {
      const double moved = x[i] + alpha * d[i];
      x[i] = moved > lower ? moved : lower;
      return x[i];
    });
    if (!f_.constrains_mean()) return;
    const double target = f_.mean_target() * static_cast<double>(n_);
    if (total > 0.0) {
      const double factor = target / total;
      loops::for_each(n_, [&](std::int64_t i) { x[i] *= factor; });
    } else {
      const double uniform = f_.mean_target();
      loops::for_each(n_, [&](std::int64_t i) { x[i] = uniform; });
    }
  }

  // The gradient r made a direction of the feasible set, in place: its mean over the free
  // unknowns removed (the multiplier of the mean constraint), zero where x sits on the bound
  // and r pushes it out of the feasible set, and its mean over the entries left removed again
  // so that a step along it keeps the mean.
  void project(const double *x, double *r) const {
    const double lower = lower_;
    const bool mean = f_.constrains_mean();
    if (mean) {
      const auto s = loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
        const double free = x[i] > lower ? 1.0 : 0.0;
        sum[0] += free * r[i];
        sum[1] += free;
      });
      const double shift = s[1] > 0.0 ? s[0] / s[1] : 0.0;
      loops::for_each(n_, [&](std::int64_t i) { r[i] -= shift; });
    }
    const auto s = loops::sums<2>(reductions_, n_, [&](std::int64_t i, double *sum) {
      const bool blocked = (x[i] <= lower) & (r[i] > 0.0);
      r[i] = blocked ? 0.0 : r[i];
      sum[0] += r[i];
      sum[1] += r[i] != 0.0 ? 1.0 : 0.0;
    });
    if (mean && s[1] > 0.0) {
      const double shift = s[0] / s[1];
      loops::for_each(n_, [&](std::int64_t i) { r[i] -= r[i] != 0.0 ? shift : 0.0; });
    }
  }

  // d <- -r + beta d where r is not zero by the bound rule, 0 there.
  void new_direction(const double *x, const double *r, double beta, double *d) const {
    const double lower = lower_;
    loops::for_each(n_, [&](std::int64_t i) {
      const bool blocked = (x[i] <= lower) & (r[i] == 0.0);
      d[i] = blocked ? 0.0 : -r[i] + beta * d[i];
    });
  }

 private:
  Formulation &f_;
  std::int64_t n_;
  double lower_;
  const Reductions &reductions_;
};

// The state the monitor sees at x with the raw gradient (before projection).
IterationState observe(const Formulation &f, const double *x, const double *gradient,
                       double value, const Monitor &monitor) {
  IterationState state;
  state.error = f.error(x, gradient);
  state.objective =
      monitor.wants_objective() ? f.reported_objective(x, gradient, value) * f.energy_unit() : 0.0;
  state.contact_fraction = monitor.wants_objective() ? f.contact_fraction(x) : 0.0;
  state.evaluations = f.counters().evaluations;
  state.transforms = f.counters().transforms;
  return state;
}

// Alg. 4: exact step along d (the objective is quadratic), projection onto the bound, the
// mean restored, then the conjugate direction with beta = r.Hd / d.Hd.
void bugnicourt(Formulation &f, Monitor &monitor) {
  const Steps steps(f);
  const std::int64_t n = f.size();
  Field &variable = f.variable();
  double *x = variable.data();
  Field r(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n)),
      h(static_cast<std::size_t>(n));

  double value = f.value_and_gradient(x, r.data());
  if (monitor.should_stop(0, observe(f, x, r.data(), value, monitor))) return;
  steps.project(x, r.data());
  steps.new_direction(x, r.data(), 0.0, d.data());

  for (std::int64_t iteration = 1;; ++iteration) {
    f.hessian_product(d.data(), h.data());
    double curvature = f.dot(d.data(), h.data());
    double descent = f.dot(r.data(), d.data());
    if (!(descent < 0.0 && curvature > 0.0)) {
      // Not a descent direction after the projection changed the free set: restart from
      // the projected steepest descent, which is one unless the iterate is stationary.
      steps.new_direction(x, r.data(), 0.0, d.data());
      f.hessian_product(d.data(), h.data());
      curvature = f.dot(d.data(), h.data());
      descent = f.dot(r.data(), d.data());
      if (!(curvature > 0.0)) {
        monitor.declare_stalled();
        return;
      }
    }
    steps.move(x, d.data(), -descent / curvature);

    value = f.value_and_gradient(x, r.data());
    if (monitor.should_stop(iteration, observe(f, x, r.data(), value, monitor))) return;
    steps.project(x, r.data());
    const double beta = f.dot(r.data(), h.data()) / curvature;
    steps.new_direction(x, r.data(), beta, d.data());
  }
}

bool on_the_gap(const OptionValues &options) { return options.text("variable") == "gap"; }

ControlsOffered controls_for(const OptionValues &options) {
  if (on_the_gap(options))
    return {{Control::mean_gap, Control::penetration}, "variable = gap"};
  return {{Control::mean_pressure, Control::penetration}, "variable = pressure"};
}

template <class Variable>
void run_on(System &system, Control control, double value, Monitor &monitor) {
  Variable formulation(system, control, value);
  bugnicourt(formulation, monitor);
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
      "energy, as for pk) or on the gap (the elastic energy)";
  spec.controls = {Control::mean_pressure, Control::mean_gap, Control::penetration};
  spec.controls_for = controls_for;
  spec.substrates = {SubstrateKind::periodic};
  spec.interactions = {InteractionKind::hard_wall};
  spec.options = {{"variable", OptionType::choice, 0.0, 0.0, 0.0, false, {"pressure", "gap"},
                   "the unknown: pressure (the dual problem; mean-pressure or penetration "
                   "control) or gap (the primal; mean-gap or penetration control)"}};
  spec.run = run;
  return spec;
}

}  // namespace asp
