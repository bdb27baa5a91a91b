// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/lbfgsb.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/loops.hpp"
#include "formulations/dual_formulation.hpp"
#include "solvers/line_search.hpp"
#include "formulations/primal_formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/nested_grids.hpp"

namespace asp {
namespace {

// The line search's parameters, L-BFGS-B's: sufficient decrease 1e-3, curvature 0.9 (loose,
// as quasi-Newton methods want, so that the unit step is nearly always taken), interval
// width 0.1; and at most 20 evaluations per search.
constexpr LineSearchSettings line_search_settings{1e-3, 0.9, 0.1, 20};
// The largest step of a search along a direction no bound limits.
constexpr double unbounded_step = 1e10;

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double epsilon = std::numeric_limits<double>::epsilon();

// Whether unknown i sits on the bound at the point t of the projected path x(t): it was on
// the bound with g pushing outwards (t = 0), or its breakpoint (x_i - lower)/g_i is at most
// t, tested without a division. The one place that decides it for every pass. (Where
// rounding makes it disagree with the heap's order, the unknown's breakpoint equals t to
// rounding: it is on the bound either way.)
inline bool at_bound(double x, double g, double lower, double t) {
  return g > 0.0 && x - lower <= t * g;
}

// The bound of unknown i: `lower` on the first `bounded` unknowns, none on the others. A
// value, so that the kernels hold it in registers.
struct Bound {
  std::int64_t bounded;
  double lower;
  double operator()(std::int64_t i) const { return i < bounded ? lower : -infinity; }
};

// An unknown's part of the direction from its x_bar: returns d = max(x_bar, bound) - x, and
// adds its shares of the sums g.d and d.d and of the maximum of -(step to the bound), whose
// negative is the largest feasible step. (The division is by d, or by -1 where d does not
// point to the bound: no lane divides by zero if the compiler evaluates both sides.)
inline double finish_unknown(double x, double g, double bound, double x_bar, double *sum,
                             double &max) {
  const double d = (x_bar > bound ? x_bar : bound) - x;
  sum[0] += g * d;
  sum[1] += d * d;
  const bool towards = d < 0.0;
  const double limit = towards ? -(bound - x) / (towards ? d : -1.0) : -infinity;
  max = max > limit ? max : limit;
  return d;
}

// Whether a set of about `size` of `total` unknowns (over all processes) is better listed by
// its complement: the same choice on every process, from global counts.
bool list_complement(std::int64_t size, std::int64_t total) { return size > total / 2; }

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
                      std::vector<double> scratch(
                          static_cast<std::size_t>((kept != nullptr ? 1 : k2 + 1) * block));
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
                      for (int j = 0; j < k2; ++j) sum[j] += bfgs.scale(j) * dot_block(gl, row(j));
                      for (int r = 0; r < k2; ++r)
                        for (int c = r; c < k2; ++c)
                          sum[k2 + r * k2 + c] +=
                              bfgs.scale(r) * bfgs.scale(c) * dot_block(row(r), row(c));
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
  const auto bound = [&](std::int64_t i) { return i < bounded ? lower : -infinity; };
  const int k2 = bfgs.columns();
  const double theta = bfgs.theta();
  const auto size = static_cast<std::size_t>(k2);
  CauchyPoint cauchy;
  cauchy.c.assign(size, 0.0);

