// The periodic elastic half-space: p~(q) = K~(q) u~(q) with K~(q) = E*|q|/2 (thesis eq. 5).
//
// The q = 0 mode has no stiffness in a periodic half-space; a finite K~(0) links mean pressure
// and mean displacement so that penetration control is well posed. Its default is the mean of
// K~ at the lowest non-zero wavevector along each axis that has more than one pixel (the
// thesis's choice; E* pi/lx in 1D).
#pragma once

#include "core/aligned_field.hpp"
#include "core/grid.hpp"

namespace asp {

class PeriodicHalfSpace {
 public:
  PeriodicHalfSpace(const Grid &grid, double contact_modulus);

  const Grid &grid() const { return grid_; }
  double contact_modulus() const { return modulus_; }
  double k0() const { return k0_; }
  void set_k0(double k0);

  // K~ of half-spectrum entry (kx, ky); K~(0) = k0.
  double stiffness(std::int64_t kx, std::int64_t ky) const;
  // The stiffness of one pixel: the pressure that a unit displacement of that pixel alone
  // needs, i.e. the diagonal of K in real space, mean over all q of K~(q).
  double pixel_stiffness() const;

  // u = K^-1 p and p = K u. `scratch` holds grid().n_spectral() entries.
  void displacement_from_pressure(const double *pressure, double *displacement,
                                  Complex *scratch) const;
  void pressure_from_displacement(const double *displacement, double *pressure,
                                  Complex *scratch) const;
  // E_el = (A/2) sum_q K~(q) |u^_q|^2, u^ the DFT divided by the pixel count (thesis eq. 6).
  double elastic_energy(const double *displacement, Complex *scratch) const;

  // 1/(N K~(q)) on the half spectrum: the compliance with the FFT normalisation folded in, so
  // that backward(compliance * forward(p)) is u in one pass. Made on first use.
  const Field &normalised_compliance() const;

 private:
  double default_k0() const;
  void apply_kernel(const double *in, double *out, Complex *scratch, bool inverse) const;

  const Grid &grid_;
  double modulus_;
  double k0_;
  mutable Field compliance_;
  mutable double pixel_stiffness_ = -1.0;  // negative: not computed yet
};

}  // namespace asp
