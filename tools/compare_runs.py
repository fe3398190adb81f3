#!/usr/bin/env python3
"""Overlay the contact results of two or more rollbem runs in one PNG (matplotlib, no display).

Usage: compare_runs.py RUN_DIR[=label] RUN_DIR[=label] ... -o picture.png [--centre]

Top: pressure and shear (with +-mu p of the first run); bottom: slip, all along x. Units are
the runs' own (summary.json `units`). --centre plots each run against x - x_c, x_c its contact
centre (summary.json): the tangential load shifts the contact of a tyred cylinder, and the paper
(Fig. 12) compares the curves centred.
"""
import os
import sys

# tools/inspect.py is named like the standard library's `inspect`, which numpy imports: keep
# this folder off the module path.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import argparse
import csv
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only: no display, no X server
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import ScalarFormatter

COLOURS = ["tab:blue", "tab:red", "tab:green", "tab:purple", "tab:orange"]


def read(run):
    with open(Path(run) / "contact.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    cols = {k: np.array([float(r[k]) for r in rows]) for k in ("x", "pressure", "shear", "slip")}
    cols["summary"] = json.loads((Path(run) / "summary.json").read_text())
    return cols


def unit(summary, key, default):
    """The unit summary.json gives a quantity (e.g. `pressure`: N/mm^2), else `default`."""
    return summary.get("units", {}).get(key, default)


def scientific(axis):
    """Tick labels as a x 10^k with the exponent shown once, not -0.0001, -0.0006, ..."""
    formatter = ScalarFormatter(useMathText=True)
    formatter.set_powerlimits((-3, 3))
    axis.set_major_formatter(formatter)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("-o", "--output", type=Path, required=True)
    ap.add_argument("--centre", action="store_true", help="plot against x - x_c (contact centre)")
    args = ap.parse_args()
    runs = []
    for spec in args.runs:
        path, _, label = spec.partition("=")
        run = read(path)
        if args.centre:
            c = run["summary"]["contact"]
            centre = 0.5 * (c["x_min"] + c["x_max"])
            run["x"] = run["x"] - centre
            label = f"{label or Path(path).name} (centre {centre:+.3f})"
        runs.append((label or Path(path).name, run))
    first = runs[0][1]
    summary = first["summary"]
    length = unit(summary, "contact.x_min", "mm")
    stress = unit(summary, "max_pressure", "N/mm^2")
    x_label = f"x - x_c [{length}]" if args.centre else f"x [{length}]"
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(12, 9), sharex=True)
    mu = summary["case"]["contact"]["friction"]
    top.plot(first["x"], mu * first["pressure"], color="gray", ls="--", lw=1, label=r"$\pm\mu p$ (first run)")
    top.plot(first["x"], -mu * first["pressure"], color="gray", ls="--", lw=1)
    for k, (label, r) in enumerate(runs):
        c = COLOURS[k % len(COLOURS)]
        top.plot(r["x"], r["pressure"], color=c, lw=2, label=f"p, {label}")
        top.plot(r["x"], r["shear"], color=c, lw=2, ls="-." if k else ":", label=f"q, {label}")
    top.set_ylabel(f"traction [{stress}]")
    for k, (label, r) in enumerate(runs):
        inside = r["pressure"] > 0
        bottom.plot(r["x"][inside], r["slip"][inside], color=COLOURS[k % len(COLOURS)], lw=2, label=f"slip, {label}")
    bottom.set_ylabel("slip / |V|")
    bottom.set_xlabel(x_label)
    for ax in (top, bottom):
        scientific(ax.yaxis)
        ax.grid(alpha=0.3)
        # Beside the axes, so that no curve is hidden behind the legend.
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
