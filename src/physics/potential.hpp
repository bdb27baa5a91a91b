// SPDX-License-Identifier: GPL-2.0-or-later
// A soft interaction potential: an energy per unit area phi(g) of the gap, defined for every
// gap (also negative: a soft wall can be penetrated), with its slope and curvature. The
// equilibrium pressure on the substrate is -phi'(g).
//
// Potentials are evaluated over many gaps at once, so that a user's callback is called once
// per evaluation, not once per pixel. The built-in potentials are continued below a threshold
// gap by their quadratic Taylor expansion there, so that no exponential or power overflows
// and the energy is finite for any finite gap; each says where its threshold lies.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/reductions.hpp"

namespace asp {

class Potential {
 public:
  virtual ~Potential() = default;

  // phi, phi' and phi'' at the n gaps; d2phi may be null when it is not needed. Built-in
  // potentials cannot fail; a user's callback that fails or writes a value that is not finite
  // makes this throw Error(callback) naming what went wrong, with the outputs undefined.
  virtual void evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                        double *d2phi) const = 0;

  // The same potential in other units: gaps divided by `length`, energies per area by
  // `pressure * length`, so that the copy's phi(g / length) = phi(g) / (pressure * length).
  virtual std::unique_ptr<Potential> in_units(double length, double pressure) const = 0;

  // The scale of the pressures it exerts, for the units of a solve on a surface without
  // slope (the largest tensile stress of an adhesive potential, say); 0 if it has none that
  // can be known beforehand (a user's callback).
  virtual double pressure_scale() const = 0;
  // The scale of gaps over which it varies (its range).
  virtual double length_scale() const = 0;
  // For messages: what the potential is, with its parameters.
  virtual std::string description() const = 0;
};

// phi(g) = gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a) (thesis eqs. 12-13): an exponential
// repulsion of range rho_r/2 and an exponential attraction of range rho_a. Each exponential
// is continued below the gap where its exponent reaches `largest_exponent` (g = -20 rho_r for
// the repulsion, g = -40 rho_a for the attraction) by its quadratic Taylor expansion there.
//
// The exponentials are most of the cost of a solve's step: evaluate() computes each pixel's
// terms without a branch or a division, and with one range for both (rho_r = rho_a, as in the
// thesis) takes the repulsion's exponential as the square of the attraction's (6.3 ns per pixel
// against 16 for two exponentials through Exponential::at, measured on 512^2 gaps).
class SoftWallPotential final : public Potential {
 public:
  static constexpr double largest_exponent = 40.0;

  // gamma_r > 0, rho_r > 0, gamma_a >= 0, rho_a > 0, all finite (System checks them).
  SoftWallPotential(double repulsion, double repulsion_range, double attraction,
                    double attraction_range);

  void evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                double *d2phi) const override;
  std::unique_ptr<Potential> in_units(double length, double pressure) const override;
  // The largest tensile stress, max phi'(g) (gamma_a^2/(8 gamma_r rho) with one range rho),
  // or the repulsion's stress 2 gamma_r/rho_r at g = 0 without attraction.
  double pressure_scale() const override;
  double length_scale() const override;
  std::string description() const override;

  // One exponential c exp(-g/r), continued below g = -largest_exponent r.
  struct Exponential {
    double coefficient, range;
    struct Terms {
      double value, slope, curvature;
    };
    Terms at(double g) const;
  };
  Exponential repulsion() const { return repulsion_; }
  Exponential attraction() const { return attraction_; }

 private:
  template <bool with_curvature, bool one_range>
  void evaluate_terms(std::int64_t n, const double *gap, double *phi, double *dphi,
                      double *d2phi) const;

  Exponential repulsion_;   // gamma_r exp(-g/(rho_r/2))
  Exponential attraction_;  // -gamma_a exp(-g/rho_a)
  bool one_range_;          // rho_r = rho_a: the repulsion is the attraction's exponential squared
};

// phi(g) = (w/2) [(z0/g)^9 - 3 (z0/g)^3]: the 9-3 wall potential (a Lennard-Jones 12-6 pair
// potential integrated over a half-space) by its work of adhesion w and equilibrium distance
// z0, whose minimum is phi(z0) = -w. Below g = z0/2, where the repulsion (z0/g)^9 would soon
// overflow and is undefined at g <= 0, it is continued by its quadratic Taylor expansion at
// z0/2 (phi = 244 w, phi' = -4536 w/z0, phi'' = 91584 w/z0^2 there). That parabola's vertex
// lies above the threshold (at about 0.55 z0), so the continuation falls all the way up to
// z0/2 and the minimum stays at z0.
class LennardJonesPotential final : public Potential {
 public:
  // The continuation threshold as a fraction of z0.
  static constexpr double threshold = 0.5;

  // w > 0, z0 > 0, finite (System checks them).
  LennardJonesPotential(double work_of_adhesion, double equilibrium_distance);

  void evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                double *d2phi) const override;
  std::unique_ptr<Potential> in_units(double length, double pressure) const override;
  // The largest tensile stress, max phi'(g) over g > z0: at the inflection point
  // g = z0 (5/2)^(1/6), (27/10) (2/5)^(2/3) w/z0, about 1.466 w/z0.
  double pressure_scale() const override;
  double length_scale() const override { return equilibrium_distance_; }
  std::string description() const override;

  double work_of_adhesion() const { return work_; }
  double equilibrium_distance() const { return equilibrium_distance_; }

 private:
  double work_;
  double equilibrium_distance_;
};

// The signature of asp_potential_fn (asperity.h): phi, phi' and phi'' at n gaps at once, with
// the caller's data; d2phi may be null; 0 to go on.
using PotentialFunction = int (*)(std::int64_t n, const double *gap, double *phi, double *dphi,
                                  double *d2phi, void *user_data);

// A user's potential, given as a callback in physical units. evaluate() calls it once for all
// gaps and throws Error(callback) if it returns non-zero or writes a value that is not finite.
// A copy in other units (in_units) converts around the call: the gaps to physical lengths
// before, phi, phi' and phi'' to the copy's units after.
class CallbackPotential final : public Potential {
 public:
  // function not null (System checks it). On a distributed grid, `processes` are its
  // reductions: a callback that fails on one process then fails the evaluation on all
  // (the others report that another process's callback failed), so that none waits forever.
  CallbackPotential(PotentialFunction function, void *user_data,
                    const Reductions *processes = nullptr);

  void evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                double *d2phi) const override;
  std::unique_ptr<Potential> in_units(double length, double pressure) const override;
  // Neither is known beforehand: 0.
  double pressure_scale() const override { return 0.0; }
  double length_scale() const override { return 0.0; }
  std::string description() const override { return "user potential (a callback)"; }

 private:
  CallbackPotential(PotentialFunction function, void *user_data, const Reductions *processes,
                    double length, double pressure);
  // The failure of this process's evaluation, if any (the message), else "".
  std::string failure(std::int64_t n, const double *physical, const double *phi,
                      const double *dphi, const double *d2phi, int status) const;

  PotentialFunction function_;
  void *user_data_;
  const Reductions *processes_;
  // A gap of this potential is `length_` physical lengths; a pressure `pressure_` physical
  // pressures (1 and 1 for the physical potential itself).
  double length_ = 1.0;
  double pressure_ = 1.0;
  // The physical gaps of a copy in other units, kept between calls so that a solve does not
  // allocate them at every evaluation. A potential serves one system or one solve, used from
  // one thread at a time (as its handle is), so no lock guards it.
  mutable std::vector<double> physical_gap_;
};

}  // namespace asp
