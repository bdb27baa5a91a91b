// SPDX-License-Identifier: GPL-2.0-or-later
// The stiffness law K~(q) of a periodic substrate: p~(q) = K~(q) u~(q) for each wavevector
// q != 0, and what the body itself says about the mean (q = 0) mode. A periodic substrate
// asks its law once per mode when it builds its compliance and stiffness arrays; nothing
// calls it per pixel. A new periodic substrate is a new law.
#pragma once

#include <memory>
#include <string>

namespace asp {

class StiffnessLaw {
 public:
  virtual ~StiffnessLaw() = default;
  // K~(q) for |q| = q > 0: positive and finite wherever the law was accepted.
  virtual double at(double q) const = 0;
  // The body's own K~(0), the mean pressure over the mean displacement of a uniform
  // pressure, when it has one (a layer on a rigid base); 0 when it has none (the half-space,
  // whose K~(0) is then a convention the substrate chooses and the user may change).
  virtual double at_zero() const = 0;
  // The substrate's name in reports and messages ("periodic half-space"), and the law as a
  // formula ("E*|q|/2").
  virtual const char *name() const = 0;
  virtual const char *formula() const = 0;
  // E*, the contact modulus E/(1 - nu^2) of the body.
  virtual double contact_modulus() const = 0;
  // The same law, for the same body on another grid (nested grids' coarser levels).
  virtual std::unique_ptr<const StiffnessLaw> copy() const = 0;
};

// The half-space, K~(q) = E*|q|/2 (thesis eq. 5), without a K~(0) of its own.
class HalfSpaceLaw final : public StiffnessLaw {
 public:
  // E* > 0 and finite (the substrate checks what its grid makes of it).
  explicit HalfSpaceLaw(double contact_modulus) : modulus_(contact_modulus) {}
  double at(double q) const override { return 0.5 * modulus_ * q; }
  double at_zero() const override { return 0.0; }
  const char *name() const override { return "periodic half-space"; }
  const char *formula() const override { return "E*|q|/2"; }
  double contact_modulus() const override { return modulus_; }
  std::unique_ptr<const StiffnessLaw> copy() const override {
    return std::make_unique<HalfSpaceLaw>(*this);
  }

 private:
  double modulus_;
};

// An elastic layer of thickness t bonded (no slip) to a rigid base, its top free of shear
// (Carbone & Mangialardi, J. Mech. Phys. Solids 56 (2008), the layer's Green's function):
// with s = |q| t and kappa = 3 - 4 nu,
//   K~(q) = (E*|q|/2) [kappa cosh 2s + 2 s^2 + (1 + kappa^2)/2] / [kappa sinh 2s - 2s],
// which tends to the half-space's E*|q|/2 for s -> infinity (the difference falls as
// s^2 exp(-2s)) and to the uniaxial-strain stiffness M/t for s -> 0, with
// M = E(1 - nu)/((1 + nu)(1 - 2 nu)) and E = E*(1 - nu^2): K~(0) = M/t is the body's own.
// nu = 1/2 (incompressible) makes M infinite, so 0 <= nu < 1/2.
class LayerLaw final : public StiffnessLaw {
 public:
  // Throws Error(invalid_argument) naming 'contact_modulus', 'poisson_ratio' or 'thickness'
  // when E* or t is not positive and finite, or nu is outside [0, 1/2), or M/t is not a
  // finite, normal double.
  LayerLaw(double contact_modulus, double poisson_ratio, double thickness);
  double at(double q) const override;
  double at_zero() const override { return uniaxial_modulus_ / thickness_; }
  const char *name() const override { return "periodic elastic layer"; }
  const char *formula() const override {
    return "the layer's (E*|q|/2)(kappa cosh 2qt + 2(qt)^2 + (1 + kappa^2)/2)/(kappa sinh 2qt "
           "- 2qt)";
  }
  double contact_modulus() const override { return modulus_; }
  std::unique_ptr<const StiffnessLaw> copy() const override {
    return std::make_unique<LayerLaw>(*this);
  }
  double poisson_ratio() const { return poisson_; }
  double thickness() const { return thickness_; }
  // M = E(1 - nu)/((1 + nu)(1 - 2 nu)), the modulus of uniaxial strain.
  double uniaxial_modulus() const { return uniaxial_modulus_; }

 private:
  double modulus_, poisson_, thickness_, uniaxial_modulus_;
};

}  // namespace asp
