#!/usr/bin/env python3
"""Overlay the contact results of two or more rollbem runs in one PNG (off-screen pyvista).

Usage: compare_runs.py RUN_DIR[=label] RUN_DIR[=label] ... -o picture.png [--centre]

Top: pressure and shear (with +-mu p of the first run); bottom: slip, all along x.
--centre plots each run against x - x_c, x_c its contact centre (summary.json): the tangential
load shifts the contact of a tyred cylinder, and the paper (Fig. 12) compares the curves centred.
"""
import os
import sys

# tools/inspect.py is named like the standard library's `inspect`, which numpy and pyvista
# import: keep this folder off the module path.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import argparse
import csv
import json
from pathlib import Path

import numpy as np
import pyvista as pv

COLOURS = ["blue", "red", "green", "magenta", "orange"]


def read(run):
    with open(Path(run) / "contact.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    cols = {k: np.array([float(r[k]) for r in rows]) for k in ("x", "pressure", "shear", "slip")}
    cols["summary"] = json.loads((Path(run) / "summary.json").read_text())
    return cols


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
    x_label = "x - x_c [mm]" if args.centre else "x [mm]"
    pv.OFF_SCREEN = True
    plotter = pv.Plotter(off_screen=True, shape=(2, 1), window_size=(1200, 900))
    plotter.subplot(0, 0)
    chart = pv.Chart2D(x_label=x_label, y_label="traction [MPa]")
    mu = runs[0][1]["summary"]["case"]["contact"]["friction"]
    first = runs[0][1]
    chart.line(first["x"], mu * first["pressure"], color="gray", style="--", label="+mu p")
    chart.line(first["x"], -mu * first["pressure"], color="gray", style="--", label="-mu p")
    for k, (label, r) in enumerate(runs):
        c = COLOURS[k % len(COLOURS)]
        chart.line(r["x"], r["pressure"], color=c, width=2, label=f"p, {label}")
        chart.line(r["x"], r["shear"], color=c, width=2, style="-." if k else "-", label=f"q, {label}")
    plotter.add_chart(chart)
    plotter.subplot(1, 0)
    chart = pv.Chart2D(x_label=x_label, y_label="slip / |V|")
    for k, (label, r) in enumerate(runs):
        inside = r["pressure"] > 0
        chart.line(r["x"][inside], r["slip"][inside], color=COLOURS[k % len(COLOURS)], width=2, label=f"slip, {label}")
    plotter.add_chart(chart)
    plotter.screenshot(str(args.output))
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
