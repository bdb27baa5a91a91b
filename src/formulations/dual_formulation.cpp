// SPDX-License-Identifier: GPL-2.0-or-later
#include "formulations/dual_formulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/loops.hpp"
#include "formulations/bound_residual.hpp"

namespace asp {

namespace {
// Linear updates of the pressure's spectrum between two transforms of it (see
// gap_of_iterate): rounding grows with their number, a transform costs 1/3 of an iteration.
constexpr int linear_updates_between_transforms = 32;
}  // namespace

DualFormulation::DualFormulation(System &system, Control control, double value,
                                 DualSteps steps)
    : ScaledFormulation(system, control, value),
      compliance_(system.substrate().normalised_compliance()) {
  compliance_factor_ = substrate_.pixel_stiffness();

  // Work arrays before anything changes, so that running out of memory changes nothing.
  spectrum_ = substrate_.make_spectrum();
  height_spectrum_ = substrate_.make_spectrum();
  if (steps != DualSteps::generic) {
    direction_ = grid_.make_field();
    pressure_spectrum_ = substrate_.make_spectrum();
  }
  if (steps == DualSteps::polonsky_keer_fourier) {
    preconditioned_ = grid_.make_field();
    substrate_.normalised_stiffness();  // made now, so that a solve allocates nothing
  }
  hold_state();
  // The gap array holds the scaled heights for their transform; every way out of a solve
  // computes the gap again (evaluate_gap, finish). The transform's own size (the padded grid
  // of a free substrate) normalises them.
  double *w = state_.gap.data();
  const double points = substrate_.transform_points();
  loops::for_each(n_, [&](std::int64_t i) { w[i] = scaled_height(i) / points; });
  substrate_.forward(w, height_spectrum_.data());
  counters_.transforms += 1;
  load_state();
}

// ---- Formulation --------------------------------------------------------------------------

void DualFormulation::gap_of(const double *pressure, double pressure_scale, double *gap) {
  // gap = backward(scale k C forward(p) - H) - delta: the scaled gap in one transform pair and
  // one pass over the spectrum (H, the spectrum of the scaled heights, carries the 1/N).
  // It overwrites the direction's spectrum, which the next linear update would read.
  linear_update_ready_ = false;
  const Complex *hs = height_spectrum_.data();
  const double factor = pressure_scale * compliance_factor_, delta = delta_;
  substrate_.apply_compliance(
      pressure, gap, spectrum_.data(),
      [&](Complex *s, const double *c, const SpectralLayout &layout) {
        loops::for_each(layout.size(), [&](std::int64_t k) { s[k] = factor * c[k] * s[k] - hs[k]; });
        // A constant in every pixel after the unnormalised backward transform.
        if (layout.is_mean(0)) s[0] -= delta;
      });
  counters_.transforms += 2;
  counters_.evaluations += 1;
}

double DualFormulation::gap_of_iterate(double *gap, bool with_energy) {
  // The spectrum of the pressure array: after a step that moved no pixel onto or off the
  // contact set, p_new = scale_old p_old - tau t exactly, so its spectrum follows from the
  // old one and that of t (still in spectrum_ from the curvature) without a transform. Every
  // few such steps it is recomputed, so that rounding cannot accumulate.
  // Without Polonsky & Keer's arrays (generic use) the pressure is transformed into the work
  // spectrum itself, and the gap's spectrum overwrites it in place.
  Complex *s = spectrum_.data();
  Complex *ps = pressure_spectrum_.empty() ? s : pressure_spectrum_.data();
  const Complex *hs = height_spectrum_.data();
  const double *c = compliance_.data();
  const double factor = scale_ * compliance_factor_;
  const auto m = static_cast<std::int64_t>(spectrum_.size());
  const bool linear = linear_update_ready_;
  if (linear) {
    ++linear_updates_;
  } else {
    substrate_.forward(state_.pressure.data(), ps);
    counters_.transforms += 1;
    linear_updates_ = 0;
  }
  // One pass: the pressure's new spectrum (if updated linearly) and the gap's; with the
  // energy, also sum_q C|P_q|^2 over the stored entries, from which p.u follows by Parseval.
  const double a = step_scale_, b = step_length_;
  const auto updated_pressure = [&](std::int64_t k) {
    const Complex p_k = a * ps[k] - b * s[k];
    ps[k] = p_k;
    return p_k;
  };
  const auto gap_entry = [&](std::int64_t k, Complex p_k) {
    s[k] = factor * c[k] * p_k - hs[k];
    return c[k] * std::norm(p_k);
  };
  double pressure_dot_displacement = 0.0;
  if (with_energy) {
    // The single-weight entries of P: read before the pass when P was just transformed (the
    // pass may overwrite it in place), after it when the pass updates P.
    const auto singles_of_p = [&]() {
      return substrate_.layout().single_entries_sum(
          [&](std::int64_t k) { return c[k] * std::norm(ps[k]); });
    };
    double singles = linear ? 0.0 : singles_of_p();
    const Reductions &reductions = grid_.reductions();
    const double all =
        linear ? loops::sums<1>(reductions, m,
                                [&](std::int64_t k, double *sum) {
                                  sum[0] += gap_entry(k, updated_pressure(k));
                                })[0]
               : loops::sums<1>(reductions, m, [&](std::int64_t k, double *sum) {
                   sum[0] += gap_entry(k, ps[k]);
                 })[0];
    if (linear) singles = singles_of_p();
    reductions.combine_sums(&singles, 1);
    pressure_dot_displacement = factor * (2.0 * all - singles);
  } else if (linear) {
    loops::for_each(m, [&](std::int64_t k) { gap_entry(k, updated_pressure(k)); });
  } else {
    loops::for_each(m, [&](std::int64_t k) { gap_entry(k, ps[k]); });
  }
  if (substrate_.layout().is_mean(0)) s[0] -= delta_;
  substrate_.backward(spectrum_.data(), gap);
  counters_.transforms += 1;
  counters_.evaluations += 1;
  linear_update_ready_ = false;
  return pressure_dot_displacement;
}

double DualFormulation::value_and_gradient(const double *x, double *gradient) {
  // Pi = sum x (u/2 - w - delta), gradient g = u - w - delta with u = K^-1 x (scaled).
  gap_of(x, 1.0, gradient);
  return loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    const double u = gradient[i] + scaled_height(i) + delta_;
    return x[i] * (0.5 * u - scaled_height(i) - delta_);
  });
}

