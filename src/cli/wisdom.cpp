// SPDX-License-Identifier: GPL-2.0-or-later
#include "wisdom.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "library.hpp"

namespace cli {

std::string wisdom_path(const ComputeOptions &compute) {
  if (compute.no_wisdom) return "";
  if (!compute.wisdom.empty()) return compute.wisdom;
  const char *cache = std::getenv("XDG_CACHE_HOME");
  if (cache != nullptr && cache[0] == '/') return std::string(cache) + "/asperity/fftw-wisdom";
  const char *home = std::getenv("HOME");
  if (home != nullptr && home[0] != '\0') return std::string(home) + "/.cache/asperity/fftw-wisdom";
  return "";
}

namespace {
void wisdom_note(const std::string &text) {
  std::fflush(stdout);
  std::fprintf(stderr, "asperity: note: %s\n", text.c_str());
}
}  // namespace

void read_wisdom(const ComputeOptions &compute) {
  const std::string path = wisdom_path(compute);
  if (path.empty()) return;
  struct stat status;
  if (stat(path.c_str(), &status) != 0 && errno == ENOENT) {
    if (!compute.wisdom.empty())
      wisdom_note("FFTW wisdom " + path + " does not exist yet" +
                  (compute.planning == ASP_FFT_ESTIMATE ? ""
                                                        : ": it is written after the solves"));
    return;
  }
  if (asp_fft_import_wisdom(path.c_str()) == ASP_OK) return;
  // The library's reason without what the note already says: "argument 'path': FFTW wisdom
  // '<path>' is not a regular file" becomes "not a regular file".
  std::string reason = refusal_message();
  for (const std::string &said :
       {std::string("argument 'path': "), "FFTW wisdom '" + path + "' ", std::string("is ")})
    if (reason.rfind(said, 0) == 0) reason.erase(0, said.size());
  wisdom_note("FFTW wisdom " + path + " ignored: " + reason);
}

void write_wisdom(const ComputeOptions &compute) {
  const std::string path = wisdom_path(compute);
  if (path.empty() || compute.planning == ASP_FFT_ESTIMATE) return;
  struct stat status;
  if (stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode)) return;
  auto not_written = [&](const std::string &why) {
    wisdom_note("FFTW wisdom not written to " + path + ": " + why);
  };
  const size_t slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  for (size_t end = directory.find('/', 1); end != std::string::npos;
       end = directory.find('/', end + 1)) {
    const std::string above = directory.substr(0, end);
    if (mkdir(above.c_str(), 0700) != 0 && errno != EEXIST)
      return not_written("cannot make " + above + ": " + std::strerror(errno));
  }
  // A new file beside the old one, renamed over it once complete.
  std::string temporary = path + ".XXXXXX";
  const int descriptor = mkstemp(&temporary[0]);
  if (descriptor < 0) return not_written(std::strerror(errno));
  close(descriptor);
  if (asp_fft_export_wisdom(temporary.c_str()) != ASP_OK) {
    const std::string why = refusal_message();
    unlink(temporary.c_str());
    return not_written(why);
  }
  if (rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    unlink(temporary.c_str());
    return not_written(why);
  }
}

}  // namespace cli
