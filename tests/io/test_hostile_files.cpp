// SPDX-License-Identifier: GPL-2.0-or-later
// Hostile files: what the readers allocate is bounded by their limits (asp::io::ReadLimits) and
// by what a file can hold, whatever the file declares. Each test builds its files (x3p archives
// are written here byte by byte, so that their headers can say what a damaged or malicious
// archive says) and reads them in a child process whose address space is capped a few hundred
// MiB above what it already uses and which is stopped after 10 s: a read must end refused, with
// a FileError naming the file and the problem, having grown the child's resident memory by at
// most 16 MiB. Before the limits, each of these reads allocated what the file declared (up to
// 8 GiB), inflated archives in full (2 GB) or read devices without end.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "temp_path.hpp"
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "io/height_map.hpp"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define ASPERITY_IO_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define ASPERITY_IO_SANITIZED 1
#endif
#endif

namespace {

using asp::io::FileError;
using asp::io::FileFormat;
using asp::io::ReadLimits;

const std::string kData = ASPERITY_IO_TEST_DATA;
constexpr int64_t kMiB = int64_t(1) << 20;
// The child's address space: what it uses when it starts the read, plus this.
constexpr int64_t kAddressSpaceMargin = 256 * kMiB;
// The most a refused hostile file may grow the child's resident memory.
constexpr int64_t kMostGrowth = 16 * kMiB;
// A read still running after this long is stopped (SIGALRM) and counts as hanging; every
// read here ends in milliseconds.
constexpr unsigned kHangSeconds = 10;

std::string data(const std::string &name) { return kData + "/" + name; }

bool contains(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}


std::string write_file(const std::string &name, const std::string &content) {
  const std::string path = temp_path(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  return path;
}

// ---- reading in a child with bounded memory and time ---------------------------------------

struct Outcome {
  enum Kind { refused, read, other_exception, killed } kind = killed;
  std::string message;   // the exception's message, or how the child ended
  int64_t grown = 0;     // bytes the read added to the child's peak resident memory
};

std::ostream &operator<<(std::ostream &out, const Outcome &o) {
  static const char *names[] = {"refused", "read", "another exception", "killed"};
  return out << names[o.kind] << " (resident memory grown by " << o.grown / 1024 << " KiB): "
             << o.message;
}

int64_t virtual_size() {
  std::ifstream statm("/proc/self/statm");
  int64_t pages = 0;
  statm >> pages;
  return pages * ::sysconf(_SC_PAGESIZE);
}

Outcome read_in_child(const std::string &path, FileFormat format,
                      const ReadLimits &limits = ReadLimits()) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) {
    ADD_FAILURE() << "pipe: " << std::strerror(errno);
    return {};
  }
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(pipe_fds[0]);
    ::alarm(kHangSeconds);
#ifndef ASPERITY_IO_SANITIZED
    // (A sanitizer reserves terabytes of address space for its shadow memory.)
    const rlim_t cap = static_cast<rlim_t>(virtual_size() + kAddressSpaceMargin);
    const struct rlimit limit = {cap, cap};
    ::setrlimit(RLIMIT_AS, &limit);
#endif
    struct rusage before, after;
    ::getrusage(RUSAGE_SELF, &before);
    char kind;
    std::string message;
    try {
      asp::io::read_height_map(path, format, limits);
      kind = 'r';
    } catch (const FileError &e) {
      kind = 'f';
      message = e.what();
    } catch (const std::exception &e) {
      kind = 'o';
      message = std::string("a ") + typeid(e).name() + ": " + e.what();
    } catch (...) {
      kind = 'o';
      message = "an exception of unknown type";
    }
    ::getrusage(RUSAGE_SELF, &after);
    const std::string report = std::string(1, kind) + " " +
                               std::to_string((after.ru_maxrss - before.ru_maxrss) * 1024) +
                               "\n" + message;
    size_t done = 0;
    while (done < report.size()) {
      const ssize_t n = ::write(pipe_fds[1], report.data() + done, report.size() - done);
      if (n <= 0) break;
      done += static_cast<size_t>(n);
    }
    ::_exit(0);
  }
  ::close(pipe_fds[1]);
  Outcome outcome;
  if (pid < 0) {
    ::close(pipe_fds[0]);
    ADD_FAILURE() << "fork: " << std::strerror(errno);
    return outcome;
  }
  std::string report;
  char buffer[4096];
  ssize_t n;
  while ((n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR))
    if (n > 0) report.append(buffer, static_cast<size_t>(n));
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    outcome.message = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) +
                      " (" + ::strsignal(WTERMSIG(status)) + ")";
    return outcome;
  }
  const auto space = report.find(' '), newline = report.find('\n');
  if (report.empty() || space == std::string::npos || newline == std::string::npos) {
    outcome.message = "no report from the child";
    return outcome;
  }
  outcome.kind = report[0] == 'f'   ? Outcome::refused
                 : report[0] == 'r' ? Outcome::read
                                    : Outcome::other_exception;
  outcome.grown = std::stoll(report.substr(space + 1, newline - space - 1));
  outcome.message = report.substr(newline + 1);
  return outcome;
}

