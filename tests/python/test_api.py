# SPDX-License-Identifier: GPL-2.0-or-later
"""The package's API: module functions, Grid, System, Solver, errors, handles."""
import gc
import os
import subprocess
import sys
import tempfile
import unittest
import weakref

import numpy as np

import asperity
from asperity import _library, errors


def _rss_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


class Module(unittest.TestCase):
    def test_versions_and_names(self):
        self.assertEqual(asperity.version(), asperity.ASP_VERSION_STRING)
        self.assertEqual(asperity.abi_version(), asperity.ASP_ABI_VERSION)
        self.assertIn("pk", asperity.algorithms())
        self.assertIn("lbfgs_fourier", asperity.algorithms())
        self.assertEqual(asperity.status_string(asperity.ASP_OK), asperity.status_string(0))
        self.assertEqual(asperity.CONTROLS["penetration"], asperity.CONTROL_PENETRATION)
        self.assertEqual(asperity.CONTROL_PENETRATION, asperity.ASP_CONTROL_PENETRATION)
        self.assertEqual(asperity.HISTORY_COLUMNS["error"], asperity.ASP_HISTORY_ERROR)
        self.assertEqual(asperity.DETREND_MODES["plane"], asperity.ASP_DETREND_PLANE)
        self.assertEqual(asperity.last_error_message(), "")

    def test_generators(self):
        grid = asperity.Grid(32, 16, 2.0, 1.0)
        for name, h in (("flat", asperity.flat(grid)), ("sphere", asperity.sphere(grid, 3.0)),
                        ("paraboloid", asperity.paraboloid(grid, 3.0)),
                        ("double_sinewave", asperity.double_sinewave(grid)),
                        ("sinusoid", asperity.sinusoid(grid, 1.0, 2, 1))):
            with self.subTest(name):
                self.assertEqual(h.shape, (16, 32))
                self.assertTrue(np.all(np.isfinite(h)))
        self.assertEqual(asperity.sphere(grid, 3.0).max(), 0.0)
        self.assertEqual(asperity.sphere(grid, 3.0)[8, 16], 0.0)  # apex at lx/2, ly/2

    def test_detrend_modes(self):
        grid = asperity.Grid(16, 8, 1.0, 1.0)
        x, y = grid.coordinates()
        h = 1.0 + 0.2 * x - 0.1 * y + 0.5 * x * x
        self.assertAlmostEqual(asperity.detrend(grid, h, "mean").mean(), 0.0, delta=1e-14)
        self.assertAlmostEqual(np.abs(asperity.detrend(grid, h, "curvature")).max(), 0.0,
                               delta=1e-12)
        with self.assertRaises(asperity.InvalidArgumentError):
            asperity.detrend(grid, h, "cubic")
        with self.assertRaises(asperity.InvalidArgumentError) as caught:
            asperity.detrend(grid, h, asperity.CONTROL_PENETRATION)  # another family
        self.assertIn("mode", str(caught.exception))

    def test_fft_wisdom_and_planning(self):
        grid = asperity.Grid(16, 16, 1.0, 1.0, fft_planning="estimate")
        system = asperity.System(grid, 1.0)
        system.topography = asperity.sinusoid(grid, 0.01, 1, 1)
        asperity.Solver("pk").solve(system, "mean_pressure", 1e-3)
        with self.assertRaises(asperity.InvalidStateError):
            asperity.set_fft_planning(grid, "measure")  # plans exist
        with tempfile.TemporaryDirectory() as work:
            path = os.path.join(work, "wisdom.txt")
            asperity.export_wisdom(path)
            self.assertTrue(os.path.exists(path))
            asperity.import_wisdom(path)
            with self.assertRaises(asperity.FileError) as caught:
                asperity.import_wisdom(os.path.join(work, "missing", "wisdom"))
            self.assertIsInstance(caught.exception, OSError)
            self.assertIn("missing", str(caught.exception))


