// SPDX-License-Identifier: GPL-2.0-or-later
// asperity_io: reading height maps from text matrices, .npy and .x3p files written by other
// programs (fixtures in data/, made by data/make_fixtures.py with NumPy and zipfile), writing
// them back, refusing malformed files with a useful message, and filling missing points.
#include <gtest/gtest.h>

#include "temp_path.hpp"
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

#include "io/height_map.hpp"

namespace {

using asp::io::FileError;
using asp::io::FileFormat;
using asp::io::HeightMap;

const std::string kData = ASPERITY_IO_TEST_DATA;
constexpr int64_t kNx = 4, kNy = 3;

std::string data(const std::string &name) { return kData + "/" + name; }

// The fixtures' common matrix: row y, column x of the file holds 10 y + x + 0.5.
double expected(int64_t x, int64_t y) { return 10.0 * y + x + 0.5; }
double expected_int(int64_t x, int64_t y) { return 10.0 * y + x - 5; }


// The message of the FileError that reading throws ("" and a failure when none is thrown).
std::string read_error(const std::string &path, FileFormat format = FileFormat::automatic) {
  try {
    asp::io::read_height_map(path, format);
  } catch (const FileError &e) {
    return e.what();
  }
  ADD_FAILURE() << "no FileError reading " << path;
  return "";
}

bool contains(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

// Checks heights[x + nx * y] against the fixtures' matrix.
void expect_layout(const HeightMap &map, double (*value)(int64_t, int64_t) = expected) {
  ASSERT_EQ(map.nx, kNx);
  ASSERT_EQ(map.ny, kNy);
  ASSERT_EQ(map.heights.size(), static_cast<size_t>(kNx * kNy));
  for (int64_t y = 0; y < kNy; ++y)
    for (int64_t x = 0; x < kNx; ++x)
      EXPECT_EQ(map.heights[x + kNx * y], value(x, y)) << "x = " << x << ", y = " << y;
}

std::string file_text(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// ---- .npy ----------------------------------------------------------------------------------

TEST(NpyRead, COrderMatrixKeepsRowsAsY) {
  // np.save of a (3, 4) C-order array: row y, column x is heights[x + nx * y]; no units.
  const HeightMap map = asp::io::read_height_map(data("c_order.npy"));
  expect_layout(map);
  EXPECT_EQ(map.format, FileFormat::npy);
  EXPECT_TRUE(std::isnan(map.lx));
  EXPECT_TRUE(std::isnan(map.ly));
  EXPECT_EQ(map.length_unit, "");
  EXPECT_EQ(map.height_unit, "");
  EXPECT_EQ(map.missing, 0);
}

TEST(NpyRead, FortranOrderReadsTheSameIndices) {
  // A Fortran-order array stores columns contiguously but a[y, x] is still row y, column x.
  expect_layout(asp::io::read_height_map(data("fortran_order.npy")));
  expect_layout(asp::io::read_height_map(data("int64_fortran.npy")), expected_int);
}

TEST(NpyRead, Float32BigEndianAndInt16Arrays) {
  // Other dtypes convert exactly to double (the fixture's values are exact in each).
  expect_layout(asp::io::read_height_map(data("float32.npy")));
  expect_layout(asp::io::read_height_map(data("big_endian.npy")));
  expect_layout(asp::io::read_height_map(data("int16.npy")), expected_int);
}

TEST(NpyRead, Version2And3Headers) {
  // Versions 2.0 and 3.0 differ from 1.0 by a 4-byte header length.
  expect_layout(asp::io::read_height_map(data("version2.npy")));
  expect_layout(asp::io::read_height_map(data("version3.npy"), FileFormat::npy));
}

TEST(NpyRead, OneDimensionalArrayIsAProfile) {
  // Shape (n,) is one profile: nx = n, ny = 1.
  const HeightMap map = asp::io::read_height_map(data("profile.npy"));
  EXPECT_EQ(map.nx, 5);
  EXPECT_EQ(map.ny, 1);
  EXPECT_EQ(map.heights, (std::vector<double>{1.5, -2.25, 3.0, 4.125, 5.0}));
}

TEST(NpyRead, MalformedFilesSayWhatIsWrong) {
  // Each refusal names the file and the problem.
  const std::string truncated = read_error(data("truncated.npy"));
  EXPECT_TRUE(contains(truncated, "truncated.npy")) << truncated;
  EXPECT_TRUE(contains(truncated, "truncated")) << truncated;
  EXPECT_TRUE(contains(truncated, "96 bytes")) << truncated;  // 12 float64 needed
  const std::string magic = read_error(data("bad_magic.npy"), FileFormat::npy);
  EXPECT_TRUE(contains(magic, "not a .npy file")) << magic;
  EXPECT_TRUE(contains(read_error(data("object.npy")), "object arrays"));
  EXPECT_TRUE(contains(read_error(data("complex.npy")), "unsupported dtype '<c16'"));
  const std::string three_d = read_error(data("three_d.npy"));
  EXPECT_TRUE(contains(three_d, "3-D array of shape (2, 2, 2)")) << three_d;
}

TEST(NpyWrite, RoundTripIsBitIdentical) {
  // write_npy then read_height_map gives back every double bit for bit, NaN included.
  std::vector<double> values(kNx * kNy);
  for (size_t i = 0; i < values.size(); ++i) values[i] = std::sin(1.0 + i) / 3.0 * 1e-7;
  values[5] = std::numeric_limits<double>::quiet_NaN();
  values[6] = std::numeric_limits<double>::denorm_min();
  const std::string path = temp_path("map.npy");
  asp::io::write_npy(path, values.data(), kNx, kNy);
  const HeightMap map = asp::io::read_height_map(path);
  ASSERT_EQ(map.nx, kNx);
  ASSERT_EQ(map.ny, kNy);
  EXPECT_EQ(std::memcmp(map.heights.data(), values.data(), 8 * values.size()), 0);
  EXPECT_EQ(map.missing, 1);
}

TEST(NpyWrite, HeaderIsWhatNumpyLoadExpects) {
  // NumPy's format: version 1.0, '<f8', C order, shape (ny, nx) or (nx,), data 64-aligned.
  const double values[3] = {1, 2, 3};
  const std::string path = temp_path("profile.npy");
  asp::io::write_npy(path, values, 3, 1);
  const std::string bytes = file_text(path);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  EXPECT_TRUE(contains(bytes, "{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }"));
  EXPECT_EQ((bytes.size() - 24) % 64, 0u);
  EXPECT_EQ(bytes[bytes.size() - 25], '\n');
  const HeightMap map = asp::io::read_height_map(path);
  EXPECT_EQ(map.nx, 3);
  EXPECT_EQ(map.ny, 1);
  asp::io::write_npy(path, values, 1, 3);  // a column: shape (3, 1)
  EXPECT_TRUE(contains(file_text(path), "'shape': (3, 1)"));
}

// ---- text ----------------------------------------------------------------------------------

TEST(TextRead, NumpySavetxtWithCommentsAndDelimiters) {
  // savetxt's '#' header and footer are comments; spaces, commas, semicolons and tabs all
  // separate values.
  const HeightMap spaces = asp::io::read_height_map(data("savetxt_comments.txt"));
  expect_layout(spaces);
  EXPECT_EQ(spaces.format, FileFormat::text);
  EXPECT_TRUE(std::isnan(spaces.lx));
  expect_layout(asp::io::read_height_map(data("savetxt_commas.csv")));
  expect_layout(asp::io::read_height_map(data("savetxt_semicolons.csv")));
}

TEST(TextRead, NanIsAMissingPoint) {
  // "nan" (savetxt, tab-separated) and "NaN" (MATLAB) are missing points, counted.
  const HeightMap map = asp::io::read_height_map(data("savetxt_nan.txt"));
  EXPECT_TRUE(std::isnan(map.heights[2 + kNx * 1]));
  EXPECT_EQ(map.missing, 1);
  EXPECT_EQ(asp::io::describe_missing(map), "1 missing point (NaN), at x = 2, y = 1");
  const HeightMap matlab = asp::io::read_height_map(data("matlab.txt"));
  EXPECT_EQ(matlab.nx, kNx);
  EXPECT_EQ(matlab.ny, kNy);
  EXPECT_TRUE(std::isnan(matlab.heights[3]));
  EXPECT_EQ(matlab.heights[1 + kNx * 2], 21.5);
}

TEST(TextRead, GwyddionHeaderGivesSizesAndUnits) {
  // Gwyddion's "# Width: 10.000 µm" etc. give lx, ly and the units ("µm" spelled "um").
  const HeightMap map = asp::io::read_height_map(data("gwyddion.txt"));
  ASSERT_EQ(map.nx, kNx);
  ASSERT_EQ(map.ny, kNy);
  EXPECT_DOUBLE_EQ(map.lx, 10.0);
  EXPECT_DOUBLE_EQ(map.ly, 7.5);
  EXPECT_EQ(map.length_unit, "um");
  EXPECT_EQ(map.height_unit, "m");
  for (int64_t y = 0; y < kNy; ++y)
    for (int64_t x = 0; x < kNx; ++x)
      EXPECT_DOUBLE_EQ(map.heights[x + kNx * y], expected(x, y) * 1e-9);
}

TEST(TextRead, OneLineIsAProfile) {
  // One data line: nx values, ny = 1, ly NaN.
  const HeightMap map = asp::io::read_height_map(data("savetxt_profile.txt"));
  EXPECT_EQ(map.nx, kNx);
  EXPECT_EQ(map.ny, 1);
  EXPECT_TRUE(std::isnan(map.ly));
}

TEST(TextRead, MalformedFilesNameTheLine) {
  // Ragged rows, words, infinities and empty files are refused with the place named.
  const std::string ragged = read_error(data("ragged.txt"));
  EXPECT_TRUE(contains(ragged, "ragged.txt: line 3 has 2 values")) << ragged;
  const std::string word = read_error(data("word.txt"));
  EXPECT_TRUE(contains(word, "word.txt: line 3, entry 2")) << word;
  EXPECT_TRUE(contains(word, "'five' is not a number")) << word;
  const std::string inf = read_error(data("infinite.txt"));
  EXPECT_TRUE(contains(inf, "line 2, entry 2")) << inf;
  EXPECT_TRUE(contains(inf, "not finite")) << inf;
  EXPECT_TRUE(contains(read_error(data("empty.txt")), "empty.txt: no values"));
  EXPECT_TRUE(contains(read_error(data("only_comments.txt")), "no values"));
}

TEST(TextRead, MissingFileNamesThePath) {
  // A file that is not there: the message names it, for every format.
  const std::string path = data("no_such_file.txt");
  for (FileFormat format :
       {FileFormat::automatic, FileFormat::text, FileFormat::npy, FileFormat::x3p}) {
    const std::string message = read_error(path, format);
    EXPECT_TRUE(contains(message, "'" + path + "'")) << message;
  }
}

TEST(TextWrite, RoundTripIsBitIdenticalWithComments) {
  // %.17g text reads back to the same doubles; comments are '#' lines the reader skips.
  std::vector<double> values(kNx * kNy);
  for (size_t i = 0; i < values.size(); ++i) values[i] = std::exp(-double(i)) / 7.0 - 0.01;
  values[0] = std::numeric_limits<double>::quiet_NaN();
  const std::string path = temp_path("map.txt");
  asp::io::write_text_matrix(path, values.data(), kNx, kNy, {"heights in m", "two\nlines"});
  const std::string text = file_text(path);
  EXPECT_EQ(text.substr(0, 30), "# heights in m\n# two\n# lines\nn");
  const HeightMap map = asp::io::read_height_map(path);
  ASSERT_EQ(map.heights.size(), values.size());
  EXPECT_EQ(map.nx, kNx);
  EXPECT_EQ(map.ny, kNy);
  EXPECT_TRUE(std::isnan(map.heights[0]));
  for (size_t i = 1; i < values.size(); ++i) EXPECT_EQ(map.heights[i], values[i]) << i;
}

TEST(TextWrite, OneScanLinePerRow) {
  // Row y of the file holds heights[x + nx * y], separated by single spaces.
  const double values[6] = {1, 2, 3, 4, 5, 6};
  const std::string path = temp_path("rows.txt");
  asp::io::write_text_matrix(path, values, 3, 2);
  EXPECT_EQ(file_text(path), "1 2 3\n4 5 6\n");
}

// ---- .x3p ----------------------------------------------------------------------------------

TEST(X3pRead, FloatSurfaceIsXFastestInMetres) {
  // The zipfile-built fixture: float64 x fastest, increments 1 µm and 2 µm.
  const HeightMap map = asp::io::read_height_map(data("surface.x3p"));
  ASSERT_EQ(map.nx, kNx);
  ASSERT_EQ(map.ny, kNy);
  for (int64_t y = 0; y < kNy; ++y)
    for (int64_t x = 0; x < kNx; ++x) EXPECT_EQ(map.heights[x + kNx * y], expected(x, y) * 1e-9);
  EXPECT_EQ(map.format, FileFormat::x3p);
  EXPECT_DOUBLE_EQ(map.lx, 4e-6);
  EXPECT_DOUBLE_EQ(map.ly, 6e-6);
  EXPECT_EQ(map.length_unit, "m");
  EXPECT_EQ(map.height_unit, "m");
}

TEST(X3pRead, Float32NanIsMissing) {
  // In float data NaN marks a missing point.
  const HeightMap map = asp::io::read_height_map(data("surface_float32_nan.x3p"));
  EXPECT_EQ(map.missing, 1);
  EXPECT_TRUE(std::isnan(map.heights[1 + kNx * 2]));
  EXPECT_EQ(map.heights[3], static_cast<double>(static_cast<float>(3.5e-9)));
}

TEST(X3pRead, IntegerDataScaledWithValidMask) {
  // int16 data: height = Offset + Increment * value; points 1 and 10 are cleared in valid.bin.
  const HeightMap map = asp::io::read_height_map(data("integer_mask.x3p"));
  ASSERT_EQ(map.heights.size(), static_cast<size_t>(kNx * kNy));
  EXPECT_EQ(map.missing, 2);
  for (int64_t y = 0; y < kNy; ++y)
    for (int64_t x = 0; x < kNx; ++x) {
      const int64_t i = x + kNx * y;
      if (i == 1 || i == 10)
        EXPECT_TRUE(std::isnan(map.heights[i])) << i;
      else
        EXPECT_DOUBLE_EQ(map.heights[i], 2e-9 + 1e-9 * expected_int(x, y)) << i;
    }
  EXPECT_EQ(asp::io::describe_missing(map), "2 missing points (NaN), the first at x = 1, y = 0");
}

TEST(X3pRead, ProfileAndInlineDataList) {
  // A PRF file is a profile (ny = 1); Record3/DataList/Datum holds the points inline.
  const HeightMap profile = asp::io::read_height_map(data("profile.x3p"));
  EXPECT_EQ(profile.nx, 5);
  EXPECT_EQ(profile.ny, 1);
  EXPECT_EQ(profile.heights[4], 16e-6);
  EXPECT_TRUE(std::isnan(profile.ly));
  const HeightMap list = asp::io::read_height_map(data("datalist.x3p"));
  ASSERT_EQ(list.heights.size(), static_cast<size_t>(kNx * kNy));
  for (int64_t y = 0; y < kNy; ++y)
    for (int64_t x = 0; x < kNx; ++x) EXPECT_EQ(list.heights[x + kNx * y], expected(x, y) * 1e-9);
}

TEST(X3pRead, MalformedArchivesAreRefused) {
  // Wrong MD5, no main.xml, a missing bin, absolute axes: each named in the message.
  const std::string md5 = read_error(data("wrong_md5.x3p"));
  EXPECT_TRUE(contains(md5, "MD5 checksum of bindata/data.bin")) << md5;
  const std::string no_xml = read_error(data("no_main_xml.x3p"));
  EXPECT_TRUE(contains(no_xml, "no main.xml")) << no_xml;
  const std::string no_bin = read_error(data("missing_bin.x3p"));
  EXPECT_TRUE(contains(no_bin, "no bindata/data.bin")) << no_bin;
  const std::string absolute = read_error(data("absolute_axis.x3p"));
  EXPECT_TRUE(contains(absolute, "CX has AxisType A")) << absolute;
  const std::string not_zip = read_error(data("c_order.npy"), FileFormat::x3p);
  EXPECT_TRUE(contains(not_zip, "not a readable .x3p")) << not_zip;
}

TEST(X3pWrite, RoundTripConvertsToMetres) {
  // write_x3p stores metres as float64; reading back gives the same heights bit for bit when
  // the units are already metres, and lx, ly from the increments.
  HeightMap map;
  map.nx = kNx;
  map.ny = kNy;
  for (int64_t i = 0; i < kNx * kNy; ++i) map.heights.push_back(std::cos(0.3 * i) * 1e-8);
  map.heights[7] = std::numeric_limits<double>::quiet_NaN();
  map.lx = 4e-6;
  map.ly = 3e-6;
  map.length_unit = "m";
  map.height_unit = "m";
  const std::string path = temp_path("map.x3p");
  asp::io::write_x3p(path, map);
  const HeightMap back = asp::io::read_height_map(path);
  ASSERT_EQ(back.nx, kNx);
  ASSERT_EQ(back.ny, kNy);
  EXPECT_EQ(std::memcmp(back.heights.data(), map.heights.data(), 8 * map.heights.size()), 0);
  EXPECT_DOUBLE_EQ(back.lx, 4e-6);
  EXPECT_DOUBLE_EQ(back.ly, 3e-6);
  EXPECT_EQ(back.missing, 1);

  // In µm and nm: converted to metres on writing.
  map.length_unit = "um";
  map.height_unit = "nm";
  map.lx = 4.0;
  map.ly = 3.0;
  map.heights[7] = 2.0;
  asp::io::write_x3p(path, map);
  const HeightMap scaled = asp::io::read_height_map(path, FileFormat::x3p);
  EXPECT_DOUBLE_EQ(scaled.lx, 4e-6);
  EXPECT_DOUBLE_EQ(scaled.heights[7], 2e-9);
}

TEST(X3pWrite, ProfileRoundTripAndUnitlessMapRefused) {
  // A one-line map is written as a PRF profile; a map without units cannot be an x3p.
  HeightMap map;
  map.nx = 5;
  map.ny = 1;
  map.heights = {1, 2, 3, 4, 5};
  map.lx = 5;
  map.ly = std::numeric_limits<double>::quiet_NaN();
  map.length_unit = "mm";
  map.height_unit = "um";
  const std::string path = temp_path("profile.x3p");
  asp::io::write_x3p(path, map);
  const HeightMap back = asp::io::read_height_map(path);
  EXPECT_EQ(back.ny, 1);
  EXPECT_DOUBLE_EQ(back.lx, 5e-3);
  EXPECT_DOUBLE_EQ(back.heights[2], 3e-6);
  map.height_unit = "";
  EXPECT_THROW(asp::io::write_x3p(path, map), FileError);
}

// ---- layout across formats -----------------------------------------------------------------

TEST(Layout, NonSquareMatrixSameInEveryFormat) {
  // heights[x + nx * y] is row y, column x of the file: written by the writers and read back
  // in each format, and read from NumPy's and zipfile's files.
  std::vector<double> values(kNx * kNy);
  for (int64_t y = 0; y < kNy; ++y)
    for (int64_t x = 0; x < kNx; ++x) values[x + kNx * y] = expected(x, y);
  const std::string npy = temp_path("layout.npy"), txt = temp_path("layout.txt"),
                    x3p = temp_path("layout.x3p");
  asp::io::write_npy(npy, values.data(), kNx, kNy);
  asp::io::write_text_matrix(txt, values.data(), kNx, kNy);
  HeightMap map;
  map.nx = kNx;
  map.ny = kNy;
  map.heights = values;
  map.lx = 4;
  map.ly = 3;
  map.length_unit = map.height_unit = "m";
  asp::io::write_x3p(x3p, map);
  for (const std::string &path : {npy, txt, x3p, data("c_order.npy"), data("fortran_order.npy"),
                                  data("savetxt_comments.txt")})
    expect_layout(asp::io::read_height_map(path));
  EXPECT_EQ(file_text(txt).substr(0, 16), "0.5 1.5 2.5 3.5\n");
}

// ---- missing points ------------------------------------------------------------------------

TEST(FillMissing, HoleInAPlaneIsFilledWithThePlane) {
  // A plane is harmonic, so the discrete Laplace solution in an interior hole is the plane.
  HeightMap map;
  map.nx = 40;
  map.ny = 30;
  auto plane = [](int64_t x, int64_t y) { return 0.7 + 0.013 * x - 0.021 * y; };
  for (int64_t y = 0; y < map.ny; ++y)
    for (int64_t x = 0; x < map.nx; ++x) map.heights.push_back(plane(x, y));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int64_t holes = 0;
  for (int64_t y = 5; y < 25; ++y)  // a large hole, 20 x 25 points
    for (int64_t x = 8; x < 33; ++x, ++holes) map.heights[x + map.nx * y] = nan;
  EXPECT_EQ(asp::io::fill_missing(map), holes);
  for (int64_t y = 0; y < map.ny; ++y)
    for (int64_t x = 0; x < map.nx; ++x)
      EXPECT_NEAR(map.heights[x + map.nx * y], plane(x, y), 1e-10) << x << ", " << y;
  EXPECT_EQ(map.missing, 0);
  EXPECT_EQ(asp::io::describe_missing(map), "no missing points");
  EXPECT_EQ(asp::io::fill_missing(map), 0);
}

TEST(FillMissing, EdgePointsAverageTheirNeighboursInsideTheGrid) {
  // Edges are not wrapped: a missing corner or edge point is the mean of its 2 or 3 neighbours.
  HeightMap map;
  map.nx = 5;
  map.ny = 4;
  for (int64_t i = 0; i < 20; ++i) map.heights.push_back(double(i * i % 7));
  const std::vector<double> known = map.heights;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  map.heights[0] = map.heights[4 + 5 * 2] = nan;
  EXPECT_EQ(asp::io::fill_missing(map), 2);
  EXPECT_NEAR(map.heights[0], (known[1] + known[5]) / 2, 1e-14);
  EXPECT_NEAR(map.heights[14], (known[9] + known[19] + known[13]) / 3, 1e-14);
}

TEST(FillMissing, ProfileHoleIsLinearAndAllMissingRefused) {
  // In one dimension a harmonic function is a straight line; a map with no heights at all
  // cannot be filled.
  HeightMap map;
  map.nx = 6;
  map.ny = 1;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  map.heights = {1, nan, nan, nan, 5, nan};
  EXPECT_EQ(asp::io::describe_missing(map), "4 missing points (NaN), the first at x = 1, y = 0");
  EXPECT_EQ(asp::io::fill_missing(map), 4);
  const std::vector<double> line = {1, 2, 3, 4, 5, 5};
  for (size_t i = 0; i < line.size(); ++i) EXPECT_NEAR(map.heights[i], line[i], 1e-12) << i;
  map.heights.assign(6, nan);
  EXPECT_THROW(asp::io::fill_missing(map), FileError);
}

// ---- units and formats ---------------------------------------------------------------------

TEST(Units, MetresPerUnitAndRefusal) {
  // Every accepted spelling, and an unknown unit refused with the accepted ones listed.
  EXPECT_EQ(asp::io::unit_in_metres("m"), 1.0);
  EXPECT_EQ(asp::io::unit_in_metres("mm"), 1e-3);
  EXPECT_EQ(asp::io::unit_in_metres("um"), 1e-6);
  EXPECT_EQ(asp::io::unit_in_metres("\xC2\xB5m"), 1e-6);  // MICRO SIGN
  EXPECT_EQ(asp::io::unit_in_metres("\xCE\xBCm"), 1e-6);  // GREEK SMALL LETTER MU
  EXPECT_EQ(asp::io::unit_in_metres("micron"), 1e-6);
  EXPECT_EQ(asp::io::unit_in_metres("nm"), 1e-9);
  EXPECT_EQ(asp::io::unit_in_metres("pm"), 1e-12);
  EXPECT_EQ(asp::io::unit_in_metres("A"), 1e-10);
  EXPECT_EQ(asp::io::unit_in_metres("\xC3\x85"), 1e-10);  // Å
  try {
    asp::io::unit_in_metres("ft");
    ADD_FAILURE() << "ft accepted";
  } catch (const std::invalid_argument &e) {
    EXPECT_TRUE(contains(e.what(), "'ft'")) << e.what();
    EXPECT_TRUE(contains(e.what(), "nm")) << e.what();
  }
}

TEST(Formats, NamesAndExtensions) {
  // Extensions suggest a format; names round-trip; an unknown name is invalid_argument.
  EXPECT_EQ(asp::io::format_from_extension("a/b.TXT"), FileFormat::text);
  EXPECT_EQ(asp::io::format_from_extension("b.csv"), FileFormat::text);
  EXPECT_EQ(asp::io::format_from_extension("b.asc"), FileFormat::text);
  EXPECT_EQ(asp::io::format_from_extension("b.dat"), FileFormat::text);
  EXPECT_EQ(asp::io::format_from_extension("b.npy"), FileFormat::npy);
  EXPECT_EQ(asp::io::format_from_extension("b.x3p"), FileFormat::x3p);
  EXPECT_EQ(asp::io::format_from_extension("dir.x3p/b"), FileFormat::automatic);
  EXPECT_EQ(asp::io::format_from_extension("b.sur"), FileFormat::automatic);
  for (FileFormat f : {FileFormat::automatic, FileFormat::text, FileFormat::npy, FileFormat::x3p})
    EXPECT_EQ(asp::io::format_from_name(asp::io::format_name(f)), f);
  EXPECT_THROW(asp::io::format_from_name("sur"), std::invalid_argument);
}

TEST(Formats, AutomaticChoiceByContent) {
  // The content decides, not the name: a .npy read as automatic, an x3p by its zip magic.
  EXPECT_EQ(asp::io::read_height_map(data("c_order.npy")).format, FileFormat::npy);
  EXPECT_EQ(asp::io::read_height_map(data("surface.x3p")).format, FileFormat::x3p);
  EXPECT_EQ(asp::io::read_height_map(data("savetxt_commas.csv")).format, FileFormat::text);
}

// ---- damaged files -------------------------------------------------------------------------

// Reads a damaged copy of a fixture: it must be read as a height map whose sizes match its
// values, all finite or missing (NaN), or refused with a FileError naming the file; nothing
// else may escape. Returns whether it was refused.
bool read_or_refused(const std::string &path, const std::string &what) {
  try {
    const HeightMap map = asp::io::read_height_map(path);
    EXPECT_GE(map.nx, 1) << what;
    EXPECT_GE(map.ny, 1) << what;
    EXPECT_EQ(map.heights.size(), static_cast<size_t>(map.nx * map.ny)) << what;
    for (double h : map.heights) EXPECT_FALSE(std::isinf(h)) << what;
    return false;
  } catch (const FileError &e) {
    EXPECT_TRUE(contains(e.what(), path)) << what << ": " << e.what();
    return true;
  } catch (const std::exception &e) {
    ADD_FAILURE() << what << ": " << typeid(e).name() << " escaped: " << e.what();
  } catch (...) {
    ADD_FAILURE() << what << ": an unknown exception escaped";
  }
  return true;
}

void write_file(const std::string &path, const std::string &content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
}

// Every fixture that reads, cut short and with a byte inverted, at every byte of its header
// and at many of the rest: the damaged files of a failed transfer or a full disk. The binary formats check their lengths
// (.npy) and checksums (.x3p), so that most damage is refused; text may still read as a
// smaller matrix.
TEST(DamagedFiles, EveryCutAndEveryInvertedByteIsReadOrRefused) {
  const char *fixtures[] = {"c_order.npy", "fortran_order.npy", "float32.npy", "int16.npy",
                            "version2.npy", "profile.npy", "gwyddion.txt", "matlab.txt",
                            "savetxt_comments.txt", "savetxt_commas.csv", "surface.x3p",
                            "integer_mask.x3p", "profile.x3p", "datalist.x3p"};
  for (const char *name : fixtures) {
    const std::string whole = file_text(data(name));
    ASSERT_FALSE(read_or_refused(data(name), name)) << name << " itself must read";
    const std::string extension = std::string(name).substr(std::string(name).rfind('.'));
    const std::string path = temp_path(std::string("damaged") + extension);
    // Every byte of the first 96 (the headers), then every 7th (cuts) or 5th (inversions).
    const auto next = [](size_t at, size_t stride) { return at < 96 ? at + 1 : at + stride; };
    int cuts = 0, cuts_refused = 0;
    for (size_t length = 0; length < whole.size(); length = next(length, 7), ++cuts) {
      write_file(path, whole.substr(0, length));
      cuts_refused += read_or_refused(path, std::string(name) + " cut to " +
                                                std::to_string(length) + " bytes");
    }
    for (size_t at = 0; at < whole.size(); at = next(at, 5)) {
      std::string damaged = whole;
      damaged[at] = static_cast<char>(~damaged[at]);
      write_file(path, damaged);
      read_or_refused(path, std::string(name) + " with byte " + std::to_string(at) + " inverted");
    }
    // Binary files cut anywhere are refused: their headers say how much follows.
    if (extension != ".txt" && extension != ".csv") {
      EXPECT_EQ(cuts_refused, cuts) << name;
    }
  }
}

// Found by fuzzing the readers. Each failed before its fix: a .npy holding an infinity was
// read as a height; an x3p archive of 812 bytes whose directory declares an entry of 4.2 GB
// made the reader allocate that much before reading (a std::bad_alloc, not a FileError, where
// memory is short); missing points next to heights above about 1e153 were filled with NaN,
// the squares of the conjugate gradients' residuals overflowing; and missing points beside a
// height of -DBL_MAX were filled with -infinity, the iteration's rounding carrying them a few
// ulps beyond it.
TEST(FuzzFindings, InfiniteNpyHeightsAreRefused) {
  const std::string message = read_error(data("infinite.npy"));
  EXPECT_TRUE(contains(message, "not finite")) << message;
}

TEST(FuzzFindings, DeclaredSizesAreNotAllocatedBeforeReading) {
  // Refused with a FileError (its data is not there), and read_error fails on anything else.
  // The allocation itself is what libFuzzer's malloc limit catches: this archive is also a
  // seed of tests/fuzz (fuzz.x3p_reader), which failed on it before the fix.
  EXPECT_FALSE(read_error(data("huge_declared_entry.x3p"), FileFormat::x3p).empty());
}

TEST(FuzzFindings, MissingPointsBesideHugeHeightsAreFilled) {
  for (double scale : {1.0, 1e200, 1e300, 1.7e308}) {
    HeightMap map;
    map.nx = 2;
    map.ny = 2;
    map.heights = {std::numeric_limits<double>::quiet_NaN(), scale, scale, scale};
    map.missing = 1;
    EXPECT_EQ(asp::io::fill_missing(map), 1);
    // The harmonic interpolation of equal heights, to the fill's relative residual of 1e-15.
    EXPECT_NEAR(map.heights[0], scale, 1e-14 * scale) << scale;
  }
}

TEST(FuzzFindings, MissingPointsBesideTheLargestHeightsStayFinite) {
  // The fuzzer's input: a 1D map of six, two known heights, one of them -DBL_MAX.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double lowest = -std::numeric_limits<double>::max();
  HeightMap map;
  map.nx = 6;
  map.ny = 1;
  map.heights = {-2.8483943054992686e+18, nan, lowest, nan, nan, nan};
  map.missing = 4;
  EXPECT_EQ(asp::io::fill_missing(map), 4);
  for (double h : map.heights) EXPECT_TRUE(std::isfinite(h)) << h;
  // Within the known range; beyond the last known point, on the open edge, the harmonic fill
  // is that point's height.
  for (double h : map.heights) EXPECT_GE(h, lowest);
  EXPECT_NEAR(map.heights[5], lowest, 1e-15 * -lowest);
  EXPECT_NEAR(map.heights[1], 0.5 * lowest, 1e-15 * -lowest);
}

}  // namespace