// Reading `path` is refused with a message naming it and containing every one of `parts`,
// cheaply (in the child's resident memory).
void expect_refused(const std::string &path, FileFormat format,
                    const std::vector<std::string> &parts,
                    const ReadLimits &limits = ReadLimits()) {
  const Outcome outcome = read_in_child(path, format, limits);
  EXPECT_EQ(outcome.kind, Outcome::refused) << path << " as " << asp::io::format_name(format)
                                            << ": " << outcome;
  EXPECT_TRUE(contains(outcome.message, path)) << outcome;
  for (const std::string &part : parts)
    EXPECT_TRUE(contains(outcome.message, part)) << "expected '" << part << "' in " << outcome;
#ifndef ASPERITY_IO_SANITIZED
  EXPECT_LE(outcome.grown, kMostGrowth) << outcome;
#endif
}

// ---- zip archives, byte by byte ------------------------------------------------------------

void put16(std::string &s, uint32_t v) {
  s += static_cast<char>(v & 0xff);
  s += static_cast<char>((v >> 8) & 0xff);
}
void put32(std::string &s, uint32_t v) {
  put16(s, v & 0xffff);
  put16(s, v >> 16);
}

// A member of an archive: the bytes it stores and what its headers declare.
struct Member {
  std::string name;
  std::string stored;        // raw deflate data when deflated
  uint16_t method = 0;       // 0 stored, 8 deflated
  uint32_t crc = 0;
  uint64_t size = 0;         // declared once inflated
  uint64_t compressed = 0;   // declared compressed
};

Member stored_member(const std::string &name, const std::string &content) {
  Member m;
  m.name = name;
  m.stored = content;
  m.crc = static_cast<uint32_t>(
      crc32(0, reinterpret_cast<const Bytef *>(content.data()), static_cast<uInt>(content.size())));
  m.size = m.compressed = content.size();
  return m;
}

// Raw deflate (as in zip archives) of content given in pieces: the CRC and the size follow.
class Deflater {
 public:
  explicit Deflater(int strategy = Z_DEFAULT_STRATEGY) {
    if (deflateInit2(&z_, Z_DEFAULT_COMPRESSION, Z_DEFLATED, -15, 8, strategy) != Z_OK)
      ADD_FAILURE() << "deflateInit2";
  }
  ~Deflater() { deflateEnd(&z_); }

  void add(const std::string &piece) { run(piece.data(), piece.size(), Z_NO_FLUSH); }
  // n copies of one byte, without holding them.
  void add_repeated(char byte, uint64_t n) {
    const std::string piece(static_cast<size_t>(std::min<uint64_t>(n, kMiB)), byte);
    for (uint64_t done = 0; done < n; done += piece.size())
      run(piece.data(), static_cast<size_t>(std::min<uint64_t>(piece.size(), n - done)),
          Z_NO_FLUSH);
  }
  Member finish(const std::string &name) {
    run(nullptr, 0, Z_FINISH);
    Member m;
    m.name = name;
    m.stored = out_;
    m.method = 8;
    m.crc = crc_;
    m.size = size_;
    m.compressed = out_.size();
    return m;
  }

