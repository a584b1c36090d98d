#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Markdown table of the closed-loop experiments' metrics (doc/experiments.md).

Usage: experiment_table.py REPORT_ROOT
REPORT_ROOT holds one folder per experiment (test/ros/experiments/<name>.test writes
$ROS_HOME/radio_follow_experiments/<name>/metrics.json)."""
import json
import os
import sys

COLUMNS = [
    ("min gap while moving (m)", "min_gap_while_moving_m", "{:.2f}"),
    ("gap held (share)", "gap_within_tolerance", "{:.0%}"),
    ("mean gap (m)", "gap_mean_m", "{:.2f}"),
    ("est. error median (m)", "estimate_error_median_m", "{:.3f}"),
    ("est. error p95 (m)", "estimate_error_p95_m", "{:.3f}"),
    ("path deviation max (m)", "path_deviation_max_m", "{:.2f}"),
    ("NEES median (1.39)", "estimate_nees_median", "{:.2f}"),
    ("inside 95 % ellipse", "estimate_within_95", "{:.2f}"),
]


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("usage: experiment_table.py REPORT_ROOT (a directory)")
    root = sys.argv[1]
    rows = []
    for name in sorted(os.listdir(root)):
        path = os.path.join(root, name, "metrics.json")
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            metrics = json.load(f)
        cells = []
        for _, key, fmt in COLUMNS:
            value = metrics.get(key)
            cells.append("-" if value is None else fmt.format(value))
        rows.append("| {} | {} |".format(name, " | ".join(cells)))
    if not rows:
        sys.exit("no metrics.json under " + root)
    print("| experiment | " + " | ".join(c[0] for c in COLUMNS) + " |")
    print("|---" * (len(COLUMNS) + 1) + "|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
