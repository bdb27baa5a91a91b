// SPDX-License-Identifier: GPL-2.0-or-later
// read_height_map: the choice of reader; format names; the file helpers the readers share.
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/height_map.hpp"
#include "io/internal.hpp"

namespace asp::io {

namespace detail {

std::string read_file(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw FileError("cannot open '" + path + "' for reading" +
                    (err ? std::string(": ") + std::strerror(err) : std::string()));
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw FileError("cannot read '" + path + "'");
  return buffer.str();
}

void write_file(const std::string &path, const std::string &bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    const int err = errno;
    throw FileError("cannot open '" + path + "' for writing" +
                    (err ? std::string(": ") + std::strerror(err) : std::string()));
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw FileError("cannot write '" + path + "'");
}

std::string format_double(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace detail

namespace {

std::string lower(std::string s) {
  for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

HeightMap read_height_map(const std::string &path, FileFormat format) {
  HeightMap map;
  if (format == FileFormat::x3p) {
    map = detail::read_x3p(path);
  } else {
    std::string bytes = detail::read_file(path);
    if (format == FileFormat::automatic) {
      if (bytes.compare(0, 6, "\x93NUMPY") == 0)
        format = FileFormat::npy;
      else if (bytes.compare(0, 4, "PK\x03\x04") == 0)
        format = FileFormat::x3p;
      else
        format = FileFormat::text;
    }
    if (format == FileFormat::npy)
      map = detail::read_npy(path, bytes);
    else if (format == FileFormat::text)
      map = detail::read_text_matrix(path, bytes);
    else
      map = detail::read_x3p(path);
  }
  // Infinities are refused in every format (the text reader names their line and column):
  // only NaN marks a missing point.
  map.missing = 0;
  for (size_t i = 0; i < map.heights.size(); ++i) {
    const double h = map.heights[i];
    if (std::isnan(h)) ++map.missing;
    if (std::isinf(h))
      throw FileError(path + ": height " + std::to_string(i) + " (x = " +
                      std::to_string(static_cast<int64_t>(i) % std::max<int64_t>(map.nx, 1)) +
                      ", y = " +
                      std::to_string(static_cast<int64_t>(i) / std::max<int64_t>(map.nx, 1)) +
                      ") is not finite (only nan marks a missing point)");
  }
  return map;
}

FileFormat format_from_extension(const std::string &path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return FileFormat::automatic;
  const std::string ext = lower(path.substr(dot + 1));
  if (ext == "txt" || ext == "asc" || ext == "csv" || ext == "dat") return FileFormat::text;
  if (ext == "npy") return FileFormat::npy;
  if (ext == "x3p") return FileFormat::x3p;
  return FileFormat::automatic;
}

FileFormat format_from_name(const std::string &name) {
  if (name == "automatic") return FileFormat::automatic;
  if (name == "text") return FileFormat::text;
  if (name == "npy") return FileFormat::npy;
  if (name == "x3p") return FileFormat::x3p;
  throw std::invalid_argument("unknown file format '" + name +
                              "': the formats are automatic, text, npy and x3p");
}

const char *format_name(FileFormat format) {
  switch (format) {
    case FileFormat::automatic:
      return "automatic";
    case FileFormat::text:
      return "text";
    case FileFormat::npy:
      return "npy";
    case FileFormat::x3p:
      return "x3p";
  }
  return "unknown";
}

}  // namespace asp::io
