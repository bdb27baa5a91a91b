// What the benchmark programs share: wall-clock time, and the FFT pair that a solver's time per
// iteration is compared with.
#pragma once

#include <algorithm>
#include <chrono>

#include "core/aligned_field.hpp"
#include "core/grid.hpp"

namespace bench {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Best of several timed batches of r2c + c2r pairs with the grid's own plans: the floor that a
// solver's iterations compare with. The machine's noise only ever adds time, hence the best.
inline double fft_pair_seconds(const asp::Grid &grid) {
  asp::Field f = grid.make_field();
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i % 7);
  asp::Spectrum s = grid.make_spectrum();
  const int repeats = std::max(3, static_cast<int>(2e7 / grid.n_pixels()));
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < repeats; ++k) {
      grid.fft().forward(f.data(), s.data());
      grid.fft().backward(s.data(), f.data());
    }
    best = std::min(best, seconds_since(start) / repeats);
  }
  return best;
}

}  // namespace bench