double DualFormulation::gradient_at_zero(double *out) {
  // g(0) = -(h - max h) - delta, scaled; Pi(0) = 0.
  const double delta = delta_;
  loops::for_each(n_, [&](std::int64_t i) { out[i] = -scaled_height(i) - delta; });
  return 0.0;
}

void DualFormulation::hessian_product(const double *direction, double *product) {
  linear_update_ready_ = false;  // the direction's spectrum is overwritten, as in gap_of
  substrate_.apply_compliance(direction, product, spectrum_.data(),
                              Substrate::KernelTimes{compliance_factor_});
  counters_.transforms += 2;
}

double DualFormulation::quadratic_part_product(const double *direction, double *product) {
  linear_update_ready_ = false;  // the direction's spectrum is overwritten, as in gap_of
  const double factor = compliance_factor_;
  double curvature = 0.0;
  substrate_.apply_compliance(direction, product, spectrum_.data(),
                              [&](Complex *s, const double *c, const SpectralLayout &layout) {
                                curvature = kernel_times_summing(grid_.reductions(), layout, s,
                                                                 c, factor);
                              });
  counters_.transforms += 2;
  return curvature;
}

double DualFormulation::error(const double *x, const double *gradient) const {
  // Under load control the penetration is the multiplier of the mean.
  return bound_residual(grid_.reductions(), n_, n_, x, gradient, 0.0,
                        control_ == Control::mean_pressure);
}

double DualFormulation::contact_fraction(const double *x, const double *) const {
  // The active set, which finish() stores as the pixels on the wall (g = 0).
  const double n = pixels_;
  const double contacts =
      loops::sum(grid_.reductions(), n_, [&](std::int64_t i) { return x[i] > 0.0 ? 1.0 : 0.0; });
  return contacts / n;
}

double DualFormulation::reported_objective(const double *x, const double *gradient,
                                           double value) const {
  // value = sum x (u/2 - w - delta) with the stored delta; under load control the
  // penetration is the multiplier, whose current estimate is delta plus the mean gradient over
  // the contact set (as evaluate_gap takes it for Polonsky-Keer's history).
  if (control_ != Control::mean_pressure) return value;
  const auto s = loops::sums<3>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
    const double in = x[i] > 0.0 ? 1.0 : 0.0;
    sum[0] += in * gradient[i];
    sum[1] += in;
    sum[2] += x[i];
  });
  return s[1] > 0.0 ? value - (s[0] / s[1]) * s[2] : value;
}

// ---- Polonsky & Keer's steps --------------------------------------------------------------

void DualFormulation::load_state() {
  double *p = state_.pressure.data();
  const double inverse_unit = 1.0 / pressure_unit_;
  const double n = pixels_;
  // Negative pressures cannot stand against a hard wall; NaN is kept so that the monitor sees
  // it (std::fmax would drop it).
  const double sum = loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    p[i] = (p[i] < 0.0 ? 0.0 : p[i]) * inverse_unit;
    return p[i] / n;
  });
  scale_ = 1.0;
  shift_ = 0.0;
  delta_ = state_.penetration / length_unit_;
  if (control_ == Control::mean_pressure) {
    // Zero load: the body just touches the highest point, so the penetration starts (and
    // ends) at 0.
    if (target_ == 0.0) delta_ = 0.0;
    if (target_ == 0.0 || !(sum > 0.0)) {
      if (std::isnan(sum)) return;  // leave the NaN for the monitor to see
      loops::for_each(n_, [&](std::int64_t i) { p[i] = target_; });
    } else {
      scale_ = target_ / sum;
    }
  } else {
    delta_ = target_;
  }
}

