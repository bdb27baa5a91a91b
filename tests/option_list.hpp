// SPDX-License-Identifier: GPL-2.0-or-later
// A test case's solver options as one string, "name=value" words separated by spaces, split
// into names and values; a value that reads wholly as a number is one (set it with the number
// setter), any other is text.
#pragma once

#include <cstdlib>
#include <string>
#include <vector>

namespace asp_test {

struct OptionWord {
  std::string name, text;
  bool numeric = false;
  double number = 0.0;
};

inline std::vector<OptionWord> option_list(const std::string &options) {
  std::vector<OptionWord> words;
  std::size_t start = 0;
  while (start < options.size()) {
    std::size_t end = options.find(' ', start);
    if (end == std::string::npos) end = options.size();
    const std::string word = options.substr(start, end - start);
    start = end + 1;
    if (word.empty()) continue;
    const std::size_t equals = word.find('=');
    OptionWord o;
    o.name = word.substr(0, equals);
    o.text = equals == std::string::npos ? std::string() : word.substr(equals + 1);
    char *rest = nullptr;
    o.number = std::strtod(o.text.c_str(), &rest);
    o.numeric = !o.text.empty() && *rest == '\0';
    words.push_back(o);
  }
  return words;
}

}  // namespace asp_test
