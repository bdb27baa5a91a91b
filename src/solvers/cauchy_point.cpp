// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/cauchy_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/loops.hpp"

namespace asp {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double epsilon = std::numeric_limits<double>::epsilon();

// Over the unknowns of a set, listed (in increasing order) either themselves or, if
// `complement`, by the unknowns outside it: the sums of g_i w_i into a (2k entries) and of
// w_i w_i^T into gram (2k x 2k), with w_i row i of W. A complement's
// sums are subtracted from the totals W^T g and W^T W that the compact matrix keeps: so that
// only the few unknowns in (or out of) contact are visited. With `kept` (2k entries per
// listed unknown), the rows gathered stay there (kept_row_entry).
void sums_over_list(const Indices &list, bool complement, const double *g,
                    const CompactBfgs &bfgs, const Reductions &reductions, double *a,
                    double *gram, double *kept) {
  const int k2 = bfgs.columns();
  const std::int64_t listed = static_cast<std::int64_t>(list.size());
  const int count = k2 + k2 * k2;
  std::vector<double> sums(static_cast<std::size_t>(count));
  // A block of listed unknowns at a time: their rows of W are gathered, the rows a few
  // entries ahead fetched while one is copied (the list's gaps defeat the prefetchers), and
  // the products are then dot products over the block.
  constexpr std::int64_t block = kept_row_block;
  loops::block_sums(reductions, listed, count, sums.data(),
                    [&](std::int64_t begin, std::int64_t end, double *sum) {
                      const std::int64_t length = end - begin;
                      const std::int64_t *at = list.data() + begin;
                      // The rows and g at the block (unless kept), then the products of
                      // one row with the others.
                      std::vector<double> scratch(
                          static_cast<std::size_t>((kept != nullptr ? 1 : k2 + 1) * block + k2));
                      double *rows = kept != nullptr ? kept + begin * k2 : scratch.data();
                      double *gl = scratch.data() + (kept != nullptr ? 0 : k2 * block);
                      // A kept block's columns lie at its own length apart.
                      const std::int64_t stride = kept != nullptr ? length : block;
                      constexpr std::int64_t ahead = 8;
                      for (std::int64_t p = 0; p < length; ++p) {
                        if (begin + p + ahead < listed) bfgs.prefetch_row(at[p + ahead]);
                        const std::int64_t i = at[p];
                        gl[p] = g[i];
                        for (int j = 0; j < k2; ++j) rows[j * stride + p] = bfgs.column(j)[i];
                      }
                      const auto dot_block = [&](const double *a, const double *b) {
                        double total = 0.0;
#pragma omp simd reduction(+ : total)
                        for (std::int64_t p = 0; p < length; ++p) total += a[p] * b[p];
                        return total;
                      };
                      const auto row = [&](int j) { return rows + j * stride; };
                      // Four products with one row at a time: a product alone is a chain
                      // of additions, each waiting for the last; four are independent.
                      const auto four_dots = [&](const double *a, const double *b,
                                                 double *out) {
                        double t0 = 0.0, t1 = 0.0, t2 = 0.0, t3 = 0.0;
                        const double *b0 = b, *b1 = b + stride, *b2 = b + 2 * stride,
                                     *b3 = b + 3 * stride;
#pragma omp simd reduction(+ : t0, t1, t2, t3)
                        for (std::int64_t p = 0; p < length; ++p) {
                          t0 += a[p] * b0[p];
                          t1 += a[p] * b1[p];
                          t2 += a[p] * b2[p];
                          t3 += a[p] * b3[p];
                        }
                        out[0] = t0;
                        out[1] = t1;
                        out[2] = t2;
                        out[3] = t3;
                      };
                      const auto products_with = [&](const double *a, int first, double *out) {
                        int c = first;
                        for (; c + 4 <= k2; c += 4) four_dots(a, row(c), out + (c - first));
                        for (; c < k2; ++c) out[c - first] = dot_block(a, row(c));
                      };
                      double *dots = scratch.data() + scratch.size() - k2;
                      products_with(gl, 0, dots);
                      for (int j = 0; j < k2; ++j) sum[j] += bfgs.scale(j) * dots[j];
                      for (int r = 0; r < k2; ++r) {
                        products_with(row(r), r, dots);
                        for (int c = r; c < k2; ++c)
                          sum[k2 + r * k2 + c] += bfgs.scale(r) * bfgs.scale(c) * dots[c - r];
                      }
                    });
  const std::vector<double> &wtg = bfgs.times_gradient(), &wtw = bfgs.gram();
  for (int j = 0; j < k2; ++j) a[j] = complement ? wtg[j] - sums[j] : sums[j];
  for (int r = 0; r < k2; ++r)
    for (int c = r; c < k2; ++c) {
      const std::size_t rc = static_cast<std::size_t>(r) * k2 + c;
      const double v = complement ? wtw[rc] - sums[k2 + rc] : sums[k2 + rc];
      gram[rc] = v;
      gram[static_cast<std::size_t>(c) * k2 + r] = v;
    }
}

double dot(const std::vector<double> &a, const std::vector<double> &b) {
  double sum = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) sum += a[j] * b[j];
  return sum;
}

}  // namespace

