// SPDX-License-Identifier: GPL-2.0-or-later
// The dual (pressure) formulation that Polonsky & Keer runs on, checked against finite
// differences and against its own definition (dual_formulation.hpp):
//     Pi(x) = (1/2) x.A x - x.b,   gradient A x - b = the scaled gap,
// with x = p/P the scaled pressure, A = k K^-1 (k the pixel stiffness, the diagonal of K) and
// b = (h - max h + delta)/L, L = P/k, the value in units of a P^2/k. Under penetration control
// delta is the given penetration; under mean-pressure control it is the Lagrange multiplier of
// the fixed mean (its current estimate), which shifts the gradient by a constant and the value
// by a multiple of sum x, both irrelevant on the feasible set; the error measure then centres
// the gap on the contact set.
//
// Tolerances. Pi is quadratic, so central differences (of the value for the gradient, of the
// gradient for the Hessian product) and the second-order Taylor expansion are exact in exact
// arithmetic for any step h: only rounding is left. One evaluation rounds with an absolute
// error of a few eps (log2 N + sqrt N) times the size of its terms, M = sum |x_i| (|(Ax)_i|/2 +
// |b_i|) for the value, max |Ax| + max |b| for a gradient entry: about 1e-14 relative on these
// grids. A central difference divides that by h. All rounding checks below therefore use
// 1e-12 times the size of the terms that were rounded, divided by h where a difference quotient
// is taken; with h = 1e-3 that is 1e-9 relative to the value, with h = 1 it is 1e-12. The
// errors seen are below 3e-15 of those sizes, 1e-14 at worst (the Rayleigh quotient of the
// uniform field, which attains the largest eigenvalue), so the margin is 100 or more; an error
// of 1e-10 relative in the value or the Hessian product, or 1e-9 in the spectrum update, fails
// them. The O(N^2) reference (a plain real DFT of K^-1) is exact to the same 1e-12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/random.hpp"
#include "physics/topography.hpp"
#include "scene.hpp"
#include "formulations/dual_formulation.hpp"

namespace {
using asp::Control;
using asp_test::pi;
using Vector = std::vector<double>;

constexpr double rounding = 1e-12;  // see the header comment
constexpr double modulus = 2.0;

// ---- scenes --------------------------------------------------------------------------------

struct Scene {
  const char *name;
  int dimension;
  std::int64_t nx, ny;
  double lx, ly;
  bool rough;  // a self-affine surface, else a sinusoid with two periods along x (and one along y)
};

struct Case {
  Scene scene;
  Control control;
};

void PrintTo(const Case &c, std::ostream *out) {
  *out << c.scene.name << (c.control == Control::mean_pressure ? "/load" : "/penetration");
}
std::string case_name(const ::testing::TestParamInfo<Case> &info) {
  return std::string(info.param.scene.name) +
         (info.param.control == Control::mean_pressure ? "Load" : "Penetration");
}

std::shared_ptr<asp::Grid> make_grid(const Scene &s, double length_scale) {
  return s.dimension == 1 ? asp_test::grid_1d(s.nx, s.lx * length_scale)
                          : asp_test::grid_2d(s.nx, s.ny, s.lx * length_scale,
                                              s.ly * length_scale);
}

// Heights on the scene's box in units of 1, so that the scaled copies are exact multiples.
Vector unit_heights(const Scene &s) {
  auto grid = make_grid(s, 1.0);
  if (s.rough) return asp_test::rough_surface(*grid, 11, 0.1, 0.5, 2.0);
  Vector h(static_cast<std::size_t>(grid->n_pixels()));
  asp::sinusoid_topography(*grid, 0.01 * s.lx, 2, s.dimension == 1 ? 0 : 1, h.data());
  return h;
}

double height_range(const Vector &h) {
  return *std::max_element(h.begin(), h.end()) - *std::min_element(h.begin(), h.end());
}

// A scene in units scaled by `length` and `pressure`, its system and the control value: a
// mean pressure of 0.02 E* (0.2 to 0.5 of the reference pressure E* h'_rms/2) or a penetration
// of 0.3 times the height range.
struct SceneSetup {
  std::shared_ptr<asp::Grid> grid;
  Vector heights;
  std::unique_ptr<asp::System> system;
  double modulus;
  double value;
};

SceneSetup make_setup(const Case &c, double length = 1.0, double pressure = 1.0) {
  SceneSetup s;
  s.grid = make_grid(c.scene, length);
  s.heights = unit_heights(c.scene);
  for (double &v : s.heights) v *= length;
  s.modulus = modulus * pressure;
  s.system.reset(new asp::System(s.grid, s.modulus));
  s.system->set_topography(s.heights.data());
  s.value = c.control == Control::mean_pressure ? 0.02 * s.modulus
                                                 : 0.3 * height_range(s.heights);
  return s;
}

// ---- an independent reference: K^-1 by a plain O(N^2) real DFT ----------------------------

// K~(q) = E*|q|/2 for every mode of the full spectrum, K~(0) the mean of K~ at the lowest
// wavevector of each axis with more than one pixel (DESIGN.md section 1).
class DirectElasticity {
 public:
  DirectElasticity(const asp::Grid &grid, double modulus)
      : nx_(grid.nx()), ny_(grid.ny()), lx_(grid.lx()), ly_(grid.ly()), modulus_(modulus) {
    double sum = 0.0;
    int axes = 0;
    if (nx_ > 1) sum += 0.5 * modulus_ * 2 * pi / lx_, ++axes;
    if (ny_ > 1) sum += 0.5 * modulus_ * 2 * pi / ly_, ++axes;
    k0_ = sum / axes;
    const std::int64_t n = nx_ * ny_;
    double stiffness_sum = 0.0;
    for (std::int64_t my = 0; my < ny_; ++my)
      for (std::int64_t mx = 0; mx < nx_; ++mx) stiffness_sum += stiffness(mx, my);
    pixel_stiffness_ = stiffness_sum / static_cast<double>(n);
    // The Green's function G(r) = (1/N) sum_q cos(q.r)/K~(q): u = G * p.
    green_.assign(static_cast<std::size_t>(n), 0.0);
    for (std::int64_t ry = 0; ry < ny_; ++ry)
      for (std::int64_t rx = 0; rx < nx_; ++rx) {
        double g = 0.0;
        for (std::int64_t my = 0; my < ny_; ++my)
          for (std::int64_t mx = 0; mx < nx_; ++mx) {
            const double phase = 2 * pi *
                                 (static_cast<double>((mx * rx) % nx_) / nx_ +
                                  static_cast<double>((my * ry) % ny_) / ny_);
            g += std::cos(phase) / stiffness(mx, my);
          }
        green_[rx + nx_ * ry] = g / static_cast<double>(n);
      }
  }

