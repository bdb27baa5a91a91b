# SPDX-License-Identifier: GPL-2.0-or-later
"""Closed forms through Python: Hertz and Westergaard (the scenes and tolerances of
tests/unit/test_contact_oracles.cpp), and the unconstrained solvers agreeing on a soft wall."""
import math
import unittest

import numpy as np

import asperity


class Hertz(unittest.TestCase):
    """A paraboloid on a periodic substrate at small contact radius a = l/12 (about 21 px)."""

    n, l, radius, modulus = 256, 1.0, 1.0, 1.0

    def solve(self, algorithm, control, value, **options):
        grid = asperity.Grid(self.n, self.n, self.l, self.l)
        system = asperity.System(grid, self.modulus)
        system.topography = asperity.paraboloid(grid, self.radius)
        solver = asperity.Solver(algorithm, tolerance=1e-10, **options)
        self.assertTrue(solver.solve(system, control, value).converged)
        return system

    def check_hertz(self, system, a):
        force = 4 * self.modulus * a ** 3 / (3 * self.radius)
        a_measured = math.sqrt(system.contact_fraction * self.l ** 2 / math.pi)
        p0 = 2 * self.modulus * a / (math.pi * self.radius)
        self.assertAlmostEqual(a_measured / a, 1.0, delta=0.02)
        self.assertAlmostEqual(system.pressure.max() / p0, 1.0, delta=0.01)
        self.assertAlmostEqual(system.mean_pressure, force / self.l ** 2,
                               delta=1e-6 * force / self.l ** 2)

    def test_pk_under_mean_pressure(self):
        a = self.l / 12
        force = 4 * self.modulus * a ** 3 / (3 * self.radius)
        system = self.solve("pk", "mean_pressure", force / self.l ** 2)
        self.check_hertz(system, a)
        # The peak sits at the centre of the box, x = lx/2, y = ly/2: out[y, x].
        peak = np.unravel_index(np.argmax(system.pressure), system.pressure.shape)
        self.assertEqual(peak, (self.n // 2, self.n // 2))
        # and lbfgsb on the gap under penetration control at pk's penetration
        gap_based = self.solve("lbfgsb", "penetration", system.penetration, variable="gap")
        self.check_hertz(gap_based, a)


class Westergaard(unittest.TestCase):
    """1D sinusoid h0 cos(2 pi x/l) in partial contact, p_mean = 0.3 p*, p* = pi E* h0/l."""

    def test_half_width_and_pressure_profile(self):
        n, l, h0, modulus = 512, 1.0, 0.02, 1.0
        grid = asperity.Grid(n, l)
        system = asperity.System(grid, modulus)
        system.set_topography(asperity.sinusoid(grid, h0, 1, 0))
        p_star = math.pi * modulus * h0 / l
        mean = 0.3 * p_star
        report = asperity.Solver("pk", tolerance=1e-12).solve(system, "mean_pressure", mean)
        self.assertTrue(report.converged)
        s2 = mean / p_star
        a = l / math.pi * math.asin(math.sqrt(s2))
        dx = l / n
        self.assertLessEqual(abs(0.5 * system.contact_fraction * n * dx - a) / dx, 1.0)
        x = grid.coordinates()
        x = np.minimum(x, l - x)
        sx = np.sin(math.pi * x / l)
        exact = np.where(x < a, 2 * mean * np.cos(math.pi * x / l)
                         * np.sqrt(np.maximum(s2 - sx ** 2, 0)) / s2, 0.0)
        peak = 2 * mean / s2 * math.sqrt(s2)
        error = system.pressure - exact
        self.assertLess(math.sqrt(np.mean(error ** 2)) / peak, 1e-3)
        self.assertLess(np.abs(error[x < 0.5 * a]).max() / peak, 1e-5)


class SoftWallSolversAgree(unittest.TestCase):
    def test_lbfgs_fourier_and_lbfgs(self):
        grid = asperity.Grid(64, 64, 1.0, 1.0)
        h = asperity.self_affine(grid, 0.8, 1.0, 0.25, 8.0 / 64, "rms_slope", 0.1, seed=7)
        results = {}
        for algorithm in ("lbfgs_fourier", "lbfgs"):
            system = asperity.System(grid, 1.0)
            system.topography = h
            system.set_soft_wall(1e-4, 2e-3, 2e-5, 4e-3)
            solver = asperity.Solver(algorithm, tolerance=1e-11)
            report = solver.solve(system, "mean_pressure", 0.002)
            self.assertTrue(report.converged, (algorithm, report))
            results[algorithm] = system
        fourier, plain = results["lbfgs_fourier"], results["lbfgs"]
        self.assertGreater(fourier.contact_fraction, 0.01)
        self.assertLess(fourier.contact_fraction, 0.5)
        scale = np.abs(fourier.pressure).max()
        np.testing.assert_allclose(plain.pressure, fourier.pressure, rtol=0, atol=1e-7 * scale)
        self.assertAlmostEqual(plain.penetration, fourier.penetration,
                               delta=1e-7 * abs(fourier.penetration))


if __name__ == "__main__":
    unittest.main()