class Loading(unittest.TestCase):
    def _import(self, **environment):
        env = {k: v for k, v in os.environ.items() if k != "ASPERITY_LIBRARY"}
        env.update(environment)
        return subprocess.run([sys.executable, "-c", "import asperity; print(asperity.library_path)"],
                              env=env, capture_output=True, text=True)

    def test_a_wrong_asperity_library_is_an_import_error_naming_it(self):
        result = self._import(ASPERITY_LIBRARY="/nonexistent/libasperity.so.1")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("ImportError", result.stderr)
        self.assertIn("ASPERITY_LIBRARY=/nonexistent/libasperity.so.1", result.stderr)

    def test_the_soname_through_the_system_loader(self):
        directory = os.path.dirname(os.path.abspath(asperity.library_path))
        result = self._import(LD_LIBRARY_PATH=directory)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.strip(), "libasperity.so.%d" % asperity.ASP_ABI_VERSION)
        result = self._import(LD_LIBRARY_PATH="/nonexistent")
        if result.returncode != 0:  # unless a libasperity is installed on the machine
            self.assertIn("libasperity.so.%d" % asperity.ASP_ABI_VERSION, result.stderr)
            self.assertIn("find_library", result.stderr)


class GridAndSystem(unittest.TestCase):
    def test_grid_shape_and_box(self):
        grid = asperity.Grid(8, 4, 2.0, 1.0)
        self.assertEqual((grid.dimension, grid.nx, grid.ny, grid.n_pixels), (2, 8, 4, 32))
        self.assertEqual(grid.box, (2.0, 1.0))
        self.assertEqual(grid.shape, (4, 8))
        line = asperity.Grid.one_d(8, 2.0)
        self.assertEqual((line.dimension, line.ny, line.ly, line.shape), (1, 1, 1.0, (8,)))
        self.assertEqual(repr(asperity.Grid.two_d(2, 3, 1.0, 1.0)), "Grid(2, 3, 1.0, 1.0)")
        with self.assertRaises(TypeError):
            asperity.Grid(8, 4, 2.0)
        with self.assertRaises(asperity.InvalidArgumentError) as caught:
            asperity.Grid(0, 1.0)
        self.assertEqual(caught.exception.status, asperity.ASP_ERR_INVALID_ARGUMENT)
        self.assertEqual(caught.exception.function, "asp_grid_create_1d")
        self.assertIn("nx", str(caught.exception))

    def test_scalars_fields_and_state(self):
        grid = asperity.Grid(64, 64, 1.0, 1.0)
        system = asperity.System(grid, 2.0)
        system.topography = asperity.paraboloid(grid, 1.0)
        asperity.Solver("pk", tolerance=1e-10).solve(system, asperity.CONTROL_MEAN_PRESSURE,
                                                     1e-4)
        self.assertAlmostEqual(system.get("mean_pressure"), 1e-4, delta=1e-12)
        self.assertEqual(system.get(asperity.MEAN_PRESSURE), system.mean_pressure)
        self.assertAlmostEqual(system.pressure.mean(), 1e-4, delta=1e-12)
        scalars = system.scalars()
        self.assertEqual(set(scalars), set(asperity.SCALARS))
        self.assertAlmostEqual(scalars["total_force"], 1e-4, delta=1e-12)
        u, g, h = system.displacement, system.gap, system.topography
        np.testing.assert_allclose(g, u - h + h.max() - system.penetration, atol=1e-12)
        penetration = system.penetration
        system.set_k0(2 * system.k0)
        self.assertNotEqual(system.penetration, penetration)
        system.set_reference_pressure(0.5)
        system.reset()
        self.assertEqual(system.mean_pressure, 0.0)
        with self.assertRaises(asperity.InvalidArgumentError):
            system.get("no_such_thing")

    def test_layer_substrate(self):
        # An elastic layer on a rigid base: K~(0) = M/t its own (read, not set), and one
        # wavevector pressed into full contact carries p = K~(0)(delta - h0) + K~(q) h, with
        # the layer's closed form of K~(q) (Carbone & Mangialardi 2008): exact per mode, to
        # the solve's tolerance (1e-12 of the reference pressure; checked to 1e-9).
        e_star, nu, t, l, h0 = 2.0, 0.25, 0.15, 1.0, 1e-3
        grid = asperity.Grid(64, l)
        layer = asperity.System(grid, e_star, substrate="layer", thickness=t, poisson_ratio=nu)
        self.assertEqual(layer.substrate, "layer")
        self.assertIn("thickness=0.15", repr(layer))
        m = e_star * (1 - nu * nu) * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
        k0 = m / t
        self.assertAlmostEqual(layer.k0 / k0, 1.0, delta=1e-14)
        with self.assertRaises(asperity.UnsupportedError):
            layer.set_k0(1.0)
        q = 2 * np.pi / l
        s, kappa = q * t, 3 - 4 * nu
        kq = 0.5 * e_star * q * (kappa * np.cosh(2 * s) + 2 * s * s + 0.5 * (1 + kappa ** 2)) / (
            kappa * np.sinh(2 * s) - 2 * s)
        h = h0 * np.cos(q * l * np.arange(64) / 64)
        layer.topography = h
        delta = h0 + 2 * kq * h0 / k0
        report = asperity.Solver("pk", tolerance=1e-12).solve(layer, "penetration", delta)
        self.assertTrue(report.converged)
        expected = k0 * (delta - h0) + kq * h
        self.assertLess(np.max(np.abs(layer.pressure - expected)), 1e-9 * k0 * (delta - h0))
        with self.assertRaises(asperity.InvalidArgumentError):
            asperity.System(grid, e_star, substrate="layer", thickness=t, poisson_ratio=0.5)
        with self.assertRaises(ValueError):
            asperity.System(grid, e_star, substrate="layer", thickness=t)
        with self.assertRaises(ValueError):
            asperity.System(grid, e_star, thickness=t)

    def test_free_substrate_and_interactions(self):
        grid = asperity.Grid(32, 32, 1.0, 1.0)
        free = asperity.System(grid, 1.0, substrate="free")
        self.assertEqual(free.substrate, "free")
        free.topography = asperity.paraboloid(grid, 1.0)
        solver = asperity.Solver("pk")
        self.assertTrue(solver.solve(free, "penetration", 0.001).converged)
        with self.assertRaises(asperity.UnsupportedError):
            free.set_k0(1.0)
        with self.assertRaises(asperity.UnsupportedError):
            free.get("k0")
        self.assertNotIn("k0", free.scalars())
        with self.assertRaises(asperity.UnsupportedError):
            asperity.System(asperity.Grid(8, 1.0), 1.0, substrate="free")
        with self.assertRaises(ValueError):
            asperity.System(grid, 1.0, substrate="elastic")

        system = asperity.System(grid, 1.0)
        system.topography = asperity.paraboloid(grid, 1.0)
        system.set_adhesion(1e-4, 1e-3)
        self.assertEqual(system.work_of_adhesion, 1e-4)
        self.assertFalse(asperity.Solver("pk").supports(system, "penetration"))
        reason = asperity.Solver("pk").unsupported_reason(system, "penetration")
        self.assertIn("adhesive", reason)
        bugnicourt = asperity.Solver("bugnicourt", variable="gap")
        self.assertTrue(bugnicourt.supports(system, "penetration"))
        self.assertTrue(bugnicourt.solve(system, "penetration", 0.001).converged)
        self.assertLess(system.interaction_energy, 0.0)
        # The contact map: 1 where the gap is 0, its mean the contact fraction; with adhesion
        # it holds the compressive core and the tensile ring around it.
        contact = system.contact
        np.testing.assert_array_equal(contact, (system.gap == 0.0).astype(float))
        self.assertEqual(contact.mean(), system.contact_fraction)
        self.assertEqual(system.get_field(asperity.FIELD_CONTACT).mean(), contact.mean())
        self.assertEqual(system.compressive_fraction,
                         np.count_nonzero((contact == 1.0) & (system.pressure > 0.0))
                         / contact.size)
        self.assertLess(system.compressive_fraction, system.contact_fraction)
        system.set_lennard_jones(1e-4, 1e-3)
        self.assertEqual(system.work_of_adhesion, 0.0)
        self.assertTrue(asperity.Solver("fire").supports(system, "penetration"))
        with self.assertRaises(asperity.InvalidArgumentError):
            system.set_soft_wall(-1.0, 1e-3)
        with self.assertRaises(asperity.InvalidArgumentError) as caught:
            asperity.Solver("pk").supports(system, asperity.FIELD_GAP)
        self.assertIn("control", str(caught.exception))


    def test_check_resolution(self):
        # The cohesive zone (pi/4) E* rho^2/w over the pixel 1/32, as the header defines it;
        # 1e-12 relative: the library forms it from logarithms (see tests/api).
        grid = asperity.Grid(32, 32, 1.0, 1.0)
        system = asperity.System(grid, 2.0)
        plain = system.check_resolution()
        self.assertEqual((plain.ratio, plain.resolved), (0.0, True))
        self.assertIn("nothing", plain.sentence)
        system.set_adhesion(1e-3, 1e-2)
        resolved = system.check_resolution()
        zone = np.pi / 4 * 2.0 * 1e-2 ** 2 / 1e-3
        self.assertAlmostEqual(resolved.ratio / (zone * 32), 1.0, delta=1e-12)
        self.assertTrue(resolved.resolved)
        self.assertTrue(resolved.sentence.startswith("resolved: "))
        system.set_adhesion(1e-1, 1e-2)
        unresolved = system.check_resolution()
        self.assertAlmostEqual(unresolved.ratio / (zone / 100 * 32), 1.0, delta=1e-12)
        self.assertFalse(unresolved.resolved)
        self.assertIn("lattice trapping", unresolved.sentence)
        ratio, flag, sentence = unresolved  # a plain tuple too
        self.assertEqual(flag, False)
        # A Python potential: no known length, and it is not called.
        calls = []

        def potential(gap):
            calls.append(1)
            return -np.exp(-gap), np.exp(-gap), None
        system.set_potential(potential)
        unknown = system.check_resolution()
        self.assertEqual((unknown.ratio, unknown.resolved), (0.0, False))
        self.assertTrue(unknown.sentence.startswith("unknown: "))
        self.assertEqual(calls, [])
        system.close()
        with self.assertRaises(asperity.NullPointerError):
            system.check_resolution()