  // The direction d = -g, zero where the bound holds the unknown (t_i = 0); the slope
  // f' = g.d and p = W^T d. One pass counts the unknowns the bound holds, sums the slope,
  // lists the unknowns off the bound (or those on it, if fewer), for the sums over the free
  // set, and puts the breakpoints t_i = (x_i - lower)/g_i in a heap, smallest first. Which of
  // the two sets to list is known only after the count: the pass lists the one the last
  // call listed, and a second pass lists the other if that guess was wrong (or if there was
  // no last call: a first guess would be wrong half the time, and on a large set). The pass
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
  constexpr std::int64_t buffered = 512;
  std::int64_t listed_buffer[buffered];
  Breakpoint breakpoint_buffer[buffered];
  double sums[2] = {0.0, 0.0};
  for (std::int64_t chunk = 0; chunk < n; chunk += loops::chunk_entries) {
    double held_count = 0.0, slope_sum = 0.0;
    const std::int64_t chunk_end = std::min(n, chunk + loops::chunk_entries);
    for (std::int64_t begin = chunk; begin < chunk_end; begin += buffered) {
      const std::int64_t end = std::min(chunk_end, begin + buffered);
      std::int64_t listed = 0, broken = 0;
      double held_here = 0.0, slope_here = 0.0;
      for (std::int64_t i = begin; i < end; ++i) {
        const double xi = x[i], gi = g[i], bi = bound(i);
        const bool held = at_bound(xi, gi, bi, 0.0);
        held_here += held ? 1.0 : 0.0;
        slope_here += held ? 0.0 : gi * gi;
        listed_buffer[listed] = i;
        listed += listing_now && held == list_held ? 1 : 0;
        // The breakpoint of an unknown off the bound that g pushes towards it (the division
        // by 1 elsewhere only keeps every entry's arithmetic harmless).
        const double breakpoint = (xi - bi) / (gi > 0.0 ? gi : 1.0);
        breakpoint_buffer[broken] = {breakpoint, i};
        broken += gi > 0.0 && xi > bi && std::isfinite(breakpoint) ? 1 : 0;
      }
      held_count += held_here;
      slope_sum += slope_here;
      list.insert(list.end(), listed_buffer, listed_buffer + listed);
      heap.insert(heap.end(), breakpoint_buffer, breakpoint_buffer + broken);
    }
    sums[0] += held_count;
    sums[1] += slope_sum;
  }
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

namespace {

// What a line search did.
enum class Search { accepted, no_descent, failed, not_finite };

// The algorithm's state between its steps: the iterate x (the formulation's variable), its
// gradient g and value, the compact matrix, and the work fields of one iteration.
class Lbfgsb {
 public:
  Lbfgsb(Formulation &f, int memory)
      : f_(f),
        n_(f.size()),
        total_(static_cast<std::int64_t>(f.total_size())),
        bounded_(f.bounded_size()),
        lower_(f.lower_bound()),
        reductions_(f.reductions()),
        x_(f.variable().data()),
        g_(static_cast<std::size_t>(n_)),
        trial_gradient_(static_cast<std::size_t>(n_)),
        x_old_(static_cast<std::size_t>(n_)),
        // The direction takes the formulation's spare array if it lends one: of the four
        // fields it is the one that never changes hands (the gradients swap, x_old goes into
        // the pairs' memory).
        d_field_(f.spare_array() != nullptr ? 0 : static_cast<std::size_t>(n_)),
        d_(f.spare_array() != nullptr ? f.spare_array() : d_field_.data()),
        bfgs_(n_, memory, reductions_) {}

  // The paper's algorithm, step by step, from x projected onto the bound: Cauchy point,
  // subspace minimisation, line search, update of the pairs, test for convergence.
  void run(Monitor &monitor) {
    project_start();
    value_ = f_.value_and_gradient(x_, g_.data());
    if (monitor.should_stop(0, observe(f_, x_, g_.data(), value_, monitor))) return;
    bool first = true;
    for (std::int64_t iteration = 1;;) {
      const CauchyPoint cauchy = generalized_cauchy_point(x_, g_.data(), n_, bounded_, lower_, bfgs_,
                                                          reductions_, work_);
      subspace_minimisation(cauchy);
      const Search search = line_search(first);
      if (search == Search::not_finite) {
        monitor.declare_breakdown();
        return;
      }
      if (search != Search::accepted) {
        // The model's direction is no use (rounding near the solution, or a poor memory):
        // start again from the steepest descent with no pairs. Without pairs there is no
        // descent left short of the tolerance: the iterate is stationary to rounding.
        if (bfgs_.pairs() == 0) {
          monitor.declare_stalled();
          return;
        }
        bfgs_.forget();
        continue;
      }
      first = false;
      update_memory();
      if (monitor.should_stop(iteration, observe(f_, x_, g_.data(), value_, monitor))) return;
      ++iteration;
    }
  }

