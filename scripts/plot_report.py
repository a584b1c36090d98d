#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Draws a follow run's report: paths of the person (ground truth), the estimate and the
robot in the world frame, and the gap and speeds over time (like the thesis's Figures
5.29-5.30). Reads <report_dir>/trajectory.csv and metrics.json, writes report.png."""
import csv
import json
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no samples")
    return rows


def num(row, key):
    value = row[key]
    return float(value) if value != "" else math.nan


def main(report_dir, follow_distance=1.6, safe_distance=1.3):
    report = Path(report_dir)
    rows = load(report / "trajectory.csv")
    metrics = json.loads((report / "metrics.json").read_text())
    t0 = num(rows[0], "t")
    t = [num(r, "t") - t0 for r in rows]
    rx = [num(r, "robot_x") for r in rows]
    ry = [num(r, "robot_y") for r in rows]
    tx = [num(r, "target_x") for r in rows]
    ty = [num(r, "target_y") for r in rows]
    # The estimate is in the robot frame: rotate and shift it into the world frame.
    ex, ey = [], []
    for r in rows:
        x, y = num(r, "estimate_x"), num(r, "estimate_y")
        yaw = num(r, "robot_yaw")
        ex.append(num(r, "robot_x") + math.cos(yaw) * x - math.sin(yaw) * y)
        ey.append(num(r, "robot_y") + math.sin(yaw) * x + math.cos(yaw) * y)
    gap = [math.hypot(a - c, b - d) for a, b, c, d in zip(tx, ty, rx, ry)]

    fig, (ax_path, ax_gap) = plt.subplots(1, 2, figsize=(13, 5.5))
    ax_path.plot(tx, ty, "k-", lw=2, label="person (ground truth)")
    ax_path.plot(ex, ey, ".", color="tab:blue", ms=2, alpha=0.5, label="estimate")
    ax_path.plot(rx, ry, "-", color="tab:red", lw=1.5, label="robot")
    ax_path.plot(rx[0], ry[0], "o", color="tab:red")
    ax_path.plot(tx[0], ty[0], "o", color="k")
    ax_path.set_aspect("equal", adjustable="datalim")
    ax_path.set_xlabel("x [m]")
    ax_path.set_ylabel("y [m]")
    ax_path.set_title("Paths in the odometry frame")
    ax_path.grid(True, alpha=0.3)
    ax_path.legend(loc="best")

    ax_gap.plot(t, gap, "k-", label="gap robot-person")
    ax_gap.axhline(follow_distance, color="tab:green", ls="--", label=f"follow distance {follow_distance} m")
    ax_gap.axhline(safe_distance, color="tab:red", ls=":", label=f"safe distance {safe_distance} m")
    ax_speed = ax_gap.twinx()
    ax_speed.plot(t, [num(r, "robot_speed") for r in rows], color="tab:red", alpha=0.6, label="robot speed")
    ax_speed.plot(t, [num(r, "target_speed") for r in rows], color="tab:gray", alpha=0.6, label="person speed")
    ax_speed.set_ylabel("speed [m/s]")
    ax_gap.set_xlabel("time [s]")
    ax_gap.set_ylabel("gap [m]")
    ax_gap.grid(True, alpha=0.3)
    lines = ax_gap.get_legend_handles_labels()
    lines2 = ax_speed.get_legend_handles_labels()
    ax_gap.legend(lines[0] + lines2[0], lines[1] + lines2[1], loc="upper right", fontsize=8)
    err = metrics.get("estimate_error_median_m")
    within = metrics.get("gap_within_tolerance")
    ax_gap.set_title(
        "Gap and speed; median estimate error "
        + (f"{err:.2f} m" if err is not None else "n/a")
        + ", gap within tolerance "
        + (f"{100 * within:.0f} %" if within is not None else "n/a"))
    fig.tight_layout()
    out = report / "report.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        raise SystemExit("usage: plot_report.py REPORT_DIR [follow_distance safe_distance]")
    main(sys.argv[1], *(float(a) for a in sys.argv[2:4]))
