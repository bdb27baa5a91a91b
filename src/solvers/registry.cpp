// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/registry.hpp"

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "solvers/bugnicourt.hpp"
#include "solvers/lbfgsb.hpp"
#include "solvers/nested_grids.hpp"
#include "solvers/polonsky_keer.hpp"
#include "solvers/unconstrained_algorithms.hpp"

namespace asp {

namespace {

// What every algorithm offers: the monitor's settings.
std::vector<OptionSpec> common_options() {
  const double largest_count = 9.2e18;  // below INT64_MAX, exactly representable
  return {
      {"tolerance", OptionType::real, 1e-8, 0.0, 1e300, true, {},
       "stop when the error falls to it"},
      {"max_iterations", OptionType::integer, 10000, 1, largest_count, false, {},
       "stop after this many iterations"},
      {"stall_window", OptionType::integer, 1000, 0, largest_count, false, {},
       "stop as stalled when this many iterations pass without the error falling below "
       "0.99 times the last error that did so (0: never)"},
      {"levels", OptionType::integer, 0, 0, 16, false, {},
       "nested grids: solve first on this many grids coarser by 2 per axis, from the "
       "coarsest up, when the state carries no pressure (0: none; \"auto\": halve while "
       "both sides stay at least 64 pixels)"},
  };
}

}  // namespace

const std::vector<std::pair<std::string, double>> &option_words(const std::string &name) {
  static const std::vector<std::pair<std::string, double>> none;
  static const std::vector<std::pair<std::string, double>> levels = {{"auto", levels_auto}};
  return name == "levels" ? levels : none;
}

namespace {

AlgorithmSpec with_common_options(AlgorithmSpec spec) {
  std::vector<OptionSpec> options = common_options();
  options.insert(options.end(), spec.options.begin(), spec.options.end());
  spec.options = std::move(options);
  return spec;
}

template <class T, class Name>
std::string names(const std::vector<T> &items, Name name) {
  std::string out;
  for (const T &item : items) out += (out.empty() ? "" : ", ") + std::string(name(item));
  return out;
}

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

}  // namespace

const std::vector<AlgorithmSpec> &algorithms() {
  static const std::vector<AlgorithmSpec> all = {with_common_options(polonsky_keer_algorithm()),
                                                 with_common_options(bugnicourt_algorithm()),
                                                 with_common_options(lbfgsb_algorithm()),
                                                 with_common_options(lbfgs_algorithm()),
                                                 with_common_options(lbfgs_fourier_algorithm()),
                                                 with_common_options(gfmd_algorithm()),
                                                 with_common_options(fire_algorithm()),
                                                 with_common_options(fire_mass_weighted_algorithm())};
  return all;
}

const AlgorithmSpec &find_algorithm(const std::string &name) {
  for (const AlgorithmSpec &a : algorithms())
    if (a.name == name) return a;
  throw Error(Status::unsupported,
              "argument 'algorithm': unknown algorithm '" + name + "' (available: " +
                  names(algorithms(), [](const AlgorithmSpec &a) { return a.name.c_str(); }) +
                  ")");
}

void check_request(const AlgorithmSpec &algorithm, const OptionValues &options,
                   const System &system, Control control) {
  const Offer offer = algorithm.offer_for != nullptr
                          ? algorithm.offer_for(options)
                          : Offer{algorithm.controls, algorithm.substrates,
                                  algorithm.interactions, "", algorithm.free_controls,
                                  algorithm.free_reason, {}, ""};
  const std::string solver =
      "solver '" + algorithm.name + "'" +
      (offer.condition.empty() ? "" : " with " + offer.condition);
  const auto &c = offer.controls;
  if (std::find(c.begin(), c.end(), control) == c.end())
    throw Error(Status::unsupported, solver + " does not offer " + control_name(control) +
                                         " control (it offers: " + names(c, control_name) + ")");
  const auto &s = offer.substrates;
  if (std::find(s.begin(), s.end(), system.substrate().kind()) == s.end())
    throw Error(Status::unsupported, solver + " does not work on a " +
                                         substrate_name(system.substrate().kind()) +
                                         " (it works on: " + names(s, substrate_name) + ")");
  const auto &f = offer.free_controls;
  if (system.substrate().kind() == SubstrateKind::free && !f.empty() &&
      std::find(f.begin(), f.end(), control) == f.end())
    throw Error(Status::unsupported, solver + " does not offer " + control_name(control) +
                                         " control on a free half-space (it offers there: " +
                                         names(f, control_name) + "): " + offer.free_reason);
  const auto &i = offer.interactions;
  const std::string interaction = interaction_name(system.interaction().kind());
  const bool vowel = interaction.find_first_of("aeio") == 0;  // "a user potential"
  if (std::find(i.begin(), i.end(), system.interaction().kind()) == i.end())
    throw Error(Status::unsupported, solver + " does not handle " + (vowel ? "an " : "a ") +
                                         interaction +
                                         " (it handles: " + names(i, interaction_name) + ")");
  const auto &l = offer.load_interactions;
  if (control == Control::mean_pressure && !l.empty() &&
      std::find(l.begin(), l.end(), system.interaction().kind()) == l.end())
    throw Error(Status::unsupported, solver + " does not offer mean_pressure control with " +
                                         (vowel ? "an " : "a ") + interaction +
                                         " (it offers it with: " + names(l, interaction_name) +
                                         "): " + offer.load_reason);
}

std::string describe(const AlgorithmSpec &algorithm) {
  std::string text = algorithm.name + ": " + algorithm.summary + "\n";
  text += "controls: " + names(algorithm.controls, control_name) + "\n";
  text += "substrates: " + names(algorithm.substrates, substrate_name) + "\n";
  if (!algorithm.free_controls.empty())
    text += "controls on a free half-space: " + names(algorithm.free_controls, control_name) +
            " (" + algorithm.free_reason + ")\n";
  text += "interactions: " + names(algorithm.interactions, interaction_name) + "\n";
  text += "options:\n";
  for (const OptionSpec &o : algorithm.options) {
    text += "  " + o.name;
    switch (o.type) {
      case OptionType::real:
      case OptionType::integer:
        text += std::string(o.type == OptionType::real ? " (real" : " (integer") +
                ", default " + number_text(o.default_value) + ", range " +
                (o.minimum_excluded ? "(" : "[") + number_text(o.minimum) + ", " +
                number_text(o.maximum) + "])";
        break;
      case OptionType::choice:
        text += " (one of " + names(o.choices, [](const std::string &c) { return c.c_str(); }) +
                "; default " + o.choices.front() + ")";
        break;
    }
    text += ": " + o.meaning + "\n";
  }
  return text;
}

}  // namespace asp
