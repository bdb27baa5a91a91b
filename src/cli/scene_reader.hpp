// SPDX-License-Identifier: GPL-2.0-or-later
// Reading one table of a TOML scene with its checks: every getter names the file, line and key
// of a value it refuses, every key read is marked, and finish() refuses the keys nobody read,
// so that a misspelt key is an error and not silently ignored.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace cli {

// The candidate closest to `word`, for a "did you mean" after an unknown key, option or
// name, or "" when none is close: within about a third of the shorter's letters by edit
// distance (insertions, deletions, substitutions and swaps of neighbours), or one that
// starts with the word ("maxiter" for "max_iterations"), underscores and hyphens aside.
std::string closest(const std::string &word, const std::vector<std::string> &candidates);

// "; did you mean NAME?" with the closest candidate (shown as `prefix` + candidate), or "".
std::string did_you_mean(const std::string &word, const std::vector<std::string> &candidates,
                         const std::string &prefix = "");

// "scene.toml:12:3" for a node of the file, the argument ("--tolerance 1e-10") for a value
// given on the command line.
std::string where(const toml::source_region &source);

class SceneTable {
 public:
  // name is the table's dotted name ("grid", "solver.options"; "" for the top level).
  SceneTable(const toml::table &table, std::string name);

  const std::string &name() const { return name_; }
  // "grid.nx" for key "nx".
  std::string key_name(const std::string &key) const;

  // Whether the key is present; a key asked about is one the table accepts, listed as such
  // when a key is unknown.
  bool has(const std::string &key) const {
    asked_.insert(key);
    return table_.contains(key);
  }
  const toml::node *node(const std::string &key);  // marks the key read; null if absent
  // Declares keys the table accepts before they are read, so that a key refused as unknown
  // or missing before the others are read is shown with all of them.
  void accepts(std::initializer_list<const char *> keys) const;

  // Numbers: an integer or a float, finite. Required (throw if missing) or with a fallback.
  double real(const std::string &key);
  double real(const std::string &key, double fallback);
  double positive(const std::string &key);  // > 0
  double positive(const std::string &key, double fallback);
  double non_negative(const std::string &key, double fallback);  // >= 0
  int64_t integer(const std::string &key, int64_t minimum);
  int64_t integer(const std::string &key, int64_t minimum, int64_t fallback);
  bool boolean(const std::string &key, bool fallback);
  std::string text(const std::string &key);
  std::string text(const std::string &key, const std::string &fallback);
  // A text from a fixed list (the first of which is the fallback when optional).
  std::string choice(const std::string &key, const std::vector<std::string> &choices);
  std::string choice(const std::string &key, const std::vector<std::string> &choices,
                     const std::string &fallback);
  std::vector<std::string> texts(const std::string &key, const std::vector<std::string> &fallback);
  std::vector<double> reals(const std::string &key);
  // A sub-table ([grid.sweep] or an inline table); null if absent, refused if not a table.
  const toml::table *table(const std::string &key);

  // A missing key that the table holds misspelt ("work_adhesion" for "work_of_adhesion") is
  // refused as the unknown key it is, with the right one; else nothing happens.
  void refuse_misspelling(const std::string &key) const;
  // Throws usage_error at the first key (in the file's order) that was not read, with every
  // key the table accepts and the closest of them.
  void finish() const;
  // Throws usage_error "WHERE: KEY: problem", at the key's value if it is present, at the table
  // otherwise.
  [[noreturn]] void refuse(const std::string &key, const std::string &problem) const;
  // Refuses when both keys are present, or (required) when neither is.
  void one_of(const std::string &a, const std::string &b, bool required) const;

 private:
  const toml::node &need(const std::string &key);
  // Every key read or asked about, sorted.
  std::vector<std::string> accepted() const;
  [[noreturn]] void unknown(const std::string &key, const toml::node &value) const;


  const toml::table &table_;
  std::string name_;
  std::set<std::string> read_;
  mutable std::set<std::string> asked_;
};

}  // namespace cli