DualFormulation::Gap DualFormulation::evaluate_gap(bool with_objective) {
  double *g = state_.gap.data();
  const double *p = state_.pressure.data();
  const double delta_before = delta_;
  const double pressure_dot_displacement = gap_of_iterate(g, with_objective);

  // Sums over the contact set I_c = {p > 0}, and those of the objective if asked for, in the
  // same pass.
  std::array<double, 5> s{};
  if (with_objective) {
    s = loops::sums<5>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
      const double in = p[i] > 0.0 ? 1.0 : 0.0;
      const double gi = in * g[i];
      sum[0] += gi;
      sum[1] += gi * gi;
      sum[2] += in;
      sum[3] += p[i] * g[i];
      sum[4] += p[i];
    });
  } else {
    const auto c = loops::sums<3>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
      const double in = p[i] > 0.0 ? 1.0 : 0.0;
      const double gi = in * g[i];
      sum[0] += gi;
      sum[1] += gi * gi;
      sum[2] += in;
    });
    std::copy(c.begin(), c.end(), s.begin());
  }
  const double contacts = s[2];
  contacts_ = contacts;
  // Under load control the penetration is whatever closes the mean gap on I_c.
  shift_ = control_ == Control::mean_pressure && contacts > 0.0 ? s[0] / contacts : 0.0;
  delta_ += shift_;
  Gap gap;
  gap.norm = std::fmax(s[1] - 2.0 * shift_ * s[0] + contacts * shift_ * shift_, 0.0);
  gap.contacts = contacts;
  // Pi = sum p (u/2 - w - delta) = sum p g_before - (1/2) sum p u + (delta_before - delta)
  // sum p, with g_before = u - w - delta_before the arrays' gap before centring; sum p u
  // comes from the spectral pass (Parseval), so that the heights need not be read.
  gap.objective = with_objective ? scale_ * (s[3] - 0.5 * pressure_dot_displacement +
                                             (delta_before - delta_) * s[4])
                                 : 0.0;
  gap_is_current_ = true;
  return gap;
}

template <class Source, class Member>
double DualFormulation::update_direction_from(Source source, Member member, double t_mean,
                                              double beta) {
  double *t = direction_.data();
  const double *g = state_.gap.data();
  const double *p = state_.pressure.data();
  const double shift = shift_;
  // Projected gradient (the error) and the new search direction in one branch-free pass, so
  // that it vectorises. The violations are also summed, only to notice NaN, which a maximum
  // may drop; and the gap's slope along the old direction, for the restart test.
  const auto r = loops::sums_and_max<3>(
      grid_.reductions(), n_, [&](std::int64_t i, double *sum, double &max) {
        const double gi = g[i] - shift;
        const bool contact = p[i] > 0.0;
        const bool in = member(p[i], gi);
        const double si = in ? source(i, gi) : 0.0;
        const double old = in ? t[i] - t_mean : 0.0;
        const double ti = si + beta * old;
        t[i] = ti;
        const double v = contact ? std::fabs(gi) : (gi > 0.0 ? 0.0 : -gi);
        max = max > v ? max : v;
        sum[0] += gi * ti;
        sum[1] += v;
        sum[2] += gi * old;
      });
  descent_ = r[0];
  old_slope_ = beta * r[2];
  return std::isfinite(r[1]) ? r[3] : r[1];
}

double DualFormulation::update_direction(double beta) {
  // The old direction made mean-free on the current contact set (load control), so that a
  // step along t keeps the mean pressure and the step length needs no centred product.
  const double t_mean = control_ == Control::mean_pressure && contacts_ > 0.0
                            ? direction_sum_on_contact_ / contacts_
                            : 0.0;
  return update_direction_from([](std::int64_t, double gi) { return gi; },
                               [](double pi, double) { return pi > 0.0; }, t_mean, beta);
}

double DualFormulation::update_preconditioned_direction(double beta) {
  const double *z = preconditioned_.data();
  const double z_mean = preconditioned_mean_;
  return update_direction_from([&](std::int64_t i, double) { return z[i] - z_mean; },
                               [](double pi, double gi) { return in_free_set(pi, gi); },
                               free_direction_mean_, beta);
}

