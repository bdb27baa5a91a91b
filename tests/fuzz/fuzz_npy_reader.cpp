// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer driver of the npy topography reader: asp::io::read_height_map with FileFormat::npy on
// arbitrary bytes, which exercises the parsing of .npy arrays (src/io/npy.cpp): the magic string,
// the version, the header's Python dict (descr, fortran_order, shape), the element types and byte
// orders, truncated data. Measured surfaces come from files made by other programs, so the reader
// must refuse any content with a FileError; the checks are those of height_map_driver.hpp.
#include "height_map_driver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::read_one(data, size, asp::io::FileFormat::npy);
  return 0;
}
