#include "core/reductions.hpp"

#include <cmath>
#include <limits>

namespace asp {

double Reductions::sum(const double *f, std::int64_t n) const {
  double s = 0.0;
  for (std::int64_t i = 0; i < n; ++i) s += f[i];
  combine_sums(&s, 1);
  return s;
}

double Reductions::dot(const double *a, const double *b, std::int64_t n) const {
  double s = 0.0;
  for (std::int64_t i = 0; i < n; ++i) s += a[i] * b[i];
  combine_sums(&s, 1);
  return s;
}

double Reductions::max(const double *f, std::int64_t n) const {
  double m = -std::numeric_limits<double>::infinity();
  for (std::int64_t i = 0; i < n; ++i) m = f[i] > m ? f[i] : m;
  combine_maxima(&m, 1);
  return m;
}

}  // namespace asp
