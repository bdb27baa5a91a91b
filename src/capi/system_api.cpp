// SPDX-License-Identifier: GPL-2.0-or-later
// asp_system_*: a contact problem, its parameters and its current state.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "capi/constants.hpp"
#include "capi/firewall.hpp"
#include "capi/handles.hpp"
#include "capi/text.hpp"
#include "core/checks.hpp"
#include "physics/resolution.hpp"

using asp::capi::Agreement;
using asp::capi::guarded;
using asp::capi::guarded_on;

namespace {
const asp::Grid *grid_of(const asp_system *system) {
  return system != nullptr ? &system->system->grid() : nullptr;
}
const asp::Grid *grid_of(const asp_grid *grid) {
  return grid != nullptr ? grid->grid.get() : nullptr;
}
}  // namespace

extern "C" {

int asp_system_create(const asp_grid *grid, double contact_modulus, asp_system **out) {
  if (out != nullptr) *out = nullptr;
  return guarded_on("asp_system_create", grid_of(grid), [&](Agreement &agreement) {
    asp::require_not_null(grid, "grid");
    asp::require_not_null(out, "out");
    agreement.checks_passed({contact_modulus}, "argument 'contact_modulus'");
    std::unique_ptr<asp_system> handle(new asp_system);
    handle->system.reset(new asp::System(grid->grid, contact_modulus));
    *out = handle.release();
  });
}

int asp_system_create_free(const asp_grid *grid, double contact_modulus, asp_system **out) {
  if (out != nullptr) *out = nullptr;
  return guarded_on("asp_system_create_free", grid_of(grid), [&](Agreement &agreement) {
    asp::require_not_null(grid, "grid");
    asp::require_not_null(out, "out");
    agreement.checks_passed({contact_modulus}, "argument 'contact_modulus'");
    std::unique_ptr<asp_system> handle(new asp_system);
    handle->system.reset(new asp::System(grid->grid, contact_modulus, asp::SubstrateKind::free));
    *out = handle.release();
  });
}

int asp_system_create_layer(const asp_grid *grid, double contact_modulus, double poisson_ratio,
                            double thickness, asp_system **out) {
  if (out != nullptr) *out = nullptr;
  return guarded_on("asp_system_create_layer", grid_of(grid), [&](Agreement &agreement) {
    asp::require_not_null(grid, "grid");
    asp::require_not_null(out, "out");
    agreement.checks_passed({contact_modulus, poisson_ratio, thickness},
                            "arguments 'contact_modulus', 'poisson_ratio' and 'thickness'");
    std::unique_ptr<asp_system> handle(new asp_system);
    handle->system.reset(new asp::System(
        grid->grid, std::make_unique<asp::LayerLaw>(contact_modulus, poisson_ratio, thickness)));
    *out = handle.release();
  });
}

void asp_system_destroy(asp_system *system) {
  // A system in use by a running call (destroyed from its callback) is left alone, and the
  // reason is the last error message.
  guarded("asp_system_destroy", [&] {
    if (system != nullptr) asp::capi::require_handle(system, "system");
    delete system;
  });
}

int asp_system_set_topography(asp_system *system, const double *heights, int64_t n) {
  return guarded_on("asp_system_set_topography", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    asp::require_array(heights, n, system->system->grid().local_pixels(), "heights");
    asp::capi::require_finite_heights(system->system->grid(), heights, n);
    agreement.checks_passed();
    system->system->set_topography(heights);
    system->has_topography = true;
  });
}

int asp_system_set_k0(asp_system *system, double k0) {
  return guarded_on("asp_system_set_k0", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    agreement.checks_passed({k0}, "argument 'k0'");
    system->system->set_k0(k0);
  });
}

int asp_system_set_adhesion(asp_system *system, double work_of_adhesion, double range) {
  return guarded_on("asp_system_set_adhesion", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    agreement.checks_passed({work_of_adhesion, range}, "arguments 'work_of_adhesion' and 'range'");
    system->system->set_adhesion(work_of_adhesion, range);
  });
}

int asp_system_set_soft_wall(asp_system *system, double gamma_r, double rho_r, double gamma_a,
                             double rho_a) {
  return guarded_on("asp_system_set_soft_wall", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    agreement.checks_passed({gamma_r, rho_r, gamma_a, rho_a},
                            "arguments 'gamma_r', 'rho_r', 'gamma_a' and 'rho_a'");
    system->system->set_soft_wall(gamma_r, rho_r, gamma_a, rho_a);
  });
}

int asp_system_set_lennard_jones(asp_system *system, double work_of_adhesion,
                                 double equilibrium_distance) {
  return guarded_on("asp_system_set_lennard_jones", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    agreement.checks_passed({work_of_adhesion, equilibrium_distance},
                            "arguments 'work_of_adhesion' and 'equilibrium_distance'");
    system->system->set_lennard_jones(work_of_adhesion, equilibrium_distance);
  });
}

int asp_system_set_hard_wall(asp_system *system) {
  return guarded_on("asp_system_set_hard_wall", grid_of(system), [&](Agreement &) {
    asp::capi::require_handle(system, "system");
    system->system->set_hard_wall();
  });
}

// The library's own signature of the callback must stay the header's.
static_assert(std::is_same<asp_potential_fn, asp::PotentialFunction>::value,
              "asp_potential_fn and asp::PotentialFunction differ");

