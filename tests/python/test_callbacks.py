# SPDX-License-Identifier: GPL-2.0-or-later
"""Python callbacks: a potential equal to the built-in soft wall, failures, progress."""
import gc
import unittest
import weakref

import numpy as np

import asperity

GAMMA_R, RHO_R, GAMMA_A, RHO_A = 2e-4, 1e-3, 1e-4, 2e-3


def soft_wall(gap):
    """The header's exponential soft wall (thesis eqs. 12-13), within its exponential range."""
    repulsion = GAMMA_R * np.exp(-2.0 * gap / RHO_R)
    attraction = GAMMA_A * np.exp(-gap / RHO_A)
    return (repulsion - attraction,
            -2.0 / RHO_R * repulsion + attraction / RHO_A,
            4.0 / RHO_R ** 2 * repulsion - attraction / RHO_A ** 2)


def scene():
    grid = asperity.Grid(32, 32, 1.0, 1.0)
    system = asperity.System(grid, 1.0)
    system.set_topography(asperity.sinusoid(grid, 0.01, 1, 1))
    return system


PENETRATION = 0.004


class PythonPotential(unittest.TestCase):
    def test_reproduces_the_built_in_soft_wall(self):
        for algorithm in ("lbfgs_fourier", "lbfgs"):
            with self.subTest(algorithm):
                built_in, python = scene(), scene()
                built_in.set_soft_wall(GAMMA_R, RHO_R, GAMMA_A, RHO_A)
                python.set_potential(soft_wall)
                for system in (built_in, python):
                    system.set_reference_pressure(1e-3)
                    solver = asperity.Solver(algorithm, tolerance=1e-12)
                    self.assertTrue(solver.solve(system, "penetration", PENETRATION).converged)
                fraction = built_in.contact_fraction
                self.assertGreater(fraction, 0.05)
                self.assertLess(fraction, 0.95)
                scale = np.abs(built_in.pressure).max()
                np.testing.assert_allclose(python.pressure, built_in.pressure, rtol=0,
                                           atol=1e-10 * scale)
                np.testing.assert_allclose(python.gap, built_in.gap, rtol=0,
                                           atol=1e-10 * np.abs(built_in.gap).max())
                self.assertAlmostEqual(python.interaction_energy, built_in.interaction_energy,
                                       delta=1e-10 * abs(built_in.interaction_energy))
                self.assertEqual(python.contact_fraction, fraction)

    def test_is_kept_alive_by_the_system(self):
        system = scene()
        system.set_potential(lambda g: soft_wall(g))
        gc.collect()
        self.assertTrue(asperity.Solver("lbfgs_fourier").solve(system, "penetration",
                                                               PENETRATION).converged)
        self.assertIsNotNone(system.potential)
        system.set_hard_wall()
        self.assertIsNone(system.potential)

    def test_an_exception_becomes_a_callback_error_and_the_system_stays_usable(self):
        system = scene()
        system.set_soft_wall(GAMMA_R, RHO_R, GAMMA_A, RHO_A)
        solver = asperity.Solver("lbfgs_fourier", tolerance=1e-10)
        solver.solve(system, "penetration", PENETRATION)
        before = system.pressure
        calls = []

        def failing(gap):
            calls.append(len(gap))
            if len(calls) > 3:
                raise RuntimeError("boom at call %d" % len(calls))
            return soft_wall(gap)

        system.set_potential(failing)
        with self.assertRaises(asperity.CallbackError) as caught:
            solver.solve(system, "penetration", 2 * PENETRATION)
        error = caught.exception
        self.assertEqual(error.status, asperity.ASP_ERR_CALLBACK)
        self.assertIsInstance(error.__cause__, RuntimeError)
        self.assertIs(error.exception, error.__cause__)
        self.assertIn("boom at call 4", str(error))
        self.assertEqual(calls[0], 32 * 32)
        # The state is that of before the failed solve, and the system solves again.
        np.testing.assert_array_equal(system.pressure, before)
        system.set_potential(soft_wall)
        self.assertTrue(solver.solve(system, "penetration", 2 * PENETRATION).converged)

    def test_bad_returns_are_callback_errors(self):
        system = scene()
        solver = asperity.Solver("lbfgs_fourier")
        for what, fn, cause in (
                ("not a tuple", lambda g: g, TypeError),
                ("wrong length", lambda g: (g[:3], g, g), ValueError),
                ("nan", lambda g: (g * np.nan, g, g), None)):
            with self.subTest(what):
                system.set_potential(fn)
                with self.assertRaises(asperity.CallbackError) as caught:
                    solver.solve(system, "penetration", PENETRATION)
                if cause is None:
                    self.assertIsNone(caught.exception.__cause__)
                    self.assertIn("phi", str(caught.exception))
                else:
                    self.assertIsInstance(caught.exception.__cause__, cause)

    def test_failure_in_get_interaction_energy(self):
        system = scene()
        system.set_potential(lambda g: 1 / 0)
        with self.assertRaises(asperity.CallbackError) as caught:
            system.get("interaction_energy")
        self.assertIsInstance(caught.exception.__cause__, ZeroDivisionError)
        self.assertEqual(system.mean_pressure, 0.0)

    def test_with_the_hard_wall_a_zero_potential_is_the_hard_wall(self):
        grid = asperity.Grid(64, 64, 1.0, 1.0)
        h = asperity.paraboloid(grid, 1.0)
        reference = asperity.System(grid, 1.0)
        reference.topography = h
        asperity.Solver("lbfgsb", tolerance=1e-10).solve(reference, "penetration", 0.002)
        system = asperity.System(grid, 1.0)
        system.topography = h
        sizes = set()

        def zero(gap):
            sizes.add(len(gap))
            return np.zeros_like(gap), np.zeros_like(gap), None

        system.set_potential(zero, hard_wall=True)
        asperity.Solver("lbfgsb", variable="gap", tolerance=1e-10).solve(
            system, "penetration", 0.002)
        self.assertAlmostEqual(system.mean_pressure, reference.mean_pressure,
                               delta=1e-6 * reference.mean_pressure)
        # All pixels at each evaluation; the library also asks for phi'(0) alone once (n = 1).
        self.assertIn(grid.n_pixels, sizes)

    def test_no_cycle_keeps_a_system_alive(self):
        system = scene()
        system.set_potential(soft_wall)
        ref = weakref.ref(system)
        del system
        self.assertIsNone(ref())


