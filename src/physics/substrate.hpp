// What an elastic substrate offers the formulations: its spectral space (where the elastic
// operator is diagonal), the transforms into it and back, the operator K and its inverse as
// arrays over that space, and the observables that depend only on elasticity.
//
// A periodic half-space works on the grid's own half spectrum; a non-periodic one will work
// on a zero-padded grid of twice the size, with transforms that pad and crop. Formulations see
// only this interface.
#pragma once

#include <cstdint>

#include "core/aligned_field.hpp"
#include "core/grid.hpp"
#include "core/spectral_layout.hpp"

namespace asp {

enum class SubstrateKind { periodic };
const char *substrate_name(SubstrateKind kind);

class Substrate {
 public:
  virtual ~Substrate() = default;
  virtual SubstrateKind kind() const = 0;
  virtual const Grid &grid() const = 0;
  virtual double contact_modulus() const = 0;

  // The spectral space: its layout, and transforms from a field on the grid into it and back
  // (unnormalised; backward destroys the spectrum it reads). Buffers come from make_spectrum.
  virtual const SpectralLayout &layout() const = 0;
  virtual Spectrum make_spectrum() const = 0;
  virtual void forward(const double *field, Complex *spectrum) const = 0;
  virtual void backward(Complex *spectrum, double *field) const = 0;

  // K and its inverse on the spectral space, with the transform's normalisation folded in:
  // backward(compliance * forward(p)) = K^-1 p and backward(stiffness * forward(u)) = K u.
  virtual const Field &normalised_compliance() const = 0;
  virtual const Field &normalised_stiffness() const = 0;
  // The diagonal of K in real space: the pressure that a unit displacement of one pixel alone
  // needs. It turns gap residuals into pressures in the error measure.
  virtual double pixel_stiffness() const = 0;

  // The stiffness of the mean (q = 0) displacement mode, and setting it (see
  // asp_system_set_k0).
  virtual double k0() const = 0;
  virtual void set_k0(double k0) = 0;

  // (A/2) sum over q != 0 of K~(q)|u^_q|^2: the energy of the deformation without the q = 0
  // term, which depends on the K~(0) convention.
  virtual double elastic_energy(const double *displacement) const = 0;
};

}  // namespace asp
