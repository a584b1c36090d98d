#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 14's latency baseline: the thesis's position solve as its reference code runs it
(seed 003 eqs 4.15-4.16; ctu-vras/follow_me `radio_locator.py`), re-implemented here with
scipy.optimize.least_squares, side by side with the locator on the same epochs.

Row by row, as bench/thesis_solver.hpp (the same formulation in Ceres):
  - a TWR range: |p - t_i|^2 - r_i^2 (squared distances, no sigma);
  - a bearing: 3 |azimuth error| in radians, the target projected on the board's plane;
  - the height fixed (2D mode): x and y are the unknowns;
least_squares with loss="soft_l1", f_scale 1 and SciPy's defaults otherwise (trust-region
reflective, finite-difference Jacobian, tolerances 1e-8), warm-started like the thesis.

It runs bench_scipy_baseline (which writes the epochs and times the C++ side), solves every
epoch with SciPy, timing each call, and prints a Markdown table: per case, the median and
p99 latency of each and the ratio SciPy / ours.

  python3 bench/thesis_scipy.py "$RF_WS"/devel/lib/radio_follow/bench_scipy_baseline
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time
from collections import OrderedDict

import numpy as np
import scipy
from scipy.optimize import least_squares

BEARING_WEIGHT = 3.0  # radio_locator.py: 3 * |angle|
WARM_UP = 20  # epochs of each pass left out, as in bench_scipy_baseline


class Epoch:
    def __init__(self):
        self.start = None
        self.modules = []
        self.ranges = []
        self.boards = []
        self.rotations = []
        self.azimuths = []

    def arrays(self):
        self.modules = np.array(self.modules).reshape(-1, 3)
        self.ranges = np.array(self.ranges)
        self.boards = np.array(self.boards).reshape(-1, 3)
        self.rotations = np.array(self.rotations).reshape(-1, 3, 3)
        self.azimuths = np.array(self.azimuths)


def read_epochs(path):
    """{case: [Epoch]} from bench_scipy_baseline's file."""
    cases = OrderedDict()
    with open(path) as f:
        for row in csv.reader(line for line in f if not line.startswith("#")):
            kind, case, k = row[0], row[1], int(row[2])
            values = [float(v) for v in row[3:]]
            epochs = cases.setdefault(case, [])
            while len(epochs) <= k:
                epochs.append(Epoch())
            e = epochs[k]
            if kind == "start":
                e.start = np.array(values[:3])
            elif kind == "range":
                e.modules.append(values[:3])
                e.ranges.append(values[3])
            elif kind == "bearing":
                e.boards.append(values[:3])
                e.azimuths.append(values[3])
                e.rotations.append(values[4:13])
            else:
                raise ValueError("unknown row kind %r in %s" % (kind, path))
    for epochs in cases.values():
        for e in epochs:
            e.arrays()
    return cases


def residuals(xy, e, height):
    """The thesis's rows for the position (xy[0], xy[1], height)."""
    p = np.array([xy[0], xy[1], height])
    rows = np.sum((p - e.modules) ** 2, axis=1) - e.ranges**2
    if len(e.azimuths):
        # Target in each board's frame (R^T (p - board)), projected on the board's plane.
        v = np.einsum("kji,kj->ki", e.rotations, p - e.boards)
        error = np.arctan2(v[:, 1], v[:, 0]) - e.azimuths
        error = np.arctan2(np.sin(error), np.cos(error))
        rows = np.concatenate((rows, BEARING_WEIGHT * np.abs(error)))
    return rows


def solve(e):
    """The thesis's call: warm-started, soft_l1 at f_scale 1, everything else SciPy's default."""
    return least_squares(residuals, e.start[:2], loss="soft_l1", f_scale=1.0, args=(e, e.start[2]))


def percentile(sorted_values, q):
    return sorted_values[int(q * (len(sorted_values) - 1))]


def time_scipy(epochs, passes):
    micros = []
    failures = 0
    for _ in range(passes):
        for k, e in enumerate(epochs):
            start = time.perf_counter()
            result = solve(e)
            elapsed = time.perf_counter() - start
            failures += not result.success
            if k >= WARM_UP:
                micros.append(1e6 * elapsed)
    micros.sort()
    return {
        "samples": len(micros),
        "median_us": percentile(micros, 0.5),
        "p99_us": percentile(micros, 0.99),
        "mean_us": sum(micros) / len(micros),
        "failures": failures,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("bench", help="path of bench_scipy_baseline")
    parser.add_argument("--passes", type=int, default=5, help="C++ passes over the epochs")
    parser.add_argument("--scipy-passes", type=int, default=1, help="SciPy passes")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "epochs.csv")
        out = subprocess.run(
            [args.bench, path, "--passes", str(args.passes)],
            check=True,
            stdout=subprocess.PIPE,
            universal_newlines=True,
        ).stdout
        cpp = {}
        for row in csv.DictReader(out.splitlines()):
            cpp[(row["case"], row["estimator"])] = {
                k: float(row[k]) for k in ("samples", "median_us", "p99_us", "mean_us")
            }
        cases = read_epochs(path)

    print(
        "SciPy %s, NumPy %s, Python %s; epochs per case %d (the first %d of each pass left out); "
        "C++ passes %d, SciPy passes %d."
        % (
            scipy.__version__,
            np.__version__,
            sys.version.split()[0],
            len(next(iter(cases.values()))),
            WARM_UP,
            args.passes,
            args.scipy_passes,
        )
    )
    print()
    names = OrderedDict(
        [
            ("locator_update_particle", "Locator::update, particle (shipped default)"),
            ("locator_update_solver", "Locator::update, solver estimator"),
            ("locator_solve", "PositionSolver::solve (the locator's solve alone)"),
            ("thesis_ceres", "thesis formulation in Ceres (thesis_solver.hpp)"),
        ]
    )
    print(
        "| case | SciPy solve median / p99 (us) | SciPy failures | ours | "
        "ours median / p99 (us) | SciPy / ours, median | SciPy / ours, p99 |"
    )
    print("|---|---|---|---|---|---|---|")
    for case, epochs in cases.items():
        s = time_scipy(epochs, args.scipy_passes)
        for key, label in names.items():
            c = cpp[(case, key)]
            print(
                "| %s | %.0f / %.0f | %d | %s | %.1f / %.1f | %.1f | %.1f |"
                % (
                    case,
                    s["median_us"],
                    s["p99_us"],
                    s["failures"],
                    label,
                    c["median_us"],
                    c["p99_us"],
                    s["median_us"] / c["median_us"],
                    s["p99_us"] / c["p99_us"],
                )
            )


if __name__ == "__main__":
    main()
