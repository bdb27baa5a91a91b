// SPDX-License-Identifier: GPL-2.0-or-later
// Text matrices: reading what Gwyddion, MATLAB and NumPy's savetxt write, and writing one.
//
// Lines starting (after blanks) with '#' or '%' are comments; "# Width: 10.000 µm",
// "# Height: ..." and "# Value units: m" (Gwyddion's header) give lx, ly and the units. Values
// are separated by blanks (spaces, tabs) or by one comma or semicolon; "nan" in any case is a
// missing point. Every data line is one scan line: row index = y, column index = x.
//
// Numbers are written with a decimal point. Decimal commas ("0,5", as spreadsheets write in
// many locales) are not read, and a file that looks like it has them is refused rather than
// read as twice as many columns of integers: a comma directly between two digits on a line
// whose values are also separated by blanks or semicolons ("0,5 0,1", "0,5;0,1"), or a file
// of two columns of integers separated by commas alone ("0,5" on every line, how a column of
// numbers with decimal commas reads).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
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

// The parser of a text matrix, given the file in pieces: it keeps the values, the current
// token and the start of a comment line, never a whole line or the whole file, so that its
// memory is that of the values it has read.
class TextParser {
 public:
  TextParser(const std::string &path, const ReadLimits &limits) : path_(path), limits_(limits) {}

  Header header;
  std::vector<double> values;
  int64_t columns = -1;

  void feed(const char *p, size_t n) {
    for (size_t k = 0; k < n; ++k) {
      const char c = p[k];
      // A carriage return ends a line only before a line feed or at the end of the file.
      if (pending_cr_) {
        pending_cr_ = false;
        if (c == '\n') {
          end_line();
          continue;
        }
        character('\r');
      }
      if (c == '\r')
        pending_cr_ = true;
      else if (c == '\n')
        end_line();
      else
        character(c);
    }
  }

  void finish() {
    pending_cr_ = false;
    end_line();
    if (values.empty())
      throw FileError(path_ + ": no values (an empty file, or only comments and blank lines)");
    // A column of numbers with decimal commas reads as two columns of integers.
    if (columns == 2 && integers_only_ && tight_commas_only_)
      decimal_comma(first_tight_line_, first_tight_column_, first_tight_text_,
                    "two columns of integers separated by commas alone are how a column of "
                    "numbers with decimal commas reads");
  }

 private:
  // Longest token kept (a longer one is not a number) and longest start of a comment line
  // kept (for the header's keys).
  static constexpr size_t kMaxToken = 256;
  static constexpr size_t kMaxComment = 1024;

  std::string path_;
  ReadLimits limits_;
  bool pending_cr_ = false;
  int64_t line_number_ = 1;
  size_t column_ = 0;  // characters of the current line so far
  enum class Kind { blank, comment, data } kind_ = Kind::blank;
  std::string comment_;
  // The data line: values so far, the token being read, the gap since the last token.
  int64_t first_data_line_ = 0;
  int64_t count_ = 0;
  bool value_since_separator_ = false;
  bool in_token_ = false;
  std::string token_;
  size_t token_column_ = 0;
  std::string last_token_;
  char gap_separator_ = 0;  // ',' or ';' when the gap has one
  size_t gap_separator_column_ = 0;
  bool gap_blank_ = false;
  bool tight_before_token_ = false;  // the gap before this token is a comma between digits
  // Decimal commas: on this line, and in the whole file.
  bool line_tight_ = false, line_other_gap_ = false;
  size_t line_tight_column_ = 0;
  std::string line_tight_text_;
  bool integers_only_ = true, tight_commas_only_ = true;
  int64_t first_tight_line_ = 0;
  size_t first_tight_column_ = 0;
  std::string first_tight_text_;

  std::string at(size_t column) const {
    return path_ + ": line " + std::to_string(line_number_) + ", column " +
           std::to_string(column + 1);
  }

  [[noreturn]] void decimal_comma(int64_t line, size_t column, const std::string &text,
                                  const std::string &why) const {
    throw FileError(path_ + ": line " + std::to_string(line) + ", column " +
                    std::to_string(column + 1) + ": '" + text +
                    "' looks like a number with a decimal comma (" + why +
                    "): decimal commas are not read; write numbers with a decimal point");
  }

  void character(char c) {
    const size_t i = column_++;
    if (kind_ == Kind::comment) {
      if (comment_.size() < kMaxComment) comment_ += c;
      return;
    }
    if (kind_ == Kind::blank) {
      if (c == ' ' || c == '\t') return;
      if (c == '#' || c == '%') {
        kind_ = Kind::comment;
        return;
      }
      kind_ = Kind::data;
    }
    // Tokens are runs of characters other than blanks, commas and semicolons; a comma or
    // semicolon with no value since the previous one (or the line's start) is an empty entry.
    if (c == ' ' || c == '\t') {
      end_token();
      gap_blank_ = true;
    } else if (c == ',' || c == ';') {
      end_token();
      if (!value_since_separator_)
        throw FileError(at(i) + ": an empty entry before '" + std::string(1, c) + "'");
      value_since_separator_ = false;
      gap_separator_ = c;
      gap_separator_column_ = i;
    } else if (in_token_) {
      if (token_.size() <= kMaxToken) token_ += c;
    } else {
      begin_token(c, i);
    }
  }

