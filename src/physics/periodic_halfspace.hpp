// SPDX-License-Identifier: GPL-2.0-or-later
// A periodic elastic substrate: p~(q) = K~(q) u~(q) with K~(q) its stiffness law
// (stiffness_law.hpp), by default the half-space's E*|q|/2 (thesis eq. 5).
//
// The q = 0 mode has no stiffness in a periodic half-space; a finite K~(0) links mean pressure
// and mean displacement so that penetration control is well posed. Its default is the mean of
// K~ at the lowest non-zero wavevector along each axis that has more than one pixel (the
// thesis's choice; E* pi/lx in 1D). A law with a K~(0) of its own (the layer on a rigid base)
// uses that, and it cannot be changed.
#pragma once

#include <memory>

#include "physics/stiffness_law.hpp"
#include "physics/substrate.hpp"

namespace asp {

class PeriodicHalfSpace final : public Substrate {
 public:
  // Throws Error(invalid_argument) naming 'contact_modulus' when the stiffness of some mode
  // of the grid, or its inverse, would not be a finite, normal double.
  PeriodicHalfSpace(const Grid &grid, double contact_modulus);
  // The same with any stiffness law (not null).
  PeriodicHalfSpace(const Grid &grid, std::unique_ptr<const StiffnessLaw> law);

  SubstrateKind kind() const override { return SubstrateKind::periodic; }
  const char *name() const override { return law_->name(); }
  MeanStiffness mean_stiffness() const override {
    return law_->at_zero() > 0.0 ? MeanStiffness::physical : MeanStiffness::convention;
  }
  const StiffnessLaw &law() const { return *law_; }
  const Grid &grid() const override { return grid_; }
  double contact_modulus() const override { return modulus_; }

  const SpectralLayout &layout() const override { return layout_; }
  Spectrum make_spectrum() const override { return grid_.make_spectrum(); }
  void forward(const double *field, Complex *spectrum) const override;
  void backward(Complex *spectrum, double *field) const override;
  double transform_points() const override { return static_cast<double>(grid_.n_pixels()); }
  // The surface is the grid (this process's pixels of it).
  std::int64_t surface_size() const override { return grid_.local_pixels(); }
  void surface_forward(const double *field, Complex *spectrum) const override {
    forward(field, spectrum);
  }
  void surface_backward(Complex *spectrum, double *field) const override {
    backward(spectrum, field);
  }

  const Field &normalised_compliance() const override;
  const Field &normalised_stiffness() const override;
  double pixel_stiffness() const override { return pixel_stiffness_; }
  double self_compliance() const override { return self_compliance_; }

  bool has_k0() const override { return true; }
  double k0() const override { return k0_; }
  // Throws Error(unsupported) naming 'k0' when the law has a K~(0) of its own.
  void set_k0(double k0) override;
  // A uniform pressure moves only the q = 0 mode.
  double uniform_pressure_stiffness() const override { return k0_; }

  double elastic_energy_of_pressure(const double *pressure) const override;
  // (A/2) sum over q != 0 of K~(q)|u^_q|^2: the energy of a displacement without the q = 0
  // term, which depends on the K~(0) convention.
  double elastic_energy(const double *displacement) const;

  // u = K^-1 p and p = K u on the grid.
  void displacement_from_pressure(const double *pressure, double *displacement) const;
  void pressure_from_displacement(const double *displacement, double *pressure) const;

 private:
  double stiffness_at(double q) const { return q > 0.0 ? law_->at(q) : k0_; }

  const Grid &grid_;
  std::unique_ptr<const StiffnessLaw> law_;
  SpectralLayout layout_;
  double modulus_;
  double k0_;
  double pixel_stiffness_ = 0.0;
  double nonzero_stiffness_sum_ = 0.0;  // sum over q != 0 of weight * K~(q)
  double nonzero_compliance_sum_ = 0.0;  // sum over q != 0 of weight / K~(q)
  double self_compliance_ = 0.0;
  // Made on first use (a solver that needs neither pays for neither).
  mutable Field compliance_;  // 1/(N K~) on the half spectrum
  mutable Field stiffness_;   // K~/N
};

}  // namespace asp
