#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Heat map of a placement_advisor result: sqrt(trace(CRLB)) of the target position over
the grid around the robot on a log colour scale, rings at the summary radii, and an inset
with the sensors on the robot (TWR modules as dots, AoA boards as arrows with their field
of view). With two summaries: both maps on one colour scale and the ratio second/first.

    plot_placement.py DIR/<layout>_summary.json [DIR/<other>_summary.json] --out MAP.png
"""
import argparse
import csv
import json
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm, TwoSlopeNorm  # noqa: E402
from matplotlib.patches import Wedge  # noqa: E402


LOG_TICKS = [k * 10.0**e for e in range(-3, 2) for k in (1, 2, 5)]


def load(summary_path):
    summary = json.loads(Path(summary_path).read_text())
    rows = list(csv.DictReader(open(Path(summary_path).parent / summary["map_csv"], newline="")))
    if not rows:
        raise SystemExit(f"{summary['map_csv']}: empty map")
    xs = sorted({float(r["x"]) for r in rows})
    n = len(xs)
    if len(rows) != n * n:
        raise SystemExit(f"{summary['map_csv']}: not a square grid")
    bound = np.array([float(r["rms_bound"]) for r in rows]).reshape(n, n)
    bound[~np.isfinite(bound)] = np.nan  # unobservable cells are drawn blank
    return summary, np.array(xs), bound


def edges(centres):
    step = centres[1] - centres[0] if len(centres) > 1 else 1.0
    return np.append(centres - step / 2, centres[-1] + step / 2)


def draw_sensors(ax, summary):
    for m in summary["twr_modules"]:
        ax.plot(m["position"][0], m["position"][1], "o", color="tab:red", ms=5)
    for b in summary["aoa_boards"]:
        x, y = b["position"][:2]
        yaw, fov = b["yaw_deg"], b["field_of_view_deg"]
        ax.add_patch(Wedge((x, y), 0.25, yaw - fov, yaw + fov, color="tab:blue", alpha=0.15))
        ax.annotate("", xy=(x + 0.15 * math.cos(math.radians(yaw)),
                            y + 0.15 * math.sin(math.radians(yaw))),
                    xytext=(x, y), arrowprops=dict(arrowstyle="->", color="tab:blue", lw=1.5))


def draw_map(fig, ax, summary, xs, values, norm, cmap, label):
    e = edges(xs)
    mesh = ax.pcolormesh(e, e, values, norm=norm, cmap=cmap, shading="flat")
    for ring in summary["rings"]:
        ax.add_patch(plt.Circle((0, 0), ring["radius"], fill=False, ls="--", lw=0.8, color="w"))
    ax.set_aspect("equal")
    ax.set_xlabel("x (ahead) [m]")
    ax.set_ylabel("y (left) [m]")
    bar = fig.colorbar(mesh, ax=ax, label=label, shrink=0.8)
    if isinstance(norm, LogNorm):
        ticks = [t for t in LOG_TICKS if norm.vmin <= t <= norm.vmax]
        bar.set_ticks(ticks)
        bar.set_ticklabels([f"{t:g}" for t in ticks])
    inset = ax.inset_axes([0.69, 0.69, 0.3, 0.3])
    inset.set_facecolor("white")
    draw_sensors(inset, summary)
    inset.set_xlim(-0.6, 0.6)
    inset.set_ylim(-0.6, 0.6)
    inset.set_aspect("equal")
    inset.tick_params(labelsize=6)
    inset.set_title("sensors [m]", fontsize=7)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("summaries", nargs="+", help="one or two *_summary.json files")
    parser.add_argument("--out", required=True, help="PNG to write")
    args = parser.parse_args()
    if len(args.summaries) > 2:
        parser.error("at most two summaries")
    maps = [load(p) for p in args.summaries]
    finite = np.concatenate([m[2][np.isfinite(m[2])] for m in maps])
    if finite.size == 0:
        raise SystemExit("the position is unobservable everywhere: nothing to draw")
    norm = LogNorm(vmin=max(finite.min(), 1e-4), vmax=finite.max())
    columns = len(maps) + (1 if len(maps) == 2 else 0)
    fig, axes = plt.subplots(1, columns, figsize=(6.2 * columns, 5.4), squeeze=False)
    mode = "2D" if maps[0][0]["planar"] else "3D"
    for ax, (summary, xs, bound) in zip(axes[0], maps):
        draw_map(fig, ax, summary, xs, bound, norm, "viridis", "sqrt(tr CRLB) [m]")
        ax.set_title(f"{summary['layout']}: {mode} bound, tag at {summary['height']:.2f} m")
    if len(maps) == 2:
        (s0, xs0, b0), (s1, xs1, b1) = maps
        if len(xs0) != len(xs1) or not np.allclose(xs0, xs1):
            raise SystemExit("the two maps have different grids")
        ratio = b1 / b0
        finite_ratio = ratio[np.isfinite(ratio)]
        span = max(abs(math.log10(finite_ratio.min())), abs(math.log10(finite_ratio.max())), 0.1)
        ratio_norm = TwoSlopeNorm(vcenter=0.0, vmin=-span, vmax=span)
        ax = axes[0][2]
        draw_map(fig, ax, s1, xs0, np.log10(ratio), ratio_norm, "RdBu_r",
                 f"log10({s1['layout']} / {s0['layout']})")
        ax.set_title(f"ratio: blue = {s1['layout']} better")
    fig.tight_layout()
    fig.savefig(args.out, dpi=90)


if __name__ == "__main__":
    main()
