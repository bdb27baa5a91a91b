// SPDX-License-Identifier: GPL-2.0-or-later
// What an elastic substrate offers the formulations: its spectral space (where the elastic
// operator is diagonal), the transforms into it and back, the operator K and its inverse as
// arrays over that space, and the observables that depend only on elasticity.
//
// A periodic half-space works on the grid's own half spectrum; a free (non-periodic) one on
// the half spectrum of a zero-padded grid of twice the size in each direction, with
// transforms that pad and crop. Formulations see only this interface.
#pragma once

#include <cstdint>

#include "core/aligned_field.hpp"
#include "core/grid.hpp"
#include "core/loops.hpp"
#include "core/spectral_layout.hpp"

namespace asp {

// Whether the substrate's box repeats (periodic) or is alone in an unloaded surface (free).
enum class SubstrateKind { periodic, free };
const char *substrate_name(SubstrateKind kind);

// A pass over a spectrum for the elastic operator's helpers below that also sums the
// quadratic form of the field it came from: s_k <- factor kernel_k s_k, returning factor
// times the sum over all modes of kernel_k |s_k|^2 as it was (Parseval, the kernel carrying
// the transform's 1/N: d.K d or d.K^-1 d of the field d with spectrum s), so that a Hessian
// product gives its curvature without a pass of its own. Stored entries count twice but for
// the single ones, which are read before the pass overwrites them.
double kernel_times_summing(const Reductions &reductions, const SpectralLayout &layout,
                            Complex *s, const double *kernel, double factor);


// What the substrate says about the stiffness K~(0) of its mean (q = 0) displacement mode:
// a convention that links mean pressure and mean displacement, which the user may set (the
// periodic half-space); a stiffness of the body itself (a layer on a rigid base); or none,
// the mean displacement following from the elasticity (the free half-space).
enum class MeanStiffness { convention, physical, none };

// What solvers and formulations ask of a substrate is what it can do, not which one it is:
// periodic() (a box whose operator is diagonal on the grid's own spectrum) and
// mean_stiffness(); name() is for reports and messages.
class Substrate {
 public:
  virtual ~Substrate() = default;
  virtual SubstrateKind kind() const = 0;
  bool periodic() const { return kind() == SubstrateKind::periodic; }
  virtual MeanStiffness mean_stiffness() const = 0;
  // "periodic half-space", "periodic elastic layer", "free half-space".
  virtual const char *name() const = 0;
  virtual const Grid &grid() const = 0;
  virtual double contact_modulus() const = 0;

  // The spectral space: its layout, and transforms from a field on the grid into it and back
  // (unnormalised: backward(forward(f)) = transform_points() f; backward destroys the
  // spectrum it reads). Buffers come from make_spectrum.
  virtual const SpectralLayout &layout() const = 0;
  virtual Spectrum make_spectrum() const = 0;
  virtual void forward(const double *field, Complex *spectrum) const = 0;
  virtual void backward(Complex *spectrum, double *field) const = 0;
  virtual double transform_points() const = 0;

  // The surface on which displacements live: the grid itself on a periodic substrate; on a
  // free one the zero-padded grid, the box and the unloaded surface around it. A field over
  // it holds the grid's pixels first, in the grid's order, then the points outside the box.
  // A primal formulation's displacement lives there, so that the pressure can vanish outside
  // the box. Transforms as above, between such fields and the same spectral space.
  virtual std::int64_t surface_size() const = 0;
  // Whether that surface reaches beyond the grid (a free substrate's does): the same on every
  // process of a distributed grid, also on one whose part of the surface is empty.
  bool surface_beyond_grid() const { return !periodic(); }
  virtual void surface_forward(const double *surface_field, Complex *spectrum) const = 0;
  virtual void surface_backward(Complex *spectrum, double *surface_field) const = 0;

  // K and its inverse on the spectral space, with the transform's normalisation folded in:
  // backward(compliance * forward(p)) = K^-1 p on the grid, and on the whole surface
  // surface_backward(stiffness * surface_forward(u)) = K u. On a free substrate K is the
  // inverse of the compliance of the padded surface: where K u vanishes outside the box,
  // u on the box is the displacement that the pressure K u on the box makes.
  virtual const Field &normalised_compliance() const = 0;
  virtual const Field &normalised_stiffness() const = 0;
  // The stiffness scale of one pixel, which turns gap residuals into pressures in the error
  // measure and sets the units of a solve (each substrate says which scale it uses).
  virtual double pixel_stiffness() const = 0;
  // The displacement of a pixel per unit pressure on it alone, every other pixel free: the
  // diagonal of K^-1. Its inverse is a pixel's stiffness when the surface around it relaxes,
  // below pixel_stiffness() on a periodic substrate (whose scale is the diagonal of K) and
  // equal to it on a free one (whose scale is this one's inverse).
  virtual double self_compliance() const = 0;

  // The mean (q = 0) displacement mode. A periodic half-space has no stiffness there of its
  // own: K~(0) is a convention that links mean pressure and mean displacement, and the user
  // may set it (asp_system_set_k0). A layer on a rigid base has its own, M/t: k0() gives it
  // and set_k0() throws Error(unsupported). A free substrate's mean displacement follows from
  // its elasticity, with nothing to choose: has_k0() is false and k0() and set_k0() throw
  // Error(unsupported).
  virtual bool has_k0() const = 0;
  virtual double k0() const = 0;
  virtual void set_k0(double k0) = 0;
  // The mean pressure over the mean displacement that a uniform pressure on the whole grid
  // makes: K~(0) on a periodic substrate. It links the scales of load and penetration.
  virtual double uniform_pressure_stiffness() const = 0;