 private:
  // The start must be feasible: x <- max(x, lower), which changes no feasible entry (there is
  // no mean constraint to restore: lbfgsb() refuses one).
  void project_start() { f_.project(x_); }

  // Step 3: the minimiser of the model over the unknowns the Cauchy point leaves free, by
  // the direct primal method: on the free set the model's Hessian is theta I - Z^T W M W^T Z,
  // whose inverse Sherman-Morrison-Woodbury gives through 2k x 2k matrices. Its minimiser,
  // for a free unknown,
  //     x_bar_i = x_i - g_i/theta + w_i.u,  u = M c/theta - N^-1 M W^T Z r/theta^2,
  // with r the model's reduced gradient at the Cauchy point and N = I - M W^T Z Z^T W/theta;
  // on the bound at the Cauchy point, x_bar_i = lower. Then Morales & Nocedal's remark:
  // x_bar is projected onto the bound, and if the step to it is no descent direction, the
  // unprojected step is cut back to the bound instead. Leaves d = x_bar - x, x_old = x.
  void subspace_minimisation(const CauchyPoint &cauchy) {
    const int k2 = bfgs_.columns();
    const double theta = bfgs_.theta(), t = cauchy.t;
    const auto size = static_cast<std::size_t>(k2);
    const std::int64_t free_count = total_ - cauchy.at_bound;
    u_.assign(size, 0.0);
    if (k2 > 0) {
      // W^T Z r = (1 - theta t) sum_free g_i w_i - (Z^T W)^T Z^T W M c, since on the free
      // set x_cauchy - x = -t g.
      const std::vector<double> &a = cauchy.free_gradient, &gram = cauchy.free_gram;
      std::vector<double> mc(size), rhs(size), v(size);
      bfgs_.times_middle(cauchy.c.data(), mc.data());
      for (std::size_t r = 0; r < size; ++r) {
        double kmc = 0.0;
        for (std::size_t c = 0; c < size; ++c) kmc += gram[r * size + c] * mc[c];
        rhs[r] = (1.0 - theta * t) * a[r] - kmc;
      }
      bfgs_.times_middle(rhs.data(), v.data());
      // N = I - M K/theta, K = Z^T W ^T Z^T W (symmetric, so M K's columns are M times K's).
      std::vector<double> mk(size * size), column(size), product(size);
      for (std::size_t c = 0; c < size; ++c) {
        for (std::size_t r = 0; r < size; ++r) column[r] = gram[r * size + c];
        bfgs_.times_middle(column.data(), product.data());
        for (std::size_t r = 0; r < size; ++r)
          mk[r * size + c] = (r == c ? 1.0 : 0.0) - product[r] / theta;
      }
      if (solve_small(mk, k2, v.data(), 1)) {
        for (std::size_t j = 0; j < size; ++j) u_[j] = mc[j] / theta - v[j] / (theta * theta);
      } else {
        // N singular to working precision: keep the Cauchy point's own direction.
        for (std::size_t j = 0; j < size; ++j) u_[j] = mc[j] / theta;
      }
    }
    if (!project_subspace_step(cauchy, free_count)) backtrack_subspace_step(cauchy);
  }

