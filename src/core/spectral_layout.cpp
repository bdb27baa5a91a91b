// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/spectral_layout.hpp"

namespace asp {

SpectralLayout::SpectralLayout(Packing packing, std::int64_t nx, std::int64_t ny, double lx,
                               double ly, std::int64_t local_rows, std::int64_t row_offset)
    : packing_(packing),
      nx_(nx),
      ny_(ny),
      lx_(lx),
      ly_(ly),
      rows_(local_rows < 0 ? ny : local_rows),
      row_offset_(row_offset),
      row_length_(packing == Packing::half_spectrum ? nx / 2 + 1 : nx),
      second_single_(nx % 2 == 0 && nx > 1 ? nx / 2 : 0) {}

}  // namespace asp
