// SPDX-License-Identifier: GPL-2.0-or-later
// ISO 25178-72 (.x3p) files: a zip archive with main.xml describing the axes and the matrix,
// md5checksum.hex (the MD5 of main.xml), and the point data in bindata/ (little-endian, x
// fastest) or inline as Record3/DataList/Datum lines.
#include <zip.h>

#include <algorithm>
#include <cerrno>
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

class Reader {
 public:
  explicit Reader(const std::string &path) : path_(path) {}

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

  // An entry of the archive, or FileError naming it.
  std::string entry(zip_t *archive, const std::string &name, const std::string &why) const {
    const zip_int64_t index = zip_name_locate(archive, name.c_str(), 0);
    if (index < 0) fail("the archive has no " + name + " (" + why + ")");
    zip_stat_t stat;
    if (zip_stat_index(archive, index, 0, &stat) != 0 || !(stat.valid & ZIP_STAT_SIZE))
      fail("cannot read " + name + " in the archive: " + zip_strerror(archive));
    zip_file_t *file = zip_fopen_index(archive, index, 0);
    if (!file) fail("cannot read " + name + " in the archive: " + zip_strerror(archive));
    // Read in pieces rather than allocating the size the archive declares, which a damaged
    // or hostile archive can set to anything: memory grows only with what is really there.
    std::string bytes;
    std::vector<char> piece(1 << 16);
    zip_uint64_t total = 0;
    while (total < stat.size) {
      const zip_uint64_t want = std::min<zip_uint64_t>(piece.size(), stat.size - total);
      const zip_int64_t got = zip_fread(file, piece.data(), want);
      if (got <= 0) break;
      bytes.append(piece.data(), static_cast<size_t>(got));
      total += static_cast<zip_uint64_t>(got);
    }
    const bool ok = total == stat.size;
    std::string error = ok ? "" : zip_file_strerror(file);
    zip_fclose(file);
    if (!ok) fail("cannot read " + name + " in the archive: " + error);
    return bytes;
  }

  bool has_entry(zip_t *archive, const std::string &name) const {
    return zip_name_locate(archive, name.c_str(), 0) >= 0;
  }

 private:
  std::string path_;
};

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

HeightMap read_x3p(const std::string &path) {
  Reader reader(path);
  {
    // Tell a missing file from a broken archive.
    std::FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) {
      const int err = errno;
      throw FileError("cannot open '" + path + "' for reading: " + std::strerror(err));
    }
    std::fclose(f);
  }
  int error = 0;
  Archive archive(zip_open(path.c_str(), ZIP_RDONLY, &error));
  if (!archive) {
    zip_error_t ze;
    zip_error_init_with_code(&ze, error);
    const std::string message = zip_error_strerror(&ze);
    zip_error_fini(&ze);
    reader.fail("not a readable .x3p (zip) archive: " + message);
  }
  zip_t *za = archive.get();
  const std::string xml = reader.entry(za, "main.xml", "every .x3p file has one");
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(xml.data(), xml.size());
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
  if (nx > (int64_t(1) << 40) / ny) reader.fail("main.xml: the matrix is too large");
  const size_t count = static_cast<size_t>(nx * ny);

  HeightMap map;
  map.nx = nx;
  map.ny = ny;
  map.heights.assign(count, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool integer = z_type == "I" || z_type == "L";

  if (pugi::xml_node link = child(record3, "DataLink")) {
    const std::string bin =
        trim(reader.need(link, "Record3/DataLink", {"PointDataLink"}).text().get());
    const std::string data = reader.entry(za, bin, "named by Record3/DataLink/PointDataLink");
    if (pugi::xml_node sum = child(link, "MD5ChecksumPointData")) {
      std::string expected = trim(sum.text().get());
      for (char &c : expected)
        if (c >= 'A' && c <= 'F') c = static_cast<char>(c - 'A' + 'a');
      const std::string actual = md5_hex(data);
      if (expected != actual)
        reader.fail("the MD5 checksum of " + bin + " is " + actual +
                    ", but Record3/DataLink/MD5ChecksumPointData says " + expected);
    }
    if (data.size() != count * size)
      reader.fail(bin + " has " + std::to_string(data.size()) + " bytes, but " +
                  std::to_string(nx) + " x " + std::to_string(ny) + " points of DataType " +
                  z_type + " take " + std::to_string(count * size));
    const auto *u = reinterpret_cast<const unsigned char *>(data.data());
    for (size_t i = 0; i < count; ++i) {
      uint64_t raw = 0;
      for (int k = size - 1; k >= 0; --k) raw = (raw << 8) | u[i * size + k];
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
    // The valid-points mask: one bit per point, least significant bit first, set = valid.
    std::string mask_name;
    pugi::xml_node mask_link = child(link, "ValidPointsLink");
    if (mask_link)
      mask_name = trim(mask_link.text().get());
    else if (integer && reader.has_entry(za, "bindata/valid.bin"))
      mask_name = "bindata/valid.bin";
    if (!mask_name.empty()) {
      const std::string mask = reader.entry(za, mask_name, "the valid points' mask");
      if (pugi::xml_node sum = child(link, "MD5ChecksumValidPoints")) {
        std::string expected = trim(sum.text().get());
        for (char &c : expected)
          if (c >= 'A' && c <= 'F') c = static_cast<char>(c - 'A' + 'a');
        const std::string actual = md5_hex(mask);
        if (expected != actual)
          reader.fail("the MD5 checksum of " + mask_name + " is " + actual +
                      ", but Record3/DataLink/MD5ChecksumValidPoints says " + expected);
      }
      if (mask.size() < (count + 7) / 8)
        reader.fail(mask_name + " has " + std::to_string(mask.size()) + " bytes, but " +
                    std::to_string(count) + " points need " + std::to_string((count + 7) / 8));
      for (size_t i = 0; i < count; ++i)
        if (!((static_cast<unsigned char>(mask[i / 8]) >> (i % 8)) & 1)) map.heights[i] = nan;
    }
  } else if (pugi::xml_node list = child(record3, "DataList")) {
    size_t i = 0;
    for (pugi::xml_node datum = list.first_child(); datum; datum = datum.next_sibling()) {
      if (datum.type() != pugi::node_element) continue;
      if (i == count)
        reader.fail("Record3/DataList has more than the " + std::to_string(count) +
                    " points of the matrix");
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
    if (i != count)
      reader.fail("Record3/DataList has " + std::to_string(i) + " points, the matrix " +
                  std::to_string(count));
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
