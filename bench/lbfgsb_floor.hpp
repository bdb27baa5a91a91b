// SPDX-License-Identifier: GPL-2.0-or-later
// What one evaluation of L-BFGS-B must cost beyond its transforms, measured: each pass the
// algorithm needs, written on its own at its best and timed on fields of the grid's size
// (the best of fifteen timings on each of three allocations), on the state a solve reached
// (the bench's scene, on the pressure). The floor of an iteration counted in field streams
// (pk_benchmark.cpp) prices every pass at the fields it reads and writes; some of
// L-BFGS-B's passes cost more than their traffic whatever their code: the new pair's
// 6m + 5 products per entry, the Cauchy point's lists and divisions, the projections'
// selects. These kernels are the measure of that part: they are not the library's passes,
// but the least each pass can be, fused where the algorithm allows (the monitor's error in
// the formulation's gradient pass, the breakpoints taken from the list of free unknowns),
// and vectorised by hand where the compiler keeps a comparison as a branch (the selects on
// two lanes, core/lanes.hpp's type, the baseline the library is built for; the pair's
// products in the best variant this CPU runs, as the library does).
//
// The passes, per evaluation (`m` stored pairs, the listed unknowns those in contact):
//   products  s = x - x_old, y = g - g_old and their products with g, s, y and the 2m stored
//             fields (16 fields at m = 5, 6m + 5 products per entry);
//   cauchy    one serial pass over x and g: the count of the unknowns on the bound, the slope,
//             the list of the free unknowns and their breakpoints, and then the heap of those;
//   step      d = max(x_bar, lower) - x and x_old = x with the slope, |d|^2 and the largest
//             feasible step, x_bar = lower on the bound and x - g/theta elsewhere, and the
//             model's correction on the listed unknowns from their rows kept by the Cauchy
//             point (the gather itself is pk_benchmark's `gather`);
//   trial     x = max(x_old + a d, lower);
//   slope     g.d at the trial point;
//   gradient  the dual formulation's: the compliance times the pressure's half spectrum,
//             then g = u - h - delta with the value sum x (u/2 - h - delta) and the bound's
//             residual (the monitor's error) in the same pass.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "core/aligned_field.hpp"
#include "core/instruction_sets.hpp"
#include "core/lanes.hpp"
#include "core/loops.hpp"
#include "solvers/pair_products.hpp"

namespace bench {

struct LbfgsbFloor {
  double products = 0.0, cauchy = 0.0, step = 0.0, trial = 0.0, slope = 0.0, gradient = 0.0;
  double total() const { return products + cauchy + step + trial + slope + gradient; }
};

namespace floor_kernels {

using asp::lanes::Pair;
using asp::lanes::store;
using Mask = decltype(Pair{} > Pair{});
constexpr int lanes = asp::lanes::width<Pair>;

inline Pair load(const double *p) { return asp::lanes::load<Pair>(p); }
inline Pair splat(double a) { return asp::lanes::splat<Pair>(a); }
inline Pair select(Mask mask, Pair a, Pair b) { return mask ? a : b; }
inline Pair larger(Pair a, Pair b) { return select(a > b, a, b); }

// The best of fifteen timings of f(), in seconds: on this shared machine one pass's best of
// five still moved by half between runs (the step's from 10 to 18 streams).
template <class F>
double best_of(F &&f) {
  double best = 1e300;
  for (int batch = 0; batch < 15; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                              .count());
  }
  return best;
}

}  // namespace floor_kernels

