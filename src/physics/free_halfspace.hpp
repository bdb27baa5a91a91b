// SPDX-License-Identifier: GPL-2.0-or-later
// The free (non-periodic) elastic half-space in 2D: pressure acts only inside the grid's box,
// and the surface beyond it is free and unloaded, so that a measured, non-periodic topography
// is solved without images of itself.
//
// Displacement and pressure are related by Love's solution (Johnson, Contact Mechanics,
// section 3.2, eq. 3.25): a pressure p uniform over one pixel displaces the surface point at
// offset r by p C(r), C(r) = (1/(pi E*)) times the integral of 1/|r - s| over the pixel,
// i.e. u = (1/(pi E*)) sum over pixels of p times that integral. On the box, u = C * p is a
// linear (aperiodic) convolution; it becomes a periodic one on the grid zero-padded to
// 2nx x 2ny (Hockney's method), whose kernel holds C at the wrapped offsets. The spectral
// space is the half spectrum of that padded grid: forward zero-pads and transforms, backward
// transforms and crops, and the compliance is the (real) spectrum of the padded kernel with
// the 1/(4 nx ny) of the transform folded in, so that backward(compliance * forward(p)) = C p
// on the box, exactly up to round-off.
//
// What it does not offer:
//  - a stiffness of the box alone: the inverse of C restricted to the box is not a
//    convolution. The stiffness it offers is that of the padded surface, the inverse of the
//    padded compliance (whose spectrum is positive); a primal formulation minimises over the
//    displacement of the whole padded surface, and where the pressure K u vanishes outside
//    the box, u on the box is C times the pressure on the box;
//  - K~(0): there is no q = 0 ambiguity; the mean displacement of a load follows from the
//    elasticity (has_k0() is false). The stiffness under a uniform pressure on the box,
//    mean pressure over the mean displacement it makes, takes K~(0)'s place as a scale;
//  - 1D grids: under plane strain the displacement of a loaded free half-space is defined
//    only relative to a reference point (it grows like the logarithm of the distance), so
//    the constructor refuses them.
//
// The elastic energy is (a/2) sum p.C p over the box, all of it: there is no q = 0 term to
// report apart.
//
// On a distributed grid each process holds the padded rows of its box rows and the rows ny
// further down, and its columns of the padded spectrum (Grid::padded_fft).
//
// Memory: a padded work field (4 nx ny doubles, 32 bytes per pixel of the box), and on first
// use the compliance ((nx + 1) 2ny doubles, 16 bytes per pixel); each spectrum from
// make_spectrum holds (nx + 1) 2ny complex numbers, 32 bytes per pixel; the stiffness, made
// only for a primal formulation, 16 bytes per pixel.
#pragma once

#include "physics/substrate.hpp"

namespace asp {

class FreeHalfSpace final : public Substrate {
 public:
  // Throws Error(unsupported) naming 'grid' for a 1D grid, and Error(invalid_argument) naming
  // 'contact_modulus' when the influence coefficients of the grid, or their inverses, would
  // not be finite, normal doubles.
  FreeHalfSpace(const Grid &grid, double contact_modulus);

  SubstrateKind kind() const override { return SubstrateKind::free; }
  const char *name() const override { return "free half-space"; }
  MeanStiffness mean_stiffness() const override { return MeanStiffness::none; }
  const Grid &grid() const override { return grid_; }
  double contact_modulus() const override { return modulus_; }

  const SpectralLayout &layout() const override { return layout_; }
  Spectrum make_spectrum() const override;
  void forward(const double *field, Complex *spectrum) const override;
  void backward(Complex *spectrum, double *field) const override;
  double transform_points() const override {
    return static_cast<double>(padded_nx_) * static_cast<double>(padded_ny_);
  }
  // The padded grid: the box's pixels, then the rest of the padded rows next to the box
  // (nx per row), then the padded rows below it (2nx per row). On a distributed grid, this
  // process's part: its box rows J and the padded rows ny + J.
  std::int64_t surface_size() const override { return 4 * grid_.local_pixels(); }
  void surface_forward(const double *surface_field, Complex *spectrum) const override;
  void surface_backward(Complex *spectrum, double *surface_field) const override;

  const Field &normalised_compliance() const override;
  // The padded surface's stiffness (above).
  const Field &normalised_stiffness() const override;
  // 1/C(0): the pressure that, on one pixel alone, displaces that pixel by one length unit.
  double pixel_stiffness() const override { return pixel_stiffness_; }
  // The pixel's own influence coefficient, whose inverse is the scale.
  double self_compliance() const override { return 1.0 / pixel_stiffness_; }

  bool has_k0() const override { return false; }
  // Throw Error(unsupported) naming 'system': a free half-space has no K~(0).
  double k0() const override;
  void set_k0(double k0) override;
  // p / mean(C p) for a uniform p on the box.
  double uniform_pressure_stiffness() const override;

  double elastic_energy_of_pressure(const double *pressure) const override;

  // u = C p on the box.
  void displacement_from_pressure(const double *pressure, double *displacement) const;

 private:
  // Fills the padded work field with the kernel and takes its spectrum (made on first use).
  void make_kernel() const;

  const Grid &grid_;
  std::int64_t nx_, ny_;                // the box
  std::int64_t padded_nx_, padded_ny_;  // 2nx x 2ny
  SpectralLayout layout_;
  double modulus_;
  double pixel_stiffness_ = 0.0;
  // Work for the transforms: this process's padded rows (the first half for the box's
  // transforms, all of them for the surface's and the kernel's).
  mutable Field padded_;
  mutable Field compliance_;
  mutable Field stiffness_;
  mutable double uniform_pressure_stiffness_ = 0.0;
  // Whether they are made: flags, not the fields' sizes, since a process of a distributed
  // grid may hold no spectral entry, and the making is collective.
  mutable bool kernel_made_ = false, stiffness_made_ = false;
};

}  // namespace asp
