#include "solvers/polonsky_keer.hpp"

#include <algorithm>
#include <cmath>

#include "core/checks.hpp"
#include "core/error.hpp"

namespace asp {

void PolonskyKeer::check_target(Control control, double value) const {
  if (control == Control::mean_pressure) {
    require_non_negative(value, "value");  // a hard wall without adhesion cannot pull
  } else {
    require_finite(value, "value");
  }
}

namespace {

// gap = backward(scale * compliance * forward(p)): the displacement of scale*p. Uses the
// spectrum buffer as scratch.
void compliance_product(const Grid &grid, const Field &compliance, const double *p, double scale,
                        Spectrum &spectrum, double *out) {
  const FftEngine &fft = grid.fft();
  fft.forward(p, spectrum.data());
  const std::size_t m = spectrum.size();
  Complex *s = spectrum.data();
  const double *c = compliance.data();
  for (std::size_t k = 0; k < m; ++k) s[k] *= scale * c[k];
  fft.backward(spectrum.data(), out);
}

}  // namespace

void PolonskyKeer::run(System &system, Control control, double value, SolveReport &report) {
  const Grid &grid = system.grid();
  const Reductions &reduce = grid.reductions();
  const PeriodicHalfSpace &substrate = system.substrate();
  const bool load_control = control == Control::mean_pressure;
  const std::int64_t n = grid.n_pixels();
  const double n_total = static_cast<double>(n);

  // Work arrays first: if memory runs out, the system's state is untouched.
  Field search = grid.make_field();    // t: search direction, zero off the contact set
  Field response = grid.make_field();  // r = K^-1 t
  Spectrum spectrum = grid.make_spectrum();
  const Field &compliance = substrate.normalised_compliance();

  ContactState &state = system.state();
  double *p = state.pressure.data();
  double *g = state.gap.data();
  double *t = search.data();
  double *r = response.data();
  const double *h = system.heights().data();
  const double h_max = system.max_height();

  const double k_pixel = substrate.pixel_stiffness();
  const double control_scale =
      load_control ? value : substrate.k0() * std::fabs(value);
  const double p_ref = system.reference_pressure(control_scale);
  system.remember_reference_pressure(p_ref);
  const double error_scale = k_pixel / p_ref;

  // Starting point. Load control: the stored pressure rescaled to the target mean, or a
  // uniform pressure. Penetration control: the stored pressure, or, from rest, each
  // interpenetrating pixel pushed back by its own stiffness.
  // Zero load: the body just touches the highest point, so the penetration starts (and ends) at 0.
  double delta = load_control ? (value == 0.0 ? 0.0 : state.penetration) : value;
  double scale = 1.0;  // pending factor on p, applied while the gap is computed
  {
    double sum_p = 0.0;
    for (std::int64_t i = 0; i < n; ++i) {
      p[i] = std::max(p[i], 0.0);
      sum_p += p[i];
    }
    reduce.combine_sums(&sum_p, 1);
    if (load_control) {
      if (value == 0.0 || sum_p <= 0.0) {
        std::fill(p, p + n, value);
      } else {
        scale = value * n_total / sum_p;
      }
    } else if (sum_p <= 0.0) {
      for (std::int64_t i = 0; i < n; ++i) p[i] = k_pixel * std::max(h[i] - h_max + delta, 0.0);
    }
  }

  double g_norm_old = 1.0;
  bool conjugate = false;  // Polonsky & Keer's delta: 0 right after the contact set grew
  std::int64_t iteration = 0;
  double error = 0.0;
  for (;; ++iteration) {
    // Gap of the current pressure; pass A applies the pending scale and sums over the
    // contact set I_c = {p > 0}.
    compliance_product(grid, compliance, p, scale, spectrum, g);
    double sums_a[3] = {0.0, 0.0, 0.0};  // sum g, sum g^2, count over I_c
    const double offset = h_max - delta;
    for (std::int64_t i = 0; i < n; ++i) {
      p[i] *= scale;
      const double gi = g[i] - h[i] + offset;
      g[i] = gi;
      if (p[i] > 0.0) {
        sums_a[0] += gi;
        sums_a[1] += gi * gi;
        sums_a[2] += 1.0;
      }
    }
    scale = 1.0;
    reduce.combine_sums(sums_a, 3);
    const double n_contact = sums_a[2];
    // Under load control the penetration is whatever closes the mean gap on I_c.
    const double shift = load_control && n_contact > 0.0 ? sums_a[0] / n_contact : 0.0;
    delta += shift;
    const double g_norm =
        std::max(sums_a[1] - 2.0 * shift * sums_a[0] + n_contact * shift * shift, 0.0);
    const double beta = conjugate ? g_norm / g_norm_old : 0.0;

    // Pass B: centre the gap, measure the projected gradient, update the search direction.
    double violation = 0.0;
    for (std::int64_t i = 0; i < n; ++i) {
      const double gi = g[i] - shift;
      g[i] = gi;
      if (p[i] > 0.0) {
        violation = std::max(violation, std::fabs(gi));
        t[i] = gi + beta * t[i];
      } else {
        violation = std::max(violation, -gi);
        t[i] = 0.0;
      }
    }
    reduce.combine_maxima(&violation, 1);
    error = violation * error_scale;
    if (!std::isfinite(error)) {
      // Cannot happen for finite input; if it ever does, leave a clean state and say so
      // rather than hand NaN to the caller.
      system.reset_state();
      report.iterations = iteration;
      report.error = HUGE_VAL;
      report.converged = false;
      return;
    }
    if (error <= options_.tolerance || iteration >= options_.max_iterations) break;
    g_norm_old = g_norm;

    if (n_contact == 0.0) {
      // Nothing carries load (penetration control from a state with no contact): restart
      // from each interpenetrating pixel pushed back by its own stiffness.
      for (std::int64_t i = 0; i < n; ++i) p[i] = k_pixel * std::max(-g[i], 0.0);
      conjugate = false;
      continue;
    }

    // Step length along t: the exact line minimum of the (centred) quadratic on I_c.
    compliance_product(grid, compliance, t, 1.0, spectrum, r);
    double sums_c[4] = {0.0, 0.0, 0.0, 0.0};  // sum r, sum t, sum r t, sum g t over I_c
    for (std::int64_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        sums_c[0] += r[i];
        sums_c[1] += t[i];
        sums_c[2] += r[i] * t[i];
        sums_c[3] += g[i] * t[i];
      }
    }
    reduce.combine_sums(sums_c, 4);
    const double r_mean = load_control ? sums_c[0] / n_contact : 0.0;
    const double curvature = sums_c[2] - r_mean * sums_c[1];
    if (!(curvature > 0.0)) break;  // t = 0 on I_c: nothing left to descend along
    const double tau = sums_c[3] / curvature;

    // Pass D: step, project onto p >= 0, and let pixels with negative gap enter the contact.
    double sums_d[2] = {0.0, 0.0};  // sum p, number of pixels that entered
    for (std::int64_t i = 0; i < n; ++i) {
      double pi = p[i];
      if (pi > 0.0) pi = std::max(pi - tau * t[i], 0.0);
      if (pi == 0.0 && g[i] < 0.0) {
        pi = -tau * g[i];
        sums_d[1] += 1.0;
      }
      p[i] = pi;
      sums_d[0] += pi;
    }
    reduce.combine_sums(sums_d, 2);
    conjugate = sums_d[1] == 0.0;
    if (load_control) {
      if (sums_d[0] > 0.0) {
        scale = value * n_total / sums_d[0];
      } else {
        std::fill(p, p + n, value);
        conjugate = false;
      }
    }
  }

  state.penetration = delta;
  report.iterations = iteration;
  report.error = error;
  report.converged = error <= options_.tolerance;
}

}  // namespace asp
