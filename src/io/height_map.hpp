// SPDX-License-Identifier: GPL-2.0-or-later
// Measured topographies from files, and fields written for NumPy: the readers and writers of
// the asperity command. They live outside the core library (which keeps FFTW and the standard
// library only) because they need libzip and pugixml; the command and the tests link them as
// the static library asperity_io.
//
// Every reader returns a HeightMap with x fastest: heights[x + nx * y]. Files store their
// matrices in one of two layouts, and each reader says which one it found:
//   - one scan line per row (rows are y, columns are x): text matrices as Gwyddion, MATLAB
//     and NumPy's savetxt write them, C-order .npy arrays of shape (ny, nx), images;
//   - x fastest in memory: .x3p point data.
// Fortran-order .npy arrays of shape (ny, nx) (y fastest in memory) are read with the same
// [row = y, column = x] indices as C-order ones.
// A one-dimensional profile (one line of text, a .npy of shape (n,), an x3p profile) has ny = 1.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace asp::io {

// A file that cannot be read or written, or whose content is not what its format says. The
// message names the file, and the place in it when there is one (line, entry, byte).
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class FileFormat { automatic, text, npy, x3p };

struct HeightMap {
  int64_t nx = 0;
  int64_t ny = 0;
  std::vector<double> heights;  // nx * ny values, x fastest; NaN where a point is missing

  // What the file says about physical sizes: the box lx x ly in length_unit (NaN and "" when
  // the file does not say; ly is NaN for a profile). heights are in height_unit ("" unknown).
  // Units are spelled as in unit_in_metres().
  double lx = 0.0;
  double ly = 0.0;
  std::string length_unit;
  std::string height_unit;

  FileFormat format = FileFormat::automatic;  // the format that was read
  std::string layout;                         // e.g. "text matrix, one scan line (y) per row"
  int64_t missing = 0;                        // how many heights are NaN
};

// The most a reader allocates for one file (docs/robustness.md). Measured surfaces come from
// instruments, colleagues and the web: every size a file declares (a shape, a matrix, an
// archive member's length) is checked against these limits and against what the file can
// hold (its length; for a zip member, its compressed length) before anything of that size is
// allocated, and an archive member is inflated no further than the size its header implies.
// A file beyond a limit is refused with a FileError that names the limit.
struct ReadLimits {
  // Heights in one map, nx * ny: 2^28 (16384 x 16384), 2 GiB as doubles. Instruments'
  // largest maps (stitched optical maps, 8192 x 8192 AFM scans) have 2^26 points or fewer.
  int64_t max_points = int64_t(1) << 28;
  // Bytes of an .x3p file's main.xml once inflated: 4 MiB. With its points in bindata/ it
  // takes a few kB; points written inline (Record3/DataList) take about 25 bytes each.
  int64_t max_xml_bytes = int64_t(4) << 20;
};

// Reads a height map. FileFormat::automatic chooses by content: the .npy magic string, a zip
// archive (x3p), otherwise text. Only regular files are read: a directory, a device
// (/dev/zero), a FIFO or a socket is refused before a byte is read, and bytes written to a
// file after it was opened are not read. Throws FileError; std::invalid_argument when a limit
// is below 1.
HeightMap read_height_map(const std::string &path, FileFormat format = FileFormat::automatic,
                          const ReadLimits &limits = ReadLimits());

// The format a file name suggests, or automatic for other names (".txt", ".asc", ".csv",
// ".dat" -> text; ".npy" -> npy; ".x3p" -> x3p); and a format's name ("text", "npy", "x3p").
FileFormat format_from_extension(const std::string &path);
FileFormat format_from_name(const std::string &name);  // throws std::invalid_argument
const char *format_name(FileFormat format);

// Metres per unit for "m", "mm", "um" (also "µm" and "micron"), "nm", "pm", "A" (ångström;
// also "Å"). Throws std::invalid_argument naming the unit and the accepted ones otherwise.
double unit_in_metres(const std::string &unit);

// Missing points (NaN heights): refused, or filled by the documented rule of fill_missing.
// fill_missing replaces each NaN by harmonic interpolation: the solution of Laplace's equation
// on the missing points with the known heights as boundary values (4-neighbour stencil, the
// grid's edges not wrapped), so a hole is bridged smoothly: each filled height is the mean of
// its neighbours inside the grid (4 inside, 3 on an edge, 2 at a corner), so a plane is filled
// exactly in an interior hole. Solved by preconditioned conjugate gradients to rounding
// accuracy. Returns how many were filled and sets map.missing to 0. Throws FileError when every
// point is missing. describe_missing says how many points are missing and where the first one
// (x fastest) is: "3 missing points (NaN), the first at x = 4, y = 0", "1 missing point (NaN),
// at x = 4, y = 0", or "no missing points".
int64_t fill_missing(HeightMap &map);
std::string describe_missing(const HeightMap &map);

// Writes values (x fastest, nx * ny of them) as a little-endian float64 .npy array of shape
// (ny, nx) in C order (shape (nx,) when ny == 1), so that numpy.load gives rows of constant y.
// Throws FileError.
void write_npy(const std::string &path, const double *values, int64_t nx, int64_t ny);

// Writes a text matrix: one scan line per row, values separated by single spaces, with the
// full precision of a double; lines starting with '#' before it for each comment line given.
void write_text_matrix(const std::string &path, const double *values, int64_t nx, int64_t ny,
                       const std::vector<std::string> &comments = {});

// Writes an ISO 25178-72 .x3p file of map (an areal surface, or a profile when ny == 1):
// main.xml with the axes' increments in metres, float64 point data in bindata/data.bin and its
// MD5 checksum. map.lx, map.ly and the heights are converted from their units to metres (a map
// without units is refused). Throws FileError.
void write_x3p(const std::string &path, const HeightMap &map);

}  // namespace asp::io
