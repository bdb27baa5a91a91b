// SPDX-License-Identifier: GPL-2.0-or-later
// Internal helpers shared by the readers and writers of asperity_io (not installed, not part of
// the interface in height_map.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/height_map.hpp"

namespace asp::io::detail {

// A regular file open for reading. Anything else (a directory, a device such as /dev/zero, a
// FIFO, a socket) is refused before a byte is read, with a FileError naming the path and what
// it is; a FIFO is opened without waiting for a writer. Reads end at the length the file had
// when it was opened.
class InputFile {
 public:
  explicit InputFile(const std::string &path);
  ~InputFile();
  InputFile(const InputFile &) = delete;
  InputFile &operator=(const InputFile &) = delete;

  const std::string &path() const { return path_; }
  int64_t size() const { return size_; }
  int descriptor() const { return fd_; }
  // Up to n bytes from the current position, fewer only at the end; FileError on failure.
  size_t read(char *buffer, size_t n);
  void seek(int64_t offset);
  // Gives up the descriptor to whoever closes it now (libzip, once it has opened the archive).
  void release() { fd_ = -1; }

 private:
  std::string path_;
  int fd_ = -1;
  int64_t size_ = 0;
  int64_t position_ = 0;
};

// Writes bytes to a file (replacing it); FileError naming the path on failure.
void write_file(const std::string &path, const std::string &bytes);

// A unit as unit_in_metres() spells it ("µm", "micron", "μm" -> "um", "Å" -> "A"), or the
// given text, trimmed, when it is not a length unit.
std::string normalise_unit(const std::string &unit);

// A double as the shortest text that reads back to the same value ("C" locale).
std::string format_double(double value);

// The RFC 1321 MD5 digest of bytes as 32 lower-case hexadecimal digits, of one string or of
// pieces given in turn to update().
std::string md5_hex(const std::string &bytes);
class Md5 {
 public:
  void update(const char *data, size_t n);
  std::string hex();  // the digest of what update() was given; ends the computation

 private:
  std::array<uint32_t, 4> state_ = {0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476};
  unsigned char block_[64] = {};
  size_t filled_ = 0;
  uint64_t length_ = 0;
};

// The readers: each reads `file` from its start and allocates within `limits`.
HeightMap read_text_matrix(InputFile &file, const ReadLimits &limits);
HeightMap read_npy(InputFile &file, const ReadLimits &limits);
HeightMap read_x3p(InputFile &file, const ReadLimits &limits);

// "more than the limit of 268435456 points per map (ReadLimits::max_points)", for messages.
std::string points_limit_text(const ReadLimits &limits);

}  // namespace asp::io::detail