class SolverApi(unittest.TestCase):
    def test_options_report_and_history(self):
        solver = asperity.Solver("lbfgsb", variable="gap", memory=7)
        self.assertEqual(solver.name, "lbfgsb")
        self.assertEqual(solver.get_option("variable"), "gap")
        self.assertEqual(solver.get_option("memory"), 7.0)
        # The constrained solvers nest grids by default: "levels" holds the word "auto", read
        # back as such; the solvers of soft walls do not.
        self.assertEqual(solver.get_option("levels"), "auto")
        self.assertEqual(asperity.Solver("pk").get_option("levels"), "auto")
        self.assertEqual(asperity.Solver("lbfgs").get_option("levels"), 0.0)
        self.assertEqual(asperity.Solver("pk", levels=2).get_option("levels"), 2.0)
        solver.tolerance = 1e-9
        self.assertEqual(solver.tolerance, 1e-9)
        solver.max_iterations = 500
        self.assertEqual(solver.max_iterations, 500)
        self.assertIn("memory", solver.describe())
        with self.assertRaises(asperity.InvalidArgumentError) as caught:
            solver.set_option("no_such_option", 1.0)
        self.assertIn("no_such_option", str(caught.exception))
        with self.assertRaises(asperity.InvalidArgumentError):
            solver.get_option("no_such_option")
        with self.assertRaises(asperity.InvalidArgumentError):
            solver.set_option("variable", 3.0)
        with self.assertRaises(asperity.InvalidStateError):
            solver.report()
        with self.assertRaises(asperity.UnsupportedError) as caught:  # not in this build
            asperity.Solver("simplex")
        self.assertIn("lbfgs_fourier", str(caught.exception))

        grid = asperity.Grid(64, 64, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        system.topography = asperity.paraboloid(grid, 1.0)
        solver.record_history = True
        report = solver.solve(system, "penetration", 0.002)
        self.assertEqual(report, solver.report())
        self.assertTrue(report.converged)
        self.assertEqual(report.termination, "converged")
        self.assertGreater(report.evaluations, 0)
        self.assertGreater(report.transforms, 0)
        self.assertGreaterEqual(report.elapsed_seconds, 0.0)
        self.assertLessEqual(report.final_error, 1e-9)
        history = solver.history
        self.assertEqual(set(history), set(asperity.HISTORY_COLUMNS))
        np.testing.assert_array_equal(history["iteration"], np.arange(report.iterations + 1))
        self.assertEqual(history["error"][-1], report.final_error)
        self.assertEqual(history["transforms"][-1], report.transforms)
        table = solver.history_array()
        self.assertEqual(table.shape, (report.iterations + 1,))
        np.testing.assert_array_equal(table["objective"], history["objective"])
        solver.set_history(False)
        solver.solve(system, "penetration", 0.002)
        self.assertEqual(len(solver.history["error"]), 0)
        with self.assertRaises(asperity.UnsupportedError):
            solver.solve(system, "mean_gap", 1e-3)
        with self.assertRaises(asperity.InvalidArgumentError):
            solver.solve(system, "mean_force", 1e-3)


class Errors(unittest.TestCase):
    def test_every_status_has_its_class(self):
        expected = {
            asperity.ASP_ERR_NULL_POINTER: (asperity.NullPointerError, TypeError),
            asperity.ASP_ERR_INVALID_ARGUMENT: (asperity.InvalidArgumentError, ValueError),
            asperity.ASP_ERR_SIZE_MISMATCH: (asperity.SizeMismatchError, ValueError),
            asperity.ASP_ERR_OUT_OF_MEMORY: (asperity.OutOfMemoryError, MemoryError),
            asperity.ASP_ERR_UNSUPPORTED: (asperity.UnsupportedError, NotImplementedError),
            asperity.ASP_ERR_INVALID_STATE: (asperity.InvalidStateError, RuntimeError),
            asperity.ASP_ERR_FFT: (asperity.FFTError, RuntimeError),
            asperity.ASP_ERR_CALLBACK: (asperity.CallbackError, asperity.Error),
            asperity.ASP_ERR_INTERNAL: (asperity.InternalError, RuntimeError),
            asperity.ASP_ERR_IO: (asperity.FileError, OSError),
        }
        self.assertEqual(set(expected), set(errors.ERROR_CLASSES))
        for status, (cls, builtin) in expected.items():
            with self.subTest(cls.__name__):
                with self.assertRaises(cls) as caught:
                    _library.check(status, "test")
                self.assertIsInstance(caught.exception, builtin)
                self.assertIsInstance(caught.exception, asperity.Error)
                self.assertEqual(caught.exception.status, status)
                self.assertTrue(cls.__doc__)
        self.assertIs(type(errors.error_for_status(99, "x")), asperity.Error)

    def test_errors_raised_by_the_library(self):
        lib = asperity._lib
        with self.assertRaises(asperity.NullPointerError) as caught:
            _library.check(lib.asp_system_reset(None), "asp_system_reset")
        self.assertIn("system", caught.exception.message)
        grid = asperity.Grid(8, 8, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        with self.assertRaises(asperity.SizeMismatchError):
            _library.check(lib.asp_system_set_topography(system.handle, np.zeros(64).ctypes.data,
                                                         63), "asp_system_set_topography")
        with self.assertRaises(asperity.OutOfMemoryError):
            asperity.System(asperity.Grid(1073741823, 1073741823, 1.0, 1.0), 1.0)
        with self.assertRaises(asperity.InvalidArgumentError):
            asperity.System(grid, -1.0)


class Topography(unittest.TestCase):
    """A solve needs a topography; a bad height is named by its pixel."""

    def test_solve_without_topography_raises(self):
        # Solved as the zeros it starts with, a forgotten topography used to report a flat
        # surface as converged.
        grid = asperity.Grid(8, 8, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        solver = asperity.Solver("pk")
        with self.assertRaises(asperity.InvalidStateError) as caught:
            solver.solve(system, "mean_pressure", 0.01)
        self.assertIn("has no topography", caught.exception.message)
        self.assertIn("asp_system_set_topography", caught.exception.message)
        system.topography = np.zeros((8, 8))  # a flat surface, set like any other
        self.assertTrue(solver.solve(system, "mean_pressure", 0.01).converged)

    def test_bad_height_named_by_its_pixel(self):
        grid = asperity.Grid(8, 4, 2.0, 1.0)
        system = asperity.System(grid, 1.0)
        heights = np.zeros((4, 8))
        heights[1, 5] = np.nan  # row y = 1, column x = 5: index 13, x fastest
        with self.assertRaises(asperity.InvalidArgumentError) as caught:
            system.set_topography(heights)
        self.assertIn("at pixel (x = 5, y = 1), index 13", caught.exception.message)


class Handles(unittest.TestCase):
    def test_system_keeps_its_grid_alive(self):
        grid = asperity.Grid(16, 16, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        grid_ref = weakref.ref(grid)
        del grid
        gc.collect()
        self.assertIsNotNone(grid_ref())
        self.assertIs(system.grid, grid_ref())
        system.topography = asperity.sinusoid(system.grid, 0.01, 1, 1)
        asperity.Solver("pk").solve(system, "mean_pressure", 1e-3)
        system_ref = weakref.ref(system)
        del system
        self.assertIsNone(system_ref())
        gc.collect()
        self.assertIsNone(grid_ref())

    def test_grid_closed_before_its_system(self):
        grid = asperity.Grid(16, 16, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        grid.close()
        grid.close()
        with self.assertRaises(asperity.NullPointerError):
            grid.handle
        # The library counts references: the system still works on its grid.
        self.assertEqual(system.pressure.shape, (16, 16))

    def test_close_and_context_managers(self):
        with asperity.Grid(8, 1.0) as grid, asperity.System(grid, 1.0) as system, \
                asperity.Solver("pk") as solver:
            system.topography = np.zeros(8)
            solver.solve(system, "mean_pressure", 1e-3)
        with self.assertRaises(asperity.NullPointerError):
            system.reset()
        with self.assertRaises(asperity.NullPointerError):
            solver.solve(system, "mean_pressure", 1e-3)
        system.close()
        solver.close()

    def test_a_thousand_systems_do_not_leak(self):
        grid = asperity.Grid(64, 64, 1.0, 1.0)
        h = asperity.sinusoid(grid, 0.01, 1, 1)
        # Each system holds 3 fields of 64*64 doubles (96 KiB): a thousand leaked would be 96 MiB.
        for _ in range(50):
            asperity.System(grid, 1.0).set_topography(h)
        gc.collect()
        before = _rss_bytes()
        refs = []
        for _ in range(1000):
            system = asperity.System(grid, 1.0)
            system.set_topography(h)
            system.set_potential(lambda g: (g, g, g))
            refs.append(weakref.ref(system))
            del system
        gc.collect()
        self.assertTrue(all(ref() is None for ref in refs))
        self.assertLess(_rss_bytes() - before, 20 * 2 ** 20)


if __name__ == "__main__":
    unittest.main()
