// SPDX-License-Identifier: GPL-2.0-or-later
// The normal contact stiffness d(mean pressure)/d(penetration) of solved states: against
// central differences of solves at delta +- h (hard wall, adhesion, soft wall, periodic and
// free substrates), against the closed forms of Westergaard's sinusoid, Hertz's sphere and the
// flat punch, and its refusal of unstable states.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "physics/normal_stiffness.hpp"
#include "physics/topography.hpp"
#include "scene.hpp"

namespace {

using asp::Control;
using asp_test::pi;
using Vector = std::vector<double>;

// The pixels on the hard wall or carrying pressure: the contact set the stiffness holds.
std::vector<bool> contact_set(const asp::System &system) {
  const auto &p = system.state().pressure;
  const auto &g = system.state().gap;
  std::vector<bool> c(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) c[i] = g[i] <= 0.0 || p[i] > 0.0;
  return c;
}

struct Scene {
  const char *algorithm;
  const char *variable;  // nullptr: the algorithm's default
};

asp::SolveReport solve(asp::System &system, const Scene &scene, double delta, double tolerance) {
  asp::Solver solver(scene.algorithm);
  if (scene.variable != nullptr) solver.set_option("variable", std::string(scene.variable));
  solver.set_option("tolerance", tolerance);
  solver.set_option("max_iterations", 200000.0);
  solver.solve(system, Control::penetration, delta);
  return solver.report();
}

// The stiffness at delta, and (p(delta + h) - p(delta - h))/(2h) from two more solves, each
// warm-started from the solution at delta; expects the contact set (with a hard wall) not to
// change between them, so that the derivative is the one the stiffness gives.
struct Comparison {
  double stiffness, difference;
  std::int64_t iterations;  // of the conjugate gradients, for the record
};
Comparison compare(asp::System &system, const Scene &scene, double delta, double h,
                   double tolerance, bool hard_wall = true) {
  EXPECT_TRUE(solve(system, scene, delta, tolerance).converged());
  const asp::NormalStiffness stiffness = asp::normal_stiffness(system);
  const auto contacts = contact_set(system);
  const asp::ContactState saved = system.state();
  double p[2];
  for (int side = 0; side < 2; ++side) {
    system.state() = saved;
    EXPECT_TRUE(solve(system, scene, delta + (side == 0 ? h : -h), tolerance).converged());
    p[side] = system.mean_pressure();
    if (hard_wall) {
      EXPECT_TRUE(contact_set(system) == contacts)
          << "the contact set changed between delta and delta " << (side == 0 ? "+" : "-")
          << " h: choose a smaller h";
    }
  }
  system.state() = saved;
  return {stiffness.value, (p[0] - p[1]) / (2 * h), stiffness.iterations};
}

// Central differences of the solves: truncation (h^2/6) p''' is nil while the contact set of
// the plain hard wall is held (p is then linear in delta), and of relative order (h/rho)^2
// with a potential of range rho (1e-10 and less here); the solves' errors, at tolerance
// 1e-12 or 1e-13 of the reference pressure, divided by 2h, are what remains (measured:
// below 1e-8 of the stiffness with the hard wall, 4e-7 and 7e-7 for the soft wall, whose
// h = 1e-5 rho is the smallest). 1e-5 relative leaves room for both.
constexpr double fd_tolerance = 1e-5;

// ---- the plain hard wall ----------------------------------------------------------------------

TEST(NormalStiffness, HardWallMatchesFiniteDifferencesOnPeriodicRoughSurface) {
  for (const Scene scene : {Scene{"pk", nullptr}, Scene{"bugnicourt", "gap"}}) {
    auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
    const Vector h = asp_test::rough_surface(*grid, 7, 0.1);
    asp::System system(grid, 1.0);
    system.set_topography(h.data());
    const double delta = 0.3 * system.height_range();
    const Comparison c = compare(system, scene, delta, 1e-7 * delta, 1e-13);
    std::printf("%s: stiffness %.10g (%lld steps), central difference %.10g\n", scene.algorithm,
                c.stiffness, static_cast<long long>(c.iterations), c.difference);
    EXPECT_GT(c.stiffness, 0.0);
    EXPECT_NEAR(c.stiffness, c.difference, fd_tolerance * c.stiffness) << scene.algorithm;
  }
}

TEST(NormalStiffness, HardWallMatchesFiniteDifferencesOnFreeSubstrate) {
  auto grid = asp_test::grid_2d(32, 24, 1.0, 0.75);
  const Vector h = asp_test::rough_surface(*grid, 11, 0.1);
  asp::System system(grid, 1.0, asp::SubstrateKind::free);
  system.set_topography(h.data());
  const double delta = 0.2 * system.height_range();
  const Comparison c = compare(system, Scene{"pk", nullptr}, delta, 1e-7 * delta, 1e-13);
  std::printf("free: stiffness %.10g (%lld steps), central difference %.10g\n", c.stiffness,
              static_cast<long long>(c.iterations), c.difference);
  EXPECT_NEAR(c.stiffness, c.difference, fd_tolerance * c.stiffness);
}

TEST(NormalStiffness, WithoutContactIsZeroAndInFullContactIsK0) {
  auto grid = asp_test::grid_2d(16, 16, 1.0, 1.0);
  Vector h(256);
  asp::sinusoid_topography(*grid, 0.01, 1, 1, h.data());
  asp::System system(grid, 2.0);
  system.set_topography(h.data());
  for (double &g : system.state().gap) g += 1.0;  // every pixel off the wall: no contact
  EXPECT_EQ(asp::normal_stiffness(system).value, 0.0);
  // Far beyond full contact the surface follows the wall everywhere: a uniform dp moves
  // only the mean mode, by dp/K~(0).
  ASSERT_TRUE(asp_test::solve_pk(system, Control::penetration, 1.0, 1e-13).converged());
  ASSERT_EQ(system.contact_fraction(), 1.0);
  EXPECT_NEAR(asp::normal_stiffness(system).value, system.substrate().k0(),
              1e-10 * system.substrate().k0());
}

// ---- Westergaard ------------------------------------------------------------------------------
// h = h0 cos(2 pi x/l) on the periodic substrate, contact half-width a, psi = pi a/l:
// p = p* sin^2 psi (p* = pi E* h0/l), and the penetration is the displacement at x = 0,
// delta = p/K~(0) + u_osc(0), whose oscillating part from the periodic line-load kernel
// -(2/(pi E*)) ln|2 sin(pi x/l)| over Westergaard's pressure is
// u_osc(0) = -(2 l/(pi E*)) p (ln sin psi - 1/2). Differentiating both in psi:
//   1/(dp/d delta) = 1/K~(0) + (2 l/(pi E*)) ln(1/sin psi).
// That is also the stiffness of a held contact of half-width a (a flat punch of that width
// gives the same, since the edge pressure of the sinusoid vanishes).
double westergaard_stiffness(double half_width, double k0, double l, double modulus) {
  return 1.0 / (1.0 / k0 - 2.0 * l / (pi * modulus) * std::log(std::sin(pi * half_width / l)));
}

// The stiffness holds the discrete contact set, of N_c pixels: it is compared with the closed
// form at that set's half-width N_c dx/2, not at the continuum's a (a pixel of width moves the
// stiffness by about 4 dx/l here, more than the discretisation error itself). What remains is
// the collocation error of the square-root edge, first order: measured -0.15 dx/a at both
// resolutions, held to 0.3 dx/a, and 4 times finer must divide it by at least 3.
TEST(NormalStiffness, WestergaardSinusoidConvergesToClosedForm) {
  const double l = 1.0, h0 = 0.01, modulus = 1.0;
  const double p_star = pi * modulus * h0 / l;
  double previous = 0.0;
  for (std::int64_t n : {256, 1024}) {
    auto grid = asp_test::grid_1d(n, l);
    Vector h(static_cast<std::size_t>(n));
    asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
    asp::System system(grid, modulus);
    system.set_topography(h.data());
    const double mean = 0.3 * p_star;
    ASSERT_TRUE(asp_test::solve_pk(system, Control::mean_pressure, mean, 1e-12).converged());
    const double a = l / pi * std::asin(std::sqrt(mean / p_star));
    const double a_discrete = 0.5 * system.contact_fraction() * l;
    ASSERT_LE(std::fabs(a_discrete - a), l / n);  // the edge within a pixel
    const double exact = westergaard_stiffness(a_discrete, system.substrate().k0(), l, modulus);
    const double error = asp::normal_stiffness(system).value / exact - 1.0;
    std::printf("Westergaard n=%lld: stiffness error %+.3e (%.3f dx/a)\n",
                static_cast<long long>(n), error, error * a * n / l);
    EXPECT_LE(std::fabs(error), 0.3 * l / n / a);
    if (previous != 0.0) EXPECT_LE(std::fabs(error), std::fabs(previous) / 3.0);
    previous = error;
  }
  // Full contact: K~(0) itself, the closed form at sin psi = 1.
  auto grid = asp_test::grid_1d(64, l);
  Vector h(64);
  asp::sinusoid_topography(*grid, h0, 1, 0, h.data());
  asp::System system(grid, modulus);
  system.set_topography(h.data());
  ASSERT_TRUE(asp_test::solve_pk(system, Control::mean_pressure, 1.5 * p_star, 1e-12).converged());
  ASSERT_EQ(system.contact_fraction(), 1.0);
  EXPECT_NEAR(asp::normal_stiffness(system).value, system.substrate().k0(),
              1e-10 * system.substrate().k0());
}

// ---- Hertz and the flat punch on the free substrate ------------------------------------------

// A sphere of radius R at delta = a^2/R: dF/d delta = 2 E* a, the stiffness of a flat punch
// of the contact's radius. The stiffness holds the discrete contact, N_c pixels, and is
// compared with 2 E* a_c at the radius of a disc of that area, a_c = sqrt(N_c dx^2/pi): what
// remains is the staircase and edge collocation error of a pixelated punch, first order
// (measured -0.10 and -0.11 dx/a at a/dx = 8 and 16, as the flat punch's -0.17 dx/r below),
// held to 0.25 dx/a, and doubling the resolution must divide it by at least 1.5. Against the
// continuum's a it is within dx/a (the discrete edge lies within half a pixel of a, and the
// stiffness follows the radius).
TEST(NormalStiffness, HertzSphereOnFreeSubstrateIsTwoModulusRadius) {
  const double radius = 1.0, modulus = 1.0, a = 0.05;
  double previous = 0.0;
  for (int a_pixels : {8, 16}) {
    const std::int64_t n = static_cast<std::int64_t>(std::lround(2.5 * a_pixels));
    const double dx = a / a_pixels, l = n * dx;
    auto grid = asp_test::grid_2d(n, n, l, l);
    Vector h(static_cast<std::size_t>(n * n));
    asp::paraboloid_topography(*grid, radius, h.data());
    asp::System system(grid, modulus, asp::SubstrateKind::free);
    system.set_topography(h.data());
    ASSERT_TRUE(
        asp_test::solve_pk(system, Control::penetration, a * a / radius, 1e-12).converged());
    const double stiffness = asp::normal_stiffness(system).value * l * l;
    const double a_contact = std::sqrt(system.contact_fraction() * l * l / pi);
    const double error = stiffness / (2.0 * modulus * a_contact) - 1.0;
    std::printf("Hertz a/dx = %d: stiffness error %+.3e (%.3f dx/a) at the contact's radius, "
                "%+.3e at a\n",
                a_pixels, error, error * a_pixels, stiffness / (2.0 * modulus * a) - 1.0);
    EXPECT_LE(std::fabs(error), 0.25 / a_pixels);
    EXPECT_LE(std::fabs(stiffness / (2.0 * modulus * a) - 1.0), 1.0 / a_pixels);
    if (previous != 0.0) EXPECT_LE(std::fabs(error), std::fabs(previous) / 1.5);
    previous = error;
  }
}

// A flat face of radius r: dF/d delta = 2 r E* (Boussinesq), for any delta in contact. The
// face made of pixels lies between the discs of radius r -+ dx/sqrt 2, and the stiffness grows
// with the face: within 0.71 dx/r, as test_free_halfspace's force over delta, which it must
// equal to the solve's tolerance (the contact set is the face, held).
TEST(NormalStiffness, FlatPunchOnFreeSubstrateIsTwoModulusRadius) {
  const double modulus = 1.0, r = 0.1;
  for (int r_pixels : {8, 16}) {
    const std::int64_t n = static_cast<std::int64_t>(std::lround(2.5 * r_pixels));
    const double dx = r / r_pixels, l = n * dx;
    auto grid = asp_test::grid_2d(n, n, l, l);
    Vector h(static_cast<std::size_t>(n * n));
    for (std::int64_t j = 0; j < n; ++j)
      for (std::int64_t i = 0; i < n; ++i)
        h[i + n * j] = std::hypot((i - n / 2) * dx, (j - n / 2) * dx) <= r ? 0.0 : -r;
    asp::System system(grid, modulus, asp::SubstrateKind::free);
    system.set_topography(h.data());
    const double delta = 1e-3 * r;
    ASSERT_TRUE(asp_test::solve_pk(system, Control::penetration, delta, 1e-12).converged());
    const double stiffness = asp::normal_stiffness(system).value * l * l;
    const double error = stiffness / (2.0 * r * modulus) - 1.0;
    std::printf("flat punch r/dx = %d: stiffness error %+.3e (%.3f dx/r)\n", r_pixels, error,
                error * r_pixels);
    EXPECT_LE(std::fabs(error), 1.0 / (std::sqrt(2.0) * r_pixels));
    EXPECT_NEAR(stiffness, system.total_force() / delta, 1e-8 * stiffness);
  }
}

// ---- with a potential -------------------------------------------------------------------------

// Exponential adhesion on the hard wall (a sphere, periodic and free substrate): the Hessian
// K + phi'' on the open gap, the wall pixels held.
TEST(NormalStiffness, AdhesiveSphereMatchesFiniteDifferences) {
  for (const asp::SubstrateKind kind : {asp::SubstrateKind::periodic, asp::SubstrateKind::free}) {
    const std::int64_t n = 32;
    auto grid = asp_test::grid_2d(n, n, 1.0, 1.0);
    Vector h(static_cast<std::size_t>(n * n));
    asp::paraboloid_topography(*grid, 1.0, h.data());
    asp::System system(grid, 1.0, kind);
    system.set_topography(h.data());
    // Cohesive zone (pi/4) E* rho^2/w = 0.08 of the box, 2.5 pixels: resolved.
    system.set_adhesion(1e-3, 0.01);
    const double delta = 0.01;
    const Comparison c = compare(system, Scene{"bugnicourt", "gap"}, delta, 1e-7, 1e-13);
    std::printf("adhesive sphere (%s): stiffness %.10g (%lld steps), central difference %.10g\n",
                asp::substrate_name(kind), c.stiffness, static_cast<long long>(c.iterations),
                c.difference);
    EXPECT_NEAR(c.stiffness, c.difference, fd_tolerance * std::fabs(c.stiffness))
        << asp::substrate_name(kind);
  }
}

// A soft wall (no hard wall: nothing held) on a rough surface, periodic and free.
TEST(NormalStiffness, SoftWallMatchesFiniteDifferences) {
  for (const asp::SubstrateKind kind : {asp::SubstrateKind::periodic, asp::SubstrateKind::free}) {
    auto grid = asp_test::grid_2d(32, 32, 1.0, 1.0);
    const Vector h = asp_test::rough_surface(*grid, 5, 0.1);
    asp::System system(grid, 1.0, kind);
    system.set_topography(h.data());
    const double range = 0.02 * system.height_range();
    system.set_soft_wall(1e-3 * range, range, 5e-4 * range, range);
    const double delta = 0.2 * system.height_range();
    const Comparison c =
        compare(system, Scene{"lbfgs", nullptr}, delta, 1e-5 * range, 1e-12, false);
    std::printf("soft wall (%s): stiffness %.10g (%lld steps), central difference %.10g\n",
                asp::substrate_name(kind), c.stiffness, static_cast<long long>(c.iterations),
                c.difference);
    EXPECT_NEAR(c.stiffness, c.difference, fd_tolerance * std::fabs(c.stiffness))
        << asp::substrate_name(kind);
  }
}

// ---- unstable states ---------------------------------------------------------------------------

// A flat surface held at a uniform gap in the attractive tail of a Lennard-Jones wall, where
// phi'' < 0: the Hessian's eigenvalues are K~(q) + phi'', least at q = 0.
TEST(NormalStiffness, RefusesStatesWhoseHessianIsNotPositiveDefinite) {
  auto grid = asp_test::grid_2d(16, 16, 1.0, 1.0);
  const Vector flat(256, 0.0);
  const double z0 = 1e-3;
  // phi''(g) at g = 1.5 z0: (w/2)(90 z0^9/g^11 - 36 z0^3/g^5) = w/z0^2 (45/1.5^11 - 18/1.5^5),
  // about -1.85 w/z0^2.
  const double curvature_per_work = (45.0 / std::pow(1.5, 11) - 18.0 / std::pow(1.5, 5)) / (z0 * z0);
  for (const bool below_diagonal : {true, false}) {
    asp::System system(grid, 1.0);
    system.set_topography(flat.data());
    const double k0 = system.substrate().k0();
    // Past the diagonal K_ii (the mean of K~, about 8 k0 here) the diagonal test refuses it;
    // between k0 and K_ii the conjugate gradients meet the negative curvature of q = 0.
    const double work = (below_diagonal ? 100.0 : 2.0) * k0 / -curvature_per_work;
    system.set_lennard_jones(work, z0);
    for (double &g : system.state().gap) g = 1.5 * z0;
    try {
      asp::normal_stiffness(system);
      ADD_FAILURE() << "an unstable state was given a stiffness";
    } catch (const asp::Error &e) {
      EXPECT_EQ(e.status(), asp::Status::invalid_state);
      EXPECT_NE(std::string(e.what()).find("not a stable equilibrium"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
