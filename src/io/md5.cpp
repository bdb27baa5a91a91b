// SPDX-License-Identifier: GPL-2.0-or-later
// MD5 (RFC 1321), for the checksums of .x3p archives.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>

#include "io/internal.hpp"

namespace asp::io::detail {

namespace {

constexpr std::array<uint32_t, 64> kSine = {
    0xd76aa478, 0xe8c7b756, 0x242070db, 0xc1bdceee, 0xf57c0faf, 0x4787c62a, 0xa8304613,
    0xfd469501, 0x698098d8, 0x8b44f7af, 0xffff5bb1, 0x895cd7be, 0x6b901122, 0xfd987193,
    0xa679438e, 0x49b40821, 0xf61e2562, 0xc040b340, 0x265e5a51, 0xe9b6c7aa, 0xd62f105d,
    0x02441453, 0xd8a1e681, 0xe7d3fbc8, 0x21e1cde6, 0xc33707d6, 0xf4d50d87, 0x455a14ed,
    0xa9e3e905, 0xfcefa3f8, 0x676f02d9, 0x8d2a4c8a, 0xfffa3942, 0x8771f681, 0x6d9d6122,
    0xfde5380c, 0xa4beea44, 0x4bdecfa9, 0xf6bb4b60, 0xbebfbc70, 0x289b7ec6, 0xeaa127fa,
    0xd4ef3085, 0x04881d05, 0xd9d4d039, 0xe6db99e5, 0x1fa27cf8, 0xc4ac5665, 0xf4292244,
    0x432aff97, 0xab9423a7, 0xfc93a039, 0x655b59c3, 0x8f0ccc92, 0xffeff47d, 0x85845dd1,
    0x6fa87e4f, 0xfe2ce6e0, 0xa3014314, 0x4e0811a1, 0xf7537e82, 0xbd3af235, 0x2ad7d2bb,
    0xeb86d391};

constexpr std::array<int, 64> kShift = {7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22,
                                        5, 9,  14, 20, 5, 9,  14, 20, 5, 9,  14, 20, 5, 9,  14, 20,
                                        4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23,
                                        6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21};

uint32_t rotl(uint32_t x, int c) { return (x << c) | (x >> (32 - c)); }

void process_block(const unsigned char *block, std::array<uint32_t, 4> &state) {
  uint32_t m[16];
  for (int i = 0; i < 16; ++i)
    m[i] = uint32_t(block[4 * i]) | uint32_t(block[4 * i + 1]) << 8 |
           uint32_t(block[4 * i + 2]) << 16 | uint32_t(block[4 * i + 3]) << 24;
  uint32_t a = state[0], b = state[1], c = state[2], d = state[3];
  for (int i = 0; i < 64; ++i) {
    uint32_t f;
    int g;
    if (i < 16) {
      f = (b & c) | (~b & d);
      g = i;
    } else if (i < 32) {
      f = (d & b) | (~d & c);
      g = (5 * i + 1) % 16;
    } else if (i < 48) {
      f = b ^ c ^ d;
      g = (3 * i + 5) % 16;
    } else {
      f = c ^ (b | ~d);
      g = (7 * i) % 16;
    }
    const uint32_t next = b + rotl(a + f + kSine[i] + m[g], kShift[i]);
    a = d;
    d = c;
    c = b;
    b = next;
  }
  state[0] += a;
  state[1] += b;
  state[2] += c;
  state[3] += d;
}

}  // namespace

void Md5::update(const char *data, size_t n) {
  const auto *u = reinterpret_cast<const unsigned char *>(data);
  length_ += n;
  if (filled_ > 0) {
    const size_t take = std::min(n, sizeof block_ - filled_);
    std::memcpy(block_ + filled_, u, take);
    filled_ += take;
    u += take;
    n -= take;
    if (filled_ < sizeof block_) return;
    process_block(block_, state_);
    filled_ = 0;
  }
  for (; n >= 64; u += 64, n -= 64) process_block(u, state_);
  std::memcpy(block_, u, n);
  filled_ = n;
}

std::string Md5::hex() {
  // Padding: 0x80, zeros to 56 mod 64, then the length in bits, little-endian.
  unsigned char tail[128] = {};
  std::memcpy(tail, block_, filled_);
  tail[filled_] = 0x80;
  const size_t tail_len = filled_ < 56 ? 64 : 128;
  const uint64_t bits = length_ * 8;
  for (int k = 0; k < 8; ++k) tail[tail_len - 8 + k] = static_cast<unsigned char>(bits >> (8 * k));
  for (size_t k = 0; k < tail_len; k += 64) process_block(tail + k, state_);
  static const char *hex = "0123456789abcdef";
  std::string out;
  for (uint32_t word : state_)
    for (int k = 0; k < 4; ++k) {
      const unsigned byte = (word >> (8 * k)) & 0xff;
      out += hex[byte >> 4];
      out += hex[byte & 15];
    }
  return out;
}

std::string md5_hex(const std::string &bytes) {
  Md5 md5;
  md5.update(bytes.data(), bytes.size());
  return md5.hex();
}

}  // namespace asp::io::detail
