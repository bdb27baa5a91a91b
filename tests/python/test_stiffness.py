# SPDX-License-Identifier: GPL-2.0-or-later
"""Solver.normal_stiffness: the flat punch's 2 a E* on the free substrate, central differences
of solves on a periodic rough surface and with a Python potential on the hard wall, the
refusals (no converged solve of this system) and a raising potential re-raised."""
import math
import unittest

import numpy as np

import asperity


class NormalStiffness(unittest.TestCase):

    def test_flat_punch_on_free_substrate(self):
        # Face of radius r = 8 pixels: within the staircase's 0.71 dx/r of 2 r E*, and equal to
        # F/delta of the solve (the face is held), as in tests/unit/test_normal_stiffness.cpp.
        r_pixels, r, modulus = 8, 0.1, 1.0
        n = 20
        dx = r / r_pixels
        grid = asperity.Grid(n, n, n * dx, n * dx)
        x = (np.arange(n) - n // 2) * dx
        heights = np.where(np.hypot(x[:, None], x[None, :]) <= r, 0.0, -r)
        system = asperity.System(grid, modulus, substrate="free")
        system.topography = heights
        solver = asperity.Solver("pk", tolerance=1e-12)
        delta = 1e-3 * r
        self.assertTrue(solver.solve(system, "penetration", delta).converged)
        k = solver.normal_stiffness(system) * (n * dx) ** 2
        self.assertLessEqual(abs(k / (2 * r * modulus) - 1), 1 / (math.sqrt(2) * r_pixels))
        self.assertAlmostEqual(k, system.total_force / delta, delta=1e-8 * k)

    def test_central_differences_and_refusals(self):
        n = 32
        grid = asperity.Grid(n, n, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        system.topography = asperity.self_affine(grid, 0.8, 1.0, 0.25, 4.0 / n,
                                                 normalise="rms_slope", target=0.1, seed=3)
        delta = 0.3 * float(np.ptp(system.topography))
        solver = asperity.Solver("pk", tolerance=1e-13)
        with self.assertRaises(asperity.InvalidStateError):
            solver.normal_stiffness(system)
        solver.solve(system, "penetration", delta)
        k = solver.normal_stiffness(system)
        # The contact set is held for h = 1e-7 delta; the solves' errors make 1e-6 at most.
        h = 1e-7 * delta
        solver.solve(system, "penetration", delta + h)
        up = system.mean_pressure
        solver.solve(system, "penetration", delta - h)
        down = system.mean_pressure
        self.assertAlmostEqual(k, (up - down) / (2 * h), delta=1e-5 * k)
        system.reset()
        with self.assertRaises(asperity.InvalidStateError):
            solver.normal_stiffness(system)

    def test_python_potential_with_the_hard_wall(self):
        # Exponential adhesion written in Python, on the hard wall, solved by lbfgsb on the gap:
        # phi'' comes from the callback. A sphere of 32^2 pixels, cohesive zone 2.5 pixels.
        # Central differences at h = 1e-7: the contact set is held and the solves' errors
        # (tolerance 1e-13) make less than 1e-6 of the stiffness.
        n, work, rho = 32, 1e-3, 0.01
        fail = []

        def adhesion(gap):
            if fail:
                raise ValueError("asked to fail")
            e = np.exp(-gap / rho)
            return -work * e, work / rho * e, -work / rho ** 2 * e

        grid = asperity.Grid(n, n, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        system.topography = asperity.paraboloid(grid, 1.0)
        system.set_potential(adhesion, hard_wall=True)
        solver = asperity.Solver("lbfgsb", variable="gap", tolerance=1e-13,
                                 max_iterations=100000)
        delta, h = 0.01, 1e-7
        self.assertTrue(solver.solve(system, "penetration", delta).converged)
        k = solver.normal_stiffness(system)
        fail.append(True)
        with self.assertRaises(asperity.CallbackError) as caught:
            solver.normal_stiffness(system)
        self.assertIsInstance(caught.exception.__cause__, ValueError)
        fail.clear()
        self.assertEqual(solver.normal_stiffness(system), k)
        pressures = []
        for value in (delta + h, delta - h):
            self.assertTrue(solver.solve(system, "penetration", value).converged)
            pressures.append(system.mean_pressure)
        self.assertAlmostEqual(k, (pressures[0] - pressures[1]) / (2 * h), delta=1e-5 * abs(k))


if __name__ == "__main__":
    unittest.main()
