// SPDX-License-Identifier: GPL-2.0-or-later
// How partial sums and maxima over the pixels one process owns become totals over the grid.
// On one process that is the identity; a distributed grid makes it an all-reduce. Every
// global sum and max goes through this class (usually via core/loops.hpp), which is what lets
// such a grid arrive without touching the solvers or the C API.
#pragma once

namespace asp {

class Reductions {
 public:
  virtual ~Reductions() = default;
  // In place: values[k] becomes the sum (max) of values[k] over all parts of the grid.
  virtual void combine_sums(double *values, int count) const = 0;
  virtual void combine_maxima(double *values, int count) const = 0;
  // One candidate per part, a key and a payload of count values (key = +infinity for none):
  // the candidate with the smallest key (the first part's on ties) wins, and key and payload
  // become its on every part. Returns whether it was this part's.
  virtual bool select_smallest(double &key, double *payload, int count) const = 0;
};

// The whole grid lives in this process.
class LocalReductions final : public Reductions {
 public:
  void combine_sums(double *, int) const override {}
  void combine_maxima(double *, int) const override {}
  bool select_smallest(double &, double *, int) const override { return true; }
};

}  // namespace asp