  // x_bar projected onto the bound: d = max(x_bar, lower) - x, x_old <- x, with the sums
  // finish_direction() forms, in the same pass. Returns whether d is a descent direction
  // (g.d < 0). The model's correction w_i.u is added over the free unknowns only: in the pass
  // if they are many; from the list if they are few, the pass then finishing the unknowns on
  // the bound and the list the free ones. The kernels read the fields and the bound through
  // locals: through the members every store to d would make them load again.
  bool project_subspace_step(const CauchyPoint &cauchy, std::int64_t free_count) {
    const int k2 = bfgs_.columns();
    const double inverse_theta = 1.0 / bfgs_.theta(), t = cauchy.t;
    const double *x = x_, *g = g_.data(), *u = u_.data();
    double *d = d_, *x_old = x_old_.data();
    const Bound bound{bounded_, lower_};
    // The free unknowns, when they are few, from a list. The Cauchy point's, with its kept
    // rows, serves as it is (the unknowns the path took to the bound are skipped);
    // otherwise those it took leave it, or a pass lists the free ones.
    const bool listed = k2 > 0 && !list_complement(free_count, total_);
    const auto fixed = [=](std::int64_t i) { return at_bound(x[i], g[i], bound(i), t); };
    const bool kept = listed && cauchy.kept_rows;
    Indices &list = work_.list;
    if (listed && !kept) {
      if (cauchy.listed_free) {
        list.erase(std::remove_if(list.begin(), list.end(), fixed), list.end());
      } else {
        list.clear();
        loops::select(n_, [&](std::int64_t i) { return !fixed(i); }, list);
      }
    }
    const CompactBfgs &bfgs = bfgs_;
    const auto finish = [=](std::int64_t i, double x_bar, double *sum, double &max) {
      d[i] = finish_unknown(x[i], g[i], bound(i), x_bar, sum, max);
    };
    std::array<double, 3> s;
    if (listed) {
      // The unknowns on the bound are finished here; the free ones get x - g/theta, and
      // their correction and finish from the list.
      const auto body = [=](std::int64_t i, double *sum, double &max) {
        x_old[i] = x[i];
        if (fixed(i))
          finish(i, bound(i), sum, max);
        else
          d[i] = x[i] - g[i] * inverse_theta;
      };
      s = loops::sums_and_max<2>(reductions_, n_, body);
      // One sweep of the list, each unknown's row of W read at once: from the kept copy, or
      // gathered, the rows a few entries ahead fetched while this one is summed (the list's
      // gaps defeat the prefetchers).
      constexpr std::int64_t ahead = 8;
      const auto listed_count = static_cast<std::int64_t>(list.size());
      const std::int64_t *at = list.data();
      std::vector<double> weight(static_cast<std::size_t>(k2));
      for (int j = 0; j < k2; ++j) weight[j] = bfgs.scale(j) * u[j];
      double sums[2] = {0.0, 0.0}, max = -infinity;
      for (std::int64_t p = 0; p < listed_count; ++p) {
        const std::int64_t i = at[p];
        double correction = 0.0;
        if (kept) {
          if (fixed(i)) continue;
          for (int j = 0; j < k2; ++j)
            correction += kept_row_entry(work_.rows, k2, listed_count, p, j) * weight[j];
        } else {
          if (p + ahead < listed_count) bfgs.prefetch_row(at[p + ahead]);
          correction = bfgs.row_times(i, u);
        }
        finish(i, d[i] + correction, sums, max);
      }
      reductions_.combine_sums(sums, 2);
      reductions_.combine_maxima(&max, 1);
      s[0] += sums[0];
      s[1] += sums[1];
      s[2] = std::max(s[2], max);
    } else {
      const auto body = [=, &bfgs](std::int64_t i, double *sum, double &max) {
        x_old[i] = x[i];
        if (fixed(i))
          finish(i, bound(i), sum, max);
        else
          finish(i, x[i] - g[i] * inverse_theta + (k2 > 0 ? bfgs.row_times(i, u) : 0.0), sum,
                 max);
      };
      s = loops::sums_and_max<2>(reductions_, n_, body);
    }
    return take_direction_sums(s);
  }

  // The backtracked step: x_bar = x_cauchy + alpha (x_unprojected - x_cauchy) on the free
  // unknowns, alpha <= 1 the largest that keeps every one feasible.
  void backtrack_subspace_step(const CauchyPoint &cauchy) {
    const double inverse_theta = 1.0 / bfgs_.theta(), t = cauchy.t;
    const double *x = x_, *g = g_.data(), *u = u_.data();
    double *d = d_;
    const CompactBfgs &bfgs = bfgs_;
    const int k2 = bfgs_.columns();
    // d <- the unprojected step from the Cauchy point, 0 at the bound.
    loops::for_each(n_, [&](std::int64_t i) {
      const double cauchy_i = x[i] - t * g[i];
      d[i] = at_bound(x[i], g[i], bound(i), t)
                 ? 0.0
                 : x[i] - g[i] * inverse_theta + (k2 > 0 ? bfgs.row_times(i, u) : 0.0) -
                       cauchy_i;
    });
    const double alpha = std::min(
        1.0, -loops::maximum(reductions_, n_, [&](std::int64_t i) {
          const double cauchy_i = x[i] - t * g[i];
          return d[i] < 0.0 ? -(bound(i) - cauchy_i) / d[i] : -infinity;
        }));
    loops::for_each(n_, [&](std::int64_t i) {
      d[i] = at_bound(x[i], g[i], bound(i), t) ? bound(i) : x[i] - t * g[i] + alpha * d[i];
    });
    finish_direction();
  }

