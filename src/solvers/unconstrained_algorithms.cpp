// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/unconstrained_algorithms.hpp"

#include <utility>

#include "formulations/displacement_formulation.hpp"
#include "solvers/fire.hpp"
#include "formulations/fourier_formulation.hpp"
#include "solvers/gfmd.hpp"
#include "solvers/lbfgs.hpp"
#include "solvers/monitor.hpp"

namespace asp {
namespace {

const std::vector<Control> soft_controls = {Control::penetration, Control::mean_pressure};

// Options shared by the algorithms of one family.
OptionSpec memory_option() {
  return {"memory", OptionType::integer, 10, 1, 100, false, {},
          "the number of step and gradient-change pairs the quasi-Newton matrix keeps (16 "
          "bytes per pixel each)"};
}
std::vector<OptionSpec> fire_options() {
  const FireParameters d;
  return {
      {"time_step", OptionType::real, d.time_step, 0.0, 1e300, false, {},
       "the first time step, in the variable's units (0: 1/sqrt of a bound on the largest "
       "curvature at the start)"},
      {"max_time_step", OptionType::real, d.largest_step, 0.0, 1e300, false, {},
       "the largest time step (0: 10/sqrt(largest elastic curvature), Bitzek et al.'s ten "
       "times a stable step of the elastic modes)"},
      {"time_step_growth", OptionType::real, d.growth, 1.0, 10.0, false, {},
       "f_inc: the factor the step grows by after `delay` steps of positive power"},
      {"time_step_shrink", OptionType::real, d.shrink, 0.0, 1.0, true, {},
       "f_dec: the factor the step shrinks by when the power turns negative"},
      {"mixing", OptionType::real, d.mixing, 0.0, 1.0, false, {},
       "alpha_start: the weight of the force's direction in the velocity after a restart"},
      {"mixing_decay", OptionType::real, d.mixing_decay, 0.0, 1.0, false, {},
       "f_alpha: the factor alpha decays by while the power stays positive"},
      {"delay", OptionType::integer, static_cast<double>(d.delay), 0, 1e9, false, {},
       "N_min: steps of positive power before the step grows"},
  };
}
FireParameters fire_parameters(const OptionValues &o) {
  FireParameters p;
  p.time_step = o.number("time_step");
  p.largest_step = o.number("max_time_step");
  p.growth = o.number("time_step_growth");
  p.shrink = o.number("time_step_shrink");
  p.mixing = o.number("mixing");
  p.mixing_decay = o.number("mixing_decay");
  p.delay = static_cast<int>(o.number("delay"));
  return p;
}

// The runs, one per algorithm and variable: the formulation, the algorithm with its options,
// the result written back.
template <class Variable>
void run_lbfgs(System &system, Control control, double value, const OptionValues &options,
               Monitor &monitor) {
  Variable formulation(system, control, value);
  lbfgs(formulation, monitor, static_cast<int>(options.number("memory")));
  conclude(formulation, system, monitor);
}

template <class Variable>
void run_fire(System &system, Control control, double value, const OptionValues &options,
              Monitor &monitor) {
  Variable formulation(system, control, value);
  fire(formulation, monitor, fire_parameters(options));
  conclude(formulation, system, monitor);
}

void run_gfmd(System &system, Control control, double value, const OptionValues &options,
              Monitor &monitor) {
  FourierFormulation formulation(system, control, value);
  GfmdParameters p;
  p.time_step = options.number("time_step");
  p.damping = options.number("damping");
  gfmd(formulation, monitor, p);
  conclude(formulation, system, monitor);
}

// What every unconstrained solver serves: the soft potentials under penetration and
// mean-pressure control, on the periodic substrate and, where the variable allows, the free.
AlgorithmSpec soft_spec(const char *name, const char *summary, bool periodic_only,
                        std::vector<OptionSpec> options, decltype(AlgorithmSpec::run) run) {
  AlgorithmSpec spec;
  spec.name = name;
  spec.summary = summary;
  spec.controls = soft_controls;
  spec.periodic_only = periodic_only;
  spec.interactions = {InteractionFamily::soft_potential};
  spec.callbacks = true;
  spec.free_controls = {Control::penetration};
  spec.free_reason =
      "mean-pressure control of an unconstrained formulation is offered on a periodic "
      "substrate only; on a free one the rigid-body penetration is not a free mode of the "
      "displacement through which the mean pressure could be imposed";
  spec.options = std::move(options);
  spec.run = run;
  return spec;
}

}  // namespace

AlgorithmSpec lbfgs_algorithm() {
  return soft_spec(
      "lbfgs",
      "limited-memory BFGS (Nocedal 1980) with a strong Wolfe line search on the displacement: "
      "the unconstrained problem of a soft potential (thesis sections 2.2.1 and 3.1.6); "
      "mean-pressure control on a periodic substrate only",
      false, {memory_option()}, run_lbfgs<DisplacementFormulation>);
}

AlgorithmSpec lbfgs_fourier_algorithm() {
  return soft_spec(
      "lbfgs_fourier",
      "limited-memory BFGS on the displacement's spectrum scaled by sqrt(K~(q)), so that the "
      "elastic Hessian is the identity (the thesis's preconditioned L-BFGS, section 4.2), in "
      "1D and 2D",
      true, {memory_option()}, run_lbfgs<FourierFormulation>);
}

AlgorithmSpec fire_algorithm() {
  return soft_spec(
      "fire",
      "the fast inertial relaxation engine (Bitzek et al. 2006, with FIRE 2.0's half step "
      "back) on the displacement, equal masses (thesis section 3.1.4)",
      false, fire_options(), run_fire<DisplacementFormulation>);
}

AlgorithmSpec fire_mass_weighted_algorithm() {
  return soft_spec(
      "fire_mass_weighted",
      "FIRE with masses proportional to K~(q) (Zhou, Moseler & Muser 2019; thesis section "
      "3.1.5): FIRE on the preconditioned Fourier variable",
      true, fire_options(), run_fire<FourierFormulation>);
}

AlgorithmSpec gfmd_algorithm() {
  const GfmdParameters d;
  return soft_spec(
      "gfmd",
      "damped Green's function molecular dynamics (Campana & Muser 2006; thesis Alg. 5), "
      "mass-weighted: Verlet steps with a damping force on the preconditioned Fourier variable",
      true,
      {{"time_step", OptionType::real, d.time_step, 0.0, 1e300, false, {},
        "a fixed time step, in the variable's units (0: 1/sqrt of a bound on the largest "
        "curvature at the iterate, at most 1, taken again every 10 steps); a step that raises "
        "the energy is undone and the motion restarts from rest, a step from rest is halved"},
       {"damping", OptionType::real, d.damping, 0.0, 1e300, false, {},
        "eta, the damping per unit time (2 damps the elastic modes, of unit frequency, "
        "critically; softer modes, adhesive or the mean under mean-pressure control, converge "
        "faster with less)"}},
      run_gfmd);
}

}  // namespace asp