  double k0() const { return k0_; }
  double pixel_stiffness() const { return pixel_stiffness_; }
  // K~ of the mode with indices (mx, my) of the full spectrum.
  double stiffness(std::int64_t mx, std::int64_t my) const {
    const double fx = static_cast<double>(std::min(mx, nx_ - mx));
    const double fy = static_cast<double>(std::min(my, ny_ - my));
    const double q = 2 * pi * std::hypot(fx / lx_, fy / ly_);
    return q > 0.0 ? 0.5 * modulus_ * q : k0_;
  }
  // The smallest and largest eigenvalue of A = k K^-1, over all modes or over q != 0.
  double eigenvalue(bool largest, bool with_mean) const {
    double e = largest ? 0.0 : HUGE_VAL;
    for (std::int64_t my = 0; my < ny_; ++my)
      for (std::int64_t mx = 0; mx < nx_; ++mx) {
        if (!with_mean && mx == 0 && my == 0) continue;
        const double v = pixel_stiffness_ / stiffness(mx, my);
        e = largest ? std::max(e, v) : std::min(e, v);
      }
    return e;
  }

  Vector displacement(const Vector &p) const {
    Vector u(p.size(), 0.0);
    for (std::int64_t iy = 0; iy < ny_; ++iy)
      for (std::int64_t ix = 0; ix < nx_; ++ix) {
        double sum = 0.0;
        for (std::int64_t jy = 0; jy < ny_; ++jy)
          for (std::int64_t jx = 0; jx < nx_; ++jx) {
            const std::int64_t rx = (ix - jx + nx_) % nx_, ry = (iy - jy + ny_) % ny_;
            sum += green_[rx + nx_ * ry] * p[jx + nx_ * jy];
          }
        u[ix + nx_ * iy] = sum;
      }
    return u;
  }

