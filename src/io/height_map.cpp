// SPDX-License-Identifier: GPL-2.0-or-later
// read_height_map: the choice of reader; format names; the file helpers the readers share.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/height_map.hpp"
#include "io/internal.hpp"

namespace asp::io {

namespace detail {

namespace {

// What a file that is not a regular one is, for the message that refuses it.
const char *file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

}  // namespace

InputFile::InputFile(const std::string &path) : path_(path) {
  // O_NONBLOCK: opening a FIFO would otherwise wait for a writer. The type is then checked on
  // the descriptor itself, so that nothing can swap the file between the check and the read.
  do {
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  } while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0) {
    const int err = errno;
    throw FileError("cannot open '" + path + "' for reading: " + std::strerror(err));
  }
  struct stat st;
  if (::fstat(fd_, &st) != 0) {
    const int err = errno;
    ::close(fd_);
    throw FileError("cannot open '" + path + "' for reading: " + std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw FileError("'" + path + "' is " + file_kind(st.st_mode) +
                    ", not a regular file: only files are read");
  }
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags != -1) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
  size_ = static_cast<int64_t>(st.st_size);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

size_t InputFile::read(char *buffer, size_t n) {
  n = static_cast<size_t>(std::min<int64_t>(static_cast<int64_t>(n), size_ - position_));
  size_t done = 0;
  while (done < n) {
    const ssize_t got = ::read(fd_, buffer + done, n - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int err = errno;
      throw FileError("cannot read '" + path_ + "': " + std::strerror(err));
    }
    if (got == 0) break;  // the file is shorter than when it was opened
    done += static_cast<size_t>(got);
  }
  position_ += static_cast<int64_t>(done);
  return done;
}

void InputFile::seek(int64_t offset) {
  if (::lseek(fd_, static_cast<off_t>(offset), SEEK_SET) != static_cast<off_t>(offset)) {
    const int err = errno;
    throw FileError("cannot read '" + path_ + "': " + std::strerror(err));
  }
  position_ = offset;
}

std::string points_limit_text(const ReadLimits &limits) {
  return "the limit of " + std::to_string(limits.max_points) + " points per map";
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

HeightMap read_height_map(const std::string &path, FileFormat format, const ReadLimits &limits) {
  if (limits.max_points < 1)
    throw std::invalid_argument("ReadLimits::max_points is " + std::to_string(limits.max_points) +
                                ": it must be at least 1");
  if (limits.max_xml_bytes < 1)
    throw std::invalid_argument("ReadLimits::max_xml_bytes is " +
                                std::to_string(limits.max_xml_bytes) + ": it must be at least 1");
  detail::InputFile file(path);
  if (format == FileFormat::automatic) {
    char magic[6];
    const std::string start(magic, file.read(magic, sizeof magic));
    file.seek(0);
    if (start.compare(0, 6, "\x93NUMPY") == 0)
      format = FileFormat::npy;
    else if (start.compare(0, 4, "PK\x03\x04") == 0)
      format = FileFormat::x3p;
    else
      format = FileFormat::text;
  }
  HeightMap map;
  if (format == FileFormat::npy)
    map = detail::read_npy(file, limits);
  else if (format == FileFormat::x3p)
    map = detail::read_x3p(file, limits);
  else
    map = detail::read_text_matrix(file, limits);
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
