# SPDX-License-Identifier: GPL-2.0-or-later
"""Fields in and out: the accepted layouts, without a copy, and the refusals."""
import unittest

import numpy as np

import asperity


def _ramp(grid):
    """h[y, x] = x + 100 y, distinct at every pixel."""
    return np.add.outer(100.0 * np.arange(grid.ny), np.arange(grid.nx))


class Layouts2D(unittest.TestCase):
    def setUp(self):
        self.grid = asperity.Grid(8, 5, 1.0, 0.5)
        self.system = asperity.System(self.grid, 1.0)
        self.h = _ramp(self.grid)  # (ny, nx) C order

    def test_outputs_are_ny_nx_c_order(self):
        h = asperity.sinusoid(self.grid, 1.0, 1, 1)
        self.assertEqual(h.shape, (5, 8))
        self.assertTrue(h.flags.c_contiguous)
        x, y = self.grid.coordinates()
        np.testing.assert_allclose(h, np.cos(2 * np.pi * x) * np.cos(2 * np.pi * y / 0.5),
                                   atol=1e-14)
        self.assertEqual(self.system.pressure.shape, (5, 8))

    def test_c_order_ny_nx_is_read_as_rows_of_x(self):
        self.system.set_topography(self.h)
        np.testing.assert_array_equal(self.system.topography, self.h)

    def test_fortran_order_nx_ny_is_the_same_memory(self):
        view = self.h.T  # shape (nx, ny), Fortran order, no copy
        self.assertEqual(view.shape, (8, 5))
        self.assertTrue(view.flags.f_contiguous)
        self.system.set_topography(view)
        np.testing.assert_array_equal(self.system.topography, self.h)

    def test_refusals_name_the_argument_and_the_layout(self):
        cases = {
            "C order (nx, ny)": (np.ascontiguousarray(self.h.T), asperity.InvalidArgumentError),
            "Fortran order (ny, nx)": (np.asfortranarray(self.h), asperity.InvalidArgumentError),
            "float32": (self.h.astype(np.float32), asperity.InvalidArgumentError),
            "int": (self.h.astype(np.int64), asperity.InvalidArgumentError),
            "strided view": (np.zeros((5, 16))[:, ::2], asperity.InvalidArgumentError),
            "wrong shape": (np.zeros((4, 8)), asperity.SizeMismatchError),
            "flat": (self.h.ravel(), asperity.SizeMismatchError),
            "3D": (self.h[None], asperity.SizeMismatchError),
            "list": (self.h.tolist(), asperity.InvalidArgumentError),
        }
        for what, (array, error) in cases.items():
            with self.subTest(what):
                with self.assertRaises(error) as caught:
                    self.system.set_topography(array)
                self.assertIn("heights", str(caught.exception))
                self.assertIsInstance(caught.exception, ValueError)
                if isinstance(array, np.ndarray) and array.ndim == 2:
                    self.assertIn(str(array.shape), str(caught.exception))
                    self.assertIn(str(array.strides), str(caught.exception))
                    self.assertIn("(ny, nx) = (5, 8)", str(caught.exception))

    def test_a_refused_array_changes_nothing(self):
        self.system.set_topography(self.h)
        with self.assertRaises(asperity.Error):
            self.system.set_topography(np.ascontiguousarray(self.h.T))
        np.testing.assert_array_equal(self.system.topography, self.h)

    def test_misaligned_and_read_only_inputs(self):
        raw = np.zeros(self.h.size * 8 + 1, dtype=np.uint8)
        misaligned = np.ndarray(self.h.shape, dtype=np.float64, buffer=raw, offset=1)
        self.assertFalse(misaligned.flags.aligned)
        misaligned[...] = self.h
        self.system.set_topography(misaligned)
        np.testing.assert_array_equal(self.system.topography, self.h)
        stats = asperity.statistics(self.grid, misaligned)
        self.assertEqual(stats, asperity.statistics(self.grid, self.h))
        asperity.detrend(self.grid, misaligned, "mean", inplace=True)
        self.assertAlmostEqual(misaligned.mean(), 0.0, delta=1e-12)

        frozen = self.h.copy()
        frozen.flags.writeable = False
        self.system.set_topography(frozen)
        with self.assertRaises(asperity.InvalidArgumentError):
            asperity.detrend(self.grid, frozen, "plane", inplace=True)
        with self.assertRaises(asperity.InvalidArgumentError):
            self.system.get_field("pressure", out=frozen)
        detrended = asperity.detrend(self.grid, frozen, "plane")  # a copy: allowed
        self.assertEqual(detrended.shape, (5, 8))
        np.testing.assert_array_equal(frozen, self.h)

    def test_get_field_into_an_out_array_of_either_order(self):
        self.system.set_topography(self.h)
        out_f = np.zeros((8, 5), order="F")
        self.assertIs(self.system.get_field("topography", out=out_f), out_f)
        np.testing.assert_array_equal(out_f, self.h.T)
        out_c = np.zeros((5, 8))
        self.system.get_field(asperity.FIELD_TOPOGRAPHY, out=out_c)
        np.testing.assert_array_equal(out_c, self.h)

    def test_detrend_copy_keeps_the_input_and_follows_its_layout(self):
        tilted = np.add.outer(0.3 * np.arange(5), 0.1 * np.arange(8)) + 2.0
        flat = asperity.detrend(self.grid, tilted.T, "plane")  # Fortran (nx, ny) input
        self.assertEqual(flat.shape, (5, 8))
        np.testing.assert_allclose(flat, 0.0, atol=1e-12)
        self.assertAlmostEqual(tilted[0, 0], 2.0)


