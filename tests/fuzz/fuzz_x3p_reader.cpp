// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer driver of the x3p topography reader: asp::io::read_height_map with FileFormat::x3p on
// arbitrary bytes, which exercises the parsing of ISO 25178-72 .x3p archives (src/io/x3p.cpp): the
// zip container (libzip), main.xml (pugixml), the axes, the point data types, the MD5 checksum and
// the validity mask. Measured surfaces come from files made by other programs, so the reader must
// refuse any content with a FileError; the checks are those of height_map_driver.hpp.
#include "height_map_driver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::read_one(data, size, asp::io::FileFormat::x3p);
  return 0;
}
