// SPDX-License-Identifier: GPL-2.0-or-later
// NumPy .npy files: reading versions 1.0, 2.0 and 3.0 of the format (little- and big-endian
// float64, float32 and signed or unsigned integers, shape (n,) or (rows, cols), C or Fortran
// order) and writing float64 arrays.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/height_map.hpp"
#include "io/internal.hpp"

namespace asp::io {

namespace detail {

namespace {

// A parser of the header's Python literal: {'descr': '<f8', 'fortran_order': False,
// 'shape': (3, 4), }
class HeaderParser {
 public:
  HeaderParser(const std::string &path, const std::string &text) : path_(path), text_(text) {}

  std::string descr;
  bool fortran_order = false;
  std::vector<int64_t> shape;

  void parse() {
    bool has_descr = false, has_order = false, has_shape = false;
    expect('{');
    while (true) {
      skip_blanks();
      if (peek() == '}') break;
      const std::string key = string_literal();
      expect(':');
      skip_blanks();
      if (key == "descr") {
        if (peek() == '[')
          fail("structured dtype (a list of fields) in 'descr': only plain numbers are read");
        if (peek() != '\'' && peek() != '"') fail("'descr' is not a string");
        descr = string_literal();
        has_descr = true;
      } else if (key == "fortran_order") {
        fortran_order = boolean();
        has_order = true;
      } else if (key == "shape") {
        shape = tuple();
        has_shape = true;
      } else {
        fail("unknown key '" + key + "' in the header");
      }
      skip_blanks();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      skip_blanks();
      if (peek() != '}') fail("expected ',' or '}'");
    }
    if (!has_descr || !has_order || !has_shape)
      fail("the header lacks one of 'descr', 'fortran_order' and 'shape'");
  }

 private:
  std::string path_;
  std::string text_;
  size_t pos_ = 0;

