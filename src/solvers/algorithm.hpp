// SPDX-License-Identifier: GPL-2.0-or-later
// What an algorithm is to the registry: its name, what it serves (controls, and what it needs
// of substrates and interactions), its options with defaults and ranges, and how to run it.
// Each algorithm's file describes itself with one of these; the registry lists them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "formulations/control.hpp"
#include "physics/system.hpp"
#include "solvers/monitor.hpp"

namespace asp {

enum class OptionType { real, integer, choice };

struct OptionSpec {
  std::string name;
  OptionType type;
  double default_value = 0.0;  // real and integer options
  double minimum = 0.0;
  double maximum = 0.0;
  bool minimum_excluded = false;              // (minimum, maximum] instead of [minimum, maximum]
  std::vector<std::string> choices;           // choice options; the first is the default
  std::string meaning;
};

// Option values by name: numbers for real and integer options, texts for choices.
struct OptionValues {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> texts;
  double number(const std::string &name) const { return numbers.at(name); }
  const std::string &text(const std::string &name) const { return texts.at(name); }
};

// What an algorithm serves with given option values, and which values those are (for the
// refusal's message, e.g. "variable = gap"), in terms of what substrates and interactions can
// do rather than which ones they are: a new substrate or potential with the same capabilities
// is taken without a change here.
struct Offer {
  std::vector<Control> controls;
  // Whether it needs a periodic substrate (its operator diagonal on the grid's own spectrum):
  // any periodic one (half-space, layer, ...) is then taken, a free one is not.
  bool periodic_only = false;
  // The interaction families it handles, and whether it takes a user's callback potential in
  // those that have a potential.
  std::vector<InteractionFamily> interactions;
  bool callbacks = false;
  std::string condition;
  // The controls offered on a substrate that is not periodic when fewer than `controls`
  // (empty: all of them), and why the others are not.
  std::vector<Control> free_controls;
  std::string free_reason;
  // The families (and callbacks or not) taken under mean-pressure control when fewer than
  // above (empty: the same), and why the others are not.
  std::vector<InteractionFamily> load_interactions;
  bool load_callbacks = false;
  std::string load_reason;
};

struct AlgorithmSpec {
  std::string name;
  std::string summary;
  // What it serves with some option values (for describe()), as in Offer.
  std::vector<Control> controls;
  bool periodic_only = false;
  std::vector<InteractionFamily> interactions;
  bool callbacks = false;
  // As in Offer: the controls on a free substrate when fewer, and why.
  std::vector<Control> free_controls;
  std::string free_reason;
  // What it serves with these option values, when that depends on them (null: the lists
  // above, whatever the options).
  Offer (*offer_for)(const OptionValues &options) = nullptr;
  std::vector<OptionSpec> options;  // every option, the common ones first
  // The default of the common option "levels" (levels_auto for "auto").
  double default_levels = 0.0;
  // The default of the common option "range_continuation" (continuation_auto for "auto").
  double default_range_continuation = 0.0;
  // Runs the algorithm from the system's state and leaves its result there (see conclude()).
  void (*run)(System &system, Control control, double value, const OptionValues &options,
              Monitor &monitor);
};

}  // namespace asp