class Progress(unittest.TestCase):
    def test_returning_true_cancels(self):
        system = scene()
        system.set_soft_wall(GAMMA_R, RHO_R, GAMMA_A, RHO_A)
        seen = []

        def progress(iteration, seconds, error):
            seen.append((iteration, seconds, error))
            return iteration >= 3

        solver = asperity.Solver("lbfgs_fourier", tolerance=1e-14)
        solver.progress = progress
        report = solver.solve(system, "penetration", PENETRATION)
        self.assertEqual(report.termination, "cancelled")
        self.assertEqual(report.termination_code, asperity.TERMINATION_CANCELLED)
        self.assertEqual(report.iterations, 3)
        self.assertEqual([s[0] for s in seen], [0, 1, 2, 3])
        self.assertTrue(all(s[1] >= 0 and s[2] > 0 for s in seen))
        solver.progress = None
        self.assertEqual(solver.solve(system, "penetration", PENETRATION).termination,
                         "converged")
        self.assertEqual(len(seen), 4)

    def test_an_exception_stops_the_solve_cleanly(self):
        system = scene()
        system.set_soft_wall(GAMMA_R, RHO_R, GAMMA_A, RHO_A)
        solver = asperity.Solver("lbfgs_fourier")

        def progress(iteration, seconds, error):
            if iteration == 2:
                raise KeyError("stop here")

        solver.set_progress(progress)
        with self.assertRaises(asperity.CallbackError) as caught:
            solver.solve(system, "penetration", PENETRATION)
        self.assertIsInstance(caught.exception.__cause__, KeyError)
        self.assertEqual(solver.termination, "cancelled")
        self.assertEqual(solver.iterations, 2)
        self.assertTrue(np.all(np.isfinite(system.pressure)))
        solver.set_progress(None)
        self.assertTrue(solver.solve(system, "penetration", PENETRATION).converged)

    def test_is_kept_alive_by_the_solver(self):
        system = scene()
        system.set_soft_wall(GAMMA_R, RHO_R, GAMMA_A, RHO_A)
        solver = asperity.Solver("lbfgs_fourier")
        count = [0]

        def make():
            def progress(iteration, seconds, error):
                count[0] += 1
            return progress

        solver.set_progress(make())
        gc.collect()
        solver.solve(system, "penetration", PENETRATION)
        self.assertEqual(count[0], solver.iterations + 1)


if __name__ == "__main__":
    unittest.main()
