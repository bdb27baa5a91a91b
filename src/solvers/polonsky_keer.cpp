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

// gap = backward(scale * compliance * forward(p) - heights) + offset, where `heights` is the
// spectrum of h divided by N: the gap in one transform pair and one pass over the spectrum.
void gap_of(const Grid &grid, const Field &compliance, const Spectrum &heights, const double *p,
            double scale, double offset, Spectrum &spectrum, double *gap) {
  const FftEngine &fft = grid.fft();
  fft.forward(p, spectrum.data());
  const std::size_t m = spectrum.size();
  Complex *s = spectrum.data();
  const Complex *hs = heights.data();
  const double *c = compliance.data();
  for (std::size_t k = 0; k < m; ++k) s[k] = scale * c[k] * s[k] - hs[k];
  s[0] += offset;  // a constant in every pixel after the unnormalised backward transform
  fft.backward(spectrum.data(), gap);
}

// t . K^-1 t from the spectrum alone (Parseval): the curvature of the energy along t, without
// transforming back.
double compliance_norm(const Grid &grid, const Field &compliance, const double *t,
                       Spectrum &spectrum) {
  grid.fft().forward(t, spectrum.data());
  const Complex *s = spectrum.data();
  const double *c = compliance.data();
  const std::int64_t snx = grid.spectral_nx();
  double sum = 0.0;
  for (std::int64_t ky = 0; ky < grid.ny(); ++ky) {
    const std::size_t row = static_cast<std::size_t>(snx * ky);
    double row_sum = 0.0;
#pragma omp simd reduction(+ : row_sum)
    for (std::int64_t kx = 0; kx < snx; ++kx)
      row_sum += c[row + kx] * std::norm(s[row + kx]);
    // Every entry stands for itself and its mirror, except kx = 0 and an even Nyquist column.
    row_sum *= 2.0;
    row_sum -= c[row] * std::norm(s[row]);
    if (grid.nx() % 2 == 0 && snx > 1)
      row_sum -= c[row + snx - 1] * std::norm(s[row + snx - 1]);
    sum += row_sum;
  }
  grid.reductions().combine_sums(&sum, 1);
  return sum;
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
  Field search = grid.make_field();  // t: search direction, zero off the contact set
  Spectrum spectrum = grid.make_spectrum();
  Spectrum height_spectrum = grid.make_spectrum();  // FFT(h)/N
  const Field &compliance = substrate.normalised_compliance();

  ContactState &state = system.state();
  double *p = state.pressure.data();
  double *g = state.gap.data();
  double *t = search.data();
  const double *h = system.heights().data();
  const double h_max = system.max_height();

  const double k_pixel = substrate.pixel_stiffness();
  const double control_scale = load_control ? value : substrate.k0() * std::fabs(value);
  const double p_ref = system.reference_pressure(control_scale);
  system.remember_reference_pressure(p_ref);
  const double error_scale = k_pixel / p_ref;

  grid.fft().forward(h, height_spectrum.data());
  for (auto &v : height_spectrum) v /= n_total;

  // Inside the loop the arrays hold p/scale and g + shift: rescaling the pressure to the
  // target mean and centring the gap on the contact set are carried as two numbers and folded
  // into the next pass over the data, instead of costing passes of their own.
  double scale = 1.0;
  double shift = 0.0;

  // Starting point. Load control: the stored pressure rescaled to the target mean, or a
  // uniform pressure. Penetration control: the stored pressure; from rest (no pressure) the
  // first iteration finds no contact and restarts from the interpenetration, below. Zero load:
  // the body just touches the highest point, so the penetration starts (and ends) at 0.
  double delta = load_control ? (value == 0.0 ? 0.0 : state.penetration) : value;
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
    }
  }

  double g_norm_old = 1.0;
  double sum_t_on_contact = 0.0;  // sum of the old direction over the new contact set
  bool conjugate = false;  // Polonsky & Keer's delta: 0 right after the contact set grew
  std::int64_t iteration = 0;
  double error = 0.0;
  for (;; ++iteration) {
    // Gap of the current pressure, and sums over the contact set I_c = {p > 0}.
    gap_of(grid, compliance, height_spectrum, p, scale, h_max - delta, spectrum, g);
    double sum_g = 0.0, sum_g2 = 0.0, n_contact = 0.0;
#pragma omp simd reduction(+ : sum_g, sum_g2, n_contact)
    for (std::int64_t i = 0; i < n; ++i) {
      const double in = p[i] > 0.0 ? 1.0 : 0.0;
      const double gi = in * g[i];
      sum_g += gi;
      sum_g2 += gi * gi;
      n_contact += in;
    }
    double sums_a[3] = {sum_g, sum_g2, n_contact};
    reduce.combine_sums(sums_a, 3);
    n_contact = sums_a[2];
    // Under load control the penetration is whatever closes the mean gap on I_c.
    shift = load_control && n_contact > 0.0 ? sums_a[0] / n_contact : 0.0;
    delta += shift;
    const double g_norm =
        std::max(sums_a[1] - 2.0 * shift * sums_a[0] + n_contact * shift * shift, 0.0);
    const double beta = conjugate ? g_norm / g_norm_old : 0.0;
    // The old direction, made mean-free on the current contact set (load control), so that a
    // step along t keeps the mean pressure and the step length needs no centred product.
    const double t_mean = load_control && n_contact > 0.0 ? sum_t_on_contact / n_contact : 0.0;

    // Projected gradient (the error) and the new search direction.
    // (Branch-free on purpose: selects and maxima written so that the loop vectorises.)
    double violation = 0.0, sum_gt = 0.0;
#pragma omp simd reduction(max : violation) reduction(+ : sum_gt)
    for (std::int64_t i = 0; i < n; ++i) {
      const double gi = g[i] - shift;
      const bool in = p[i] > 0.0;
      const double ti = in ? gi + beta * (t[i] - t_mean) : 0.0;
      t[i] = ti;
      const double v = in ? std::fabs(gi) : -gi;
      violation = violation > v ? violation : v;
      sum_gt += gi * ti;
    }
    reduce.combine_maxima(&violation, 1);
    reduce.combine_sums(&sum_gt, 1);
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
      // Nothing carries load (penetration control from rest, or a state without contact):
      // start from each interpenetrating pixel pushed back by its own stiffness.
      for (std::int64_t i = 0; i < n; ++i) p[i] = k_pixel * std::max(-(g[i] - shift), 0.0);
      scale = 1.0;
      conjugate = false;
      continue;
    }

    // Exact line minimum along t of the quadratic energy.
    const double curvature = compliance_norm(grid, compliance, t, spectrum);
    if (!(curvature > 0.0)) break;  // t = 0: nothing left to descend along
    const double tau = sum_gt / curvature;

    // Step, project onto p >= 0, and let pixels with negative gap enter the contact set.
    double sum_p = 0.0, entered = 0.0, sum_t = 0.0;
