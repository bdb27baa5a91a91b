// SPDX-License-Identifier: GPL-2.0-or-later
// A solver: one algorithm of the registry, its option values, the progress callback, and the
// report and history of its last solve.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "physics/system.hpp"
#include "formulations/control.hpp"
#include "formulations/formulation.hpp"
#include "solvers/monitor.hpp"
#include "solvers/nested_grids.hpp"
#include "solvers/range_continuation.hpp"
#include "solvers/registry.hpp"

namespace asp {

struct SolveReport {
  bool available = false;  // false until a solve has run (and after one that failed)
  std::int64_t iterations = 0;
  std::int64_t evaluations = 0;  // objective or gradient evaluations
  std::int64_t transforms = 0;   // forward or backward FFTs
  double error = 0.0;
  Termination termination = Termination::iteration_limit;
  double seconds = 0.0;
  bool converged() const { return termination == Termination::converged; }
};

class Solver {
 public:
  // The algorithm of that name with its default options (throws Error(unsupported) naming
  // the known algorithms otherwise).
  explicit Solver(const std::string &algorithm);

  const AlgorithmSpec &algorithm() const { return algorithm_; }

  // Throws Error(unsupported), as solve() would, if this algorithm with these options cannot
  // serve the system under the control; changes nothing.
  void check_supported(const System &system, Control control) const {
    check_request(algorithm_, options_, system, control);
    nested_levels(system, options_.number("levels"));  // refuses levels the grid cannot take
    check_range_continuation(system, options_.number("range_continuation"));
  }

  // Options by name; unknown names, wrong types and values out of range are refused with
  // Error(invalid_argument) naming the option and what is valid.
  void set_option(const std::string &name, double value);
  void set_option(const std::string &name, const std::string &value);
  double option(const std::string &name) const;
  const std::string &option_text(const std::string &name) const;
  // The algorithm and every option's name and value as one number (an FNV-1a hash, its bits
  // in a double: compared bit for bit, never computed with), so that the processes of a
  // distributed solve can check that they solve alike.
  double fingerprint() const;

  void set_progress(ProgressFunction progress, void *user_data);
  void set_history(bool on) { record_history_ = on; }
  bool history_on() const { return record_history_; }

  // Forgets the last solve's report and history, so that a refused or failed solve leaves no
  // report behind that could be mistaken for its own.
  void forget_last_solve();

  // Forgets the last solve, checks the request (throws Error before touching the system), runs
  // the algorithm from the system's current state and records the report and, if asked, the
  // history.
  void solve(System &system, Control control, double value);

  const SolveReport &report() const { return report_; }
  const History &history() const { return history_; }

 private:
  const OptionSpec &spec_of(const std::string &name) const;

  const AlgorithmSpec &algorithm_;
  OptionValues options_;
  ProgressFunction progress_ = nullptr;
  void *progress_data_ = nullptr;
  bool record_history_ = false;
  SolveReport report_;
  History history_;
};

}  // namespace asp
