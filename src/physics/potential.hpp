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
class SoftWallPotential final : public Potential {
 public:
  static constexpr double largest_exponent = 40.0;

  // gamma_r > 0, rho_r > 0, gamma_a >= 0, rho_a > 0, all finite (System checks them).
  SoftWallPotential(double repulsion, double repulsion_range, double attraction,
                    double attraction_range);

  void evaluate(std::int64_t n, const double *gap, double *phi, double *dphi,
                double *d2phi) const override;
  std::unique_ptr<Potential> in_units(double length, double pressure) const override;
  // The largest tensile stress of the attraction alone, gamma_a/rho_a, or the repulsion's
  // stress 2 gamma_r/rho_r at g = 0 without attraction.
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
  Exponential repulsion_;   // gamma_r exp(-g/(rho_r/2))
  Exponential attraction_;  // -gamma_a exp(-g/rho_a)
};

}  // namespace asp