double DualFormulation::curvature() {
  // t.K^-1 t = (1/N) sum_q weight C'|T_q|^2 by Parseval, C' = k C the scaled compliance with
  // the 1/N of the transform already in it.
  substrate_.forward(direction_.data(), spectrum_.data());
  counters_.transforms += 1;
  const Complex *s = spectrum_.data();
  const double *c = compliance_.data();
  double sum = substrate_.layout().weighted_sum(
      [&](std::int64_t k) { return c[k] * std::norm(s[k]); });
  grid_.reductions().combine_sums(&sum, 1);
  return compliance_factor_ * sum;
}

bool DualFormulation::step(double tau) {
  double *p = state_.pressure.data();
  const double *g = state_.gap.data();
  const double *t = direction_.data();
  const double shift = shift_, scale = scale_;
  const bool along = preconditioned_steps();
  // Step, project onto p >= 0, and let pixels with a negative gap enter the contact set
  // (along the preconditioned direction, which covers them, or with -tau g).
  // The last sum counts pixels whose new pressure is not the plain step (clipped or
  // entered): when there are none, the pressure's spectrum can be updated linearly.
  // Off the contact set t = 0 (update_direction made it so) and p = 0, so the plain step
  // leaves such pixels at 0 without a test of their old pressure.
  const auto s = loops::sums<4>(grid_.reductions(), n_, [&](std::int64_t i, double *sum) {
    const double gi = g[i] - shift;
    const double stepped = scale * p[i] - tau * t[i];
    double pi = stepped > 0.0 ? stepped : 0.0;
    const bool enters = along ? (p[i] == 0.0) & (pi > 0.0) : (pi == 0.0) & (gi < 0.0);
    pi = enters && !along ? -tau * gi : pi;
    sum[0] += pi;
    sum[1] += enters ? 1.0 : 0.0;
    sum[2] += pi > 0.0 ? t[i] : 0.0;
    sum[3] += pi != stepped ? 1.0 : 0.0;
    p[i] = pi;
  });
  gap_is_current_ = false;
  direction_sum_on_contact_ = s[2];
  step_scale_ = scale;
  step_length_ = tau;
  linear_update_ready_ = s[3] == 0.0 && linear_updates_ < linear_updates_between_transforms;
  scale_ = 1.0;
  bool entered = s[1] > 0.0;
  if (control_ == Control::mean_pressure) {
    const double n = pixels_;
    if (s[0] > 0.0) {
      scale_ = target_ * n / s[0];
    } else {
      loops::for_each(n_, [&](std::int64_t i) { p[i] = target_; });
      entered = true;
      linear_update_ready_ = false;
    }
  }
  return entered;
}

void DualFormulation::admit_interpenetrating_pixels() {
  double *p = state_.pressure.data();
  const double *g = state_.gap.data();
  const double shift = shift_, scale = scale_;
  // The scaled pixel stiffness is 1: pressure -g closes a lone pixel's gap g < 0.
  const double sum = loops::sum(grid_.reductions(), n_, [&](std::int64_t i) {
    const double gi = g[i] - shift;
    const double old_p = scale * p[i];
    p[i] = old_p > 0.0 ? old_p : (gi < 0.0 ? -gi : 0.0);
    return p[i];
  });
  scale_ = 1.0;
  if (control_ == Control::mean_pressure && sum > 0.0)
    scale_ = target_ * pixels_ / sum;
  direction_sum_on_contact_ = 0.0;
  linear_update_ready_ = false;
  gap_is_current_ = false;
}

Field &DualFormulation::variable() {
  // A generic solver reads and writes the iterate itself: the pending scale of the pressure
  // array is folded in, and the gap and the pressure's spectrum count as stale from here on.
  if (scale_ != 1.0) {
    double *p = state_.pressure.data();
    const double scale = scale_;
    loops::for_each(n_, [&](std::int64_t i) { p[i] *= scale; });
    scale_ = 1.0;
  }
  linear_update_ready_ = false;
  gap_is_current_ = false;
  return state_.pressure;
}

bool DualFormulation::finish() {
  if (!gap_is_current_) evaluate_gap(false);
  // The arrays hold p/scale and g + shift (scaled): the physical state, with the active set
  // p > 0 on the wall (System::store_solved_state gives its gap exactly 0 and the others a
  // positive one). No ending leaves the surfaces interpenetrating.
  const double *p = state_.pressure.data();
  const double *g = state_.gap.data();
  const double pressure_factor = scale_ * pressure_unit_;
  const double shift = shift_, length = length_unit_;
  const double delta = delta_ * length;
  return system_.store_solved_state(
      [&](std::int64_t i) {
        const double pi = p[i] * pressure_factor;
        return SolvedPixel{pi, (g[i] - shift) * length, pi > 0.0};
      },
      [&](double) { return delta; }, pressure_unit_);
}

}  // namespace asp
