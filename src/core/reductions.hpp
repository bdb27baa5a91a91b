// Reductions over a grid's pixels. Kernels compute partial sums over the pixels they own and
// then call combine_*; on one process that is the identity, while a distributed grid would
// make it an all-reduce. Keeping every global sum and max behind this class is what lets such
// a grid arrive without touching the solvers or the C API.
#pragma once

#include <cstdint>

namespace asp {

class Reductions {
 public:
  virtual ~Reductions() = default;
  // In place: values[k] becomes the sum (max) of values[k] over all parts of the grid.
  virtual void combine_sums(double *values, int count) const = 0;
  virtual void combine_maxima(double *values, int count) const = 0;

  double sum(const double *f, std::int64_t n) const;
  double dot(const double *a, const double *b, std::int64_t n) const;
  double max(const double *f, std::int64_t n) const;
};

// The whole grid lives in this process.
class LocalReductions final : public Reductions {
 public:
  void combine_sums(double *, int) const override {}
  void combine_maxima(double *, int) const override {}
};

}  // namespace asp