class LayoutsSquareAndDegenerate(unittest.TestCase):
    def test_square_grid_decides_by_memory_order(self):
        grid = asperity.Grid(6, 6, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        h = _ramp(grid)
        system.set_topography(h)  # C order: a[y, x]
        np.testing.assert_array_equal(system.topography, h)
        system.set_topography(np.asfortranarray(h))  # Fortran order: a[x, y]
        np.testing.assert_array_equal(system.topography, h.T)
        with self.assertRaises(asperity.InvalidArgumentError):
            system.set_topography(np.zeros((12, 6))[::2])  # (6, 6) but rows 96 bytes apart

    def test_one_by_n_strip(self):
        grid = asperity.Grid(1, 7, 1.0, 1.0)
        system = asperity.System(grid, 1.0)
        column = np.arange(7.0).reshape(7, 1)  # (ny, nx)
        system.set_topography(column)
        np.testing.assert_array_equal(system.topography, column)
        system.set_topography(np.arange(7.0).reshape(1, 7))  # (nx, ny): same memory
        np.testing.assert_array_equal(system.topography, column)

    def test_one_d(self):
        grid = asperity.Grid(16, 2.0)
        self.assertEqual(grid.shape, (16,))
        system = asperity.System(grid, 1.0)
        h = asperity.sinusoid(grid, 0.1, 2)
        self.assertEqual(h.shape, (16,))
        system.set_topography(h)
        np.testing.assert_array_equal(system.topography, h)
        with self.assertRaises(asperity.InvalidArgumentError):
            system.set_topography(np.zeros(32)[::2])
        with self.assertRaises(asperity.SizeMismatchError):
            system.set_topography(h.reshape(1, 16))
        with self.assertRaises(asperity.SizeMismatchError):
            system.set_topography(np.zeros(15))


class VectorsOut(unittest.TestCase):
    def test_power_spectrum_and_statistics(self):
        grid = asperity.Grid(64, 64, 1.0, 1.0)
        h = asperity.self_affine(grid, 0.8, 1.0, 0.5, 4.0 / 64, "rms_height", 0.01, seed=3)
        self.assertEqual(h.shape, (64, 64))
        self.assertAlmostEqual(asperity.statistics(grid, h).rms_height, 0.01, delta=1e-12)
        slope_only = asperity.statistics(grid, h, rms_height=False, rms_curvature=False)
        self.assertIsNone(slope_only.rms_height)
        self.assertGreater(slope_only.rms_slope, 0.0)
        q, c = asperity.power_spectrum(grid, h, 16)
        self.assertEqual(q.shape, (16,))
        self.assertEqual(c.shape, (16,))
        self.assertTrue(np.all(np.diff(q) > 0))
        same = asperity.self_affine(grid, 0.8, 1.0, 0.5, 4.0 / 64, asperity.RMS_HEIGHT, 0.01,
                                    seed=3)
        np.testing.assert_array_equal(same, h)


if __name__ == "__main__":
    unittest.main()