 private:
  std::int64_t nx_, ny_;
  double lx_, ly_, modulus_, k0_ = 0.0, pixel_stiffness_ = 0.0;
  Vector green_;
};

// ---- the interface, as a solver sees it ------------------------------------------------------

double value_of(asp::Formulation &f, const Vector &x, Vector *gradient = nullptr) {
  Vector g(x.size());
  const double v = f.value_and_gradient(x.data(), g.data());
  if (gradient) *gradient = g;
  return v;
}
Vector hessian(asp::Formulation &f, const Vector &d) {
  Vector hd(d.size());
  f.hessian_product(d.data(), hd.data());
  return hd;
}
Vector plus(const Vector &x, double h, const Vector &d) {
  Vector y(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) y[i] = x[i] + h * d[i];
  return y;
}
using asp_test::max_abs;
double norm(const Vector &v) {
  double s = 0.0;
  for (double e : v) s += e * e;
  return std::sqrt(s);
}

// The size of the terms whose rounding the value at x carries, M = sum |x| (|Ax|/2 + |b|),
// and a gradient entry, max |Ax| + max |b|, with b = A x - gradient; all through the
// interface.
struct Size {
  double value, gradient;
};
Size size_at(asp::Formulation &f, const Vector &x) {
  Vector g;
  value_of(f, x, &g);
  const Vector ax = hessian(f, x);
  Size s{0.0, 0.0};
  double max_b = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double b = ax[i] - g[i];
    s.value += std::fabs(x[i]) * (0.5 * std::fabs(ax[i]) + std::fabs(b));
    max_b = std::max(max_b, std::fabs(b));
  }
  s.gradient = max_abs(ax) + max_b;
  return s;
}

// A scaled pressure: O(1) values with about 30 % zeros.
Vector random_pressure(std::int64_t n, std::uint64_t seed) {
  asp::Random random(seed);
  Vector x(static_cast<std::size_t>(n));
  for (double &v : x) v = random.uniform() < 0.3 ? 0.0 : 2.0 * random.uniform();
  return x;
}
Vector random_direction(std::int64_t n, asp::Random &random) {
  Vector d(static_cast<std::size_t>(n));
  for (double &v : d) v = random.gaussian();
  return d;
}

// Directions: random ones, one pixel alone, and the uniform (q = 0) field.
std::vector<Vector> directions(std::int64_t n, std::uint64_t seed) {
  asp::Random random(seed);
  std::vector<Vector> ds;
  for (int k = 0; k < 4; ++k) ds.push_back(random_direction(n, random));
  Vector pixel(static_cast<std::size_t>(n), 0.0);
  pixel[static_cast<std::size_t>(n / 3)] = 1.0;
  ds.push_back(pixel);
  ds.push_back(Vector(static_cast<std::size_t>(n), 1.0));
  return ds;
}

class DualFormulationTest : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    setup_ = make_setup(GetParam());
    formulation_.reset(new asp::DualFormulation(*setup_.system, GetParam().control, setup_.value));
    n_ = setup_.grid->n_pixels();
    x_ = random_pressure(n_, 5);
  }
  asp::Formulation &f() { return *formulation_; }

  SceneSetup setup_;
  std::unique_ptr<asp::DualFormulation> formulation_;
  std::int64_t n_ = 0;
  Vector x_;
};

// ---- 1. the gradient is the derivative of the value ------------------------------------------

TEST_P(DualFormulationTest, GradientMatchesCentralDifferencesOfTheValue) {
  Vector g;
  value_of(f(), x_, &g);
  for (const Vector &d : directions(n_, 17)) {
    const double slope = f().dot(g.data(), d.data());
    for (double h : {1.0, 1e-3}) {
      const Vector up = plus(x_, h, d), down = plus(x_, -h, d);
      const double difference = (value_of(f(), up) - value_of(f(), down)) / (2 * h);
      const double size = std::max(size_at(f(), up).value, size_at(f(), down).value);
      EXPECT_NEAR(difference, slope, rounding * (size / h + std::fabs(slope)))
          << "h = " << h << ", relative " << std::fabs(difference - slope) / (size / h);
    }
  }
}

// ---- 2. the Hessian product -------------------------------------------------------------------

TEST_P(DualFormulationTest, HessianProductMatchesCentralDifferencesOfTheGradient) {
  const Size at_x = size_at(f(), x_);
  for (const Vector &d : directions(n_, 19)) {
    const Vector hd = hessian(f(), d);
    for (double h : {1.0, 1e-3}) {
      Vector g_up, g_down;
      value_of(f(), plus(x_, h, d), &g_up);
      value_of(f(), plus(x_, -h, d), &g_down);
      const double scale = (at_x.gradient + h * max_abs(hd)) / h;
      for (std::int64_t i = 0; i < n_; ++i)
        ASSERT_NEAR((g_up[i] - g_down[i]) / (2 * h), hd[i], rounding * scale)
            << "pixel " << i << ", h = " << h;
    }
  }
}

