#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the simulated calibration run's range calibrations into the shipped layouts:
every TWR module's `calibration` in config/layouts/<name>.yaml becomes what
`lab layout_calibration --layout <name> --hardware-seed N` prints (the realistic sensor
profile's simulated robot N, doc/simulator.md, "Calibration run"). Nothing else in the
files changes. Run it when the ROS demo switches to `sensor_profile: realistic`
(config/simulator.yaml), with that file's `hardware_seed`.

The boards' fitted yaw (`rpy_deg`) is printed by the tool but not written: the ROS
simulator reads the same file as where the boards were meant to be and mounts them
rotated from there, so a corrected yaw in the file would turn the simulated boards by
the error twice. (A real robot's file takes both; the lockstep loop keeps the two layouts
apart, ClosedLoopConfig::locator_layout.)

Usage: calibrate_layouts.py [--hardware-seed N] [--dry-run] [layout ...]   (default: all)
"""
import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
ENTRY = re.compile(r'^(\s*-\s*\{id:\s*"?)([^",}]+)("?.*?)\b(calibration): \[[^\]]*\](.*)$')


def calibrated_entries(tool, layout, hardware_seed):
    """{(field, id): "[...]"} from the tool's output."""
    out = subprocess.run([tool, "layout_calibration", "--layout", layout, "--hardware-seed", str(hardware_seed)],
                         check=True, capture_output=True, text=True).stdout
    entries = {}
    for line in out.splitlines():
        m = ENTRY.match(line)
        if m:
            value = re.search(r"\b%s: (\[[^\]]*\])" % m.group(4), line).group(1)
            entries[(m.group(4), m.group(2))] = value
    return entries


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hardware-seed", type=int, default=1)
    parser.add_argument("--dry-run", action="store_true", help="print, do not write")
    parser.add_argument("layouts", nargs="*")
    args = parser.parse_args()
    tool = os.path.join(os.environ["RF_WS"], "devel/lib/radio_follow/lab")
    names = args.layouts or sorted(p.stem for p in (REPO / "config/layouts").glob("*.yaml"))
    for name in names:
        path = REPO / "config/layouts" / (name + ".yaml")
        entries = calibrated_entries(tool, name, args.hardware_seed)
        lines = path.read_text().splitlines(keepends=True)
        changed = 0
        for i, line in enumerate(lines):
            m = ENTRY.match(line.rstrip("\n"))
            if m and (m.group(4), m.group(2)) in entries:
                field = m.group(4)
                new = re.sub(r"\b%s: \[[^\]]*\]" % field,
                             "%s: %s" % (field, entries[(field, m.group(2))]), line)
                changed += new != line
                lines[i] = new
        if args.dry_run:
            sys.stdout.write("".join(lines))
        else:
            path.write_text("".join(lines))
        print("%s: %d entries changed (hardware seed %d)" % (path, changed, args.hardware_seed),
              file=sys.stderr)


if __name__ == "__main__":
    main()
