// SPDX-License-Identifier: GPL-2.0-or-later
// ISO 25178-72 (.x3p) files: a zip archive with main.xml describing the axes and the matrix,
// md5checksum.hex (the MD5 of main.xml), and the point data in bindata/ (little-endian, x
// fastest) or inline as Record3/DataList/Datum lines.
#include <zip.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <memory>
#include <pugixml.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/height_map.hpp"
#include "io/internal.hpp"

namespace asp::io {

namespace detail {

namespace {

struct ArchiveCloser {
  void operator()(zip_t *archive) const { zip_discard(archive); }
};
using Archive = std::unique_ptr<zip_t, ArchiveCloser>;

std::string trim(const std::string &s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// The child element whose name without a namespace prefix is `name`.
pugi::xml_node child(pugi::xml_node node, const char *name) {
  for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element) continue;
    const char *n = c.name();
    const char *colon = std::strrchr(n, ':');
    if (std::strcmp(colon ? colon + 1 : n, name) == 0) return c;
  }
  return {};
}

struct FileCloser {
  void operator()(zip_file_t *file) const { zip_fclose(file); }
};
using MemberFile = std::unique_ptr<zip_file_t, FileCloser>;

// Members are inflated in pieces of this size.
constexpr size_t kPieceBytes = 1 << 16;
// The most deflate makes of a compressed byte: a copy of 258 bytes costs at least 2 bits.
constexpr zip_uint64_t kDeflateRatio = 1032;
// A valid-points mask may be this much longer than its points need (trailing padding).
constexpr zip_uint64_t kMaskSlackBytes = 1 << 16;

// A member of the archive and the size its directory entry declares once inflated.
struct Member {
  std::string name;
  zip_uint64_t index = 0;
  zip_uint64_t size = 0;
};

class Reader {
 public:
  Reader(const std::string &path, int64_t archive_bytes)
      : path_(path), archive_bytes_(static_cast<zip_uint64_t>(archive_bytes)) {}

  [[noreturn]] void fail(const std::string &what) const { throw FileError(path_ + ": " + what); }

  // The element at a path of names below `node`; FileError naming the path when absent.
  pugi::xml_node need(pugi::xml_node node, const std::string &where,
                      std::initializer_list<const char *> names) const {
    std::string at = where;
    for (const char *name : names) {
      at += "/";
      at += name;
      node = child(node, name);
      if (!node) fail("main.xml has no " + at);
    }
    return node;
  }

  double number(pugi::xml_node node, const std::string &where) const {
    const std::string text = trim(node.text().get());
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
      fail("main.xml: " + where + " is '" + text + "', not a number");
    return v;
  }

  int64_t count(pugi::xml_node node, const std::string &where) const {
    const std::string text = trim(node.text().get());
    char *end = nullptr;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || v < 0)
      fail("main.xml: " + where + " is '" + text + "', not a count");
    return v;
  }

  // A member of the archive, or FileError naming it. Its declared size is refused when the
  // archive cannot hold it: compressed bytes beyond the archive's own length, or more bytes
  // than its compressed ones inflate to (stored: as many; deflated: 1032 times as many).
  // Other compression methods, whose expansion has no such bound, are refused (x3p writers
  // deflate).
  Member member(zip_t *archive, const std::string &name, const std::string &why) const {
    const zip_int64_t index = zip_name_locate(archive, name.c_str(), 0);
    if (index < 0) fail("the archive has no " + name + " (" + why + ")");
    zip_stat_t stat;
    zip_stat_init(&stat);
    const zip_uint64_t needed = ZIP_STAT_SIZE | ZIP_STAT_COMP_SIZE | ZIP_STAT_COMP_METHOD;
    if (zip_stat_index(archive, static_cast<zip_uint64_t>(index), 0, &stat) != 0 ||
        (stat.valid & needed) != needed)
      fail("cannot read " + name + " in the archive: " + zip_strerror(archive));
    const std::string declares = name + " declares " + std::to_string(stat.size) +
                                 " bytes compressed into " + std::to_string(stat.comp_size);
    if (stat.comp_size > archive_bytes_)
      fail(declares + ", but the whole archive has " + std::to_string(archive_bytes_));
    if (stat.comp_method == ZIP_CM_STORE) {
      if (stat.size > stat.comp_size) fail(declares + ", stored uncompressed");
    } else if (stat.comp_method == ZIP_CM_DEFLATE) {
      if (stat.size > 0 && (stat.size - 1) / kDeflateRatio >= stat.comp_size)
        fail(declares + ": more than deflate makes of them (" + std::to_string(kDeflateRatio) +
             " times as many)");
    } else {
      fail(name + " is compressed by method " + std::to_string(stat.comp_method) +
           ": only stored and deflated members are read");
    }
    return {name, static_cast<zip_uint64_t>(index), stat.size};
  }