TEST_P(DualFormulationTest, HessianIsSymmetricAndPositiveWithTheSpectrumOfKInverse) {
  const DirectElasticity direct(*setup_.grid, setup_.modulus);
  const double lowest = direct.eigenvalue(false, true), highest = direct.eigenvalue(true, true);
  const double lowest_fluctuation = direct.eigenvalue(false, false);
  const auto ds = directions(n_, 23);
  for (std::size_t a = 0; a < ds.size(); ++a) {
    const Vector ha = hessian(f(), ds[a]);
    // Positive, between the extreme eigenvalues k/K~(q) of A (Rayleigh quotient).
    const double dd = f().dot(ds[a].data(), ds[a].data());
    const double dhd = f().dot(ds[a].data(), ha.data());
    EXPECT_GT(dhd, 0.0);
    EXPECT_GE(dhd, lowest * dd * (1 - rounding));
    EXPECT_LE(dhd, highest * dd * (1 + rounding));
    for (std::size_t b = a + 1; b < ds.size(); ++b) {
      const Vector hb = hessian(f(), ds[b]);
      const double ahb = f().dot(ds[a].data(), hb.data());
      const double bha = f().dot(ds[b].data(), ha.data());
      EXPECT_NEAR(ahb, bha, rounding * (norm(ds[a]) * norm(hb) + norm(ds[b]) * norm(ha)))
          << a << ", " << b;
    }
  }
  // A direction without a mean (no q = 0 part) still has positive curvature, at least the
  // smallest eigenvalue over q != 0.
  Vector d = ds[0];
  double mean = 0.0;
  for (double v : d) mean += v / static_cast<double>(n_);
  for (double &v : d) v -= mean;
  const double dhd = f().dot(d.data(), hessian(f(), d).data());
  EXPECT_GT(dhd, 0.0);
  EXPECT_GE(dhd, lowest_fluctuation * f().dot(d.data(), d.data()) * (1 - rounding));
}

// Modes are eigenvectors of A = k K^-1 with eigenvalue k/K~(q); the uniform field has k/K~(0).
TEST_P(DualFormulationTest, HessianActsOnAFourierModeAsKInverse) {
  const DirectElasticity direct(*setup_.grid, setup_.modulus);
  const std::int64_t nx = setup_.grid->nx(), ny = setup_.grid->ny();
  const std::int64_t modes[][2] = {{0, 0}, {1, 0}, {nx / 2, 0}, {2, ny / 2}, {nx - 3, ny / 3}};
  for (const auto &m : modes) {
    Vector mode(static_cast<std::size_t>(n_));
    for (std::int64_t j = 0; j < ny; ++j)
      for (std::int64_t i = 0; i < nx; ++i)
        mode[i + nx * j] = std::cos(2 * pi * (static_cast<double>((m[0] * i) % nx) / nx +
                                              static_cast<double>((m[1] * j) % ny) / ny) +
                                    0.3);
    const double eigenvalue = direct.pixel_stiffness() / direct.stiffness(m[0], m[1]);
    const Vector hm = hessian(f(), mode);
    for (std::int64_t i = 0; i < n_; ++i)
      ASSERT_NEAR(hm[i], eigenvalue * mode[i], rounding * eigenvalue)
          << "mode (" << m[0] << ", " << m[1] << "), pixel " << i;
  }
}

TEST_P(DualFormulationTest, SecondOrderTaylorExpansionIsExact) {
  Vector g;
  const double fx = value_of(f(), x_, &g);
  const Size at_x = size_at(f(), x_);
  for (const Vector &d : directions(n_, 29)) {
    const Vector y = plus(x_, 1.0, d);
    const double fy = value_of(f(), y);
    const double gd = f().dot(g.data(), d.data());
    const double dhd = f().dot(d.data(), hessian(f(), d).data());
    EXPECT_NEAR(fy, fx + gd + 0.5 * dhd,
                rounding * (at_x.value + size_at(f(), y).value + std::fabs(gd) + dhd));
  }
}

// ---- 3. inner product and bounds -------------------------------------------------------------

