# SPDX-License-Identifier: GPL-2.0-or-later
"""Solver.get: every report key by name and by ASP_REPORT_* constant gives what the solver's
properties (the getters of their own) give, whole numbers as int; names and keys of no report
figure, and a solver without a report, are refused."""
import unittest

import numpy as np

import asperity


class SolverReport(unittest.TestCase):

    def setUp(self):
        n = 32
        grid = asperity.Grid(n, n, 1.0, 1.0)
        self.system = asperity.System(grid, 1.0)
        self.system.topography = asperity.self_affine(grid, 0.8, 1.0, 0.5, 4.0 / n,
                                                      normalise="rms_slope", target=0.1,
                                                      seed=3)

    def check_agrees(self, solver):
        report = solver.report()
        properties = {
            "termination": report.termination_code, "converged": int(report.converged),
            "iterations": report.iterations, "evaluations": report.evaluations,
            "transforms": report.transforms, "final_error": report.final_error,
            "elapsed_seconds": report.elapsed_seconds,
            "history_length": len(solver.history["iteration"]),
        }
        self.assertEqual(set(properties), set(asperity.REPORT_KEYS))
        for name, expected in properties.items():
            by_name = solver.get(name)
            by_key = solver.get(asperity.REPORT_KEYS[name])
            self.assertEqual(by_name, expected, name)
            self.assertEqual(by_key, expected, name)
            self.assertIs(type(by_name), float if name in ("final_error", "elapsed_seconds")
                          else int, name)
        self.assertEqual(solver.get("REPORT_ITERATIONS"), report.iterations)
        self.assertEqual(solver.history_length, properties["history_length"])
        self.assertGreater(report.iterations, 0)

    def test_every_key_agrees_with_the_properties(self):
        solver = asperity.Solver("pk")
        solver.set_history(True)
        solver.solve(self.system, "mean_pressure", 0.005)
        self.assertEqual(solver.termination, "converged")
        self.check_agrees(solver)
        self.assertEqual(solver.get("history_length"), solver.iterations + 1)

        solver.set_history(False)
        solver.max_iterations = 2
        self.system.reset()
        solver.solve(self.system, "mean_pressure", 0.005)
        self.assertEqual(solver.termination, "iteration_limit")
        self.check_agrees(solver)
        self.assertEqual(solver.get("history_length"), 0)

    def test_refusals(self):
        solver = asperity.Solver("pk")
        with self.assertRaisesRegex(asperity.InvalidStateError, "no report"):
            solver.get("iterations")
        solver.solve(self.system, "mean_pressure", 0.005)
        with self.assertRaisesRegex(asperity.InvalidArgumentError, "'iteration'"):
            solver.get("iteration")
        with self.assertRaisesRegex(asperity.InvalidArgumentError, "ASP_HISTORY_ITERATION"):
            solver.get(asperity.HISTORY_ITERATION)
        with self.assertRaisesRegex(asperity.InvalidArgumentError, "'key'.*42"):
            solver.get(42)
        with self.assertRaises(asperity.InvalidArgumentError):
            solver.get(1.5)
        self.assertEqual(solver.get(np.int64(asperity.REPORT_ITERATIONS)), solver.iterations)


if __name__ == "__main__":
    unittest.main()
