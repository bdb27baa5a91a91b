// SPDX-License-Identifier: GPL-2.0-or-later
#include "resolution.hpp"

#include <string>

namespace cli {

void print_resolution(std::FILE *out, const Contact &contact) {
  const asp_system *system = contact.system.get();
  int resolved = 1;
  int64_t length = 0;
  check(asp_system_check_resolution(system, nullptr, &resolved, nullptr, 0, &length),
        "checking the resolution of the interaction");
  if (resolved) return;
  std::string sentence(static_cast<size_t>(length) + 1, '\0');
  check(asp_system_check_resolution(system, nullptr, nullptr, sentence.data(), length + 1,
                                    nullptr),
        "checking the resolution of the interaction");
  sentence.resize(static_cast<size_t>(length));
  std::fprintf(out, "warning           %s\n", sentence.c_str());
}

}  // namespace cli
