// SPDX-License-Identifier: GPL-2.0-or-later
// Fields are contiguous arrays allocated by FFTW's allocator, so that every array has the
// alignment the FFT plans were made for and plans can be executed on any field.
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace asp {

// Bytes currently held by fields; the benchmark reads it to report memory per pixel.
std::int64_t field_bytes_in_use();
std::int64_t field_bytes_peak();
void reset_field_bytes_peak();
// A ceiling on the bytes fields may hold together (0: none, the default): an allocation that
// would pass it throws std::bad_alloc, so that tests can make memory run out at a chosen point.
void set_field_bytes_limit(std::int64_t bytes);

// Memory aligned for FFTW, zeroed by the calling thread's loop threads (core/threads.hpp), so
// that a large field's pages are first touched, and faulted in, on all of them.
void *allocate_field_bytes(std::size_t bytes);
void free_field_bytes(void *pointer, std::size_t bytes) noexcept;

template <class T>
struct FieldAllocator {
  using value_type = T;
  FieldAllocator() = default;
  template <class U>
  FieldAllocator(const FieldAllocator<U> &) noexcept {}
  T *allocate(std::size_t n) {
    // A count whose byte size wraps around is a request no machine can serve.
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    return static_cast<T *>(allocate_field_bytes(n * sizeof(T)));
  }
  void deallocate(T *p, std::size_t n) noexcept { free_field_bytes(p, n * sizeof(T)); }
  // The memory comes zeroed: a value-initialised element of a trivial type (a Field(n)'s
  // doubles) is left as it is instead of being zeroed again, on one thread. Other types, and
  // elements given a value, are constructed as usual.
  template <class U>
  void construct(U *p) noexcept(std::is_nothrow_default_constructible<U>::value) {
    if (std::is_trivially_default_constructible<U>::value) {
      ::new (static_cast<void *>(p)) U;
    } else {
      ::new (static_cast<void *>(p)) U();
    }
  }
  template <class U, class... Args>
  void construct(U *p, Args &&...args) {
    ::new (static_cast<void *>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const FieldAllocator<U> &) const noexcept { return true; }
  template <class U>
  bool operator!=(const FieldAllocator<U> &) const noexcept { return false; }
};

using Complex = std::complex<double>;
using Field = std::vector<double, FieldAllocator<double>>;            // real space, x fastest
using Spectrum = std::vector<Complex, FieldAllocator<Complex>>;       // r2c half spectrum

}  // namespace asp