TEST_P(DualFormulationTest, DotIsThePlainSumOverPixelsAndTheBoundIsZero) {
  asp::Random random(31);
  const Vector a = random_direction(n_, random), b = random_direction(n_, random);
  double plain = 0.0, magnitude = 0.0;
  for (std::int64_t i = 0; i < n_; ++i) {
    plain += a[i] * b[i];
    magnitude += std::fabs(a[i] * b[i]);
  }
  // Two summations in possibly different orders: each within (N - 1) eps sum |a b|.
  EXPECT_NEAR(f().dot(a.data(), b.data()), plain, 2 * n_ * DBL_EPSILON * magnitude);
  EXPECT_EQ(f().dot(a.data(), b.data()), f().dot(b.data(), a.data()));
  const Vector ones(static_cast<std::size_t>(n_), 1.0);
  EXPECT_EQ(f().dot(ones.data(), ones.data()), static_cast<double>(n_));
  EXPECT_EQ(f().lower_bound(), 0.0);
  EXPECT_EQ(f().size(), n_);
  EXPECT_EQ(static_cast<std::int64_t>(f().variable().size()), n_);
}

// ---- 4. the error measure ------------------------------------------------------------------

// DESIGN.md section 2 and asp_solver_solve: the largest of |g| where x > 0 and max(-g, 0)
// where x = 0, in scaled units (the scaled pixel stiffness is 1). Under load control the gap
// counts relative to its mean over {x > 0}, the penetration being the multiplier of the mean.
double error_by_definition(Control control, const Vector &x, const Vector &g) {
  double shift = 0.0;
  if (control == Control::mean_pressure) {
    double sum = 0.0, count = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i] > 0.0) sum += g[i], count += 1.0;
    shift = count > 0.0 ? sum / count : 0.0;
  }
  double e = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = g[i] - shift;
    e = std::max(e, x[i] > 0.0 ? std::fabs(r) : std::max(-r, 0.0));
  }
  return e;
}

TEST_P(DualFormulationTest, ErrorMatchesItsDefinition) {
  const Control control = GetParam().control;
  Vector g;
  value_of(f(), x_, &g);
  const double scale = max_abs(g);
  EXPECT_NEAR(f().error(x_.data(), g.data()), error_by_definition(control, x_, g),
              rounding * scale);

  // A KKT point (equal gaps where x > 0, larger ones where x = 0) has error 0 up to the
  // rounding of the mean; moving one free pixel's gap below the others shows up exactly.
  Vector kkt(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) kkt[i] = x_[i] > 0.0 ? 0.25 : 0.25 + 0.1 * i;
  const double shift = control == Control::mean_pressure ? 0.25 : 0.0;
  EXPECT_NEAR(f().error(x_.data(), kkt.data()), 0.25 - shift, rounding);
  const auto free_pixel = std::find(x_.begin(), x_.end(), 0.0) - x_.begin();
  kkt[free_pixel] = -0.5;
  EXPECT_NEAR(f().error(x_.data(), kkt.data()), error_by_definition(control, x_, kkt), rounding);

  // No pressure anywhere and every gap open (a negative penetration): nothing is violated,
  // the error is 0 and not the negative of the smallest gap.
  const Vector zero(g.size(), 0.0);
  Vector open(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) open[i] = 0.5 + 0.01 * i;
  EXPECT_EQ(error_by_definition(control, zero, open), 0.0);
  EXPECT_EQ(f().error(zero.data(), open.data()), 0.0);
}

// ---- the value and the gradient against their definition, with an O(N^2) K^-1 ----------------

// Pi(p) = (a/2) p.K^-1 p - a p.(h - max h + delta) and its gradient over a, the gap
// K^-1 p - (h - max h) - delta, in physical units, then turned into the scaled ones.
struct Reference {
  double value;
  Vector gradient;
  double value_size, gradient_size;
};
Reference reference(const SceneSetup &s, const DirectElasticity &direct, const Vector &x,
                    double pressure_unit, double delta) {
  const double k = direct.pixel_stiffness();
  const double length_unit = pressure_unit / k;
  const double a = s.grid->pixel_area();
  const double top = *std::max_element(s.heights.begin(), s.heights.end());
  Vector p(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) p[i] = pressure_unit * x[i];
  const Vector u = direct.displacement(p);
  Reference r{0.0, Vector(x.size()), 0.0, 0.0};
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = s.heights[i] - top + delta;
    r.value += a * (0.5 * p[i] * u[i] - p[i] * w);
    r.gradient[i] = (u[i] - w) / length_unit;
    r.value_size += a * std::fabs(p[i]) * (0.5 * std::fabs(u[i]) + std::fabs(w));
    r.gradient_size = std::max(r.gradient_size, (std::fabs(u[i]) + std::fabs(w)) / length_unit);
  }
  const double energy_unit = a * pressure_unit * length_unit;
  r.value /= energy_unit;
  r.value_size /= energy_unit;
  return r;
}

