// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/line_search.hpp"

#include <algorithm>
#include <cmath>

namespace asp {
namespace {

// Before the minimum is bracketed, the next trial lies between these multiples of the
// distance from the best step (More & Thuente's extrapolation bounds).
constexpr double extrapolate_least = 1.1;
constexpr double extrapolate_most = 4.0;

// The minimiser of the cubic through (a, fa, ga) and (b, fb, gb), written as a step from a
// towards b in a form that does not overflow (the scale s factors out the largest term).
// When the cubic has no real minimiser (only possible in the third case below) the
// discriminant is taken as 0.
double cubic_minimiser(double a, double fa, double ga, double b, double fb, double gb,
                       bool clip_discriminant) {
  const double theta = 3.0 * (fa - fb) / (b - a) + ga + gb;
  const double s = std::max({std::fabs(theta), std::fabs(ga), std::fabs(gb)});
  double discriminant = (theta / s) * (theta / s) - (ga / s) * (gb / s);
  if (clip_discriminant) discriminant = std::max(discriminant, 0.0);
  double gamma = s * std::sqrt(discriminant);
  if (b < a) gamma = -gamma;
  const double p = (gamma - ga) + theta;
  const double q = ((gamma - ga) + gamma) + gb;
  return a + (p / q) * (b - a);
}

// The minimiser of the quadratic through (a, fa, ga) and (b, fb).
double quadratic_minimiser(double a, double fa, double ga, double b, double fb) {
  return a + ((ga / ((fa - fb) / (b - a) + ga)) / 2.0) * (b - a);
}

// The zero of the secant of the slopes ga at a and gb at b.
double secant_minimiser(double a, double ga, double b, double gb) {
  return b + (gb / (gb - ga)) * (a - b);
}

}  // namespace

StrongWolfeSearch::Outcome StrongWolfeSearch::start(double value, double slope,
                                                    double first_step, double largest_step) {
  step_ = first_step;
  smallest_ = 0.0;
  largest_ = largest_step;
  f0_ = value;
  g0_ = slope;
  decrease_slope_ = ftol_ * slope;
  bracketed_ = false;
  modified_ = true;
  width_ = largest_ - smallest_;
  previous_width_ = 2.0 * width_;
  best_ = other_ = 0.0;
  f_best_ = f_other_ = value;
  g_best_ = g_other_ = slope;
  low_ = 0.0;
  high_ = step_ + extrapolate_most * step_;
  last_decreases_ = false;
  return Outcome::evaluate;
}

StrongWolfeSearch::Outcome StrongWolfeSearch::next(double f, double g) {
  const double sufficient = f0_ + step_ * decrease_slope_;
  last_decreases_ = f <= sufficient;
  // The first stage ends once a step has decreased f enough and has a non-negative slope.
  if (modified_ && last_decreases_ && g >= 0.0) modified_ = false;

  if (last_decreases_ && std::fabs(g) <= gtol_ * -g0_) return Outcome::found;
  // No progress possible: rounding, an interval below the tolerance, or a step held at its
  // bounds.
  if (bracketed_ && (step_ <= low_ || step_ >= high_)) return Outcome::stuck;
  if (bracketed_ && high_ - low_ <= xtol_ * high_) return Outcome::stuck;
  if (step_ == largest_ && last_decreases_ && g <= decrease_slope_) return Outcome::stuck;
  if (step_ == smallest_ && (!last_decreases_ || g >= decrease_slope_)) return Outcome::stuck;

  // In the first stage, while f has not risen above the best point but misses the
  // sufficient decrease, the search works on the modified function psi(a) = phi(a) -
  // phi(0) - decrease a phi'(0), whose minimisers meet the decrease condition.
  if (modified_ && f <= f_best_ && f > sufficient) {
    const double shift = decrease_slope_;
    double fb = f_best_ - best_ * shift, gb = g_best_ - shift;
    double fo = f_other_ - other_ * shift, go = g_other_ - shift;
    interpolate(best_, fb, gb, other_, fo, go, step_, f - step_ * shift, g - shift);
    f_best_ = fb + best_ * shift;
    g_best_ = gb + shift;
    f_other_ = fo + other_ * shift;
    g_other_ = go + shift;
  } else {
    interpolate(best_, f_best_, g_best_, other_, f_other_, g_other_, step_, f, g);
  }

  // Bisect when the interval does not shrink fast enough.
  if (bracketed_) {
    if (std::fabs(other_ - best_) >= 0.66 * previous_width_)
      step_ = best_ + 0.5 * (other_ - best_);
    previous_width_ = width_;
    width_ = std::fabs(other_ - best_);
    low_ = std::min(best_, other_);
    high_ = std::max(best_, other_);
  } else {
    low_ = step_ + extrapolate_least * (step_ - best_);
    high_ = step_ + extrapolate_most * (step_ - best_);
  }
  step_ = std::min(std::max(step_, smallest_), largest_);
  // If no further progress is possible, the best step so far is the last trial.
  if (bracketed_ && (step_ <= low_ || step_ >= high_ || high_ - low_ <= xtol_ * high_))
    step_ = best_;
  return Outcome::evaluate;
}

void StrongWolfeSearch::interpolate(double &best, double &f_best, double &g_best,
                                    double &other, double &f_other, double &g_other,
                                    double trial, double f_trial, double g_trial) {
  const bool opposite_slopes = g_trial * (g_best / std::fabs(g_best)) < 0.0;
  double next;
  if (f_trial > f_best) {
    // Case 1, a higher value: the minimum is bracketed. The cubic step if it is closer to
    // the best point, else the average of the cubic and the quadratic step.
    const double cubic = cubic_minimiser(best, f_best, g_best, trial, f_trial, g_trial, false);
    const double quadratic = quadratic_minimiser(best, f_best, g_best, trial, f_trial);
    next = std::fabs(cubic - best) < std::fabs(quadratic - best)
               ? cubic
               : cubic + (quadratic - cubic) / 2.0;
    // At least a tenth of the way to the trial (Nocedal & Wright's safeguard, section 3.5):
    // where f rises by many orders of magnitude (a steep exponential wall), the cubic's
    // minimiser is a difference of nearly equal terms, and rounding can put it anywhere
    // near the best point, even behind it.
    const double least = best + 0.1 * (trial - best);
    if (!(trial > best ? next >= least : next <= least)) next = least;
    bracketed_ = true;
  } else if (opposite_slopes) {
    // Case 2, a lower value and slopes of opposite sign: bracketed. The cubic or the secant
    // step, whichever is farther from the trial.
    const double cubic = cubic_minimiser(trial, f_trial, g_trial, best, f_best, g_best, false);
    const double secant = secant_minimiser(best, g_best, trial, g_trial);
    next = std::fabs(cubic - trial) > std::fabs(secant - trial) ? cubic : secant;
    bracketed_ = true;
  } else if (std::fabs(g_trial) < std::fabs(g_best)) {
    // Case 3, a lower value, slopes of the same sign, and a smaller slope. The cubic step is
    // used only if the cubic tends to infinity in the direction of the step or its minimum
    // lies beyond the trial; otherwise the step goes to the end of the allowed range.
    const double theta = 3.0 * (f_best - f_trial) / (trial - best) + g_best + g_trial;
    const double s = std::max({std::fabs(theta), std::fabs(g_best), std::fabs(g_trial)});
    double gamma =
        s * std::sqrt(std::max(0.0, (theta / s) * (theta / s) - (g_best / s) * (g_trial / s)));
    if (trial > best) gamma = -gamma;
    const double p = (gamma - g_trial) + theta;
    const double q = (gamma + (g_best - g_trial)) + gamma;
    const double r = p / q;
    const double cubic = r < 0.0 && gamma != 0.0 ? trial + r * (best - trial)
                         : trial > best        ? high_
                                               : low_;
    const double secant = secant_minimiser(best, g_best, trial, g_trial);
    if (bracketed_) {
      // The step closer to the trial, kept inside the bracket.
      next = std::fabs(cubic - trial) < std::fabs(secant - trial) ? cubic : secant;
      next = trial > best ? std::min(trial + 0.66 * (other - trial), next)
                          : std::max(trial + 0.66 * (other - trial), next);
    } else {
      // The step farther from the trial, inside the range allowed before a bracket (More &
      // Thuente's [stp + 1.1 (stp - stx), stp + 4 (stp - stx)]).
      next = std::fabs(cubic - trial) > std::fabs(secant - trial) ? cubic : secant;
      next = std::max(low_, std::min(high_, next));
    }
  } else {
    // Case 4, a lower value, slopes of the same sign, and a slope that does not decrease:
    // the cubic through the trial and the other end if bracketed, else the range's end.
    if (bracketed_)
      next = cubic_minimiser(trial, f_trial, g_trial, other, f_other, g_other, false);
    else
      next = trial > best ? high_ : low_;
  }

  // The new interval: the trial replaces the end it may replace.
  if (f_trial > f_best) {
    other = trial;
    f_other = f_trial;
    g_other = g_trial;
  } else {
    if (opposite_slopes) {
      other = best;
      f_other = f_best;
      g_other = g_best;
    }
    best = trial;
    f_best = f_trial;
    g_best = g_trial;
  }
  step_ = next;
}

}  // namespace asp
