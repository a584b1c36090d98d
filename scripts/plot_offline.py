#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Draws a locator_offline result: estimate and ground truth in the robot frame, the
error over time, and the median / 95th-percentile error by direction (the thesis's
Figures 5.10-5.13 break the error down the same way). Reads <dir>/estimates.csv and
summary.json, writes <dir>/offline.png."""
import csv
import json
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def num(row, key):
    value = row[key]
    return float(value) if value != "" else math.nan


def main(out_dir):
    out = Path(out_dir)
    with open(out / "estimates.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{out}/estimates.csv: no rows")
    summary = json.loads((out / "summary.json").read_text())
    t0 = num(rows[0], "t")
    fig, (paths, errors, sectors) = plt.subplots(1, 3, figsize=(16, 5))

    paths.plot([num(r, "truth_y") for r in rows], [num(r, "truth_x") for r in rows], "k-",
               lw=1.5, label="ground truth")
    paths.plot([num(r, "y") for r in rows], [num(r, "x") for r in rows], ".", ms=2,
               color="tab:blue", label="estimate")
    paths.plot([0], [0], "s", color="tab:red", label="robot")
    paths.invert_xaxis()  # y (left) to the left, as seen from above with x ahead
    paths.set_xlabel("y, left [m]")
    paths.set_ylabel("x, ahead [m]")
    paths.set_title("Target in the robot frame")
    paths.axis("equal")
    paths.grid(alpha=0.3)
    paths.legend(loc="best", fontsize=8)

    errors.plot([num(r, "t") - t0 for r in rows], [num(r, "error") for r in rows], "-",
                lw=0.8, color="tab:blue")
    overall = summary["overall"]
    errors.set_title("Error: median {:.3f} m, p95 {:.3f} m".format(
        overall["median_m"] or math.nan, overall["p95_m"] or math.nan))
    errors.set_xlabel("time [s]")
    errors.set_ylabel("position error [m]")
    errors.grid(alpha=0.3)

    centres = [s["center_deg"] for s in summary["by_sector"]]
    med = [s["errors"]["median_m"] or 0.0 for s in summary["by_sector"]]
    p95 = [s["errors"]["p95_m"] or 0.0 for s in summary["by_sector"]]
    counts = [s["errors"]["count"] for s in summary["by_sector"]]
    x = range(len(centres))
    sectors.bar([i - 0.2 for i in x], med, width=0.4, label="median")
    sectors.bar([i + 0.2 for i in x], p95, width=0.4, label="95th percentile")
    sectors.set_xticks(list(x))
    sectors.set_xticklabels([f"{c}°\n({n})" for c, n in zip(centres, counts)], fontsize=8)
    sectors.set_xlabel("direction of the target (CCW from ahead), samples")
    sectors.set_ylabel("error [m]")
    sectors.set_title("Error by direction")
    sectors.legend(fontsize=8)
    sectors.grid(alpha=0.3, axis="y")

    fig.tight_layout()
    fig.savefig(out / "offline.png", dpi=100)
    print(f"wrote {out / 'offline.png'}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit("usage: plot_offline.py DIR (locator_offline --out DIR)")
    main(sys.argv[1])