// One measure of every pass, on fields allocated for it: x the pressure a solve reached and
// g its gap (the gradient on the pressure), n entries, memory m; on one thread.
inline LbfgsbFloor lbfgsb_floor_once(const std::vector<double> &pressure,
                                     const std::vector<double> &gap, int memory) {
  using namespace floor_kernels;
  const auto n = static_cast<std::int64_t>(pressure.size());
  const auto size = static_cast<std::size_t>(n);
  const int k2 = 2 * memory;
  const double lower = 0.0, theta = 2.0, step = 0.75;
  asp::Field x(size), g(size), x_old(size), g_old(size), d(size), h(size);
  for (std::size_t i = 0; i < size; ++i) {
    x[i] = pressure[i];
    g[i] = gap[i];
    x_old[i] = 0.9 * pressure[i];
    g_old[i] = 0.9 * gap[i] + 1e-3;
    h[i] = 0.5 * gap[i];
  }
  std::vector<asp::Field> stored(static_cast<std::size_t>(k2), asp::Field(size, 1e-3));
  std::vector<const double *> stored_s, stored_y;
  for (int j = 0; j < memory; ++j) {
    stored_s.push_back(stored[2 * j].data());
    stored_y.push_back(stored[2 * j + 1].data());
  }
  LbfgsbFloor floor;
  double sink = 0.0;  // keeps every kernel's results alive
  // The kernels read and write through local pointers, as the library's do: through the
  // captured fields every store would make them load their pointers again.
  double *xp = x.data(), *gp = g.data(), *x_oldp = x_old.data(), *g_oldp = g_old.data(),
         *dp = d.data(), *hp = h.data();

  // products: the library's kernel in the best variant this CPU runs, in the library's
  // blocks (the stored fields read in pieces the prefetchers follow). It turns x_old and
  // g_old into s and y in place, as the library does; timed again and again, they take
  // other (finite) values, at the same cost.
  {
    const asp::PairProducts products = asp::pair_products(asp::best_kernel_variant());
    const asp::PairBlock block{x.data(),        g.data(),        x_old.data(), g_old.data(),
                               stored_s.data(), stored_y.data(), memory};
    std::vector<double> sums(static_cast<std::size_t>(6 * memory + 5));
    const std::int64_t piece = asp::loops::sweep_block(n);
    floor.products = best_of([&] {
      std::fill(sums.begin(), sums.end(), 0.0);
      for (std::int64_t b = 0; b < n; b += piece)
        products(block, b, std::min(n, b + piece), sums.data());
      sink += sums[0];
    });
  }

  // cauchy: one pass lists the free unknowns (without a branch); their breakpoints, a division
  // each, come from the list (an unknown on the bound has none), and then their heap.
  std::vector<std::int64_t> list(size);
  std::int64_t listed = 0;
  {
    struct Breakpoint {
      double t;
      std::int64_t i;
    };
    std::vector<Breakpoint> breakpoints(size);
    floor.cauchy = best_of([&] {
      const double *x = xp, *g = gp;
      std::int64_t *at = list.data();
      Breakpoint *found = breakpoints.data();
      double held = 0.0, slope = 0.0;
      listed = 0;
      for (std::int64_t i = 0; i < n; ++i) {
        const double xi = x[i], gi = g[i];
        const bool on_bound = gi > 0.0 && xi <= lower;
        held += on_bound ? 1.0 : 0.0;
        slope += on_bound ? 0.0 : gi * gi;
        at[listed] = i;
        listed += on_bound ? 0 : 1;
      }
      std::int64_t broken = 0;
      for (std::int64_t p = 0; p < listed; ++p) {
        const std::int64_t i = at[p];
        const double xi = x[i], gi = g[i];
        found[broken] = {(xi - lower) / (gi > 0.0 ? gi : 1.0), i};
        broken += gi > 0.0 && xi > lower ? 1 : 0;
      }
      std::make_heap(breakpoints.begin(), breakpoints.begin() + broken,
                     [](const Breakpoint &a, const Breakpoint &b) { return a.t > b.t; });
      sink += held + slope;
    });
  }

  // step: the pass over every unknown, then the listed ones' correction from kept rows.
  {
    asp::Field kept(static_cast<std::size_t>(listed) * k2 + 1, 1e-3);
    std::vector<double> weight(static_cast<std::size_t>(k2), 0.5);
    const double inverse_theta = 1.0 / theta;
    floor.step = best_of([&] {
      const double *x = xp, *g = gp, *rows = kept.data(), *w = weight.data();
      const std::int64_t *at = list.data();
      double *d = dp, *x_old = x_oldp;
      const Pair zero = splat(0.0), bound = splat(lower), t = splat(0.0);
      const Pair minus_one = splat(-1.0), none = splat(-std::numeric_limits<double>::infinity());
      const Pair scale = splat(inverse_theta);
      Pair slope = zero, norm = zero, max = none;
      std::int64_t i = 0;
      for (; i + lanes <= n; i += lanes) {
        const Pair xi = load(&x[i]), gi = load(&g[i]);
        store(&x_old[i], xi);
        const Mask fixed = (gi > zero) & (xi - bound <= t * gi);
        const Pair to_bound = bound - xi;
        const Pair di = select(fixed, to_bound, zero);
        store(&d[i], select(fixed, to_bound, xi - gi * scale));
        slope += gi * di;
        norm += di * di;
        max = larger(max, select(di < zero, minus_one, none));
      }
      double sums[2] = {asp::lanes::lane_sum(slope), asp::lanes::lane_sum(norm)};
      double largest = asp::lanes::lane_max(max);
      for (; i < n; ++i) d[i] = x_old[i] = x[i];
      for (std::int64_t p = 0; p < listed; ++p) {
        const std::int64_t j = at[p];
        double correction = 0.0;
        for (int c = 0; c < k2; ++c) correction += rows[c * listed + p] * w[c];
        const double x_bar = d[j] + correction;
        const double dj = (x_bar > lower ? x_bar : lower) - x[j];
        d[j] = dj;
        sums[0] += g[j] * dj;
        sums[1] += dj * dj;
        const double limit = dj < 0.0 ? (x[j] - lower) / dj : largest;
        largest = limit > largest ? limit : largest;
      }
      sink += sums[0] + sums[1] + largest;
    });
  }

  // trial: x = max(x_old + a d, lower).
  {
    asp::Field trial(size);
    floor.trial = best_of([&] {
      const double *x_old = x_oldp, *d = dp;
      double *out = trial.data();
      const Pair a = splat(step), bound = splat(lower);
      std::int64_t i = 0;
      for (; i + lanes <= n; i += lanes)
        store(&out[i], larger(load(&x_old[i]) + a * load(&d[i]), bound));
      for (; i < n; ++i) out[i] = std::max(x_old[i] + step * d[i], lower);
    });
    sink += trial[size / 2];
  }

  // slope: g.d.
  floor.slope = best_of([&] {
    const double *g = gp, *d = dp;
    double total = 0.0;
#pragma omp simd reduction(+ : total)
    for (std::int64_t i = 0; i < n; ++i) total += g[i] * d[i];
    sink += total;
  });

  // gradient: the compliance on the half spectrum, then one pass for g, the value and the
  // bound's residual.
  {
    const std::size_t half = size / 2 + static_cast<std::size_t>(std::sqrt(double(n)));
    std::vector<std::complex<double>> spectrum(half, {1.0, 0.5});
    asp::Field compliance(half, 0.25), u(size, 1.0);
    const double *up = u.data();
    floor.gradient = best_of([&] {
      double *s = reinterpret_cast<double *>(spectrum.data());
      const double *c = compliance.data(), *u = up, *h = hp, *x = xp;
      double *g = g_oldp;
#pragma omp simd
      for (std::size_t k = 0; k < half; ++k) {
        s[2 * k] *= c[k];
        s[2 * k + 1] *= c[k];
      }
      const Pair delta = splat(0.125), half_pair = splat(0.5), zero = splat(0.0);
      Pair value = zero, residual = zero;
      std::int64_t i = 0;
      for (; i + lanes <= n; i += lanes) {
        const Pair ui = load(&u[i]), hi = load(&h[i]), xi = load(&x[i]);
        const Pair gi = ui - hi - delta;
        store(&g[i], gi);
        value += xi * (half_pair * ui - hi - delta);
        // The bound's residual: |g| where the pressure is positive, g's negative part else.
        const Pair magnitude = larger(gi, -gi);
        residual = larger(residual, select(xi > zero, magnitude, larger(-gi, zero)));
      }
      sink += asp::lanes::lane_sum(value) + asp::lanes::lane_max(residual) + spectrum[1].real();
    });
  }
  if (sink == -1.0) std::printf(" ");
  return floor;
}

// Each pass's least time over three measures, each on fields of its own: whether a field
// gets huge pages (core/aligned_field.cpp) depends on the memory the system has free at
// that moment, and the step's pass took 10 streams on some fields and 20 on others.
inline LbfgsbFloor lbfgsb_floor_seconds(const std::vector<double> &pressure,
                                        const std::vector<double> &gap, int memory) {
  LbfgsbFloor least = lbfgsb_floor_once(pressure, gap, memory);
  for (int round = 1; round < 3; ++round) {
    const LbfgsbFloor next = lbfgsb_floor_once(pressure, gap, memory);
    least.products = std::min(least.products, next.products);
    least.cauchy = std::min(least.cauchy, next.cauchy);
    least.step = std::min(least.step, next.step);
    least.trial = std::min(least.trial, next.trial);
    least.slope = std::min(least.slope, next.slope);
    least.gradient = std::min(least.gradient, next.gradient);
  }
  return least;
}

}  // namespace bench