TEST_P(DualFormulationTest, ValueAndGradientMatchTheirDefinition) {
  // A reference pressure of our choosing, so that the units are known to the test.
  const double unit = 0.37 * setup_.modulus;
  setup_.system->set_reference_pressure(unit);
  const Control control = GetParam().control;
  asp::DualFormulation dual(*setup_.system, control, setup_.value);
  const DirectElasticity direct(*setup_.grid, setup_.modulus);
  const double k = direct.pixel_stiffness();
  EXPECT_NEAR(dual.energy_unit(), setup_.grid->pixel_area() * unit * unit / k,
              1e-14 * dual.energy_unit());

  Vector g;
  const double value = value_of(dual, x_, &g);
  const double delta = control == Control::penetration ? setup_.value : 0.0;
  Reference r = reference(setup_, direct, x_, unit, delta);
  if (control == Control::mean_pressure) {
    // The multiplier is whatever the formulation holds (0 before a solve): the gradient may
    // differ from the reference by a constant c = -delta/L, and the value by c sum x.
    double c = 0.0, sum_x = 0.0;
    for (std::int64_t i = 0; i < n_; ++i) c += (g[i] - r.gradient[i]) / n_, sum_x += x_[i];
    for (std::int64_t i = 0; i < n_; ++i) r.gradient[i] += c;
    r.value += c * sum_x;
  }
  EXPECT_NEAR(value, r.value, rounding * r.value_size);
  for (std::int64_t i = 0; i < n_; ++i)
    ASSERT_NEAR(g[i], r.gradient[i], rounding * r.gradient_size) << "pixel " << i;
}

// ---- 5. dimensionless: the same scene in other units gives the same numbers ------------------

TEST_P(DualFormulationTest, ScaledNumbersDoNotDependOnThePhysicalUnits) {
  const Case c = GetParam();
  Vector g;
  const double value = value_of(f(), x_, &g);
  const Size size = size_at(f(), x_);
  const Vector d = directions(n_, 37)[0];
  const Vector hd = hessian(f(), d);
  const double error = f().error(x_.data(), g.data());
  const double scales[][2] = {{1e50, 1e50}, {1e-50, 1e-50}, {1e50, 1e-50}, {1e-50, 1e50}};
  for (const auto &s : scales) {
    SCOPED_TRACE("lengths x " + std::to_string(s[0]) + ", pressures x " + std::to_string(s[1]));
    SceneSetup other = make_setup(c, s[0], s[1]);
    asp::DualFormulation dual(*other.system, c.control, other.value);
    Vector g_other;
    EXPECT_NEAR(value_of(dual, x_, &g_other), value, rounding * size.value);
    for (std::int64_t i = 0; i < n_; ++i)
      ASSERT_NEAR(g_other[i], g[i], rounding * size.gradient) << "pixel " << i;
    const Vector hd_other = hessian(dual, d);
    for (std::int64_t i = 0; i < n_; ++i)
      ASSERT_NEAR(hd_other[i], hd[i], rounding * max_abs(hd)) << "pixel " << i;
    EXPECT_NEAR(dual.error(x_.data(), g_other.data()), error, rounding * size.gradient);
    // The energy unit a P^2/k carries the physical scale: lengths^3 pressure in 2D.
    const double expected = s[0] * s[0] * s[0] * s[1] / (c.scene.dimension == 1 ? s[0] : 1.0);
    EXPECT_NEAR(dual.energy_unit() / formulation_->energy_unit(), expected, 1e-14 * expected);
  }
}

const Scene scenes[] = {
    {"Rough32x32", 2, 32, 32, 1.0, 1.0, true},
    {"Rough31x17", 2, 31, 17, 1.3, 0.7, true},
    {"Sinusoid24x9", 2, 24, 9, 1.0, 0.5, false},
    {"Rough1D64", 1, 64, 1, 2.0, 1.0, true},
    {"Sinusoid1D45", 1, 45, 1, 1.0, 1.0, false},
};

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const Scene &s : scenes)
    for (Control c : {Control::mean_pressure, Control::penetration}) cases.push_back({s, c});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Scenes, DualFormulationTest, ::testing::ValuesIn(all_cases()),
                         case_name);

// ---- 6. the state written back agrees with an O(N^2) K^-1 ------------------------------------

