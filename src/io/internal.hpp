// SPDX-License-Identifier: GPL-2.0-or-later
// Internal helpers shared by the readers and writers of asperity_io (not installed, not part of
// the interface in height_map.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "io/height_map.hpp"

namespace asp::io::detail {

// The whole file as bytes; FileError naming the path when it cannot be opened or read.
std::string read_file(const std::string &path);

// Writes bytes to a file (replacing it); FileError naming the path on failure.
void write_file(const std::string &path, const std::string &bytes);

// A unit as unit_in_metres() spells it ("µm", "micron", "μm" -> "um", "Å" -> "A"), or the
// given text, trimmed, when it is not a length unit.
std::string normalise_unit(const std::string &unit);

// A double as the shortest text that reads back to the same value ("C" locale).
std::string format_double(double value);

// The RFC 1321 MD5 digest of bytes as 32 lower-case hexadecimal digits.
std::string md5_hex(const std::string &bytes);

HeightMap read_text_matrix(const std::string &path, const std::string &bytes);
HeightMap read_npy(const std::string &path, const std::string &bytes);
HeightMap read_x3p(const std::string &path);

}  // namespace asp::io::detail
