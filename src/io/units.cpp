// SPDX-License-Identifier: GPL-2.0-or-later
// Length units: metres per unit and their accepted spellings.
#include <stdexcept>
#include <string>

#include "io/height_map.hpp"
#include "io/internal.hpp"

namespace asp::io {

namespace detail {

std::string normalise_unit(const std::string &unit) {
  const auto first = unit.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = unit.find_last_not_of(" \t\r\n");
  const std::string u = unit.substr(first, last - first + 1);
  // "µm" with MICRO SIGN (U+00B5) or GREEK SMALL LETTER MU (U+03BC), in UTF-8 or Latin-1.
  if (u == "\xC2\xB5m" || u == "\xCE\xBCm" || u == "\xB5m" || u == "micron" || u == "microns" ||
      u == "um")
    return "um";
  // "Å" as LATIN CAPITAL LETTER A WITH RING ABOVE (U+00C5) or ANGSTROM SIGN (U+212B).
  if (u == "\xC3\x85" || u == "\xE2\x84\xAB" || u == "\xC5" || u == "A") return "A";
  return u;
}

}  // namespace detail

double unit_in_metres(const std::string &unit) {
  const std::string u = detail::normalise_unit(unit);
  if (u == "m") return 1.0;
  if (u == "mm") return 1e-3;
  if (u == "um") return 1e-6;
  if (u == "nm") return 1e-9;
  if (u == "pm") return 1e-12;
  if (u == "A") return 1e-10;
  throw std::invalid_argument("unknown length unit '" + unit +
                              "': the accepted units are m, mm, um (also \xC2\xB5m and micron), "
                              "nm, pm and A (\xC3\x85ngstr\xC3\xB6m, also \xC3\x85)");
}

}  // namespace asp::io
