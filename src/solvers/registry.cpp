// SPDX-License-Identifier: GPL-2.0-or-later
#include "solvers/registry.hpp"

#include <algorithm>
#include <cstdio>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "solvers/bugnicourt.hpp"
#include "solvers/lbfgsb.hpp"
#include "solvers/nested_grids.hpp"
#include "solvers/polonsky_keer.hpp"
#include "solvers/range_continuation.hpp"
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
      {"range_continuation", OptionType::real, 0, 0, 1e6, false, {},
       "with exponential adhesion, solve a cold start first with the range times this "
       "factor (>= 1) to 1e-2, then with the scene's own range (0: none; \"auto\": the "
       "factor that makes the cohesive zone 2 pixels long, where it is at most half a "
       "pixel)"},
  };
}

}  // namespace

const std::vector<std::pair<std::string, double>> &option_words(const std::string &name) {
  static const std::vector<std::pair<std::string, double>> none;
  static const std::vector<std::pair<std::string, double>> levels = {{"auto", levels_auto}};
  static const std::vector<std::pair<std::string, double>> continuation = {
      {"auto", continuation_auto}};
  if (name == "levels") return levels;
  return name == "range_continuation" ? continuation : none;
}

namespace {

AlgorithmSpec with_common_options(AlgorithmSpec spec) {
  std::vector<OptionSpec> options = common_options();
  for (OptionSpec &option : options)
    if (option.name == "levels") option.default_value = spec.default_levels;
    else if (option.name == "range_continuation")
      option.default_value = spec.default_range_continuation;
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

// The default of a number option, as the word it stands for where it has one ("auto").
std::string default_text(const OptionSpec &option) {
  for (const auto &word : option_words(option.name))
    if (word.second == option.default_value) return word.first;
  return number_text(option.default_value);
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

namespace {
// The interactions an offer handles, as text: "non-adhesive hard wall, hard wall with a
// potential (not a user's callback)".
std::string handled(const std::vector<InteractionFamily> &families, bool callbacks) {
  std::string text = names(families, family_name);
  const bool with_potential =
      std::find_if(families.begin(), families.end(), [](InteractionFamily f) {
        return f != InteractionFamily::hard_wall;
      }) != families.end();
  if (with_potential && !callbacks) text += " (not a user's callback)";
  return text;
}

bool takes(const std::vector<InteractionFamily> &families, bool callbacks,
           const Interaction &interaction) {
  return std::find(families.begin(), families.end(), interaction.family()) != families.end() &&
         (callbacks || !interaction.potential_from_callback());
}

constexpr const char *periodic_substrates = "periodic substrates (half-space, elastic layer)";
}  // namespace

void check_request(const AlgorithmSpec &algorithm, const OptionValues &options,
                   const System &system, Control control, const double *value) {
  Offer offer;
  if (algorithm.offer_for != nullptr) {
    offer = algorithm.offer_for(options);
  } else {
    offer.controls = algorithm.controls;
    offer.periodic_only = algorithm.periodic_only;
    offer.interactions = algorithm.interactions;
    offer.callbacks = algorithm.callbacks;
    offer.free_controls = algorithm.free_controls;
    offer.free_reason = algorithm.free_reason;
  }
  const std::string solver =
      "solver '" + algorithm.name + "'" +
      (offer.condition.empty() ? "" : " with " + offer.condition);
  const auto &c = offer.controls;
  if (std::find(c.begin(), c.end(), control) == c.end())
    throw Error(Status::unsupported, solver + " does not offer " + control_name(control) +
                                         " control (it offers: " + names(c, control_name) + ")");
  const Substrate &substrate = system.substrate();
  if (offer.periodic_only && !substrate.periodic())
    throw Error(Status::unsupported, solver + " does not work on a " + substrate.name() +
                                         " (it works on " + periodic_substrates + " only)");
  const auto &f = offer.free_controls;
  if (!substrate.periodic() && !f.empty() && std::find(f.begin(), f.end(), control) == f.end())
    throw Error(Status::unsupported, solver + " does not offer " + control_name(control) +
                                         " control on a " + substrate.name() +
                                         " (it offers there: " + names(f, control_name) +
                                         "): " + offer.free_reason);
  const Interaction &interaction = system.interaction();
  const std::string name = interaction_name(interaction.kind());
  const bool vowel = name.find_first_of("aeio") == 0;  // "a user potential"
  if (!takes(offer.interactions, offer.callbacks, interaction))
    throw Error(Status::unsupported, solver + " does not handle " + (vowel ? "an " : "a ") +
                                         name + " (it handles: " +
                                         handled(offer.interactions, offer.callbacks) + ")");
  if (control == Control::mean_pressure && !offer.load_interactions.empty() &&
      !takes(offer.load_interactions, offer.load_callbacks, interaction))
    throw Error(Status::unsupported,
                solver + " does not offer mean_pressure control with " +
                    (vowel ? "an " : "a ") + name + " (it offers it with: " +
                    handled(offer.load_interactions, offer.load_callbacks) +
                    "): " + offer.load_reason);

  // The value, where the request has one: the same for every algorithm.
  if (value == nullptr) return;
  require_finite(*value, "value");
  if (control == Control::mean_pressure && *value < 0.0 &&
      interaction.family() == InteractionFamily::hard_wall)
    throw Error(Status::invalid_argument,
                "argument 'value' is " + format_number(*value) +
                    ": a non-adhesive hard wall cannot carry a negative mean pressure");
  if (control == Control::mean_gap && *value < 0.0)
    throw Error(Status::invalid_argument, "argument 'value' is " + format_number(*value) +
                                              ": a mean gap cannot be negative");
}

std::string describe(const AlgorithmSpec &algorithm) {
  std::string text = algorithm.name + ": " + algorithm.summary + "\n";
  text += "controls: " + names(algorithm.controls, control_name) + "\n";
  text += std::string("substrates: ") + periodic_substrates +
          (algorithm.periodic_only ? " only" : "; free half-space") + "\n";
  if (!algorithm.free_controls.empty() && !algorithm.periodic_only)
    text += "controls on a free half-space: " + names(algorithm.free_controls, control_name) +
            " (" + algorithm.free_reason + ")\n";
  text += "interactions: " + handled(algorithm.interactions, algorithm.callbacks) + "\n";
  text += "options:\n";
  for (const OptionSpec &o : algorithm.options) {
    text += "  " + o.name;
    switch (o.type) {
      case OptionType::real:
      case OptionType::integer:
        text += std::string(o.type == OptionType::real ? " (real" : " (integer") +
                ", default " + default_text(o) + ", range " +
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
