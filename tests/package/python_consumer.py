# SPDX-License-Identifier: GPL-2.0-or-later
"""The packaged Python module against the packaged library: a small rough contact solved by
pk, and the same contact's mean pressure read back from the field."""
import asperity

grid = asperity.Grid(64, 64, 1.0, 1.0)
heights = asperity.self_affine(grid, hurst=0.8, long_cutoff=1.0, rolloff=0.25,
                               short_cutoff=0.125, normalise="rms_slope", target=0.1, seed=1)
system = asperity.System(grid, 1.0)
system.topography = heights
solver = asperity.Solver("pk", tolerance=1e-10)
report = solver.solve(system, "mean_pressure", 0.01)
assert report.converged, report
assert abs(system.pressure.mean() - 0.01) < 1e-12, system.pressure.mean()
print("python:", asperity.version(), "contact fraction", system.contact_fraction)