int asp_system_set_potential(asp_system *system, asp_potential_fn fn, void *user_data,
                             int hard_wall) {
  return guarded_on("asp_system_set_potential", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    asp::require_not_null(reinterpret_cast<const void *>(fn), "fn");
    agreement.checks_passed({static_cast<double>(hard_wall != 0)}, "argument 'hard_wall'");
    system->system->set_user_potential(fn, user_data, hard_wall != 0);
  });
}

int asp_system_set_reference_pressure(asp_system *system, double reference_pressure) {
  return guarded_on(
      "asp_system_set_reference_pressure", grid_of(system), [&](Agreement &agreement) {
        asp::capi::require_handle(system, "system");
        agreement.checks_passed({reference_pressure}, "argument 'reference_pressure'");
        asp::require_non_negative(reference_pressure, "reference_pressure");
        system->system->set_reference_pressure(reference_pressure);
      });
}

int asp_system_reset(asp_system *system) {
  return guarded_on("asp_system_reset", grid_of(system), [&](Agreement &) {
    asp::capi::require_handle(system, "system");
    system->system->reset_state();
  });
}

int asp_system_get(const asp_system *system, int key, double *value) {
  return guarded_on("asp_system_get", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    asp::require_not_null(value, "value");
    asp::capi::require_member(key, asp::capi::Family::scalar_key, "key");
    // Keys differ in the sums and transforms they take: all processes must ask for the same.
    agreement.checks_passed({Agreement::bits(key)}, "argument 'key'");
    const asp::capi::BusyScope busy(system);  // the potential callback may run
    const asp::System &s = *system->system;
    const asp::ExponentialAdhesion *adhesion = asp::exponential_adhesion(s.interaction());
    double result = 0.0;
    switch (key) {
      case ASP_CONTACT_FRACTION: result = s.contact_fraction(); break;
      case ASP_MEAN_PRESSURE: result = s.mean_pressure(); break;
      case ASP_MEAN_GAP: result = s.mean_gap(); break;
      case ASP_ELASTIC_ENERGY: result = s.elastic_energy(); break;
      case ASP_PENETRATION: result = s.state().penetration; break;
      case ASP_TOTAL_FORCE: result = s.total_force(); break;
      case ASP_K0:
        if (!s.substrate().has_k0())
          throw asp::Error(asp::Status::unsupported,
                           "argument 'key' is ASP_K0, but the system is on a free "
                           "half-space, which has no K~(0) (no q = 0 ambiguity)");
        result = s.substrate().k0();
        break;
      case ASP_REFERENCE_PRESSURE: result = s.last_reference_pressure(); break;
      case ASP_MEAN_MODE_ENERGY: result = s.mean_mode_energy(); break;
      case ASP_ATTRACTIVE_FRACTION: result = s.attractive_fraction(); break;
      case ASP_REPULSIVE_FORCE: result = s.repulsive_force(); break;
      case ASP_ATTRACTIVE_FORCE: result = s.attractive_force(); break;
      case ASP_INTERACTION_ENERGY: result = s.interaction_energy(); break;
      case ASP_WORK_OF_ADHESION: result = adhesion != nullptr ? adhesion->work() : 0.0; break;
      case ASP_ADHESION_RANGE: result = adhesion != nullptr ? adhesion->range() : 0.0; break;
      case ASP_COMPRESSIVE_FRACTION: result = s.compressive_fraction(); break;
      default: throw asp::Error(asp::Status::internal, "scalar key without a getter");
    }
    if (!std::isfinite(result))
      throw asp::Error(asp::Status::invalid_argument,
                       "argument 'key' " + std::to_string(key) +
                           ": the result overflows a double in these units; rescale them");
    *value = result;
  });
}

int asp_system_get_field(const asp_system *system, int field, double *values, int64_t n) {
  return guarded_on("asp_system_get_field", grid_of(system), [&](Agreement &agreement) {
    asp::capi::require_handle(system, "system");
    const asp::System &s = *system->system;
    asp::capi::require_member(field, asp::capi::Family::field, "field");
    asp::require_array(values, n, s.grid().local_pixels(), "values");
    agreement.checks_passed();
    const asp::Field *source = nullptr;
    switch (field) {
      case ASP_FIELD_PRESSURE: source = &s.state().pressure; break;
      case ASP_FIELD_GAP: source = &s.state().gap; break;
      case ASP_FIELD_TOPOGRAPHY: source = &s.heights(); break;
      case ASP_FIELD_DISPLACEMENT: s.displacement(values); return;
      case ASP_FIELD_CONTACT: {
        // A soft wall's map calls the potential, which may be a user's callback.
        const asp::capi::BusyScope busy(system);
        s.contact_map(values);
        return;
      }
      default: throw asp::Error(asp::Status::internal, "field without a getter");
    }
    std::copy(source->begin(), source->end(), values);
  });
}

int asp_system_check_resolution(const asp_system *system, double *ratio, int *resolved,
                                char *buffer, int64_t size, int64_t *length) {
  // Reads parameters only, the same on every process: nothing collective, so no agreement.
  return guarded("asp_system_check_resolution", [&] {
    asp::capi::require_handle(system, "system");
    asp::require_at_least(size, 0, "size");
    if (size > 0) asp::require_not_null(buffer, "buffer");
    const asp::Resolution r = asp::resolution(*system->system);
    if (ratio != nullptr) *ratio = r.ratio;
    if (resolved != nullptr) *resolved = r.resolved ? 1 : 0;
    asp::capi::copy_text(r.sentence, buffer, size, length);
  });
}

}  // extern "C"