  [[noreturn]] void fail(const std::string &what) const {
    throw FileError(path_ + ": invalid .npy header (at character " + std::to_string(pos_ + 1) +
                    " of \"" + text_ + "\"): " + what);
  }
  void skip_blanks() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void expect(char c) {
    skip_blanks();
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  std::string string_literal() {
    skip_blanks();
    const char quote = peek();
    if (quote != '\'' && quote != '"') fail("expected a string");
    const auto end = text_.find(quote, pos_ + 1);
    if (end == std::string::npos) fail("unterminated string");
    std::string s = text_.substr(pos_ + 1, end - pos_ - 1);
    pos_ = end + 1;
    return s;
  }
  bool boolean() {
    if (text_.compare(pos_, 4, "True") == 0) {
      pos_ += 4;
      return true;
    }
    if (text_.compare(pos_, 5, "False") == 0) {
      pos_ += 5;
      return false;
    }
    fail("expected True or False");
  }
  std::vector<int64_t> tuple() {
    std::vector<int64_t> values;
    expect('(');
    while (true) {
      skip_blanks();
      if (peek() == ')') {
        ++pos_;
        return values;
      }
      if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("expected a dimension");
      int64_t v = 0;
      while (std::isdigit(static_cast<unsigned char>(peek()))) {
        if (v > (std::numeric_limits<int64_t>::max() - 9) / 10) fail("dimension too large");
        v = v * 10 + (text_[pos_++] - '0');
      }
      if (peek() == 'L') ++pos_;  // Python 2's long integers
      values.push_back(v);
      skip_blanks();
      if (peek() == ',') ++pos_;
      else if (peek() != ')') fail("expected ',' or ')'");
    }
  }
};

// A .npy header longer than this is refused before it is read: NumPy writes about 128 bytes
// for an array of numbers (its own reader refuses more than 10000 by default).
constexpr size_t kMaxHeaderBytes = 65536;
// The data are read in pieces of this size.
constexpr size_t kPieceBytes = 1 << 16;

uint64_t load_unsigned(const unsigned char *p, int size, bool big_endian) {
  uint64_t v = 0;
  for (int k = 0; k < size; ++k) {
    const int byte = big_endian ? k : size - 1 - k;
    v = (v << 8) | p[byte];
  }
  return v;
}

std::string shape_text(const std::vector<int64_t> &shape) {
  std::string s = "(";
  for (size_t i = 0; i < shape.size(); ++i) {
    if (i) s += ", ";
    s += std::to_string(shape[i]);
  }
  if (shape.size() == 1) s += ",";
  return s + ")";
}

}  // namespace

HeightMap read_npy(InputFile &file, const ReadLimits &limits) {
  const std::string &path = file.path();
  char start[12];
  const std::string bytes(start, file.read(start, sizeof start));
  if (bytes.size() < 6 || bytes.compare(0, 6, "\x93NUMPY") != 0)
    throw FileError(path + ": not a .npy file (the first 6 bytes are not \\x93NUMPY)");
  if (bytes.size() < 10) throw FileError(path + ": truncated .npy file: no header length");
  const auto *u = reinterpret_cast<const unsigned char *>(bytes.data());
  const int major = u[6], minor = u[7];
  size_t header_len, header_start;
  if (major == 1) {
    header_len = load_unsigned(u + 8, 2, false);
    header_start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw FileError(path + ": truncated .npy file: no header length");
    header_len = load_unsigned(u + 8, 4, false);
    header_start = 12;
  } else {
    throw FileError(path + ": unsupported .npy format version " + std::to_string(major) + "." +
                    std::to_string(minor) + " (versions 1.0, 2.0 and 3.0 are read)");
  }
  // What the file can hold, then the limit, before the header is read.
  const auto file_size = static_cast<size_t>(file.size());
  if (file_size < header_start + header_len)
    throw FileError(path + ": truncated .npy file: the header of " + std::to_string(header_len) +
                    " bytes ends after byte " + std::to_string(file_size));
  if (header_len > kMaxHeaderBytes)
    throw FileError(path + ": a .npy header of " + std::to_string(header_len) +
                    " bytes: more than the limit of " + std::to_string(kMaxHeaderBytes) +
                    " bytes for a header (arrays of numbers have headers of about 128)");
  std::string header_text(header_len, '\0');
  file.seek(static_cast<int64_t>(header_start));
  if (file.read(&header_text[0], header_len) != header_len)
    throw FileError(path + ": truncated .npy file: the header of " + std::to_string(header_len) +
                    " bytes is cut short");
  HeaderParser header(path, header_text);
  header.parse();

  // The dtype: a byte order ('<', '>', '|' or '=') then a kind and a size.
  const std::string &d = header.descr;
  if (d.size() >= 2 && d[1] == 'O')
    throw FileError(path + ": object arrays ('" + d + "') are not read: only numbers are");
  if (d.size() < 3 || std::string("<>|=").find(d[0]) == std::string::npos)
    throw FileError(path + ": unsupported dtype '" + d + "'");
  const bool big_endian = d[0] == '>';
  const char kind = d[1];
  const std::string size_text = d.substr(2);
  int size = 0;
  if (size_text == "1" || size_text == "2" || size_text == "4" || size_text == "8")
    size = size_text[0] - '0';
  const bool supported = (kind == 'f' && (size == 4 || size == 8)) ||
                         ((kind == 'i' || kind == 'u') && size > 0);
  if (!supported)
    throw FileError(path + ": unsupported dtype '" + d +
                    "': float64, float32 and integer arrays are read");

  const auto &shape = header.shape;
  int64_t nx, ny;
  if (shape.size() == 1) {
    nx = shape[0];
    ny = 1;
  } else if (shape.size() == 2) {
    ny = shape[0];
    nx = shape[1];
  } else {
    throw FileError(path + ": a " + std::to_string(shape.size()) + "-D array of shape " +
                    shape_text(shape) + ": only shapes (n,) and (rows, columns) are read");
  }
  if (nx <= 0 || ny <= 0)
    throw FileError(path + ": an empty array of shape " + shape_text(shape));
  if (nx > std::numeric_limits<int64_t>::max() / ny / size)
    throw FileError(path + ": shape " + shape_text(shape) + " too large");
  if (nx > limits.max_points / ny)
    throw FileError(path + ": shape " + shape_text(shape) + ": more than " +
                    points_limit_text(limits));
  const size_t count = static_cast<size_t>(nx * ny);
  const size_t data_start = header_start + header_len;
  const size_t available = file_size - data_start;
  if (available < count * size)
    throw FileError(path + ": truncated .npy data: shape " + shape_text(shape) + " of '" + d +
                    "' needs " + std::to_string(count * size) + " bytes after the header (byte " +
                    std::to_string(data_start) + "), the file has " + std::to_string(available));

  HeightMap map;
  map.nx = nx;
  map.ny = ny;
  map.heights.resize(count);
  // The data in pieces, in the file's order: element k is [row, column] = [y, x] with
  // k = x + nx * y in C order and k = y + ny * x in Fortran order (rows fastest).
  std::vector<char> piece(kPieceBytes);
  file.seek(static_cast<int64_t>(data_start));
  size_t k = 0;
  while (k < count) {
    const size_t n = std::min(count - k, kPieceBytes / size);
    const size_t got = file.read(piece.data(), n * size);
    if (got != n * size)
      throw FileError(path + ": truncated .npy data: shape " + shape_text(shape) + " of '" + d +
                      "' needs " + std::to_string(count * size) +
                      " bytes after the header, the file ends after " +
                      std::to_string(k * size + got));
    const auto *p = reinterpret_cast<const unsigned char *>(piece.data());
    for (size_t e = 0; e < n; ++e, ++k) {
      const uint64_t raw = load_unsigned(p + e * size, size, big_endian);
      double v;
      if (kind == 'f' && size == 8) {
        std::memcpy(&v, &raw, 8);
      } else if (kind == 'f') {
        const auto raw32 = static_cast<uint32_t>(raw);
        float f;
        std::memcpy(&f, &raw32, 4);
        v = f;
      } else if (kind == 'u') {
        v = static_cast<double>(raw);
      } else {
        // Sign-extend a two's-complement integer of `size` bytes.
        const int shift = 64 - 8 * size;
        v = static_cast<double>(static_cast<int64_t>(raw << shift) >> shift);
      }
      const size_t index = header.fortran_order
                               ? static_cast<size_t>(k / ny) + static_cast<size_t>(nx) * (k % ny)
                               : k;
      map.heights[index] = v;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  map.lx = nan;
  map.ly = nan;
  map.format = FileFormat::npy;
  if (ny == 1 && shape.size() == 1)
    map.layout = ".npy array of shape (n,), one profile";
  else if (header.fortran_order)
    map.layout = "Fortran-order .npy array (ny, nx), y fastest in memory, [row, column] = [y, x]";
  else
    map.layout = "C-order .npy array (ny, nx), one scan line (y) per row";
  return map;
}

}  // namespace detail

void write_npy(const std::string &path, const double *values, int64_t nx, int64_t ny) {
  if (nx <= 0 || ny <= 0 || values == nullptr)
    throw FileError("cannot write '" + path + "': no values (nx = " + std::to_string(nx) +
                    ", ny = " + std::to_string(ny) + ")");
  const std::string shape =
      ny == 1 ? "(" + std::to_string(nx) + ",)"
              : "(" + std::to_string(ny) + ", " + std::to_string(nx) + ")";
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': " + shape + ", }";
  // Version 1.0: magic (6) + version (2) + length (2) + header, padded with spaces and ended
  // by a newline so that the data start on a multiple of 64 bytes.
  size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  if (header.size() > 65535)
    throw FileError("cannot write '" + path + "': header too long for .npy version 1.0");
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  out += header;
  const size_t count = static_cast<size_t>(nx * ny);
  out.reserve(out.size() + 8 * count);
  for (size_t i = 0; i < count; ++i) {
    uint64_t raw;
    std::memcpy(&raw, &values[i], 8);
    for (int k = 0; k < 8; ++k) out += static_cast<char>((raw >> (8 * k)) & 0xff);
  }
  detail::write_file(path, out);
}

}  // namespace asp::io
