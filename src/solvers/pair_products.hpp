// SPDX-License-Identifier: GPL-2.0-or-later
// The pass that enters a new pair into the compact matrix (compact_bfgs.hpp), over one block
// of entries: it forms s = x - x_old and y = g - g_old and meets them and g with every stored
// pair. At six products per stored pair and entry it is the one pass of the solvers whose
// arithmetic sets its time on the x86-64 baseline: with five stored pairs at 2048^2 it took 39
// ms compiled for SSE2 and 24 ms for AVX2 with FMA, the fields' own traffic about 17 ms
// (docs/performance.md). So it has both variants (core/instruction_sets.hpp).
#pragma once

#include <cstdint>

#include "core/instruction_sets.hpp"

namespace asp {

struct PairBlock {
  const double *x, *g;  // the new iterate and its gradient
  double *s, *y;        // x_old and g_old in; s and y out
  const double *const *stored_s, *const *stored_y;
  int stored;  // the stored pairs
};

// Adds to sum, for each stored pair j, s.s_j, s.y_j, y.s_j, y.y_j, g.s_j, g.y_j (6 entries
// each), then s.s, s.y, y.y, g.s, g.y of the new pair, over the entries [begin, end); and
// writes s and y there.
using PairProducts = void (*)(const PairBlock &block, std::int64_t begin, std::int64_t end,
                              double *sum);

// The variant's kernel (the CPU must run it: cpu_runs).
PairProducts pair_products(KernelVariant variant);

}  // namespace asp