  // ---- The elastic operator: a forward transform, one pass over the spectrum with the
  // kernel (the normalised compliance or stiffness above), a backward transform. Every
  // formulation and substrate applies K or K^-1 through these, whatever the layout (periodic
  // or padded, serial or distributed):
  //   apply_compliance(pressure, displacement): u = K^-1 p, from the grid onto the grid (on a
  //     free substrate the displacement of the box);
  //   compliance_onto_surface(pressure, surface_displacement): the same displacement over the
  //     whole surface (on a free substrate outside the box too, where no pressure acts);
  //   surface_compliance(surface_field, surface_out): K^-1 over the whole surface, the inverse
  //     of apply_stiffness (a preconditioner's, where the surface reaches beyond the grid);
  //   grid_stiffness(field, out): K of a field on the grid, read back on the grid (on a free
  //     substrate the field padded with zeros and the result cropped to the box: not the
  //     inverse of apply_compliance there, but a preconditioner's approximation of it);
  //   apply_stiffness(surface_displacement, surface_pressure): p = K u over the surface;
  //   stiffness_of_spectrum(spectrum, surface_pressure): the same from surface_forward(u),
  //     for a caller that holds the displacement's spectrum already (it is overwritten).
  // `spectrum` is a work buffer from make_spectrum(), or null for one made for the call: a
  // solver's loop passes its own, so that it allocates nothing; it holds no meaning after
  // the call. `pass(s, kernel, layout)` is the pass over the spectrum s: by default
  // KernelTimes, s_k <- factor kernel_k s_k; a caller that fuses other work into that pass
  // (a Parseval sum, a mode left out, a right-hand side) gives its own, which must leave in
  // s what the backward transform is to read. Collective on a distributed grid; the fields
  // must not overlap the substrate's own work arrays (they are the caller's).
  struct KernelTimes {
    double factor = 1.0;
    // Without the q = 0 mode (the entry the layout calls the mean, on the process holding
    // it): the mean-pressure controls, where the load sets the mean pressure instead.
    bool without_mean = false;
    void operator()(Complex *s, const double *kernel, const SpectralLayout &layout) const {
      const double f = factor;
      loops::for_each(layout.size(), [&](std::int64_t k) { s[k] *= f * kernel[k]; });
      if (without_mean && layout.is_mean(0)) s[0] = 0.0;
    }
  };
  template <class Pass = KernelTimes>
  void apply_compliance(const double *pressure, double *displacement,
                        Complex *spectrum = nullptr, Pass &&pass = Pass()) const {
    elastic_operator(normalised_compliance(), false, false, pressure, displacement, spectrum,
                     pass);
  }
  template <class Pass = KernelTimes>
  void compliance_onto_surface(const double *pressure, double *surface_displacement,
                               Complex *spectrum = nullptr, Pass &&pass = Pass()) const {
    elastic_operator(normalised_compliance(), false, true, pressure, surface_displacement,
                     spectrum, pass);
  }
  template <class Pass = KernelTimes>
  void surface_compliance(const double *surface_field, double *surface_out,
                          Complex *spectrum = nullptr, Pass &&pass = Pass()) const {
    elastic_operator(normalised_compliance(), true, true, surface_field, surface_out, spectrum,
                     pass);
  }
  template <class Pass = KernelTimes>
  void grid_stiffness(const double *field, double *out, Complex *spectrum = nullptr,
                      Pass &&pass = Pass()) const {
    elastic_operator(normalised_stiffness(), false, false, field, out, spectrum, pass);
  }
  template <class Pass = KernelTimes>
  void apply_stiffness(const double *surface_displacement, double *surface_pressure,
                       Complex *spectrum = nullptr, Pass &&pass = Pass()) const {
    elastic_operator(normalised_stiffness(), true, true, surface_displacement,
                     surface_pressure, spectrum, pass);
  }
  template <class Pass = KernelTimes>
  void stiffness_of_spectrum(Complex *spectrum, double *surface_pressure,
                             Pass &&pass = Pass()) const {
    pass(spectrum, normalised_stiffness().data(), layout());
    surface_backward(spectrum, surface_pressure);
  }

  // The elastic energy reported for a pressure on the grid: for a periodic substrate the
  // (A/2) sum over q != 0 of K~(q)|u^_q|^2 of u = K^-1 p, without the q = 0 term that
  // depends on the K~(0) convention; for a free one (a/2) sum p.K^-1 p, all of it.
  virtual double elastic_energy_of_pressure(const double *pressure) const = 0;

 private:
  template <class Pass>
  void elastic_operator(const Field &kernel, bool from_surface, bool onto_surface,
                        const double *in, double *out, Complex *spectrum, Pass &pass) const {
    // The kernel is fetched (and made, on first use) before the transforms: a free
    // substrate makes it in the work field that its transforms use.
    const double *k = kernel.data();
    Spectrum own;
    if (spectrum == nullptr) {
      own = make_spectrum();
      spectrum = own.data();
    }
    if (from_surface)
      surface_forward(in, spectrum);
    else
      forward(in, spectrum);
    pass(spectrum, k, layout());
    if (onto_surface)
      surface_backward(spectrum, out);
    else
      backward(spectrum, out);
  }
};

}  // namespace asp
