#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Markdown tables for scripts/results.sh from the tools' raw outputs.

  results_tables.py bench BENCH.json          locator solve vs the thesis's, mirror test
  results_tables.py homing-range OUT...       range over lab homing_experiment outputs
  results_tables.py placement DIR...          rings of placement_advisor summaries
  results_tables.py offline-speed LOG...      replay speed of locator_offline runs
  results_tables.py median X...               median of numbers
"""
import json
import os
import re
import statistics
import sys


def bench(path):
    """Google Benchmark JSON (aggregates) -> two tables with same-run ratios."""
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        rows[b["run_name"]] = b
    ctx = data["context"]
    print("Medians of %d repetitions; machine: %d CPUs at %.0f MHz, load average %s.\n" % (
        rows and next(iter(rows.values())).get("repetitions", 0), ctx["num_cpus"],
        ctx["mhz_per_cpu"], " ".join("%.2f" % x for x in ctx.get("load_avg", []))))
    print("| case | locator solve (us, mean) | p50 / p99 (us) | thesis's solve (us, mean) "
          "| p50 / p99 (us) | locator / thesis |")
    print("|---|---|---|---|---|---|")
    for name in ("spot_twr", "tracked", "cube_1_bearing", "spot_1_bearing", "spot_all_in_fov"):
        ours = rows.get("solve/" + name)
        theirs = rows.get("thesisSolve/" + name)
        if not ours or not theirs:
            continue
        print("| %s | %.1f | %.1f / %.1f | %.1f | %.1f / %.1f | %.2f |" % (
            name, ours["real_time"], ours["p50_us"], ours["p99_us"], theirs["real_time"],
            theirs["p50_us"], theirs["p99_us"], ours["real_time"] / theirs["real_time"]))
    print()
    print("| layout | Locator::update, mirror test off (us, mean) | p50 / p99 (us) "
          "| mirror test on (default) (us, mean) | p50 / p99 (us) | on / off |")
    print("|---|---|---|---|---|---|")
    for name in ("spot", "spot_twr"):
        off = rows.get("locatorUpdate/%s/0" % name)
        on = rows.get("locatorUpdate/%s/2" % name)
        if not off or not on:
            continue
        print("| %s | %.1f | %.1f / %.1f | %.1f | %.1f / %.1f | %.2f |" % (
            name, off["real_time"], off["p50_us"], off["p99_us"], on["real_time"],
            on["p50_us"], on["p99_us"], on["real_time"] / off["real_time"]))


def parse_table(text):
    """Rows of a Markdown table as lists of cells (header and rule dropped)."""
    rows = []
    for line in text.splitlines():
        if not line.startswith("|") or line.startswith("| ---") or line.startswith("|---"):
            continue
        rows.append([c.strip() for c in line.strip().strip("|").split("|")])
    return rows[1:]


def span(values):
    lo, hi = min(values), max(values)
    return lo if lo == hi else "%s-%s" % (lo, hi)


def homing_range(paths):
    tables = []
    for p in paths:
        with open(p) as f:
            tables.append([r for r in parse_table(f.read()) if r[0] != "seed 000"])
    print("| config | success % | time s | net vel. m/s | goal err. m | final err. m | path eff. |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for i, row in enumerate(tables[0]):
        cells = [row[0]]
        for col in range(1, len(row)):
            values = sorted({t[i][col] for t in tables}, key=float)
            cells.append(span(values))
        print("| " + " | ".join(cells) + " |")
    goal5 = [t[-1][4] for t in tables]
    print("\nconfiguration 5's goal error by target set (seed 1..%d): %s" % (
        len(tables), ", ".join(goal5)))


def placement(dirs):
    print("| layout | bound | 2 m median / worst | 4 m | 8 m | weak sectors | warnings |")
    print("|---|---|---|---|---|---|---|")
    for d in dirs:
        order = ["spot", "spot_twr", "tracked", "cube"]
        names = [n for n in os.listdir(d) if n.endswith("_summary.json")]
        names.sort(key=lambda n: (order.index(n[:-13]) if n[:-13] in order else len(order), n))
        for name in names:
            with open(os.path.join(d, name)) as f:
                s = json.load(f)
            rings = []
            for r in s["rings"]:
                worst = "%.3f" % r["worst"] if r["unobservable_fraction"] == 0 else (
                    "unobservable on %.0f %%" % (100 * r["unobservable_fraction"]))
                rings.append("%.3f / %s" % (r["median"], worst))
            weak = ", ".join(
                "%+.1f deg (%s)" % (x["centre_deg"], "unobservable" if x["worst_ratio"] is None
                                    else "%.1fx" % x["worst_ratio"])
                for x in s["sectors"] if x["weak"]) or "none"
            print("| %s | %s | %s | %d |" % (
                s["layout"], "2D" if s["planar"] else "3D", " | ".join(rings + [weak]),
                len(s["warnings"])))


def offline_speed(paths):
    walls, speeds = [], []
    for p in paths:
        with open(p) as f:
            m = re.search(r"replayed in ([0-9.e-]+) s \(([0-9.e+]+) x real time\)", f.read())
        if m:
            walls.append(float(m.group(1)))
            speeds.append(float(m.group(2)))
    print("%.4f %.0f %.0f %.0f" % (statistics.median(walls), statistics.median(speeds),
                                   min(speeds), max(speeds)))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    cmd, args = sys.argv[1], sys.argv[2:]
    if cmd == "bench":
        bench(args[0])
    elif cmd == "homing-range":
        homing_range(args)
    elif cmd == "placement":
        placement(args)
    elif cmd == "offline-speed":
        offline_speed(args)
    elif cmd == "median":
        print("%.4g" % statistics.median(float(x) for x in args))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
