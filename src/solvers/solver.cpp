#include "solvers/solver.hpp"

#include <chrono>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "solvers/polonsky_keer.hpp"

namespace asp {

const char *control_name(Control control) {
  switch (control) {
    case Control::mean_pressure: return "mean pressure";
    case Control::penetration: return "penetration";
    case Control::mean_gap: return "mean gap";
  }
  return "unknown";
}

void Solver::check_target(Control, double value) const { require_finite(value, "value"); }

void Solver::solve(System &system, Control control, double value) {
  if (!supports(control))
    throw Error(Status::unsupported, std::string("solver '") + name() + "' does not offer " +
                                         control_name(control) + " control");
  check_target(control, value);
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  run(system, control, value, report);
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.available = true;
  report_ = report;
}

std::unique_ptr<Solver> make_solver(const std::string &name) {
  if (name == "pk") return std::unique_ptr<Solver>(new PolonskyKeer());
  throw Error(Status::unsupported,
              "argument 'algorithm': unknown algorithm '" + name + "' (available: \"pk\")");
}

}  // namespace asp