  // Inflates a member to the size it declares and no further, handing it to take(bytes, n)
  // in pieces of kPieceBytes (the last one shorter); FileError when it inflates to less or
  // to more than that size, or when its CRC is wrong.
  template <class Take>
  void inflate(zip_t *archive, const Member &m, Take take) const {
    MemberFile file(zip_fopen_index(archive, m.index, 0));
    if (!file) fail("cannot read " + m.name + " in the archive: " + zip_strerror(archive));
    std::vector<char> piece(static_cast<size_t>(std::min<zip_uint64_t>(kPieceBytes, m.size)) + 1);
    zip_uint64_t total = 0;
    while (total < m.size) {
      const zip_uint64_t want = std::min<zip_uint64_t>(kPieceBytes, m.size - total);
      zip_uint64_t filled = 0;
      while (filled < want) {
        const zip_int64_t got = zip_fread(file.get(), piece.data() + filled, want - filled);
        if (got < 0)
          fail("cannot read " + m.name + " in the archive: " + zip_file_strerror(file.get()));
        if (got == 0)
          fail("cannot read " + m.name + " in the archive: it ends after " +
               std::to_string(total + filled) + " of the " + std::to_string(m.size) +
               " bytes it declares");
        filled += static_cast<zip_uint64_t>(got);
      }
      take(piece.data(), static_cast<size_t>(want));
      total += want;
    }
    // One byte more must be the end: libzip then checks the CRC and the length.
    const zip_int64_t more = zip_fread(file.get(), piece.data(), 1);
    if (more > 0)
      fail(m.name + " inflates to more than the " + std::to_string(m.size) +
           " bytes the archive declares for it");
    if (more < 0)
      fail("cannot read " + m.name + " in the archive: " + zip_file_strerror(file.get()));
  }

  std::string whole(zip_t *archive, const Member &m) const {
    std::string bytes;
    bytes.reserve(static_cast<size_t>(m.size));
    inflate(archive, m, [&](const char *p, size_t n) { bytes.append(p, n); });
    return bytes;
  }

  bool has_entry(zip_t *archive, const std::string &name) const {
    return zip_name_locate(archive, name.c_str(), 0) >= 0;
  }

 private:
  std::string path_;
  zip_uint64_t archive_bytes_;
};

// A checksum as main.xml gives it, in lower case.
std::string lower_hex(std::string text) {
  for (char &c : text)
    if (c >= 'A' && c <= 'F') c = static_cast<char>(c - 'A' + 'a');
  return text;
}

struct Axis {
  double increment = 1.0;
  double offset = 0.0;
};

Axis lateral_axis(const Reader &reader, pugi::xml_node axes, const char *name) {
  const std::string where = std::string("Record1/Axes/") + name;
  pugi::xml_node axis = reader.need(axes, "Record1/Axes", {name});
  const std::string type = trim(reader.need(axis, where, {"AxisType"}).text().get());
  if (type == "A")
    reader.fail("main.xml: " + where +
                " has AxisType A (absolute coordinates per point): only incremental axes (I) "
                "are read");
  if (type != "I") reader.fail("main.xml: " + where + " has an unknown AxisType '" + type + "'");
  Axis result;
  result.increment = reader.number(reader.need(axis, where, {"Increment"}), where + "/Increment");
  if (pugi::xml_node offset = child(axis, "Offset"))
    result.offset = reader.number(offset, where + "/Offset");
  if (!(result.increment > 0))
    reader.fail("main.xml: " + where + "/Increment must be positive");
  return result;
}

}  // namespace