  // From x_bar in d: d <- max(x_bar, lower) - x, x_old <- x, and the slope g.d, |d|^2 and the
  // largest feasible step along d. Returns whether d descends.
  bool finish_direction() {
    const double *x = x_, *g = g_.data();
    double *d = d_, *x_old = x_old_.data();
    const Bound bound{bounded_, lower_};
    return take_direction_sums(loops::sums_and_max<2>(
        reductions_, n_, [=](std::int64_t i, double *sum, double &max) {
          x_old[i] = x[i];
          d[i] = finish_unknown(x[i], g[i], bound(i), d[i], sum, max);
        }));
  }

  // The slope g.d, |d| and the largest feasible step from the sums g.d, d.d and the maximum
  // of -(step to the bound). Returns whether d descends.
  bool take_direction_sums(const std::array<double, 3> &s) {
    slope_ = s[0];
    direction_norm_ = std::sqrt(s[1]);
    largest_step_ = std::isfinite(s[2]) ? std::min(-s[2], unbounded_step) : unbounded_step;
    return slope_ < 0.0;
  }

  // Step 4: a line search along d from x_old for the strong Wolfe conditions, with the step
  // at most the largest feasible one. The first iteration tries 1/|d| (capped at the
  // largest step, 1 there, the paper's choice), later ones the unit step. On success x, its
  // gradient (in trial_gradient_) and value_ are the accepted point's; otherwise x is back
  // at x_old.
  Search line_search(bool first) {
    if (!std::isfinite(slope_) || !std::isfinite(direction_norm_)) return Search::not_finite;
    if (!(slope_ < 0.0)) return Search::no_descent;
    const double largest = first ? std::min(1.0, largest_step_) : largest_step_;
    const double step = first ? std::min(1.0 / direction_norm_, largest) : std::min(1.0, largest);
    const LineSearchResult result = search_line(
        line_search_settings, value_, slope_, step, largest,
        [&](double trial, double &value, double &slope) {
          move_to(trial);
          value = f_.value_and_gradient(x_, trial_gradient_.data());
          slope = f_.dot(trial_gradient_.data(), d_);
        },
        &value_);
    if (result == LineSearchResult::accepted) return Search::accepted;
    move_to(0.0);
    return result == LineSearchResult::not_finite ? Search::not_finite : Search::failed;
  }

  // x <- max(x_old + step d, lower): the bound holds bitwise whatever the rounding.
  void move_to(double step) {
    const double *x_old = x_old_.data(), *d = d_;
    double *x = x_;
    loops::for_each(n_, [&](std::int64_t i) {
      const double moved = x_old[i] + step * d[i];
      x[i] = moved > bound(i) ? moved : bound(i);
    });
  }

  // Step 5: the pair s = x - x_old, y = g_new - g enters the memory unless the curvature
  // condition fails; the accepted gradient becomes g.
  void update_memory() {
    bfgs_.add_pair(x_, x_old_, trial_gradient_.data(), g_);
    std::swap(g_, trial_gradient_);
  }

  Formulation &f_;
  std::int64_t n_;
  std::int64_t total_;  // unknowns over all processes
  // The bound of unknown i: lower_bound() on the first bounded_, none on the others.
  double bound(std::int64_t i) const { return i < bounded_ ? lower_ : -infinity; }

