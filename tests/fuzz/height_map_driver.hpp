// SPDX-License-Identifier: GPL-2.0-or-later
// The body shared by the libFuzzer drivers of the topography readers (fuzz_text_reader.cpp,
// fuzz_npy_reader.cpp, fuzz_x3p_reader.cpp): the input is the content of a file, read with
// asp::io::read_height_map in one format, as the asperity command reads a measured surface.
//
// The contract (src/io/height_map.hpp): a reader throws asp::io::FileError and nothing else for
// any content, and what it returns is a height map of at least one pixel, whose heights are
// nx * ny numbers, each finite or NaN (a missing point), counted in `missing`, read in the
// format asked for. A map with missing points (but not only missing points) is then filled
// as the command fills it, after which every height is finite. Any other exception, a crash,
// a leak or undefined behaviour is a finding.
//
// The bytes go to a memory file (memfd) that the reader opens by its /proc/self/fd path: the
// readers take a path, as the command gives them one, and libzip opens x3p archives itself.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include "io/height_map.hpp"

namespace fuzz {

// Filling solves a Laplace problem over the missing points; larger maps are only read, so that
// every input runs in milliseconds.
constexpr int64_t max_filled_pixels = 64 * 64;

[[noreturn]] inline void broken(const char *what) {
  std::fprintf(stderr, "topography reader contract broken: %s\n", what);
  __builtin_trap();
}

inline std::string memory_file(const uint8_t *data, size_t size) {
  static const int fd = memfd_create("fuzz-height-map", 0);
  if (fd < 0 || ftruncate(fd, 0) != 0) broken("cannot make the memory file");
  size_t written = 0;
  while (written < size) {
    const ssize_t n = pwrite(fd, data + written, size - written, static_cast<off_t>(written));
    if (n <= 0) broken("cannot write the memory file");
    written += static_cast<size_t>(n);
  }
  return "/proc/self/fd/" + std::to_string(fd);
}

inline void read_one(const uint8_t *data, size_t size, asp::io::FileFormat format) {
  const std::string path = memory_file(data, size);
  asp::io::HeightMap map;
  try {
    map = asp::io::read_height_map(path, format);
  } catch (const asp::io::FileError &e) {
    if (std::string(e.what()).empty()) broken("a FileError without a message");
    return;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    broken("an exception other than FileError");
  } catch (...) {
    broken("an exception other than FileError");
  }
  if (map.format != format) broken("the map says another format");
  if (map.nx < 1 || map.ny < 1) broken("a map without pixels");
  if (static_cast<uint64_t>(map.heights.size()) != static_cast<uint64_t>(map.nx * map.ny))
    broken("heights.size() != nx * ny");
  int64_t missing = 0;
  bool infinite = false;
  for (double h : map.heights) {
    if (std::isnan(h))
      ++missing;
    else if (!std::isfinite(h))
      infinite = true;
  }
  if (missing != map.missing) broken("missing is not the count of NaN heights");
  // Every reader refuses infinite heights (only NaN marks a missing point).
  if (infinite) broken("an infinite height");
  (void)asp::io::describe_missing(map);
  if (missing == 0 || missing == map.nx * map.ny || map.nx * map.ny > max_filled_pixels) return;
  try {
    if (asp::io::fill_missing(map) != missing) broken("fill_missing filled another count");
  } catch (const asp::io::FileError &e) {
    broken("fill_missing refused a map with known heights");
  }
  for (double h : map.heights)
    if (!std::isfinite(h)) broken("a height not finite after fill_missing");
  if (map.missing != 0) broken("missing not 0 after fill_missing");
}

}  // namespace fuzz