 private:
  z_stream z_ = {};
  std::string out_;
  uint32_t crc_ = 0;
  uint64_t size_ = 0;

  void run(const char *p, size_t n, int flush) {
    if (n > 0)  // (crc32 of no buffer is the initial value, not an update)
      crc_ = static_cast<uint32_t>(
          crc32(crc_, reinterpret_cast<const Bytef *>(p), static_cast<uInt>(n)));
    size_ += n;
    z_.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(p));
    z_.avail_in = static_cast<uInt>(n);
    unsigned char buffer[1 << 16];
    int result;
    do {
      z_.next_out = buffer;
      z_.avail_out = sizeof buffer;
      result = deflate(&z_, flush);
      out_.append(reinterpret_cast<char *>(buffer), sizeof buffer - z_.avail_out);
    } while (z_.avail_out == 0 || (flush == Z_FINISH && result != Z_STREAM_END));
  }
};

Member deflated_member(const std::string &name, const std::string &content) {
  Deflater d;
  d.add(content);
  return d.finish(name);
}

// A zip archive of the members, their local headers and central directory saying what each
// member declares (32-bit sizes: the hostile ones here declare at most 2 GiB).
std::string zip_archive(const std::vector<Member> &members) {
  std::string out, directory;
  for (const Member &m : members) {
    const auto offset = static_cast<uint32_t>(out.size());
    const auto header = [&](std::string &s, bool central) {
      put32(s, central ? 0x02014b50 : 0x04034b50);
      if (central) put16(s, 20);  // made by
      put16(s, 20);               // needed to extract: 2.0
      put16(s, 0);                // flags
      put16(s, m.method);
      put16(s, 0);                // time
      put16(s, 0x21);             // date: 1980-01-01
      put32(s, m.crc);
      put32(s, static_cast<uint32_t>(m.compressed));
      put32(s, static_cast<uint32_t>(m.size));
      put16(s, static_cast<uint32_t>(m.name.size()));
      put16(s, 0);  // extra field
      if (central) {
        put16(s, 0);  // comment
        put16(s, 0);  // disk
        put16(s, 0);  // internal attributes
        put32(s, 0);  // external attributes
        put32(s, offset);
      }
      s += m.name;
    };
    header(out, false);
    out += m.stored;
    header(directory, true);
  }
  const auto directory_offset = static_cast<uint32_t>(out.size());
  out += directory;
  put32(out, 0x06054b50);
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<uint32_t>(members.size()));
  put16(out, static_cast<uint32_t>(members.size()));
  put32(out, static_cast<uint32_t>(directory.size()));
  put32(out, directory_offset);
  put16(out, 0);
  return out;
}

const std::string kXmlStart =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n";
const std::string kXmlEnd = "</p:ISO5436_2>\n";

// main.xml of an areal surface of nx x ny float64 points in bindata/data.bin (no checksum).
std::string main_xml(int64_t nx, int64_t ny) {
  const auto axis = [](const char *name) {
    return std::string("<") + name +
           "><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-06</Increment>"
           "<Offset>0</Offset></" + name + ">";
  };
  return kXmlStart + "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType>"
         "<Axes>" + axis("CX") + axis("CY") +
         "<CZ><AxisType>A</AxisType><DataType>D</DataType></CZ></Axes></Record1>\n"
         "<Record3><MatrixDimension><SizeX>" + std::to_string(nx) + "</SizeX><SizeY>" +
         std::to_string(ny) + "</SizeY><SizeZ>1</SizeZ></MatrixDimension>"
         "<DataLink><PointDataLink>bindata/data.bin</PointDataLink></DataLink></Record3>\n" +
         kXmlEnd;
}