  std::int64_t bounded_;
  double lower_;
  const Reductions &reductions_;
  double *x_;
  double value_ = 0.0;
  Field g_, trial_gradient_, x_old_;
  Field d_field_;  // empty when the direction is the formulation's spare array
  double *d_;
  CompactBfgs bfgs_;
  std::vector<double> u_;
  double slope_ = 0.0, direction_norm_ = 0.0, largest_step_ = 0.0;
  CauchyWork work_;  // the Cauchy point's, whose list and rows the step reads
};

bool on_the_gap(const OptionValues &options) { return options.text("variable") == "gap"; }

// L-BFGS-B keeps the unknowns in a box, but no mean-value equality: it serves penetration
// control on either variable, and load control on the gap, whose formulation takes the load
// as a work term without a constraint (not with a user's potential: see
// primal_formulation.hpp).
constexpr const char *load_with_potential =
    "under a tensile load the separation of the surfaces cannot be told from a user's "
    "potential's values";

Offer offer_for(const OptionValues &options) {
  if (on_the_gap(options))
    return {{Control::penetration, Control::mean_pressure},
            false,
            {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential},
            true,
            "variable = gap",
            {},
            "",
            {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential},
            false,
            load_with_potential};
  return {{Control::penetration},
          false,
          {InteractionFamily::hard_wall},
          false,
          "variable = pressure",
          {},
          "",
          {},
          false,
          ""};
}

template <class Variable>
void run_on(System &system, Control control, double value, int memory, Monitor &monitor) {
  Variable formulation(system, control, value);
  lbfgsb(formulation, monitor, memory);
  conclude(formulation, system, monitor);
}

void run(System &system, Control control, double value, const OptionValues &options,
         Monitor &monitor) {
  const int memory = static_cast<int>(options.number("memory"));
  if (on_the_gap(options))
    run_on<PrimalFormulation>(system, control, value, memory, monitor);
  else
    run_on<DualFormulation>(system, control, value, memory, monitor);
}

}  // namespace

void lbfgsb(Formulation &f, Monitor &monitor, int memory) {
  if (f.constrains_mean())
    throw Error(Status::internal, "lbfgsb cannot keep a mean-value constraint");
  Lbfgsb algorithm(f, memory);
  algorithm.run(monitor);
}

AlgorithmSpec lbfgsb_algorithm() {
  AlgorithmSpec spec;
  spec.name = "lbfgsb";
  spec.summary =
      "Byrd, Lu, Nocedal & Zhu's limited-memory BFGS for bound constraints (L-BFGS-B, SIAM "
      "J. Sci. Comput. 1995; thesis section 3.1.6) on the pressure (the complementary energy, "
      "as for pk; no adhesion) or on the gap (the elastic energy plus the interaction "
      "energy; with or without adhesion), under penetration control, and on the gap also "
      "under load control";
  spec.controls = {Control::penetration, Control::mean_pressure};
  spec.offer_for = offer_for;
  spec.interactions = {InteractionFamily::hard_wall, InteractionFamily::hard_wall_with_potential};
  spec.callbacks = true;
  spec.options = {
      {"variable", OptionType::choice, 0.0, 0.0, 0.0, false, {"pressure", "gap"},
       "the unknown: pressure (the dual problem; no adhesion) or gap (the primal; with or "
       "without adhesion, or a user's potential with the hard wall); penetration control on "
       "either, mean-pressure control on the gap (tensile loads included; not with a "
       "user's potential)"},
      {"memory", OptionType::integer, 5, 1, 100, false, {},
       "the number of step and gradient-change pairs the quasi-Newton matrix keeps (16 bytes "
       "per pixel each)"},
  };
  // Nested grids by default: on the bench scene to 1e-8 (on the gap) they take 0.62 to 0.83
  // times the time of a plain solve from 512^2 to 2048^2, and their iterations grow 1.06
  // times from 1024^2 to 2048^2 against 1.35 (docs/performance.md, "Nested grids with
  // bugnicourt and lbfgsb"). Below 128 pixels a side, from a warm start and with a user's
  // potential, none are taken.
  spec.default_levels = levels_auto;
  spec.run = run;
  return spec;
}

}  // namespace asp