HeightMap read_x3p(InputFile &input, const ReadLimits &limits) {
  const std::string &path = input.path();
  Reader reader(path, input.size());
  input.seek(0);
  int error = 0;
  // libzip reads through its own copy of the descriptor and, once the archive is open,
  // closes ours.
  Archive archive(zip_fdopen(input.descriptor(), 0, &error));
  if (!archive) {
    zip_error_t ze;
    zip_error_init_with_code(&ze, error);
    const std::string message = zip_error_strerror(&ze);
    zip_error_fini(&ze);
    reader.fail("not a readable .x3p (zip) archive: " + message);
  }
  input.release();
  zip_t *za = archive.get();
  const Member xml_member = reader.member(za, "main.xml", "every .x3p file has one");
  if (xml_member.size > static_cast<zip_uint64_t>(limits.max_xml_bytes))
    reader.fail("main.xml inflates to " + std::to_string(xml_member.size) +
                " bytes (as the archive declares): more than the limit of " +
                std::to_string(limits.max_xml_bytes) + " bytes for main.xml");
  std::string xml = reader.whole(za, xml_member);  // parsed in place: outlives the document
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer_inplace(&xml[0], xml.size());
  if (!parsed)
    reader.fail("main.xml is not valid XML (byte " + std::to_string(parsed.offset) +
                "): " + parsed.description());
  pugi::xml_node root = document.document_element();
  const char *root_name = root.name();
  const char *colon = std::strrchr(root_name, ':');
  if (std::strcmp(colon ? colon + 1 : root_name, "ISO5436_2") != 0)
    reader.fail(std::string("main.xml's root element is <") + root_name + ">, not ISO5436_2");

  const std::string feature = trim(reader.need(root, "", {"Record1", "FeatureType"}).text().get());
  if (feature != "SUR" && feature != "PRF")
    reader.fail("main.xml: Record1/FeatureType '" + feature +
                "' is not read (only SUR, an areal surface, and PRF, a profile)");
  pugi::xml_node axes = reader.need(root, "", {"Record1", "Axes"});
  const Axis ax = lateral_axis(reader, axes, "CX");
  pugi::xml_node cy = child(axes, "CY");
  Axis ay;
  if (cy || feature == "SUR") ay = lateral_axis(reader, axes, "CY");
  pugi::xml_node cz = reader.need(axes, "Record1/Axes", {"CZ"});
  std::string z_type = "D";
  if (pugi::xml_node t = child(cz, "DataType")) z_type = trim(t.text().get());
  int size;
  if (z_type == "D")
    size = 8;
  else if (z_type == "F")
    size = 4;
  else if (z_type == "L")
    size = 4;
  else if (z_type == "I")
    size = 2;
  else
    reader.fail("main.xml: Record1/Axes/CZ/DataType '" + z_type +
                "' is not one of D, F, L and I");
  double z_increment = 1.0, z_offset = 0.0;
  if (pugi::xml_node n = child(cz, "Increment"))
    z_increment = reader.number(n, "Record1/Axes/CZ/Increment");
  if (pugi::xml_node n = child(cz, "Offset")) z_offset = reader.number(n, "Record1/Axes/CZ/Offset");

  pugi::xml_node record3 = reader.need(root, "", {"Record3"});
  pugi::xml_node dims = reader.need(record3, "Record3", {"MatrixDimension"});
  const int64_t nx = reader.count(reader.need(dims, "Record3/MatrixDimension", {"SizeX"}),
                                  "Record3/MatrixDimension/SizeX");
  const int64_t ny = reader.count(reader.need(dims, "Record3/MatrixDimension", {"SizeY"}),
                                  "Record3/MatrixDimension/SizeY");
  int64_t nz = 1;
  if (pugi::xml_node n = child(dims, "SizeZ")) nz = reader.count(n, "Record3/MatrixDimension/SizeZ");
  if (nz != 1)
    reader.fail("main.xml: Record3/MatrixDimension/SizeZ is " + std::to_string(nz) +
                ": only one layer (SizeZ = 1) is read");
  if (nx <= 0 || ny <= 0) reader.fail("main.xml: an empty matrix (SizeX or SizeY is 0)");
  if (feature == "PRF" && ny != 1)
    reader.fail("main.xml: a profile (PRF) with SizeY = " + std::to_string(ny));
  if (nx > std::min(limits.max_points, std::numeric_limits<int64_t>::max() / 8) / ny)
    reader.fail("main.xml: a matrix of " + std::to_string(nx) + " x " + std::to_string(ny) +
                " points: more than " + points_limit_text(limits));
  const size_t count = static_cast<size_t>(nx * ny);

  HeightMap map;
  map.nx = nx;
  map.ny = ny;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool integer = z_type == "I" || z_type == "L";

  if (pugi::xml_node link = child(record3, "DataLink")) {
    const std::string bin =
        trim(reader.need(link, "Record3/DataLink", {"PointDataLink"}).text().get());
    const Member data = reader.member(za, bin, "named by Record3/DataLink/PointDataLink");
    const size_t bytes = count * static_cast<size_t>(size);
    if (data.size != bytes)
      reader.fail(bin + " inflates to " + std::to_string(data.size) +
                  " bytes (as the archive declares), but " + std::to_string(nx) + " x " +
                  std::to_string(ny) + " points of DataType " + z_type + " take " +
                  std::to_string(bytes));
    map.heights.resize(count);
    Md5 md5;
    size_t i = 0;
    reader.inflate(za, data, [&](const char *piece, size_t n) {
      md5.update(piece, n);
      const auto *u = reinterpret_cast<const unsigned char *>(piece);
      for (size_t at = 0; at < n; at += static_cast<size_t>(size), ++i) {
        uint64_t raw = 0;
        for (int k = size - 1; k >= 0; --k) raw = (raw << 8) | u[at + static_cast<size_t>(k)];
        double v;
        if (z_type == "D") {
          std::memcpy(&v, &raw, 8);
        } else if (z_type == "F") {
          const auto raw32 = static_cast<uint32_t>(raw);
          float f;
          std::memcpy(&f, &raw32, 4);
          v = f;
        } else if (z_type == "L") {
          v = static_cast<int32_t>(static_cast<uint32_t>(raw));
        } else {
          v = static_cast<int16_t>(static_cast<uint16_t>(raw));
        }
        map.heights[i] = v;
      }
    });
    if (pugi::xml_node sum = child(link, "MD5ChecksumPointData")) {
      const std::string expected = lower_hex(trim(sum.text().get()));
      const std::string actual = md5.hex();
      if (expected != actual)
        reader.fail("the MD5 checksum of " + bin + " is " + actual +
                    ", but Record3/DataLink/MD5ChecksumPointData says " + expected);
    }
    // The valid-points mask: one bit per point, least significant bit first, set = valid.
    std::string mask_name;
    pugi::xml_node mask_link = child(link, "ValidPointsLink");
    if (mask_link)
      mask_name = trim(mask_link.text().get());
    else if (integer && reader.has_entry(za, "bindata/valid.bin"))
      mask_name = "bindata/valid.bin";
    if (!mask_name.empty()) {
      const Member mask_member = reader.member(za, mask_name, "the valid points' mask");
      const size_t need = (count + 7) / 8;
      if (mask_member.size < need || mask_member.size > need + kMaskSlackBytes)
        reader.fail(mask_name + " has " + std::to_string(mask_member.size) + " bytes, but " +
                    std::to_string(count) + " points need " + std::to_string(need));
      const std::string mask = reader.whole(za, mask_member);
      if (pugi::xml_node sum = child(link, "MD5ChecksumValidPoints")) {
        const std::string expected = lower_hex(trim(sum.text().get()));
        const std::string actual = md5_hex(mask);
        if (expected != actual)
          reader.fail("the MD5 checksum of " + mask_name + " is " + actual +
                      ", but Record3/DataLink/MD5ChecksumValidPoints says " + expected);
      }
      for (size_t p = 0; p < count; ++p)
        if (!((static_cast<unsigned char>(mask[p / 8]) >> (p % 8)) & 1)) map.heights[p] = nan;
    }
  } else if (pugi::xml_node list = child(record3, "DataList")) {
    // The points are counted before any is stored.
    size_t points = 0;
    for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling())
      if (datum.type() == pugi::node_element) ++points;
    if (points > count)
      reader.fail("Record3/DataList has more than the " + std::to_string(count) +
                  " points of the matrix");
    if (points != count)
      reader.fail("Record3/DataList has " + std::to_string(points) + " points, the matrix " +
                  std::to_string(count));
    map.heights.resize(count);
    size_t i = 0;
    for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling()) {
      if (datum.type() != pugi::node_element) continue;
      const std::string text = trim(datum.text().get());
      if (text.empty()) {
        map.heights[i++] = nan;  // an empty Datum is a missing point
        continue;
      }
      char *end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (*end != '\0')
        reader.fail("Record3/DataList, Datum " + std::to_string(i + 1) + ": '" + text +
                    "' is not a number");
      map.heights[i++] = v;
    }
  } else {
    reader.fail("main.xml's Record3 has neither a DataLink nor a DataList");
  }
  // Scaled values: offset + increment * stored value (NaN stays NaN).
  if (z_increment != 1.0 || z_offset != 0.0)
    for (double &h : map.heights) h = z_offset + z_increment * h;

  map.lx = static_cast<double>(nx) * ax.increment;
  map.ly = ny > 1 ? static_cast<double>(ny) * ay.increment : nan;
  map.length_unit = "m";
  map.height_unit = "m";
  map.format = FileFormat::x3p;
  map.layout = ny == 1 ? "x3p profile (PRF), x fastest" : "x3p point data, x fastest";
  return map;
}

}  // namespace detail