  void begin_token(char c, size_t i) {
    const auto digit = [](char d) { return d >= '0' && d <= '9'; };
    tight_before_token_ = false;
    if (count_ > 0) {
      // How this value is separated from the previous one: a comma directly between two
      // digits is what a decimal comma looks like.
      if (gap_separator_ == ',' && !gap_blank_ && digit(last_token_.back()) && digit(c)) {
        tight_before_token_ = true;
      } else {
        tight_commas_only_ = false;
        if (gap_separator_ != ',') line_other_gap_ = true;
      }
    }
    in_token_ = true;
    token_.assign(1, c);
    token_column_ = i;
  }

  void end_token() {
    if (!in_token_) return;
    in_token_ = false;
    ++count_;
    const auto entry = [&] {
      return path_ + ": line " + std::to_string(line_number_) + ", entry " +
             std::to_string(count_) + " (column " + std::to_string(token_column_ + 1) + "): '";
    };
    double v;
    if (token_.size() > kMaxToken)
      throw FileError(entry() + token_.substr(0, 32) + "...' (more than " +
                      std::to_string(kMaxToken) + " characters) is not a number");
    if (!parse_number(token_, v)) throw FileError(entry() + token_ + "' is not a number");
    if (std::isinf(v))
      throw FileError(entry() + token_ + "' is not finite (only nan marks a missing point)");
    if (std::isnan(v)) v = std::numeric_limits<double>::quiet_NaN();
    if (values.size() >= static_cast<uint64_t>(limits_.max_points))
      throw FileError(path_ + ": line " + std::to_string(line_number_) + ": more than " +
                      points_limit_text(limits_));
    if (values.size() == values.capacity())
      values.reserve(static_cast<size_t>(std::min<uint64_t>(
          std::max<uint64_t>(2 * values.capacity(), 1024), limits_.max_points)));
    values.push_back(v);
    value_since_separator_ = true;
    const size_t sign = token_[0] == '-' || token_[0] == '+' ? 1 : 0;
    if (token_.size() == sign || token_.find_first_not_of("0123456789", sign) != std::string::npos)
      integers_only_ = false;
    if (tight_before_token_ && !line_tight_) {
      line_tight_ = true;
      line_tight_column_ = gap_separator_column_;
      line_tight_text_ = last_token_ + "," + token_;
      if (first_tight_line_ == 0) {
        first_tight_line_ = line_number_;
        first_tight_column_ = line_tight_column_;
        first_tight_text_ = line_tight_text_;
      }
    }
    last_token_ = token_;
    gap_separator_ = 0;
    gap_blank_ = false;
  }

  void end_line() {
    if (kind_ == Kind::comment) {
      if (values.empty()) read_header_line(comment_, header);
    } else if (kind_ == Kind::data) {
      end_token();
      if (count_ == 0)
        throw FileError(path_ + ": line " + std::to_string(line_number_) +
                        " has separators but no values");
      if (line_tight_ && line_other_gap_)
        decimal_comma(line_number_, line_tight_column_, line_tight_text_,
                      "the line's values are also separated by blanks or semicolons");
      if (columns < 0) {
        columns = count_;
        first_data_line_ = line_number_;
      } else if (count_ != columns) {
        throw FileError(path_ + ": line " + std::to_string(line_number_) + " has " +
                        std::to_string(count_) + " values, but the first row (line " +
                        std::to_string(first_data_line_) + ") has " + std::to_string(columns));
      }
    }
    ++line_number_;
    column_ = 0;
    kind_ = Kind::blank;
    comment_.clear();
    count_ = 0;
    value_since_separator_ = false;
    gap_separator_ = 0;
    gap_blank_ = false;
    line_tight_ = line_other_gap_ = false;
  }
};

}  // namespace

HeightMap read_text_matrix(InputFile &file, const ReadLimits &limits) {
  TextParser parser(file.path(), limits);
  std::vector<char> piece(1 << 16);
  bool first = true;
  while (true) {
    const size_t got = file.read(piece.data(), piece.size());
    if (got == 0) break;
    size_t skip = 0;
    // A UTF-8 byte-order mark, as some Windows programs write.
    if (first && got >= 3 && std::string(piece.data(), 3) == "\xEF\xBB\xBF") skip = 3;
    first = false;
    parser.feed(piece.data() + skip, got - skip);
  }
  parser.finish();

  const std::string &path = file.path();
  HeightMap map;
  const Header &header = parser.header;
  const int64_t columns = parser.columns;
  std::vector<double> &values = parser.values;
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
