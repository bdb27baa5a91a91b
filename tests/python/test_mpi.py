# SPDX-License-Identifier: GPL-2.0-or-later
"""asperity.Grid.mpi: a grid shared among the processes of an mpi4py communicator.

Run under MPI, every process running the same tests in the same order (the calls on a
distributed grid are collective):

    mpirun -np 2 python3 test_mpi.py

Each process compares its rows with a serial grid of its own: the self-affine surface to the
bit, the solution of a pk solve on the periodic and the free substrate to 1e-10 (FFTW-MPI's transforms round differently from the
serial ones), the shapes of the arrays going in and out. A failure on any process fails the
run on every process.
"""
import sys
import unittest

import numpy as np
from mpi4py import MPI

import asperity

COMM = MPI.COMM_WORLD
NX, NY = 64, 48
# The C tests' scene: a box of one unit per pixel.
SURFACE = dict(hurst=0.8, long_cutoff=64.0, rolloff=16.0, short_cutoff=4.0,
               normalise="rms_slope", target=0.1, seed=42)


class DistributedGrid(unittest.TestCase):
    def setUp(self):
        self.grid = asperity.Grid.mpi(COMM, NX, NY, float(NX), float(NY))
        self.serial = asperity.Grid(NX, NY, float(NX), float(NY))
        self.local_ny, self.offset = self.grid.slab
        self.rows = slice(self.offset, self.offset + self.local_ny)

    def tearDown(self):
        self.grid.close()
        self.serial.close()

    def test_the_slabs_cover_the_grid_in_order(self):
        slabs = COMM.allgather(self.grid.slab)
        self.assertEqual(sum(rows for rows, _ in slabs), NY)
        self.assertEqual([offset for _, offset in slabs],
                         list(np.cumsum([0] + [rows for rows, _ in slabs[:-1]])))
        self.assertEqual((self.grid.nx, self.grid.ny, self.grid.n_pixels), (NX, NY, NX * NY))
        self.assertEqual(self.grid.local_pixels, NX * self.local_ny)
        self.assertTrue(repr(self.grid).startswith("Grid.mpi("))

    def test_each_process_has_its_rows_of_the_serial_surface(self):
        mine = asperity.self_affine(self.grid, **SURFACE)
        whole = asperity.self_affine(self.serial, **SURFACE)
        self.assertTrue(np.array_equal(mine, whole[self.rows]))
        # Statistics are the whole surface's.
        local = asperity.statistics(self.grid, mine)
        serial = asperity.statistics(self.serial, whole)
        for a, b in zip(local, serial):
            self.assertAlmostEqual(a, b, delta=1e-12 * abs(b))

    def test_arrays_have_the_shape_of_the_process_rows(self):
        shape = (self.local_ny, NX)
        self.assertEqual(self.grid.shape, shape)
        self.assertEqual(self.grid.local_ny, self.local_ny)
        heights = asperity.self_affine(self.grid, **SURFACE)
        self.assertEqual(heights.shape, shape)
        self.assertEqual(asperity.sinusoid(self.grid, 1.0, 2, 3).shape, shape)
        self.assertEqual(asperity.detrend(self.grid, heights).shape, shape)
        x, y = self.grid.coordinates()
        self.assertEqual(x.shape, shape)
        np.testing.assert_array_equal(y[:, 0], np.arange(self.offset, self.offset + self.local_ny))
        with asperity.System(self.grid, 1.0) as system:
            system.set_topography(heights)
            system.set_topography(np.asfortranarray(heights.T))  # (nx, local_ny), x fastest
            for name in ("pressure", "gap", "displacement", "topography"):
                self.assertEqual(system.get_field(name).shape, shape, name)
            self.assertEqual(system.pressure.shape, shape)
            out = np.empty(shape)
            self.assertIs(system.get_field("topography", out=out), out)
            np.testing.assert_array_equal(out, heights)
            # The whole grid's shape is not this process's.
            with self.assertRaisesRegex(asperity.SizeMismatchError, "this process: %d rows"
                                        % self.local_ny):
                system.set_topography(np.zeros((NY, NX)))

    def test_a_pk_solve_gives_the_serial_solution(self):
        for substrate in ("periodic", "free"):
            with self.subTest(substrate=substrate):
                self.check_pk_solve(substrate)

    def check_pk_solve(self, substrate):
        results = []
        for grid in (self.grid, self.serial):
            heights = asperity.self_affine(grid, **SURFACE)
            with asperity.System(grid, 1.0, substrate=substrate) as system, \
                    asperity.Solver("pk", tolerance=1e-11) as solver:
                system.set_topography(heights)
                report = solver.solve(system, "mean_pressure", 0.01)
                self.assertTrue(report.converged)
                results.append((system.pressure, system.gap,
                                {name: system.get(name) for name in
                                 ("mean_pressure", "mean_gap", "contact_fraction",
                                  "elastic_energy", "penetration")}))
        (pressure, gap, scalars), (serial_pressure, serial_gap, serial_scalars) = results
        self.assertEqual(pressure.shape, (self.local_ny, NX))
        for mine, whole in ((pressure, serial_pressure), (gap, serial_gap)):
            np.testing.assert_allclose(mine, whole[self.rows], rtol=0,
                                       atol=1e-10 * np.abs(whole).max())
        for name, value in serial_scalars.items():
            self.assertAlmostEqual(scalars[name], value, delta=1e-10 * abs(value), msg=name)
        # Scalars are the whole grid's: the same on every process.
        self.assertEqual(len({tuple(sorted(s.items())) for s in COMM.allgather(scalars)}), 1)

    def test_nan_heights_on_one_process_fail_on_every_process(self):
        heights = asperity.self_affine(self.grid, **SURFACE)
        if COMM.rank == COMM.size - 1 and self.local_ny > 0:
            heights[self.local_ny // 2, NX // 3] = np.nan
        failure = None
        with asperity.System(self.grid, 1.0) as system:
            try:
                system.set_topography(heights)
            except asperity.Error as exc:
                failure = exc
            # Every process got the same exception; the grid stays usable on all of them.
            outcomes = COMM.allgather(None if failure is None else
                                      (type(failure).__name__, failure.status, failure.message))
            system.set_topography(asperity.self_affine(self.grid, **SURFACE))
        self.assertIsInstance(failure, asperity.InvalidArgumentError)
        self.assertEqual(len(set(outcomes)), 1, outcomes)
        self.assertIn("on process %d of %d" % (COMM.size - 1, COMM.size), failure.message)


def main():
    runner = unittest.TextTestRunner(
        stream=sys.stderr, verbosity=2 if COMM.rank == 0 else 0)
    result = runner.run(unittest.defaultTestLoader.loadTestsFromTestCase(DistributedGrid))
    failed = COMM.allreduce(0 if result.wasSuccessful() else 1)
    if COMM.rank == 0:
        print("%d of %d processes failed" % (failed, COMM.size))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
