// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/spectral_layout.hpp"

namespace asp {

SpectralLayout::SpectralLayout(Packing packing, std::int64_t nx, std::int64_t ny, double lx,
                               double ly, std::int64_t lines, std::int64_t first_line)
    : packing_(packing),
      nx_(nx),
      ny_(ny),
      lx_(lx),
      ly_(ly),
      first_line_(first_line),
      line_length_(packing == Packing::half_spectrum ? nx / 2 + 1 : ny),
      second_single_(nx % 2 == 0 && nx > 1 && packing != Packing::transposed_half_spectrum
                         ? nx / 2
                         : 0) {
  const std::int64_t all = packing == Packing::transposed_half_spectrum ? nx / 2 + 1 : ny;
  lines_ = lines < 0 ? all : lines;
}

}  // namespace asp
