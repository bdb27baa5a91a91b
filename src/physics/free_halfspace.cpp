// SPDX-License-Identifier: GPL-2.0-or-later
#include "physics/free_halfspace.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "core/checks.hpp"
#include "core/error.hpp"
#include "core/loops.hpp"

namespace asp {

namespace {
constexpr double pi = 3.14159265358979323846;

bool normal(double v) { return std::isfinite(v) && v >= DBL_MIN; }

// The integral of 1/r over the rectangle [0, x] x [0, y] (signed by the signs of x and y) up
// to terms in one variable only, which cancel between the four corners of a rectangle:
// x asinh(y/|x|) + y asinh(x/|y|). With x ln(y + r) = x ln|x| + x asinh(y/|x|), this is
// Johnson's eq. 3.25 in a form without the cancellation of y + r for y < 0. Corners of
// pixels lie at half-integer offsets, never on an axis.
double corner_integral(double x, double y) {
  return x * std::asinh(y / std::fabs(x)) + y * std::asinh(x / std::fabs(y));
}

// The integral of 1/r over the pixel at offset (i, j) from the point, in units of the pixel
// width dx: coordinates in units of dx, aspect = dy/dx.
double pixel_integral(double i, double j, double aspect) {
  const double x1 = i - 0.5, x2 = i + 0.5, y1 = aspect * (j - 0.5), y2 = aspect * (j + 0.5);
  return corner_integral(x2, y2) - corner_integral(x1, y2) - corner_integral(x2, y1) +
         corner_integral(x1, y1);
}
}  // namespace

FreeHalfSpace::FreeHalfSpace(const Grid &grid, double contact_modulus)
    : grid_(grid),
      nx_(grid.nx()),
      ny_(grid.ny()),
      padded_nx_(2 * grid.nx()),
      padded_ny_(2 * grid.ny()),
      layout_(grid.padded_spectrum()),
      modulus_(contact_modulus) {
  if (grid.dimension() != 2)
    throw Error(Status::unsupported,
                "argument 'grid' is 1D: a free (non-periodic) half-space needs a 2D grid. "
                "Under plane strain the displacement of a loaded free half-space grows like "
                "the logarithm of the distance and is defined only relative to a reference "
                "point, so a 1D free substrate has no unique force-penetration relation; use a "
                "periodic system in 1D");
  require_positive(contact_modulus, "contact_modulus");

  // The largest coefficient (a pixel on itself), the smallest (the farthest offset of the
  // padded grid), their sum over the padded grid (at most 4N times the largest) and the
  // stiffness scales that follow must be finite, normal doubles.
  const double dx = grid.lx() / static_cast<double>(nx_);
  const double aspect = (grid.ly() / static_cast<double>(ny_)) / dx;
  const double factor = dx / (pi * modulus_);
  const double self = factor * pixel_integral(0.0, 0.0, aspect);
  const double farthest = factor * pixel_integral(static_cast<double>(nx_),
                                                  static_cast<double>(ny_), aspect);
  const double n_padded = transform_points();
  pixel_stiffness_ = 1.0 / self;
  if (!normal(self) || !normal(farthest) || !normal(pixel_stiffness_) ||
      !normal(n_padded * self) || !normal(1.0 / (n_padded * self)))
    throw Error(Status::invalid_argument,
                "argument 'contact_modulus' is " + format_number(contact_modulus) +
                    ": on this grid the influence coefficients of a pixel range from " +
                    format_number(farthest) + " to " + format_number(self) +
                    ", which doubles cannot hold with their inverses and sums; rescale the "
                    "units");
  // The padded work field, before anything is planned or transformed: a box too large for
  // memory fails here, when the system is made.
  padded_ = Field(static_cast<std::size_t>(4 * grid.local_pixels()), 0.0);
}

Spectrum FreeHalfSpace::make_spectrum() const {
  return Spectrum(static_cast<std::size_t>(layout_.size()));
}

void FreeHalfSpace::forward(const double *field, Complex *spectrum) const {
  // The padded transform without the work of its zero rows (PaddedRealFft).
  grid_.padded_fft().forward(field, spectrum, padded_.data());
}

void FreeHalfSpace::backward(Complex *spectrum, double *field) const {
  grid_.padded_fft().backward(spectrum, field, padded_.data());
}

void FreeHalfSpace::surface_forward(const double *surface_field, Complex *spectrum) const {
  // Box rows, then the rest of those rows, then the rows below, into the padded rows.
  double *pad = padded_.data();
  const std::int64_t width = padded_nx_, rows = grid_.local_rows(), box = nx_ * rows;
  const double *beside = surface_field + box;
  const double *below = beside + box;
  for (std::int64_t j = 0; j < rows; ++j) {
    std::copy(surface_field + nx_ * j, surface_field + nx_ * (j + 1), pad + width * j);
    std::copy(beside + nx_ * j, beside + nx_ * (j + 1), pad + width * j + nx_);
  }
  std::copy(below, below + width * rows, pad + width * rows);
  grid_.padded_fft().surface_forward(pad, spectrum);
}

void FreeHalfSpace::surface_backward(Complex *spectrum, double *surface_field) const {
  double *pad = padded_.data();
  grid_.padded_fft().surface_backward(spectrum, pad);
  const std::int64_t width = padded_nx_, rows = grid_.local_rows(), box = nx_ * rows;
  double *beside = surface_field + box;
  double *below = beside + box;
  for (std::int64_t j = 0; j < rows; ++j) {
    std::copy(pad + width * j, pad + width * j + nx_, surface_field + nx_ * j);
    std::copy(pad + width * j + nx_, pad + width * (j + 1), beside + nx_ * j);
  }
  std::copy(pad + width * rows, pad + width * 2 * rows, below);
}

void FreeHalfSpace::make_kernel() const {
  // C at offset (i, j), i in [0, nx], j in [0, ny], from the corner integrals of two rows of
  // corners at a time: row l holds F((k + 1/2) dx, (l + 1/2) dy) for k in [0, nx], and
  // F(-x, y) = F(x, -y) = -F(x, y) gives the corners at -1/2. The kernel is even in each
  // axis; offset i sits at index i and 2nx - i of the padded grid (the offset nx, which no
  // two pixels of the box have, at nx), so that its spectrum is real. This process fills its
  // padded rows: those of its box rows J (offset J) and the rows ny + J (offset ny - J).
  const double dx = grid_.lx() / static_cast<double>(nx_);
  const double aspect = (grid_.ly() / static_cast<double>(ny_)) / dx;
  const double factor = dx / (pi * modulus_);
  const auto columns = static_cast<std::size_t>(nx_ + 1);
  // d_l(i) = F(x_{i+1/2}, y_{l+1/2}) - F(x_{i-1/2}, y_{l+1/2}); C(i, j) = d_j(i) - d_{j-1}(i).
  std::vector<double> below(columns), above(columns);
  const auto differences = [&](std::int64_t l, std::vector<double> &d) {
    const double y = aspect * (static_cast<double>(l) + 0.5);
    double left = -corner_integral(0.5, y);
    for (std::size_t k = 0; k < columns; ++k) {
      const double right = corner_integral(static_cast<double>(k) + 0.5, y);
      d[k] = right - left;
      left = right;
    }
  };
  double *pad = padded_.data();
  const std::int64_t rows = grid_.local_rows(), first = grid_.row_offset();
  // The kernel rows of offsets first_offset, first_offset + 1, ... (count of them), each
  // into padded row row_of(offset); returns the sum over them of the offset's pixel pairs
  // times C, for the mean displacement of a unit pressure on the box: the sum over offsets of
  // C times the number of pixel pairs at that offset, (nx - |i|)(ny - |j|), over N.
  const auto fill = [&](std::int64_t first_offset, std::int64_t count, auto row_of) {
    double pairs_sum = 0.0;
    if (count == 0) return pairs_sum;
    differences(first_offset, above);
    if (first_offset == 0)
      for (std::size_t k = 0; k < columns; ++k) below[k] = -above[k];
    else
      differences(first_offset - 1, below);
    for (std::int64_t j = first_offset; j < first_offset + count; ++j) {
      if (j > first_offset) {
        std::swap(below, above);
        differences(j, above);
      }
      double *row = pad + padded_nx_ * row_of(j);
      const double pairs_y = j == ny_ ? 0.0 : (j == 0 ? 1.0 : 2.0) * static_cast<double>(ny_ - j);
      double row_sum = 0.0;
      for (std::int64_t i = 0; i <= nx_; ++i) {
        const double c = factor * (above[static_cast<std::size_t>(i)] -
                                   below[static_cast<std::size_t>(i)]);
        row[i] = c;
        row[(padded_nx_ - i) % padded_nx_] = c;
        const double pairs_x =
            i == nx_ ? 0.0 : (i == 0 ? 1.0 : 2.0) * static_cast<double>(nx_ - i);
        row_sum += pairs_x * c;
      }
      pairs_sum += pairs_y * row_sum;
    }
    return pairs_sum;
  };
  // Box rows J: offsets J, local row J - first. The rows ny + J: offsets ny - J, from
  // ny - (first + rows - 1) up to ny - first, local row rows + J - first (their pairs are
  // those of the box rows of the same offset, counted there).
  double displacement_sum =
      fill(first, rows, [&](std::int64_t offset) { return offset - first; });
  fill(ny_ - (first + rows - 1), rows,
       [&](std::int64_t offset) { return rows + (ny_ - offset) - first; });
  grid_.reductions().combine_sums(&displacement_sum, 1);
  const double n = static_cast<double>(grid_.n_pixels());
  const double mean_displacement = displacement_sum / n;

  Spectrum s = make_spectrum();
  grid_.padded_fft().surface_forward(pad, s.data());
  Field c(static_cast<std::size_t>(layout_.size()));
  const double inverse_points = 1.0 / transform_points();
  loops::for_each(layout_.size(), [&](std::int64_t k) { c[k] = s[k].real() * inverse_points; });
  compliance_ = std::move(c);
  uniform_pressure_stiffness_ = 1.0 / mean_displacement;
  kernel_made_ = true;
}

const Field &FreeHalfSpace::normalised_compliance() const {
  if (!kernel_made_) make_kernel();
  return compliance_;
}

const Field &FreeHalfSpace::normalised_stiffness() const {
  if (!stiffness_made_) {
    // 1/C~ with the 1/N of the transform: 1/(N^2 c) for the normalised compliance c = C~/N.
    // The padded kernel's spectrum is positive (it is that of 1/r smoothed over a pixel,
    // wrapped), which the constructor of a primal formulation relies on; checked here.
    const Field &c = normalised_compliance();
    const double n = transform_points();
    Field s(c.size());
    bool positive = true;
    for (std::size_t k = 0; k < c.size(); ++k) {
      s[k] = 1.0 / (n * n * c[k]);
      positive = positive && c[k] > 0.0 && std::isfinite(s[k]);
    }
    // Every process learns whether any entry failed, so that all throw together.
    double failed = positive ? 0.0 : 1.0;
    grid_.reductions().combine_maxima(&failed, 1);
    if (failed != 0.0)
      throw Error(Status::internal,
                  "the padded compliance of this free half-space has a spectral entry that is "
                  "not positive, or whose inverse is not finite; its stiffness does not exist");
    stiffness_ = std::move(s);
    stiffness_made_ = true;
  }
  return stiffness_;
}

double FreeHalfSpace::uniform_pressure_stiffness() const {
  if (!kernel_made_) make_kernel();
  return uniform_pressure_stiffness_;
}

namespace {
[[noreturn]] void refuse_k0() {
  throw Error(Status::unsupported,
              "argument 'system' is on a free half-space, which has no K~(0): there is no "
              "q = 0 ambiguity, the mean displacement follows from the elasticity");
}
}  // namespace

double FreeHalfSpace::k0() const { refuse_k0(); }

void FreeHalfSpace::set_k0(double) { refuse_k0(); }

void FreeHalfSpace::displacement_from_pressure(const double *pressure,
                                               double *displacement) const {
  apply_compliance(pressure, displacement);
}

double FreeHalfSpace::elastic_energy_of_pressure(const double *pressure) const {
  // (a/2) sum p.C p = (a/2) sum over the padded spectrum of C~|P|^2 (Parseval; the padded
  // pressure is zero outside the box). The pressure is divided by its largest magnitude
  // first, so that squares cannot overflow for any representable field.
  const std::int64_t n = grid_.local_pixels();
  const double largest = loops::maximum(grid_.reductions(), n,
                                        [&](std::int64_t i) { return std::fabs(pressure[i]); });
  if (!(largest > 0.0)) return 0.0;
  const Field &compliance = normalised_compliance();
  Field p = grid_.make_field();
  loops::for_each(n, [&](std::int64_t i) { p[i] = pressure[i] / largest; });
  Spectrum s = make_spectrum();
  forward(p.data(), s.data());
  const double *c = compliance.data();
  double sum = layout_.weighted_sum([&](std::int64_t k) { return c[k] * std::norm(s[k]); });
  grid_.reductions().combine_sums(&sum, 1);
  return 0.5 * grid_.pixel_area() * sum * largest * largest;
}

}  // namespace asp