// The gap of the pressure, g_p = u - h + max h - delta with u = K^-1 p computed by the plain
// DFT, to 1e-12 of the terms, set onto the wall: exactly 0 where p > 0 (the active set), and
// > 0 elsewhere (g_p where that is positive, the smallest positive double where it is not,
// which g_p's 0 matches to that tolerance).
void expect_gap_of_pressure(const SceneSetup &s, const char *what) {
  SCOPED_TRACE(what);
  const asp::ContactState &state = s.system->state();
  const DirectElasticity direct(*s.grid, s.modulus);
  const Vector p(state.pressure.begin(), state.pressure.end());
  const Vector u = direct.displacement(p);
  const double top = *std::max_element(s.heights.begin(), s.heights.end());
  const double scale = max_abs(u) + height_range(s.heights) + std::fabs(state.penetration);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] > 0.0) {
      ASSERT_EQ(state.gap[i], 0.0) << "pixel " << i;
      continue;
    }
    ASSERT_GT(state.gap[i], 0.0) << "pixel " << i;
    const double g_p = u[i] - s.heights[i] + top - state.penetration;
    ASSERT_NEAR(state.gap[i], std::max(g_p, 0.0), rounding * scale) << "pixel " << i;
  }
}

const Scene small_scenes[] = {
    {"Rough8x6", 2, 8, 6, 1.0, 0.75, true},
    {"Sinusoid7x5", 2, 7, 5, 1.0, 1.0, false},
    {"Rough1D9", 1, 9, 1, 1.0, 1.0, true},
};

class DualFormulationState : public ::testing::TestWithParam<Case> {};
class DualFormulationScene : public ::testing::TestWithParam<Scene> {};
void PrintTo(const Scene &s, std::ostream *out) { *out << s.name; }
std::string scene_name(const ::testing::TestParamInfo<Scene> &info) { return info.param.name; }

TEST_P(DualFormulationState, GapAfterFinishIsThatOfThePressure) {
  const Case c = GetParam();
  // Converged and unconverged Polonsky-Keer solves (the latter stop between steps, some
  // of which update the pressure's spectrum without a transform).
  for (std::int64_t iterations : {1, 2, 3, 5, 8, 13, 100000}) {
    SceneSetup s = make_setup(c);
    const auto report = asp_test::solve_pk(*s.system, c.control, s.value, 1e-13, iterations);
    ASSERT_NE(report.termination, asp::Termination::breakdown);
    expect_gap_of_pressure(s, ("after " + std::to_string(iterations) + " iterations").c_str());
    const double mean = s.system->mean_pressure();
    if (c.control == Control::mean_pressure)
      EXPECT_NEAR(mean, s.value, 1e-14 * s.value);
    else
      EXPECT_NEAR(s.system->state().penetration, s.value, 1e-15 * s.value);
  }
  // The formulation driven by hand from a warm, non-equilibrium state: construct, one gap, finish.
  SceneSetup s = make_setup(c);
  asp::Random random(41);
  for (double &p : s.system->state().pressure)
    p = random.uniform() < 0.4 ? 0.0 : 0.04 * s.modulus * random.uniform();
  s.system->state().penetration = 0.2 * height_range(s.heights);
  asp::DualFormulation dual(*s.system, c.control, s.value);
  dual.evaluate_gap(false);
  ASSERT_TRUE(dual.finish());
  expect_gap_of_pressure(s, "construct, one gap, finish");
}

// A generic solver sees only the Formulation interface: it writes its own iterate, with the
// mean the constraint asks for, and finish() must store that pressure and the gap it makes.
TEST_P(DualFormulationState, FinishStoresAnIterateWrittenThroughTheInterface) {
  const Case c = GetParam();
  SceneSetup s = make_setup(c);
  // A warm state whose pressure the formulation holds with a pending scale (load control).
  asp::Random random(47);
  for (double &p : s.system->state().pressure) p = 0.02 * s.modulus * random.uniform();
  asp::DualFormulation dual(*s.system, c.control, s.value);
  asp::Formulation &f = dual;
  EXPECT_EQ(f.constrains_mean(), c.control == Control::mean_pressure);
  asp::Field &x = f.variable();
  for (double &xi : x) xi = random.uniform() < 0.5 ? 0.0 : random.uniform();
  f.project(x.data());
  const std::vector<double> written(x.begin(), x.end());
  ASSERT_TRUE(f.finish());
  expect_gap_of_pressure(s, "iterate written through the interface");
  // The stored pressure is the written iterate in physical units: one common factor.
  const std::size_t largest = static_cast<std::size_t>(
      std::max_element(written.begin(), written.end()) - written.begin());
  const double unit = s.system->state().pressure[largest] / written[largest];
  for (std::size_t i = 0; i < written.size(); ++i)
    ASSERT_NEAR(s.system->state().pressure[i], unit * written[i], 1e-15 * unit * written[i]);
  if (c.control == Control::mean_pressure)
    EXPECT_NEAR(s.system->mean_pressure(), s.value, 1e-14 * s.value);
  else
    EXPECT_NEAR(s.system->state().penetration, s.value, 1e-15 * s.value);
}