std::string x3p(const std::string &xml, const Member &data) {
  return zip_archive({deflated_member("main.xml", xml), data});
}

const std::vector<FileFormat> kEveryFormat = {FileFormat::automatic, FileFormat::text,
                                              FileFormat::npy, FileFormat::x3p};

// ---- finding 4: the x3p reader allocated what main.xml declares ----------------------------

TEST(HostileFiles, X3pDeclaring2To28PointsIsRefusedBeforeAllocating) {
  // A few hundred bytes declaring 16384 x 16384 float64 points (2 GiB) with 96 bytes of data:
  // refused by the data member's declared size before the heights are allocated.
  const std::string small_data =
      write_file("small_data.x3p", x3p(main_xml(16384, 16384),
                                       stored_member("bindata/data.bin", std::string(96, '\0'))));
  expect_refused(small_data, FileFormat::x3p,
                 {"bindata/data.bin inflates to 96 bytes (as the archive declares), but 16384 x "
                  "16384 points of DataType D take 2147483648"});
  expect_refused(small_data, FileFormat::automatic, {"take 2147483648"});

  // The data member declares the 2 GiB, but a deflated member of 20 bytes cannot hold them.
  Member lying = stored_member("bindata/data.bin", std::string(20, '\x55'));
  lying.method = 8;
  lying.size = uint64_t(1) << 31;
  expect_refused(write_file("deflate_cannot_hold.x3p", x3p(main_xml(16384, 16384), lying)),
                 FileFormat::x3p,
                 {"bindata/data.bin declares 2147483648 bytes compressed into 20: more than "
                  "deflate makes of them (1032 times as many)"});

  // Nor a stored member of 20 bytes.
  lying.method = 0;
  expect_refused(write_file("stored_cannot_hold.x3p", x3p(main_xml(16384, 16384), lying)),
                 FileFormat::x3p,
                 {"bindata/data.bin declares 2147483648 bytes compressed into 20, stored "
                  "uncompressed"});
  // Other methods (bzip2 here; an unknown one, found by fuzzing) expand without such a bound.
  for (uint16_t method : {12, 0xe1f3}) {
    lying.method = method;
    expect_refused(write_file("method_" + std::to_string(method) + ".x3p",
                              x3p(main_xml(16384, 16384), lying)),
                   FileFormat::x3p,
                   {"bindata/data.bin is compressed by method " + std::to_string(method) +
                    ": only stored and deflated members are read"});
  }
}

TEST(HostileFiles, X3pBeyondThePointLimitIsRefused) {
  // 32768 x 32768 points (8 GiB of doubles) ended in std::bad_alloc.
  const std::string path = write_file(
      "huge_matrix.x3p",
      x3p(main_xml(32768, 32768), stored_member("bindata/data.bin", std::string(96, '\0'))));
  expect_refused(path, FileFormat::x3p,
                 {"main.xml: a matrix of 32768 x 32768 points: more than the limit of "
                  "268435456 points per map"});
  // The limit is the caller's: the 4 x 3 fixture with one point fewer allowed, and exactly.
  ReadLimits limits;
  limits.max_points = 11;
  expect_refused(data("surface.x3p"), FileFormat::x3p,
                 {"a matrix of 4 x 3 points: more than the limit of 11 points per map"}, limits);
  limits.max_points = 12;
  EXPECT_EQ(asp::io::read_height_map(data("surface.x3p"), FileFormat::x3p, limits).nx, 4);
}

// ---- finding 5: archives were inflated in full ---------------------------------------------

