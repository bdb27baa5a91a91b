// SPDX-License-Identifier: GPL-2.0-or-later
#include "capi/constants.hpp"

#include <string>

#include "asperity/asperity.h"
#include "core/error.hpp"

namespace asp {
namespace capi {
namespace {

struct Constant {
  int value;
  const char *name;
  Family family;
};

#define ASP_CONSTANT(name, family) {name, #name, Family::family}
const Constant constants[] = {
    ASP_CONSTANT(ASP_FFT_ESTIMATE, planning),
    ASP_CONSTANT(ASP_FFT_MEASURE, planning),
    ASP_CONSTANT(ASP_FFT_PATIENT, planning),
    ASP_CONSTANT(ASP_RMS_HEIGHT, normalisation),
    ASP_CONSTANT(ASP_RMS_SLOPE, normalisation),
    ASP_CONSTANT(ASP_CONTACT_FRACTION, scalar_key),
    ASP_CONSTANT(ASP_MEAN_PRESSURE, scalar_key),
    ASP_CONSTANT(ASP_MEAN_GAP, scalar_key),
    ASP_CONSTANT(ASP_ELASTIC_ENERGY, scalar_key),
    ASP_CONSTANT(ASP_PENETRATION, scalar_key),
    ASP_CONSTANT(ASP_TOTAL_FORCE, scalar_key),
    ASP_CONSTANT(ASP_K0, scalar_key),
    ASP_CONSTANT(ASP_REFERENCE_PRESSURE, scalar_key),
    ASP_CONSTANT(ASP_MEAN_MODE_ENERGY, scalar_key),
    ASP_CONSTANT(ASP_ATTRACTIVE_FRACTION, scalar_key),
    ASP_CONSTANT(ASP_REPULSIVE_FORCE, scalar_key),
    ASP_CONSTANT(ASP_ATTRACTIVE_FORCE, scalar_key),
    ASP_CONSTANT(ASP_INTERACTION_ENERGY, scalar_key),
    ASP_CONSTANT(ASP_WORK_OF_ADHESION, scalar_key),
    ASP_CONSTANT(ASP_ADHESION_RANGE, scalar_key),
    ASP_CONSTANT(ASP_COMPRESSIVE_FRACTION, scalar_key),
    ASP_CONSTANT(ASP_FIELD_PRESSURE, field),
    ASP_CONSTANT(ASP_FIELD_GAP, field),
    ASP_CONSTANT(ASP_FIELD_DISPLACEMENT, field),
    ASP_CONSTANT(ASP_FIELD_TOPOGRAPHY, field),
    ASP_CONSTANT(ASP_FIELD_CONTACT, field),
    ASP_CONSTANT(ASP_CONTROL_MEAN_PRESSURE, control),
    ASP_CONSTANT(ASP_CONTROL_PENETRATION, control),
    ASP_CONSTANT(ASP_CONTROL_MEAN_GAP, control),
    ASP_CONSTANT(ASP_HISTORY_ITERATION, history_column),
    ASP_CONSTANT(ASP_HISTORY_EVALUATIONS, history_column),
    ASP_CONSTANT(ASP_HISTORY_TRANSFORMS, history_column),
    ASP_CONSTANT(ASP_HISTORY_SECONDS, history_column),
    ASP_CONSTANT(ASP_HISTORY_ERROR, history_column),
    ASP_CONSTANT(ASP_HISTORY_OBJECTIVE, history_column),
    ASP_CONSTANT(ASP_HISTORY_CONTACT_FRACTION, history_column),
    ASP_CONSTANT(ASP_TERMINATION_CONVERGED, termination),
    ASP_CONSTANT(ASP_TERMINATION_ITERATION_LIMIT, termination),
    ASP_CONSTANT(ASP_TERMINATION_CANCELLED, termination),
    ASP_CONSTANT(ASP_TERMINATION_STALLED, termination),
    ASP_CONSTANT(ASP_TERMINATION_BREAKDOWN, termination),
    ASP_CONSTANT(ASP_TERMINATION_SEPARATED, termination),
    ASP_CONSTANT(ASP_DETREND_MEAN, detrend),
    ASP_CONSTANT(ASP_DETREND_PLANE, detrend),
    ASP_CONSTANT(ASP_DETREND_CURVATURE, detrend),
    ASP_CONSTANT(ASP_REPORT_TERMINATION, report_key),
    ASP_CONSTANT(ASP_REPORT_CONVERGED, report_key),
    ASP_CONSTANT(ASP_REPORT_ITERATIONS, report_key),
    ASP_CONSTANT(ASP_REPORT_EVALUATIONS, report_key),
    ASP_CONSTANT(ASP_REPORT_TRANSFORMS, report_key),
    ASP_CONSTANT(ASP_REPORT_FINAL_ERROR, report_key),
    ASP_CONSTANT(ASP_REPORT_ELAPSED_SECONDS, report_key),
    ASP_CONSTANT(ASP_REPORT_HISTORY_LENGTH, report_key),
};
#undef ASP_CONSTANT

const char *family_name(Family family) {
  switch (family) {
    case Family::planning: return "an FFT planning (ASP_FFT_*)";
    case Family::normalisation: return "a normalisation (ASP_RMS_*)";
    case Family::scalar_key: return "a scalar result key";
    case Family::field: return "a field (ASP_FIELD_*)";
    case Family::control: return "a control (ASP_CONTROL_*)";
    case Family::history_column: return "a history column (ASP_HISTORY_*)";
    case Family::termination: return "a termination reason (ASP_TERMINATION_*)";
    case Family::detrend: return "a detrending mode (ASP_DETREND_*)";
    case Family::report_key: return "a solver report key (ASP_REPORT_*)";
  }
  return "unknown";
}

}  // namespace

void require_member(int value, Family expected, const char *argument) {
  const Constant *found = nullptr;
  for (const Constant &c : constants)
    if (c.value == value) found = &c;
  if (found != nullptr && found->family == expected) return;

  std::string message = std::string("argument '") + argument + "' must be " +
                        family_name(expected) + ", got " + std::to_string(value);
  if (found != nullptr)
    message += std::string(", which is ") + found->name + ", " + family_name(found->family);
  message += "; valid:";
  for (const Constant &c : constants)
    if (c.family == expected) message += std::string(" ") + c.name;
  throw Error(Status::invalid_argument, message);
}

}  // namespace capi
}  // namespace asp