CauchyPoint generalized_cauchy_point(const double *x, const double *g, std::int64_t n,
                                     std::int64_t bounded, double lower,
                                     const CompactBfgs &bfgs, const Reductions &reductions,
                                     CauchyWork &work) {
  const Bound bound{bounded, lower};
  const int k2 = bfgs.columns();
  const double theta = bfgs.theta();
  const auto size = static_cast<std::size_t>(k2);
  CauchyPoint cauchy;
  cauchy.c.assign(size, 0.0);

  // The direction d = -g, zero where the bound holds the unknown (t_i = 0); the slope
  // f' = g.d and p = W^T d. One pass counts the unknowns the bound holds, sums the slope,
  // lists the unknowns off the bound (or those on it, if fewer), for the sums over the free
  // set, and collects the breakpoints t_i = (x_i - lower)/g_i (below), which then go into a
  // heap, smallest first. Which of the two sets to list is known only after the count: the
  // pass lists the one the last call listed, and a second pass lists the other if that guess
  // was wrong (or if there was no last call: a first guess would be wrong half the time, and
  // on a large set). The pass
  // is serial, as its lists are; its sums, chunk by chunk as the loops' (for their
  // rounding), do not depend on the thread count. The entries of the lists go first to
  // small buffers, written without a branch or a call (which would send the sums to memory
  // at every entry), and from there to the lists.
  using Listed = CauchyWork::Listed;
  const Listed guess = work.last_listed;
  Indices &list = work.list;
  Breakpoints &heap = work.heap;
  list.clear();
  heap.clear();
  const bool listing_now = k2 > 0 && guess != Listed::none_yet;
  const bool list_held = guess == Listed::on_bound;
  // The breakpoint of an unknown off the bound that g pushes towards it (the division by 1
  // elsewhere only keeps every entry's arithmetic harmless), and whether it has one. Every
  // unknown off the bound is free: when the pass lists the free set, their breakpoints come
  // from the list afterwards, a division for each listed unknown instead of one for every
  // unknown.
  const auto breakpoint_at = [](double xi, double gi, double bi) {
    return (xi - bi) / (gi > 0.0 ? gi : 1.0);
  };
  const auto has_breakpoint = [](double xi, double gi, double bi, double t) {
    return gi > 0.0 && xi > bi && std::isfinite(t);
  };
  const bool breakpoints_in_pass = !(listing_now && !list_held);
  // The pass is a template on whether it collects them, so that its loop carries no test of
  // that.
  constexpr std::int64_t buffered = 512;
  std::int64_t listed_buffer[buffered];
  Breakpoint breakpoint_buffer[buffered];
  double sums[2] = {0.0, 0.0};
  const auto pass = [&](auto with_breakpoints) {
    for (std::int64_t chunk = 0; chunk < n; chunk += loops::chunk_entries) {
      std::int64_t held_count = 0;
      double slope_sum = 0.0;
      const std::int64_t chunk_end = std::min(n, chunk + loops::chunk_entries);
      for (std::int64_t begin = chunk; begin < chunk_end; begin += buffered) {
        const std::int64_t end = std::min(chunk_end, begin + buffered);
        std::int64_t listed = 0, broken = 0, held_here = 0;
        // The slope in two sums, the entries taken in turn: in one, each addition waits for
        // the last, and that chain set the pass's pace (the count is an integer's).
        double slope_even = 0.0, slope_odd = 0.0;
        const auto entry = [&](std::int64_t i, double &slope) {
          const double xi = x[i], gi = g[i], bi = bound(i);
          const bool held = at_bound(xi, gi, bi, 0.0);
          held_here += held ? 1 : 0;
          slope += held ? 0.0 : gi * gi;
          listed_buffer[listed] = i;
          listed += listing_now && held == list_held ? 1 : 0;
          if constexpr (decltype(with_breakpoints)::value) {
            const double t = breakpoint_at(xi, gi, bi);
            breakpoint_buffer[broken] = {t, i};
            broken += has_breakpoint(xi, gi, bi, t) ? 1 : 0;
          }
        };
        std::int64_t i = begin;
        for (; i + 2 <= end; i += 2) {
          entry(i, slope_even);
          entry(i + 1, slope_odd);
        }
        if (i < end) entry(i, slope_even);
        held_count += held_here;
        slope_sum += slope_even + slope_odd;
        list.insert(list.end(), listed_buffer, listed_buffer + listed);
        heap.insert(heap.end(), breakpoint_buffer, breakpoint_buffer + broken);
      }
      sums[0] += static_cast<double>(held_count);
      sums[1] += slope_sum;
    }
  };
  if (breakpoints_in_pass)
    pass(std::true_type{});
  else
    pass(std::false_type{});
  reductions.combine_sums(sums, 2);
  const auto held = static_cast<std::int64_t>(sums[0]);
  double unknowns = static_cast<double>(n);
  reductions.combine_sums(&unknowns, 1);
  const auto total = static_cast<std::int64_t>(unknowns);
  double slope = -sums[1];
  cauchy.at_bound = held;
  const bool complement = list_complement(total - held, total);
  const Listed listing = complement ? Listed::on_bound : Listed::free;
  if (k2 > 0 && listing != guess) {
    list.clear();
    const auto listed = [&](std::int64_t i) {
      return at_bound(x[i], g[i], bound(i), 0.0) == complement;
    };
    loops::select(n, listed, list);
  }
  work.last_listed = listing;
  if (!breakpoints_in_pass) {
    // In increasing order of the unknowns, as from the pass: the heap is the same.
    const auto add = [&](std::int64_t i) {
      const double xi = x[i], gi = g[i], bi = bound(i), t = breakpoint_at(xi, gi, bi);
      if (has_breakpoint(xi, gi, bi, t)) heap.push_back({t, i});
    };
    if (listing == Listed::free) {
      for (const std::int64_t i : list) add(i);
    } else {
      for (std::int64_t i = 0; i < n; ++i) add(i);
    }
  }
  const auto later = [](const Breakpoint &a, const Breakpoint &b) { return a.t > b.t; };
  std::make_heap(heap.begin(), heap.end(), later);
  cauchy.listed_free = k2 > 0 && !complement;
  cauchy.free_gradient.assign(size, 0.0);
  cauchy.free_gram.assign(size * size, 0.0);
  // The rows gathered at the free unknowns are kept for the subspace minimisation when they
  // are few (an eighth of the unknowns at most: 2k/8 fields of memory).
  cauchy.kept_rows = cauchy.listed_free && static_cast<std::int64_t>(list.size()) <= n / 8;
  Field &rows = work.rows;
  if (cauchy.kept_rows && rows.size() < list.size() * size) rows = Field(list.size() * size);
  if (k2 > 0)
    sums_over_list(list, complement, g, bfgs, reductions, cauchy.free_gradient.data(),
                   cauchy.free_gram.data(), cauchy.kept_rows ? rows.data() : nullptr);
  if (!(slope < 0.0)) return cauchy;  // the path does not move: x is its own Cauchy point

  // M p and M c are carried along with p and c, so that a segment needs one product with M.
  // p = W^T d = -(the sum of g_i w_i over the free set).
  std::vector<double> p(size), mp(size), mc(size, 0.0), w(size), mw(size);
  for (std::size_t j = 0; j < size; ++j) p[j] = -cauchy.free_gradient[j];
  if (k2 > 0) bfgs.times_middle(p.data(), mp.data());
  // f'' = d.B d = -theta f' - p.M p.
  double curvature = -theta * slope - dot(p, mp);
  const double initial_curvature = curvature;
  double to_minimum = -slope / curvature;

  // Segment after segment, until the minimum of the model lies inside one. The next
  // breakpoint is the smallest over all processes: each offers its own smallest, with what
  // the step needs of it (g_b, z_b and row b of W), and every process takes the winner's.
  double t = 0.0;
  std::vector<double> offer(2 + size);
  for (;;) {
    double next = infinity;
    if (!heap.empty()) {
      const Breakpoint &b = heap.front();
      next = b.t;
      offer[0] = g[b.i];
      offer[1] = bound(b.i) - x[b.i];
      for (int j = 0; j < k2; ++j) offer[2 + j] = bfgs.entry(j, b.i);
    }
    const bool mine = reductions.select_smallest(next, offer.data(), static_cast<int>(offer.size()));
    if (next == infinity) break;
    const double length = next - t;
    if (to_minimum < length) break;
    if (mine) {
      std::pop_heap(heap.begin(), heap.end(), later);
      heap.pop_back();
    }
    ++cauchy.at_bound;
    // Unknown b reaches the bound: z_b = lower - x_b, and it leaves the direction.
    const double gb = offer[0], zb = offer[1];
    for (std::size_t j = 0; j < size; ++j) {
      cauchy.c[j] += length * p[j];
      mc[j] += length * mp[j];
    }
    for (int j = 0; j < k2; ++j) w[j] = offer[2 + j];
    if (k2 > 0) bfgs.times_middle(w.data(), mw.data());
    slope += length * curvature + gb * gb + theta * gb * zb - gb * dot(w, mc);
    curvature += -theta * gb * gb - 2.0 * gb * dot(mw, p) - gb * gb * dot(w, mw);
    // Rounding must not make the model's curvature vanish or change sign.
    curvature = std::max(epsilon * initial_curvature, curvature);
    for (std::size_t j = 0; j < size; ++j) {
      p[j] += gb * w[j];
      mp[j] += gb * mw[j];
      for (std::size_t c = 0; c < size; ++c) cauchy.free_gram[j * size + c] -= w[j] * w[c];
    }
    to_minimum = -slope / curvature;
    t = next;
  }
  to_minimum = std::max(to_minimum, 0.0);
  cauchy.t = t + to_minimum;
  for (std::size_t j = 0; j < size; ++j) {
    cauchy.c[j] += to_minimum * p[j];
    cauchy.free_gradient[j] = -p[j];
  }
  return cauchy;
}

}  // namespace asp