TEST(HostileFiles, X3pDataMemberInflatingFarBeyondTheGridIsNotInflated) {
  // 256 MiB of zeros (a quarter of a MiB deflated) for a 4 x 3 grid, the size declared
  // truthfully: refused by the declared size, nothing inflated.
  Deflater bomb(Z_RLE);
  bomb.add_repeated('\0', 256 * kMiB);
  const Member member = bomb.finish("bindata/data.bin");
  ASSERT_LT(member.stored.size(), 1 * kMiB);
  expect_refused(write_file("data_bomb.x3p", x3p(main_xml(4, 3), member)), FileFormat::x3p,
                 {"bindata/data.bin inflates to 268435456 bytes (as the archive declares), but "
                  "4 x 3 points of DataType D take 96"});

  // The same data declaring the 96 bytes the grid takes: inflated to 96 bytes and one more,
  // which refuses it (it was read as 12 zeros).
  Member lying = member;
  lying.size = 96;
  expect_refused(write_file("data_bomb_lying.x3p", x3p(main_xml(4, 3), lying)), FileFormat::x3p,
                 {"bindata/data.bin inflates to more than the 96 bytes the archive declares"});
}

TEST(HostileFiles, X3pXmlBombIsRefusedAtTheXmlLimit) {
  const Member points = stored_member("bindata/data.bin", std::string(96, '\0'));
  // A main.xml of 256 MiB (blanks inside the root element), declared truthfully.
  Deflater bomb(Z_RLE);
  bomb.add(kXmlStart);
  bomb.add_repeated(' ', 256 * kMiB);
  bomb.add(kXmlEnd);
  Member xml = bomb.finish("main.xml");
  ASSERT_LT(xml.stored.size(), 1 * kMiB);
  const std::string declared = std::to_string(xml.size);
  expect_refused(write_file("xml_bomb.x3p", zip_archive({xml, points})), FileFormat::x3p,
                 {"main.xml inflates to " + declared +
                  " bytes (as the archive declares): more than the limit of 4194304 bytes for "
                  "main.xml"});
  // Declaring 1000 bytes: inflated to 1000 bytes and one more.
  xml.size = 1000;
  expect_refused(write_file("xml_bomb_lying.x3p", zip_archive({xml, points})), FileFormat::x3p,
                 {"main.xml inflates to more than the 1000 bytes the archive declares"});

  // Within the limit, 100000 nested elements are parsed (without recursion) and refused for
  // what they lack.
  std::string nested = kXmlStart;
  for (int i = 0; i < 100000; ++i) nested += "<a>";
  for (int i = 0; i < 100000; ++i) nested += "</a>";
  nested += kXmlEnd;
  expect_refused(write_file("xml_nested.x3p", x3p(nested, points)), FileFormat::x3p,
                 {"main.xml has no /Record1"});

  // The limit is the caller's: below the fixture's main.xml.
  ReadLimits limits;
  limits.max_xml_bytes = 100;
  expect_refused(data("surface.x3p"), FileFormat::x3p,
                 {"main.xml inflates to", "more than the limit of 100 bytes for main.xml"},
                 limits);
}

// ---- finding 6: devices, FIFOs and directories were read without end ------------------------

TEST(HostileFiles, DevicesFifosAndDirectoriesAreRefusedBeforeReading) {
  const std::string fifo = temp_path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  const std::string directory = temp_path("directory");
  std::filesystem::create_directory(directory);
  struct Case {
    std::string path, kind;
  };
  std::vector<Case> cases = {{fifo, "a FIFO (named pipe)"}, {directory, "a directory"}};
  for (const char *device : {"/dev/zero", "/dev/urandom"})
    if (::access(device, R_OK) == 0) cases.push_back({device, "a character device"});
  for (const Case &c : cases)
    for (FileFormat format : kEveryFormat)
      expect_refused(c.path, format, {"'" + c.path + "' is " + c.kind + ", not a regular file"});
  // A link to a regular file is read.
  const std::string link = temp_path("link.npy");
  std::filesystem::create_symlink(data("c_order.npy"), link);
  EXPECT_EQ(asp::io::read_height_map(link).nx, 4);
}

// ---- finding 7: decimal commas were read as more columns of integers ------------------------

