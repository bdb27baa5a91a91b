// What every algorithm shares: options, the report of the last run, and the solve entry point
// that checks the request and times the run.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "physics/system.hpp"

namespace asp {

enum class Control { mean_pressure = 1, penetration = 2, mean_gap = 3 };

const char *control_name(Control control);

struct SolverOptions {
  double tolerance = 1e-8;
  std::int64_t max_iterations = 10000;
};

struct SolveReport {
  bool available = false;  // false until a solve has run
  std::int64_t iterations = 0;
  double error = 0.0;
  bool converged = false;
  double seconds = 0.0;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual const char *name() const = 0;
  virtual bool supports(Control control) const = 0;

  // Checks the request (throws Error before touching the system), runs the algorithm from the
  // system's current state and records the report.
  void solve(System &system, Control control, double value);

  SolverOptions &options() { return options_; }
  const SolveReport &report() const { return report_; }

 protected:
  // Runs the algorithm; fills iterations, error and converged of the report.
  virtual void run(System &system, Control control, double value, SolveReport &report) = 0;
  // Extra checks of the target value for this algorithm.
  virtual void check_target(Control control, double value) const;

  SolverOptions options_;

 private:
  SolveReport report_;
};

// "pk", ...; throws Error(unsupported) naming the known algorithms for anything else.
std::unique_ptr<Solver> make_solver(const std::string &name);

}  // namespace asp
