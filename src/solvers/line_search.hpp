// SPDX-License-Identifier: GPL-2.0-or-later
// A line search for the strong Wolfe conditions, after More & Thuente (ACM TOMS 20, 1994),
// the search of MINPACK-2's dcsrch that L-BFGS-B uses. It works by reverse communication: the
// caller evaluates phi(step) = f(x + step d) and its slope phi'(step) = g(x + step d).d at the
// step it proposes, and reports them back, until the search says the step is acceptable or
// that it cannot find one. It knows nothing about the vectors themselves.
//
// The conditions, for 0 < step <= largest step:
//   sufficient decrease  phi(step) <= phi(0) + decrease step phi'(0),
//   curvature            |phi'(step)| <= curvature |phi'(0)|.
#pragma once

#include <cmath>

namespace asp {

// The value a search should compare at `step`, given phi(step) = value and phi'(step) = slope
// and phi(0) = value0, phi'(0) = slope0. Near a minimum phi(step) - phi(0) falls below the
// rounding of phi itself, and the sufficient decrease condition can no longer be checked from
// values: there, as in Hager & Zhang's approximate Wolfe conditions (SIAM J. Optim. 16, 2005),
// the change is taken from the slopes by the trapezoidal rule, phi(0) + step (phi'(0) +
// phi'(step))/2, exact for a quadratic. "Near" is a change below 1e-6 of |phi(0)| (their
// epsilon).
inline double comparable_value(double value, double slope, double step, double value0,
                               double slope0) {
  constexpr double values_resolved = 1e-6;
  if (std::fabs(value - value0) > values_resolved * std::fabs(value0)) return value;
  return value0 + 0.5 * step * (slope0 + slope);
}

class StrongWolfeSearch {
 public:
  enum class Outcome {
    evaluate,  // evaluate phi and phi' at step() and call next() with them
    found,     // step() meets both conditions
    // No further progress is possible (the interval of uncertainty fell below the rounding
    // of the step, or the step sits at its bounds): step() holds the best point the search
    // has, which meets the sufficient decrease condition if sufficient_decrease() says so.
    stuck,
  };

  // decrease and curvature as above (0 < decrease < curvature < 1); relative_width stops the
  // search when the interval of uncertainty is that small relative to its end.
  StrongWolfeSearch(double decrease, double curvature, double relative_width)
      : ftol_(decrease), gtol_(curvature), xtol_(relative_width) {}

  // Starts a search from phi(0) = value, phi'(0) = slope < 0, with a first trial step in
  // (0, largest]. Returns Outcome::evaluate.
  Outcome start(double value, double slope, double first_step, double largest_step);
  // phi and phi' at step(); returns what to do next.
  Outcome next(double value, double slope);

  double step() const { return step_; }
  // Whether the last evaluated step meets the sufficient decrease condition.
  bool sufficient_decrease() const { return last_decreases_; }

 private:
  // One step of the safeguarded interpolation: updates the interval [best, other] (ends
  // with their values and slopes) with the trial, and proposes the next trial step.
  void interpolate(double &best, double &f_best, double &g_best, double &other,
                   double &f_other, double &g_other, double trial, double f_trial,
                   double g_trial);

  double ftol_, gtol_, xtol_;
  double step_ = 0.0, smallest_ = 0.0, largest_ = 0.0;
  double f0_ = 0.0, g0_ = 0.0, decrease_slope_ = 0.0;
  // The interval of uncertainty: the best step so far and the other end.
  double best_ = 0.0, f_best_ = 0.0, g_best_ = 0.0;
  double other_ = 0.0, f_other_ = 0.0, g_other_ = 0.0;
  double low_ = 0.0, high_ = 0.0;  // where the next trial may lie
  double width_ = 0.0, previous_width_ = 0.0;
  bool bracketed_ = false;
  bool modified_ = true;  // the first stage, with the modified function
  bool last_decreases_ = false;
};

// A whole search along a direction, for the quasi-Newton solvers: from phi(0) = value0 and
// phi'(0) = slope0 < 0, trial steps from `first` (at most `largest`), each evaluated by
// evaluate(step, value, slope), which moves the iterate to the step and writes phi and phi'
// there, until a step is accepted: one that meets both conditions, or the best point of a
// search that can go no further if it meets the sufficient decrease and is not the step 0.
// Returns accepted (the iterate at that step, its value in *accepted_value), failed (none in
// `evaluations` trials, or stuck without one) or not_finite (a value or slope that is not
// finite); after the last two the caller moves the iterate back.
struct LineSearchSettings {
  double decrease, curvature, relative_width;
  int evaluations;
};
enum class LineSearchResult { accepted, failed, not_finite };
template <class Evaluate>
LineSearchResult search_line(const LineSearchSettings &settings, double value0, double slope0,
                             double first, double largest, Evaluate &&evaluate,
                             double *accepted_value) {
  StrongWolfeSearch search(settings.decrease, settings.curvature, settings.relative_width);
  StrongWolfeSearch::Outcome outcome = search.start(value0, slope0, first, largest);
  for (int evaluation = 0; evaluation < settings.evaluations; ++evaluation) {
    double value = 0.0, slope = 0.0;
    evaluate(search.step(), value, slope);
    if (!std::isfinite(value) || !std::isfinite(slope)) return LineSearchResult::not_finite;
    outcome = search.next(comparable_value(value, slope, search.step(), value0, slope0), slope);
    const bool accepted = outcome == StrongWolfeSearch::Outcome::found ||
                          (outcome == StrongWolfeSearch::Outcome::stuck &&
                           search.sufficient_decrease() && search.step() > 0.0);
    if (accepted) {
      *accepted_value = value;
      return LineSearchResult::accepted;
    }
    if (outcome == StrongWolfeSearch::Outcome::stuck) break;
  }
  return LineSearchResult::failed;
}

}  // namespace asp
