// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer driver of the text topography reader: asp::io::read_height_map with FileFormat::text on
// arbitrary bytes, which exercises the parsing of text matrices (src/io/text_matrix.cpp): numbers
// separated by spaces, commas, semicolons or tabs, comment lines, Gwyddion's header with sizes and
// units, NaN for missing points. Measured surfaces come from files made by other programs, so the
// reader must refuse any content with a FileError; the checks are those of height_map_driver.hpp.
#include "height_map_driver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::read_one(data, size, asp::io::FileFormat::text);
  return 0;
}
