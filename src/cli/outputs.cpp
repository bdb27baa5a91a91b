// SPDX-License-Identifier: GPL-2.0-or-later
#include "outputs.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/height_map.hpp"

namespace cli {

const char *const pressure_unit = "E* unit";

std::string prepare_directory(const std::string &directory, const std::string &where) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory))
    throw usage_error(where + ": cannot make the output directory '" + directory +
                      "': " + (error ? error.message() : "a file of that name exists"));
  return directory;
}

std::string cell(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string cell(int64_t value) { return std::to_string(value); }

std::string column(const std::string &name, const std::string &unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

void CsvTable::write(const std::string &path) const {
  std::ofstream file(path);
  if (!file) throw failure(path + ": cannot open for writing: " + std::strerror(errno));
  for (size_t c = 0; c < header_.size(); ++c) file << (c ? "," : "") << header_[c];
  file << '\n';
  for (const std::vector<std::string> &row : rows_) {
    for (size_t c = 0; c < row.size(); ++c) file << (c ? "," : "") << row[c];
    file << '\n';
  }
  file.flush();
  if (!file) throw failure(path + ": writing failed");
}

std::vector<double> read_field(const Contact &contact, int field) {
  std::vector<double> values(contact.surface.heights.size());
  check(asp_system_get_field(contact.system.get(), field, values.data(),
                             static_cast<int64_t>(values.size())),
        "reading a field of the system");
  return values;
}

std::vector<double> contact_map(const std::vector<double> &pressure) {
  std::vector<double> in_contact(pressure.size());
  for (size_t i = 0; i < pressure.size(); ++i) in_contact[i] = pressure[i] > 0.0 ? 1.0 : 0.0;
  return in_contact;
}

std::vector<std::string> write_fields(const Contact &contact,
                                      const std::vector<std::string> &names,
                                      const std::string &directory) {
  std::vector<std::string> written;
  for (const std::string &name : names) {
    std::vector<double> values;
    if (name == "pressure") values = read_field(contact, ASP_FIELD_PRESSURE);
    else if (name == "gap") values = read_field(contact, ASP_FIELD_GAP);
    else if (name == "displacement") values = read_field(contact, ASP_FIELD_DISPLACEMENT);
    else if (name == "topography") values = read_field(contact, ASP_FIELD_TOPOGRAPHY);
    else values = contact_map(read_field(contact, ASP_FIELD_PRESSURE));
    const std::string path = directory + "/" + name + ".npy";
    try {
      asp::io::write_npy(path, values.data(), contact.surface.nx, contact.surface.ny);
    } catch (const std::exception &e) {
      throw failure(e.what());
    }
    written.push_back(path);
  }
  return written;
}

}  // namespace cli
