// SPDX-License-Identifier: GPL-2.0-or-later
// The files the commands write: CSV tables (a header line whose column names carry their
// units), fields as .npy, and the directory they go to.
#pragma once

#include <string>
#include <vector>

#include "contact.hpp"
#include "scene.hpp"

namespace cli {

// The output directory, created (with its parents) before any work, so that a directory
// that cannot be made is a bad argument found before the solve. Throws usage_error.
std::string prepare_directory(const std::string &directory, const std::string &where);

// A file of the output directory, written under a fresh name beside its own (".NAME.XXXXXX",
// created anew: an existing name, a symbolic link included, is never opened) and renamed onto
// its name once complete. Whatever was at the name (an older output, a symbolic link planted
// there) is replaced, never followed or written through. Unless committed, the fresh file is
// removed when the object goes.
class OutputFile {
 public:
  explicit OutputFile(std::string path);  // throws failure naming path
  ~OutputFile();
  OutputFile(const OutputFile &) = delete;
  OutputFile &operator=(const OutputFile &) = delete;

  const std::string &path() const { return path_; }
  // The fresh file's name, for a writer that takes a name (the .npy writer, gnuplot): no one
  // but a user who may replace any file of the directory can put something else there.
  const std::string &fresh() const { return fresh_; }
  // Appends bytes to the fresh file; throws failure naming path.
  void write(const std::string &bytes);
  // Renames the fresh file onto path; throws failure naming path.
  void commit();

 private:
  std::string path_;
  std::string fresh_;
  int descriptor_ = -1;
  bool committed_ = false;
};

// A CSV table: the header's names, then rows of cells (numbers written with %.17g).
class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> header) : header_(std::move(header)) {}
  void add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  void write(const std::string &path) const;  // throws failure naming the file

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

std::string cell(double value);
std::string cell(int64_t value);

// "name [unit]", or "name" when the unit is "".
std::string column(const std::string &name, const std::string &unit);

// The unit of pressures: that of E* (the scene does not fix one).
extern const char *const pressure_unit;

// The unit of pressures of a surface's scene, for CSV columns and plot labels: its
// substrate.pressure_unit, else pressure_unit.
std::string pressure_unit_of(const Surface &surface);
// The unit of a total force (1D: per unit length): the pressure's times the area's, "MPa um^2".
std::string force_unit_of(const Surface &surface);
// The same after a number in a report: "MPa", else "in the units of E*" (not "units of E*",
// which reads as a multiple of E*).
std::string pressure_unit_text(const Surface &surface);

// The last component of a path (a scene's file name in plot titles, where a long path would
// crowd the title out).
std::string file_name(const std::string &path);

// Reads one field of the system (ASP_FIELD_*).
std::vector<double> read_field(const Contact &contact, int field);

// Writes the fields the scene asks for as DIRECTORY/NAME.npy; returns the paths written.
std::vector<std::string> write_fields(const Contact &contact, const std::vector<std::string> &names,
                                      const std::string &directory);

// The pixels in contact as 1, the others as 0: the library's map (ASP_FIELD_CONTACT), whose
// mean is the contact fraction the report gives.
std::vector<double> contact_map(const Contact &contact);

}  // namespace cli
