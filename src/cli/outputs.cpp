// SPDX-License-Identifier: GPL-2.0-or-later
#include "outputs.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "io/height_map.hpp"

namespace cli {
namespace {

// text with every occurrence of `from` replaced by `to`.
std::string replaced(std::string text, const std::string &from, const std::string &to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  const size_t slash = path_.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "" : path_.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path_ : path_.substr(slash + 1);
  // O_EXCL creates the file or fails, whatever is at the name (a symbolic link included); a
  // name taken is tried again with other letters. The mode is the one any new file gets
  // (0666 less the umask), as mkstemp's 0600 would not be.
  static std::mt19937_64 draw{std::random_device{}()};
  const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  for (int attempt = 0; attempt < 100 && descriptor_ < 0; ++attempt) {
    std::string suffix;
    for (std::uint64_t bits = draw(), k = 0; k < 8; ++k, bits /= 62) suffix += letters[bits % 62];
    fresh_ = directory + "." + name + "." + suffix;
    descriptor_ = open(fresh_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (descriptor_ < 0 && errno != EEXIST) break;
  }
  if (descriptor_ < 0) {
    const std::string why = std::strerror(errno);
    fresh_.clear();
    throw failure(path_ + ": cannot open for writing: " + why);
  }
}

OutputFile::~OutputFile() {
  if (descriptor_ >= 0) close(descriptor_);
  if (!committed_ && !fresh_.empty()) unlink(fresh_.c_str());
}

void OutputFile::write(const std::string &bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t written = ::write(descriptor_, bytes.data() + done, bytes.size() - done);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0)
      throw failure(path_ + ": writing failed: " +
                    (written < 0 ? std::strerror(errno) : "nothing written"));
    done += static_cast<size_t>(written);
  }
}

void OutputFile::commit() {
  const int descriptor = descriptor_;
  descriptor_ = -1;
  if (close(descriptor) != 0) throw failure(path_ + ": writing failed: " + std::strerror(errno));
  if (rename(fresh_.c_str(), path_.c_str()) != 0)
    throw failure(path_ + ": cannot put the new file in its place: " + std::strerror(errno));
  committed_ = true;
}

const char *const pressure_unit = "E* unit";

std::string file_name(const std::string &path) {
  return path.substr(path.find_last_of('/') + 1);
}

std::string force_unit_of(const Surface &surface) {
  if (surface.unit.empty()) return pressure_unit_of(surface);
  return pressure_unit_of(surface) + " " + surface.unit + (surface.one_dimensional ? "" : "^2");
}

std::string pressure_unit_of(const Surface &surface) {
  return surface.pressure_unit.empty() ? pressure_unit : surface.pressure_unit;
}

std::string pressure_unit_text(const Surface &surface) {
  return surface.pressure_unit.empty() ? "in the units of E*" : surface.pressure_unit;
}

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
  std::string text;
  for (size_t c = 0; c < header_.size(); ++c) text += (c ? "," : "") + header_[c];
  text += '\n';
  for (const std::vector<std::string> &row : rows_) {
    for (size_t c = 0; c < row.size(); ++c) text += (c ? "," : "") + row[c];
    text += '\n';
  }
  OutputFile file(path);
  file.write(text);
  file.commit();
}

std::vector<double> read_field(const Contact &contact, int field) {
  std::vector<double> values(contact.surface.heights.size());
  check(asp_system_get_field(contact.system.get(), field, values.data(),
                             static_cast<int64_t>(values.size())),
        "reading a field of the system");
  return values;
}

std::vector<double> contact_map(const Contact &contact) {
  // Not the sign of the pressure: off contact a soft wall's pressure is an attraction of
  // rounding size, and with adhesion the contact's edge is under tension.
  return read_field(contact, ASP_FIELD_CONTACT);
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
    else values = contact_map(contact);
    const std::string path = directory + "/" + name + ".npy";
    OutputFile file(path);
    try {
      asp::io::write_npy(file.fresh(), values.data(), contact.surface.nx, contact.surface.ny);
    } catch (const std::exception &e) {
      // The writer names the file it wrote, the fresh one: the message names the output.
      throw failure(path + ": " + replaced(e.what(), "'" + file.fresh() + "'", "it"));
    }
    file.commit();
    written.push_back(path);
  }
  return written;
}

}  // namespace cli