TEST(HostileFiles, DecimalCommasAreRefused) {
  // Blank-, semicolon- and tab-separated values with decimal commas, and a single column.
  const std::string blanks = write_file("blanks.txt", "0,5 0,1 0,3\n0,2 0,4 0,6\n");
  expect_refused(blanks, FileFormat::text,
                 {": line 1, column 2: '0,5' looks like a number with a decimal comma (the "
                  "line's values are also separated by blanks or semicolons): decimal commas "
                  "are not read; write numbers with a decimal point"});
  expect_refused(blanks, FileFormat::automatic, {"decimal comma"});
  expect_refused(write_file("semicolons.csv", "# heights\n-1,25;2,5\n3,75;4,0\n"),
                 FileFormat::text,
                 {"line 2, column 3: '-1,25' looks like a number with a decimal comma"});
  expect_refused(write_file("tabs.txt", "0,5\t0,1\r\n"), FileFormat::text,
                 {"line 1, column 2: '0,5'", "decimal point"});
  expect_refused(write_file("column.txt", "0,5\n0,25\n-1,5\n"), FileFormat::text,
                 {"line 1, column 2: '0,5' looks like a number with a decimal comma (two columns "
                  "of integers separated by commas alone are how a column of numbers with "
                  "decimal commas reads)"});
}

TEST(HostileFiles, CommaSeparatedValuesStillRead) {
  // Commas between values with decimal points, commas followed by blanks, and integer matrices
  // of other than two columns are what they look like.
  const auto read = [](const std::string &name, const std::string &content) {
    return asp::io::read_height_map(write_file(name, content), FileFormat::text);
  };
  const asp::io::HeightMap points = read("points.csv", "1.5,2.5\n3.5,4.5\n");
  EXPECT_EQ(points.nx, 2);
  EXPECT_EQ(points.heights, (std::vector<double>{1.5, 2.5, 3.5, 4.5}));
  const asp::io::HeightMap spaced = read("spaced.csv", "1, 2\n3, 4\n");
  EXPECT_EQ(spaced.heights, (std::vector<double>{1, 2, 3, 4}));
  const asp::io::HeightMap integers = read("integers.csv", "1,2,3\n4,5,6\n");
  EXPECT_EQ(integers.nx, 3);
  EXPECT_EQ(integers.ny, 2);
  const asp::io::HeightMap mixed = read("mixed.csv", "1,5.5\n2,6.5\n");
  EXPECT_EQ(mixed.heights, (std::vector<double>{1, 5.5, 2, 6.5}));
}

// ---- the limits of the other readers --------------------------------------------------------

TEST(HostileFiles, NpyAndTextReadersKeepToTheirLimits) {
  // The point limit, one below the fixtures' 12 points and exactly.
  ReadLimits limits;
  limits.max_points = 11;
  expect_refused(data("c_order.npy"), FileFormat::npy,
                 {"shape (3, 4): more than the limit of 11 points per map"}, limits);
  expect_refused(data("savetxt_comments.txt"), FileFormat::text,
                 {": line 5: more than the limit of 11 points per map"}, limits);
  limits.max_points = 12;
  EXPECT_EQ(asp::io::read_height_map(data("c_order.npy"), FileFormat::npy, limits).nx, 4);
  EXPECT_EQ(asp::io::read_height_map(data("savetxt_comments.txt"), FileFormat::text, limits).nx, 4);

  // What the file holds: 2^28 doubles declared in 128 bytes.
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (16384, 16384), }";
  header += std::string(117 - header.size(), ' ') + "\n";
  const std::string small = write_file(
      "small.npy", std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(header.size()) +
                       '\0' + header);
  expect_refused(small, FileFormat::npy,
                 {"truncated .npy data: shape (16384, 16384) of '<f8' needs 2147483648 bytes"});
  // A version 2.0 header of 100000 bytes (a plain array's takes about 128).
  std::string v2 = std::string("\x93NUMPY\x02\x00", 8);
  put32(v2, 100000);
  v2 += std::string(100000, ' ');
  expect_refused(write_file("long_header.npy", v2), FileFormat::npy,
                 {"a .npy header of 100000 bytes: more than the limit of 65536 bytes"});
}

}  // namespace
