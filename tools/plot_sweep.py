#!/usr/bin/env python3
"""Plot columns of a rollbem sweep (sweep.csv) against a varied key, one PNG (matplotlib, no
display).

Usage: plot_sweep.py SWEEP_DIR[=label] [SWEEP_DIR[=label] ...] --x KEY --y COLUMN [--y COLUMN]
                     [--x-scale FACTOR] [--x-label TEXT] [--logx] -o picture.png

--x is a `--vary` key of the sweep (its column in sweep.csv), --y any result column
(docs/outputs.md lists them: rolling_resistance, pressure_centre, creep, ...). --x-scale
multiplies the x values (e.g. by tau_c/a to plot against V*tau_c/a). Failed runs are skipped;
the script exits 1 if a sweep has no run to plot.
"""
import os
import sys

# tools/inspect.py is named like the standard library's `inspect`, which numpy imports: keep
# this folder off the module path.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import argparse
import csv
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only: no display, no X server
import matplotlib.pyplot as plt

MARKERS = ["o", "s", "^", "D", "v"]


def read(sweep, x, ys):
    path = Path(sweep) / "sweep.csv"
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["status"] == "ok"]
    for key in [x, *ys]:
        if rows and key not in rows[0]:
            sys.exit(f"{path}: no column `{key}` (columns: {', '.join(rows[0])})")
    if not rows:
        sys.exit(f"{path}: no converged run to plot")
    return [(float(r[x]), [float(r[y]) for y in ys]) for r in rows]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("sweeps", nargs="+", help="sweep folders, each optionally =label")
    ap.add_argument("--x", required=True, help="the varied key, e.g. load.speed")
    ap.add_argument("--y", action="append", required=True, help="a result column of sweep.csv")
    ap.add_argument("--x-scale", type=float, default=1.0, help="factor applied to the x values")
    ap.add_argument("--x-label", help="axis label (default: the key)")
    ap.add_argument("--logx", action="store_true", help="logarithmic x axis")
    ap.add_argument("-o", "--output", required=True, help="PNG to write")
    args = ap.parse_args()
    fig, axes = plt.subplots(len(args.y), 1, figsize=(7, 3.2 * len(args.y)), squeeze=False)
    for k, spec in enumerate(args.sweeps):
        folder, _, label = spec.partition("=")
        points = sorted(read(folder, args.x, args.y))
        xs = [p[0] * args.x_scale for p in points]
        for j, y in enumerate(args.y):
            ax = axes[j][0]
            ax.plot(xs, [p[1][j] for p in points], marker=MARKERS[k % len(MARKERS)], label=label or folder)
            ax.set_ylabel(y)
            ax.grid(True, alpha=0.3)
            if args.logx:
                ax.set_xscale("log")
    axes[-1][0].set_xlabel(args.x_label or args.x)
    axes[0][0].legend(loc="best")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


if __name__ == "__main__":
    main()