#pragma omp simd reduction(+ : sum_p, entered, sum_t)
    for (std::int64_t i = 0; i < n; ++i) {
      const double gi = g[i] - shift;
      const double old_p = scale * p[i];
      const double stepped = old_p - tau * t[i];
      double pi = old_p > 0.0 ? stepped : 0.0;
      pi = pi > 0.0 ? pi : 0.0;
      const bool enters = (pi == 0.0) & (gi < 0.0);
      pi = enters ? -tau * gi : pi;
      entered += enters ? 1.0 : 0.0;
      sum_t += pi > 0.0 ? t[i] : 0.0;
      p[i] = pi;
      sum_p += pi;
    }
    double sums_d[3] = {sum_p, entered, sum_t};
    reduce.combine_sums(sums_d, 3);
    sum_t_on_contact = sums_d[2];
    conjugate = sums_d[1] == 0.0;
    scale = 1.0;
    if (load_control) {
      if (sums_d[0] > 0.0) {
        scale = value * n_total / sums_d[0];
      } else {
        std::fill(p, p + n, value);
        conjugate = false;
      }
    }
  }

  // Leave the true pressure and the centred gap in the state.
  for (std::int64_t i = 0; i < n; ++i) {
    p[i] *= scale;
    g[i] -= shift;
  }
  state.penetration = delta;
  report.iterations = iteration;
  report.error = error;
  report.converged = error <= options_.tolerance;
}

}  // namespace asp
