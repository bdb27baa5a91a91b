// SPDX-License-Identifier: GPL-2.0-or-later
// Text matrices: reading what Gwyddion, MATLAB and NumPy's savetxt write, and writing one.
//
// Lines starting (after blanks) with '#' or '%' are comments; "# Width: 10.000 µm",
// "# Height: ..." and "# Value units: m" (Gwyddion's header) give lx, ly and the units. Values
// are separated by blanks (spaces, tabs) or by one comma or semicolon; "nan" in any case is a
// missing point. Every data line is one scan line: row index = y, column index = x.
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "io/height_map.hpp"
#include "io/internal.hpp"

namespace asp::io {

namespace detail {

namespace {

std::string trim(const std::string &s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::string lower(std::string s) {
  for (char &c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

// A number as C's strtod reads it in the "C" locale, whole token only; false otherwise.
bool parse_number(const std::string &token, double &value) {
  const char *begin = token.data();
  const char *end = begin + token.size();
  if (begin != end && *begin == '+') ++begin;
  if (begin == end || *begin == '+') return false;
  const auto result = std::from_chars(begin, end, value);
  return result.ec == std::errc() && result.ptr == end;
}

// "10.000 µm" -> 10 and "um"; false when the text does not start with a number.
bool parse_quantity(const std::string &text, double &value, std::string &unit) {
  std::string t = trim(text);
  size_t end = 0;
  while (end < t.size() && t[end] != ' ' && t[end] != '\t') ++end;
  std::string number = t.substr(0, end);
  for (char &c : number)
    if (c == ',') c = '.';  // a decimal comma from a localised export
  if (!parse_number(number, value) || !std::isfinite(value)) return false;
  unit = normalise_unit(t.substr(end));
  return true;
}

struct Header {
  bool has_width = false, has_height = false;
  double width = 0, height = 0;
  std::string width_unit, height_unit, value_unit;
};

void read_header_line(const std::string &comment, Header &header) {
  const auto colon = comment.find(':');
  if (colon == std::string::npos) return;
  const std::string key = lower(trim(comment.substr(0, colon)));
  const std::string value = comment.substr(colon + 1);
  if (key == "width")
    header.has_width = parse_quantity(value, header.width, header.width_unit);
  else if (key == "height")
    header.has_height = parse_quantity(value, header.height, header.height_unit);
  else if (key == "value units" || key == "value unit" || key == "z units" || key == "z unit")
    header.value_unit = normalise_unit(value);
}

}  // namespace

HeightMap read_text_matrix(const std::string &path, const std::string &bytes) {
  HeightMap map;
  Header header;
  std::vector<double> values;
  int64_t columns = -1;
  int64_t first_data_line = 0;
  int64_t line_number = 0;
  size_t pos = 0;
  // A UTF-8 byte-order mark, as some Windows programs write.
  if (bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3;
  while (pos < bytes.size()) {
    size_t eol = bytes.find('\n', pos);
    if (eol == std::string::npos) eol = bytes.size();
    std::string line = bytes.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;  // a blank line
    if (line[first] == '#' || line[first] == '%') {
      if (values.empty()) read_header_line(line.substr(first + 1), header);
      continue;
    }
    // Tokens are runs of characters other than blanks, commas and semicolons; a comma or
    // semicolon with no value since the previous one (or the line's start) is an empty entry.
    int64_t count = 0;
    bool value_since_separator = false;
    size_t i = 0;
    while (i < line.size()) {
      const char c = line[i];
      if (c == ' ' || c == '\t') {
        ++i;
      } else if (c == ',' || c == ';') {
        if (!value_since_separator)
          throw FileError(path + ": line " + std::to_string(line_number) + ", column " +
                          std::to_string(i + 1) + ": an empty entry before '" +
                          std::string(1, c) + "'");
        value_since_separator = false;
        ++i;
      } else {
        size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != ',' &&
               line[j] != ';')
          ++j;
        const std::string token = line.substr(i, j - i);
        ++count;
        double v;
        if (!parse_number(token, v))
          throw FileError(path + ": line " + std::to_string(line_number) + ", entry " +
                          std::to_string(count) + " (column " + std::to_string(i + 1) +
                          "): '" + token + "' is not a number");
        if (std::isinf(v))
          throw FileError(path + ": line " + std::to_string(line_number) + ", entry " +
                          std::to_string(count) + " (column " + std::to_string(i + 1) +
                          "): '" + token +
                          "' is not finite (only nan marks a missing point)");
        if (std::isnan(v)) v = std::numeric_limits<double>::quiet_NaN();
        values.push_back(v);
        value_since_separator = true;
        i = j;
      }
    }
    if (count == 0)
      throw FileError(path + ": line " + std::to_string(line_number) + " has separators but no values");
    if (columns < 0) {
      columns = count;
      first_data_line = line_number;
    } else if (count != columns) {
      throw FileError(path + ": line " + std::to_string(line_number) + " has " +
                      std::to_string(count) + " values, but the first row (line " +
                      std::to_string(first_data_line) + ") has " + std::to_string(columns));
    }
  }
  if (values.empty())
    throw FileError(path + ": no values (an empty file, or only comments and blank lines)");

  map.nx = columns;
  map.ny = static_cast<int64_t>(values.size()) / columns;
  map.heights = std::move(values);
  map.format = FileFormat::text;
  map.layout = map.ny == 1 ? "text matrix, one profile on one line"
                           : "text matrix, one scan line (y) per row";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  map.lx = nan;
  map.ly = nan;
  if (header.has_width) {
    map.lx = header.width;
    map.length_unit = header.width_unit;
  }
  if (header.has_height && map.ny > 1) {
    map.ly = header.height;
    if (!header.has_width) {
      map.length_unit = header.height_unit;
    } else if (header.height_unit != header.width_unit) {
      // Both in the width's unit when both are length units; otherwise as the file says.
      try {
        map.ly = header.height * unit_in_metres(header.height_unit) /
                 unit_in_metres(header.width_unit);
      } catch (const std::invalid_argument &) {
        throw FileError(path + ": the header's Width is in '" + header.width_unit +
                        "' but its Height in '" + header.height_unit + "'");
      }
    }
  }
  map.height_unit = header.value_unit;
  return map;
}

}  // namespace detail

void write_text_matrix(const std::string &path, const double *values, int64_t nx, int64_t ny,
                       const std::vector<std::string> &comments) {
  if (nx <= 0 || ny <= 0 || values == nullptr)
    throw FileError("cannot write '" + path + "': no values (nx = " + std::to_string(nx) +
                    ", ny = " + std::to_string(ny) + ")");
  std::string out;
  for (const std::string &comment : comments) {
    // One '#' line per line of the comment, so that a newline in it cannot start a data row.
    size_t start = 0;
    while (true) {
      const auto eol = comment.find('\n', start);
      out += "# " + comment.substr(start, eol == std::string::npos ? std::string::npos
                                                                      : eol - start);
      out += '\n';
      if (eol == std::string::npos) break;
      start = eol + 1;
    }
  }
  char buffer[64];
  for (int64_t y = 0; y < ny; ++y) {
    for (int64_t x = 0; x < nx; ++x) {
      const double v = values[x + nx * y];
      if (std::isnan(v)) {
        out += "nan";
      } else {
        // %.17g, independent of the C locale.
        const auto result =
            std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17);
        out.append(buffer, result.ptr);
      }
      out += x + 1 < nx ? ' ' : '\n';
    }
  }
  detail::write_file(path, out);
}

}  // namespace asp::io