// Polonsky & Keer's own error (update_direction) follows the same definition: a negative
// penetration leaves every gap open and no pressure, a state without any violation.
TEST_P(DualFormulationScene, NoContactHasErrorZero) {
  const Case c{GetParam(), Control::penetration};
  SceneSetup s = make_setup(c);
  const auto report = asp_test::solve_pk(*s.system, c.control, -0.1 * height_range(s.heights));
  EXPECT_TRUE(report.converged());
  EXPECT_EQ(s.system->mean_pressure(), 0.0);
  EXPECT_EQ(report.error, 0.0);
}

// Under load control the penetration in the objective is the multiplier: the stored one when
// constructed, then the one that closes the mean gap on the contact set. The objective reported by
// evaluate_gap is the value the generic interface gives at the same iterate, and its gap is the
// gradient there.
TEST_P(DualFormulationScene, MultiplierUnderLoadControl) {
  const Case c{GetParam(), Control::mean_pressure};
  SceneSetup s = make_setup(c);
  const double unit = 0.37 * s.modulus;
  s.system->set_reference_pressure(unit);
  const DirectElasticity direct(*s.grid, s.modulus);
  const double length_unit = unit / direct.pixel_stiffness();
  const std::int64_t n = s.grid->n_pixels();
  asp::Random random(43);
  Vector warm(static_cast<std::size_t>(n));
  double mean = 0.0;
  for (double &p : warm) {
    p = random.uniform() < 0.4 ? 0.0 : random.uniform();
    mean += p / n;
  }
  std::copy(warm.begin(), warm.end(), s.system->state().pressure.begin());
  const double stored = 0.2 * height_range(s.heights);
  s.system->state().penetration = stored;

  asp::DualFormulation dual(*s.system, c.control, s.value);
  // The starting iterate: the warm pressure rescaled to the target mean, in units of P.
  Vector x(warm.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = warm[i] * (s.value / mean) / unit;
  Vector g;
  const double value = value_of(dual, x, &g);
  const Reference r = reference(s, direct, x, unit, stored);
  EXPECT_NEAR(value, r.value, rounding * r.value_size);
  for (std::int64_t i = 0; i < n; ++i)
    ASSERT_NEAR(g[i], r.gradient[i], rounding * r.gradient_size) << "pixel " << i;

  const double objective = dual.evaluate_gap(true).objective;
  ASSERT_TRUE(dual.finish());
  const asp::ContactState &state = s.system->state();
  EXPECT_NE(state.penetration, stored);
  // The iterate written back, and the value and gradient there with the new multiplier.
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = state.pressure[i] / unit;
  const Reference after = reference(s, direct, x, unit, state.penetration);
  EXPECT_NEAR(value_of(dual, x, &g), after.value, rounding * after.value_size);
  EXPECT_NEAR(objective, after.value, rounding * after.value_size);
  for (std::int64_t i = 0; i < n; ++i)
    ASSERT_NEAR(g[i], after.gradient[i], rounding * after.gradient_size) << "pixel " << i;
  // The new multiplier closes the mean gap of the pressure (the gradient) over the contact
  // set; the stored gap is that gap set onto the wall (expect_gap_of_pressure).
  double gap_sum = 0.0, gap_size = 0.0;
  for (std::int64_t i = 0; i < n; ++i)
    if (state.pressure[i] > 0.0) gap_sum += g[i], gap_size += std::fabs(g[i]);
  EXPECT_NEAR(gap_sum * length_unit, 0.0,
              rounding * (gap_size * length_unit + n * std::fabs(state.penetration)));
  expect_gap_of_pressure(s, "after one gap");
}

std::vector<Case> small_cases() {
  std::vector<Case> cases;
  for (const Scene &s : small_scenes)
    for (Control c : {Control::mean_pressure, Control::penetration}) cases.push_back({s, c});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(SmallScenes, DualFormulationState, ::testing::ValuesIn(small_cases()),
                         case_name);
INSTANTIATE_TEST_SUITE_P(SmallScenes, DualFormulationScene, ::testing::ValuesIn(small_scenes),
                         scene_name);

}  // namespace
