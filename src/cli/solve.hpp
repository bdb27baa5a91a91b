// SPDX-License-Identifier: GPL-2.0-or-later
// One solve of a contact and what it reports: how it ended, its work, the contact's results
// and (when recorded) its history, iteration by iteration.
#pragma once

#include <string>
#include <vector>

#include "contact.hpp"
#include "progress.hpp"

namespace cli {

// The history columns the library records, by name (the CSV header uses these names).
struct HistoryColumn {
  int key;  // ASP_HISTORY_*
  const char *name;
};
extern const std::vector<HistoryColumn> history_columns;

struct SolveReport {
  std::string algorithm;
  int termination = 0;  // ASP_TERMINATION_*
  int64_t iterations = 0;
  int64_t evaluations = 0;
  int64_t transforms = 0;
  double seconds = 0.0;      // wall-clock time, as the library measured it
  double cpu_seconds = 0.0;  // the process's processor time during the solve, all threads
  double error = 0.0;
  double tolerance = 0.0;
  // The contact after the solve.
  double mean_pressure = 0.0;
  double penetration = 0.0;
  double mean_gap = 0.0;
  double contact_fraction = 0.0;      // ASP_CONTACT_FRACTION
  double compressive_fraction = 0.0;  // ASP_COMPRESSIVE_FRACTION
  double total_force = 0.0;
  // history[c][row] for history_columns[c]; empty when the history was off.
  std::vector<std::vector<double>> history;

  bool converged() const;
};

// Solves the contact under the control from the system's state, with the progress line, and
// reads the report. A refusal by the library (the solver does not serve the scene) is a
// usage error naming `where`; every value read is checked to be finite (the library promises
// it; a non-finite one is reported as a failure).
SolveReport solve(asp_solver *solver, const std::string &algorithm, Contact &contact,
                  int control, double value, ProgressLine &progress, bool record_history,
                  const std::string &where);

}  // namespace cli