void write_x3p(const std::string &path, const HeightMap &map) {
  const auto fail = [&](const std::string &what) {
    throw FileError("cannot write '" + path + "': " + what);
  };
  if (map.nx <= 0 || map.ny <= 0 || map.heights.size() != static_cast<size_t>(map.nx * map.ny))
    fail("inconsistent height map: " + std::to_string(map.heights.size()) + " heights for nx = " +
         std::to_string(map.nx) + ", ny = " + std::to_string(map.ny));
  double length_scale = 0, height_scale = 0;
  try {
    length_scale = unit_in_metres(map.length_unit);
    height_scale = unit_in_metres(map.height_unit);
  } catch (const std::invalid_argument &e) {
    fail(std::string("an .x3p file needs lengths and heights in known units: ") + e.what());
  }
  if (!(map.lx > 0) || !std::isfinite(map.lx)) fail("lx must be positive");
  const double dx = map.lx * length_scale / static_cast<double>(map.nx);
  double dy = dx;
  if (map.ny > 1) {
    if (!(map.ly > 0) || !std::isfinite(map.ly)) fail("ly must be positive for an areal map");
    dy = map.ly * length_scale / static_cast<double>(map.ny);
  }
  const size_t count = map.heights.size();
  std::string data;
  data.reserve(8 * count);
  for (double h : map.heights) {
    const double v = h * height_scale;
    uint64_t raw;
    std::memcpy(&raw, &v, 8);
    for (int k = 0; k < 8; ++k) data += static_cast<char>((raw >> (8 * k)) & 0xff);
  }
  const std::string feature = map.ny == 1 ? "PRF" : "SUR";
  const auto axis = [](const char *name, double increment) {
    return std::string("      <") + name + ">\n        <AxisType>I</AxisType>\n" +
           "        <DataType>D</DataType>\n        <Increment>" +
           detail::format_double(increment) + "</Increment>\n        <Offset>0</Offset>\n      </" +
           name + ">\n";
  };
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\" "
      "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
      "xsi:schemaLocation=\"http://www.opengps.eu/2008/ISO5436_2 "
      "http://www.opengps.eu/2008/ISO5436_2/ISO5436_2.xsd\">\n"
      "  <Record1>\n"
      "    <Revision>ISO5436 - 2000</Revision>\n"
      "    <FeatureType>" + feature + "</FeatureType>\n"
      "    <Axes>\n" + axis("CX", dx) + axis("CY", dy) +
      "      <CZ>\n        <AxisType>A</AxisType>\n        <DataType>D</DataType>\n"
      "      </CZ>\n"
      "    </Axes>\n"
      "  </Record1>\n"
      "  <Record3>\n"
      "    <MatrixDimension>\n"
      "      <SizeX>" + std::to_string(map.nx) + "</SizeX>\n"
      "      <SizeY>" + std::to_string(map.ny) + "</SizeY>\n"
      "      <SizeZ>1</SizeZ>\n"
      "    </MatrixDimension>\n"
      "    <DataLink>\n"
      "      <PointDataLink>bindata/data.bin</PointDataLink>\n"
      "      <MD5ChecksumPointData>" + detail::md5_hex(data) + "</MD5ChecksumPointData>\n"
      "    </DataLink>\n"
      "  </Record3>\n"
      "  <Record4>\n"
      "    <ChecksumFile>md5checksum.hex</ChecksumFile>\n"
      "  </Record4>\n"
      "</p:ISO5436_2>\n";
  const std::string checksum = detail::md5_hex(xml) + " *main.xml\n";

  int error = 0;
  zip_t *archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (!archive) {
    zip_error_t ze;
    zip_error_init_with_code(&ze, error);
    const std::string message = zip_error_strerror(&ze);
    zip_error_fini(&ze);
    fail(message);
  }
  // The buffers outlive zip_close, which reads them.
  const auto add = [&](const char *name, const std::string &bytes) {
    zip_source_t *source = zip_source_buffer(archive, bytes.data(), bytes.size(), 0);
    if (!source || zip_file_add(archive, name, source, ZIP_FL_OVERWRITE | ZIP_FL_ENC_UTF_8) < 0) {
      const std::string message = zip_strerror(archive);
      if (source) zip_source_free(source);
      zip_discard(archive);
      fail(std::string("adding ") + name + ": " + message);
    }
  };
  add("main.xml", xml);
  add("md5checksum.hex", checksum);
  if (zip_dir_add(archive, "bindata", ZIP_FL_ENC_UTF_8) < 0) {
    const std::string message = zip_strerror(archive);
    zip_discard(archive);
    fail("adding bindata/: " + message);
  }
  add("bindata/data.bin", data);
  if (zip_close(archive) != 0) {
    const std::string message = zip_strerror(archive);
    zip_discard(archive);
    fail(message);
  }
}

}  // namespace asp::io
