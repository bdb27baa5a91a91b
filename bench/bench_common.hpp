// SPDX-License-Identifier: GPL-2.0-or-later
// What the benchmark programs share: wall-clock time, the process's peak resident size, the
// FFT pair that a solver's time per iteration is compared with, and options from the command
// line.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/aligned_field.hpp"
#include "core/grid.hpp"
#include "core/loops.hpp"
#include "core/threads.hpp"
#include "solvers/solver.hpp"

namespace bench {

// Sets a solver's option from a command-line word: a number where the whole word reads as
// one, else the word (a choice, or "auto").
inline void set_option(asp::Solver &solver, const std::string &name, const std::string &value) {
  char *end = nullptr;
  const double number = std::strtod(value.c_str(), &end);
  if (!value.empty() && *end == '\0')
    solver.set_option(name, number);
  else
    solver.set_option(name, value);
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The process's peak resident size in bytes (VmHWM: the whole process, the libraries' buffers
// included), 0 where /proc/self/status does not tell it.
inline double peak_resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kilobytes = 0.0;
      status >> kilobytes;
      return 1024.0 * kilobytes;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0.0;
}

// Best of several timed batches of r2c + c2r pairs of shape nx x ny with the grid's plans (the
// grid's own shape, or the padded one of a free substrate): the floor that a solver's
// iterations compare with. The machine's noise only ever adds time, hence the best.
inline double fft_pair_seconds(const asp::Grid &grid, std::int64_t nx, std::int64_t ny) {
  asp::Field f(static_cast<std::size_t>(nx * ny));
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i % 7);
  asp::Spectrum s(static_cast<std::size_t>((nx / 2 + 1) * ny));
  const asp::RealFft &fft = grid.real_fft(nx, ny);
  const int repeats = std::max(3, static_cast<int>(2e7 / static_cast<double>(nx * ny)));
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < repeats; ++k) {
      fft.forward(f.data(), s.data());
      fft.backward(s.data(), f.data());
    }
    best = std::min(best, seconds_since(start) / repeats);
  }
  return best;
}

inline double fft_pair_seconds(const asp::Grid &grid) {
  return fft_pair_seconds(grid, grid.nx(), grid.ny());
}

// Best of several timed passes z = x + a y over three fields of the grid's size, on the grid's
// threads, over 3: the time to stream one field (8 bytes per pixel, read or written) between
// memory and the cores. An iteration's element-wise passes cost about this much per array
// they read or write, once the fields no longer fit in the cache.
inline double field_stream_seconds(const asp::Grid &grid) {
  const auto n = grid.n_pixels();
  asp::Field x(static_cast<std::size_t>(n)), y(x.size()), z(x.size());
  const asp::ThreadScope threads(grid.threads());
  asp::loops::for_each(n, [&](std::int64_t i) {
    x[i] = static_cast<double>(i % 5);
    y[i] = static_cast<double>(i % 3);
  });
  const int repeats = std::max(3, static_cast<int>(2e7 / static_cast<double>(n)));
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < repeats; ++k) {
      const double a = 1.0 / (k + 2);
      asp::loops::for_each(n, [&](std::int64_t i) { z[i] = x[i] + a * y[i]; });
    }
    best = std::min(best, seconds_since(start) / repeats / 3.0);
  }
  return best;
}

// What one transform pair cost inside a solve that made `transforms` transforms, from the
// seconds the library's transform clock (core/transform_clock.hpp) counted over it; 0 for a
// solve without transforms.
inline double pair_in_solve(double transform_seconds, std::int64_t transforms) {
  return transforms > 0 ? transform_seconds / (0.5 * static_cast<double>(transforms)) : 0.0;
}

}  // namespace bench
