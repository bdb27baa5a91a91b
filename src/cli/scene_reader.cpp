// SPDX-License-Identifier: GPL-2.0-or-later
#include "scene_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include "exit_status.hpp"

namespace cli {
namespace {

const char *type_name(const toml::node &node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date or time";
  }
}

std::string shown(const toml::node &node) {
  std::ostringstream text;
  if (auto string = node.as_string())
    text << '"' << string->get() << '"';
  else if (auto real = node.as_floating_point())
    text << real->get();
  else if (auto integer = node.as_integer())
    text << integer->get();
  else if (auto flag = node.as_boolean())
    text << (flag->get() ? "true" : "false");
  else
    text << type_name(node);
  return text.str();
}

std::string listed(const std::vector<std::string> &words) {
  std::string text;
  for (size_t k = 0; k < words.size(); ++k)
    text += (k == 0 ? "" : k + 1 == words.size() ? " or " : ", ") + ('"' + words[k] + '"');
  return text;
}

bool before(const toml::source_position &a, const toml::source_position &b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

// Lower case, without underscores and hyphens: "max_iterations" and "MaxIterations" compare
// alike.
std::string folded(const std::string &word) {
  std::string text;
  for (char c : word)
    if (c != '_' && c != '-') text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// The optimal-string-alignment distance: insertions, deletions, substitutions and swaps of
// two neighbours, each counting one.
size_t edit_distance(const std::string &a, const std::string &b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                          d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string closest(const std::string &word, const std::vector<std::string> &candidates) {
  const std::string w = folded(word);
  std::string best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const std::string &candidate : candidates) {
    const std::string c = folded(candidate);
    if (c.empty() || w.empty() || candidate == word) continue;
    size_t distance = edit_distance(w, c);
    // Close: a third of the shorter word's letters may differ (at least one), so that short
    // words are not matched to anything; an abbreviation of three letters or more is close
    // too ("tol" for "tolerance"), ranked after every word within the distance.
    const bool near = distance <= std::max<size_t>(1, std::min(w.size(), c.size()) / 3);
    const bool abbreviation = w.size() >= 3 && c.compare(0, w.size(), w) == 0;
    if (!near && !abbreviation) continue;
    if (!near) distance = c.size();
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string did_you_mean(const std::string &word, const std::vector<std::string> &candidates,
                         const std::string &prefix) {
  const std::string c = closest(word, candidates);
  return c.empty() ? "" : "; did you mean " + prefix + c + "?";
}

std::string where(const toml::source_region &source) {
  const std::string path = source.path ? *source.path : std::string("scene");
  if (path.rfind("--", 0) == 0) return path;  // a value given on the command line
  std::string text = path;
  if (source.begin.line > 0)
    text += ":" + std::to_string(source.begin.line) + ":" + std::to_string(source.begin.column);
  return text;
}

SceneTable::SceneTable(const toml::table &table, std::string name)
    : table_(table), name_(std::move(name)) {}

std::string SceneTable::key_name(const std::string &key) const {
  return name_.empty() ? key : name_ + "." + key;
}

void SceneTable::refuse(const std::string &key, const std::string &problem) const {
  const toml::node *value = table_.get(key);
  const toml::source_region &source = value != nullptr ? value->source() : table_.source();
  throw usage_error(where(source) + ": " + key_name(key) + ": " + problem);
}

void SceneTable::accepts(std::initializer_list<const char *> keys) const {
  for (const char *key : keys) asked_.insert(key);
}

const toml::node *SceneTable::node(const std::string &key) {
  read_.insert(key);
  return table_.get(key);
}

const toml::node &SceneTable::need(const std::string &key) {
  const toml::node *value = node(key);
  if (value == nullptr) {
    refuse_misspelling(key);
    const std::string table = name_.empty() ? "the scene" : "[" + name_ + "]";
    throw usage_error(where(table_.source()) + ": " + key_name(key) + ": missing: " + table +
                      " needs the key '" + key + "'");
  }
  return *value;
}

double SceneTable::real(const std::string &key) {
  const toml::node &value = need(key);
  double number = 0.0;
  if (auto real = value.as_floating_point())
    number = real->get();
  else if (auto integer = value.as_integer())
    number = static_cast<double>(integer->get());
  else
    refuse(key, std::string("expected a number, got ") + type_name(value) + " " + shown(value));
  if (!std::isfinite(number)) refuse(key, "expected a finite number, got " + shown(value));
  return number;
}

double SceneTable::real(const std::string &key, double fallback) {
  return has(key) ? real(key) : (read_.insert(key), fallback);
}

double SceneTable::positive(const std::string &key) {
  const double value = real(key);
  if (!(value > 0.0)) refuse(key, "must be > 0, got " + shown(*table_.get(key)));
  return value;
}

double SceneTable::positive(const std::string &key, double fallback) {
  return has(key) ? positive(key) : (read_.insert(key), fallback);
}

double SceneTable::non_negative(const std::string &key, double fallback) {
  if (!has(key)) return read_.insert(key), fallback;
  const double value = real(key);
  if (value < 0.0) refuse(key, "must be >= 0, got " + shown(*table_.get(key)));
  return value;
}

int64_t SceneTable::integer(const std::string &key, int64_t minimum) {
  const toml::node &value = need(key);
  auto integer = value.as_integer();
  if (integer == nullptr)
    refuse(key, std::string("expected a whole number, got ") + type_name(value) + " " +
                    shown(value));
  if (integer->get() < minimum)
    refuse(key, "must be >= " + std::to_string(minimum) + ", got " + shown(value));
  return integer->get();
}

int64_t SceneTable::integer(const std::string &key, int64_t minimum, int64_t fallback) {
  return has(key) ? integer(key, minimum) : (read_.insert(key), fallback);
}

bool SceneTable::boolean(const std::string &key, bool fallback) {
  if (!has(key)) return read_.insert(key), fallback;
  const toml::node &value = need(key);
  auto flag = value.as_boolean();
  if (flag == nullptr)
    refuse(key, std::string("expected true or false, got ") + type_name(value) + " " +
                    shown(value));
  return flag->get();
}

std::string SceneTable::text(const std::string &key) {
  const toml::node &value = need(key);
  auto string = value.as_string();
  if (string == nullptr)
    refuse(key, std::string("expected a string, got ") + type_name(value) + " " + shown(value));
  return string->get();
}

std::string SceneTable::text(const std::string &key, const std::string &fallback) {
  return has(key) ? text(key) : (read_.insert(key), fallback);
}

std::string SceneTable::choice(const std::string &key, const std::vector<std::string> &choices) {
  const std::string value = text(key);
  for (const std::string &c : choices)
    if (value == c) return value;
  refuse(key, "\"" + value + "\" is not one of " + listed(choices));
}

std::string SceneTable::choice(const std::string &key, const std::vector<std::string> &choices,
                               const std::string &fallback) {
  return has(key) ? choice(key, choices) : (read_.insert(key), fallback);
}

std::vector<std::string> SceneTable::texts(const std::string &key,
                                           const std::vector<std::string> &fallback) {
  if (!has(key)) return read_.insert(key), fallback;
  const toml::node &value = need(key);
  auto array = value.as_array();
  if (array == nullptr)
    refuse(key, std::string("expected an array of strings, got ") + type_name(value));
  std::vector<std::string> words;
  for (const toml::node &item : *array) {
    auto string = item.as_string();
    if (string == nullptr)
      throw usage_error(where(item.source()) + ": " + key_name(key) +
                        ": expected an array of strings, got " + type_name(item) + " " +
                        shown(item));
    words.push_back(string->get());
  }
  return words;
}

std::vector<double> SceneTable::reals(const std::string &key) {
  const toml::node &value = need(key);
  auto array = value.as_array();
  if (array == nullptr)
    refuse(key, std::string("expected an array of numbers, got ") + type_name(value));
  std::vector<double> numbers;
  for (const toml::node &item : *array) {
    double number = std::numeric_limits<double>::quiet_NaN();
    if (auto real = item.as_floating_point()) number = real->get();
    else if (auto integer = item.as_integer()) number = static_cast<double>(integer->get());
    else
      throw usage_error(where(item.source()) + ": " + key_name(key) +
                        ": expected an array of numbers, got " + type_name(item) + " " +
                        shown(item));
    if (!std::isfinite(number))
      throw usage_error(where(item.source()) + ": " + key_name(key) +
                        ": expected finite numbers, got " + shown(item));
    numbers.push_back(number);
  }
  return numbers;
}

const toml::table *SceneTable::table(const std::string &key) {
  const toml::node *value = node(key);
  if (value == nullptr) return nullptr;
  if (!value->is_table())
    refuse(key, std::string("expected a table, got ") + type_name(*value) + " " + shown(*value));
  return value->as_table();
}

void SceneTable::one_of(const std::string &a, const std::string &b, bool required) const {
  if (has(a) && has(b)) refuse(b, "give either '" + a + "' or '" + b + "', not both");
  if (required && !has(a) && !has(b)) {
    refuse_misspelling(a);
    refuse_misspelling(b);
    const std::string table = name_.empty() ? "the scene" : "[" + name_ + "]";
    throw usage_error(where(table_.source()) + ": " + key_name(a) + ": missing: " + table +
                      " needs '" + a + "' or '" + b + "'");
  }
}

void SceneTable::refuse_misspelling(const std::string &key) const {
  for (auto &&[present, value] : table_) {
    const std::string name(present.str());
    if (read_.count(name) == 0 && asked_.count(name) == 0 && closest(name, {key}) == key)
      unknown(name, value);
  }
}

void SceneTable::finish() const {
  std::string first;
  const toml::node *first_node = nullptr;
  for (auto &&[key, value] : table_) {
    const std::string name(key.str());
    if (read_.count(name) != 0) continue;
    if (first_node == nullptr || before(value.source().begin, first_node->source().begin)) {
      first = name;
      first_node = &value;
    }
  }
  if (first_node != nullptr) unknown(first, *first_node);
}

std::vector<std::string> SceneTable::accepted() const {
  std::set<std::string> keys = read_;
  keys.insert(asked_.begin(), asked_.end());
  return std::vector<std::string>(keys.begin(), keys.end());
}

void SceneTable::unknown(const std::string &key, const toml::node &value) const {
  const std::vector<std::string> keys = accepted();
  std::string known;
  for (const std::string &k : keys) known += (known.empty() ? "" : ", ") + k;
  throw usage_error(where(value.source()) + ": " + key_name(key) + ": unknown key" +
                    did_you_mean(key, keys) +
                    (known.empty() ? "" : " (the keys here are: " + known + ")"));
}

}  // namespace cli
