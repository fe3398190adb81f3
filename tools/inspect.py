#!/usr/bin/env python3
"""Render a rollbem result to a PNG, off-screen, with pyvista.

Usage: inspect.py RUN_DIR [-o picture.png]

Top: the contact line coloured by node state (0 open, 1 stick, 2 slip), with the traction
vectors (q, p) drawn as arrows. Bottom: pressure, shear and the friction bounds ±mu p along x,
and the slip (finite difference and, where present, the boundary-integral slip_hbem). Bodies
warped by their displacement and interior stress maps are added when the run has them
(`boundary_*.vtu`, `interior_*.vtu`).
"""
import os
import sys

# This file is named like the standard library's `inspect`, which numpy and pyvista import:
# drop its own folder from the module path before importing them.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import argparse  # noqa: E402
import json  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pyvista as pv  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir", type=Path)
    ap.add_argument("-o", "--output", type=Path, default=None, help="PNG file (default RUN_DIR/inspect.png)")
    args = ap.parse_args()
    d = args.run_dir
    out = args.output or d / "inspect.png"
    summary = json.loads((d / "summary.json").read_text())
    mu = summary["case"]["contact"]["friction"]
    line = pv.read(d / "contact.vtu")
    x = np.asarray(line.points)[:, 0]
    p, q, slip = (np.asarray(line[k]) for k in ("pressure", "shear", "slip"))

    pv.OFF_SCREEN = True
    plotter = pv.Plotter(off_screen=True, shape=(3, 1), window_size=(1200, 1200))

    plotter.subplot(0, 0)
    plotter.add_text(summary.get("title", ""), font_size=10)
    extent = x.max() - x.min()
    scale = 0.3 * extent / max(p.max(), 1e-300)
    tractions = np.asarray(line["traction"]) * scale
    plotter.add_mesh(line, scalars="state", line_width=6, cmap=["gray", "royalblue", "orangered"], clim=[0, 2],
                     scalar_bar_args={"title": "state (0 open, 1 stick, 2 slip)"})
    plotter.add_arrows(np.asarray(line.points), tractions, color="black")
    plotter.view_xy()
    bodies = [pv.read(b) for b in sorted(d.glob("boundary_*.vtu"))]
    if bodies:
        # The bodies, warped by their (real) displacement magnified so that the largest one is
        # 3 % of the picture; the factor is printed on the picture.
        plotter.subplot(0, 0)
        plotter.clear()
        size = max(np.ptp(np.asarray(b.points), axis=0).max() for b in bodies)
        umax = max(np.abs(np.asarray(b["displacement"])).max() for b in bodies)
        factor = 0.03 * size / max(umax, 1e-300)
        for b in bodies:
            plotter.add_mesh(b, color="lightgray", line_width=1)
            warped = b.warp_by_vector("displacement", factor=factor)
            warped["|traction|"] = np.linalg.norm(np.asarray(b["traction"]), axis=1)
            plotter.add_mesh(warped, scalars="|traction|", line_width=4, cmap="viridis")
        plotter.add_text(f"{summary.get('title', '')}\nbodies warped by displacement x {factor:.3g}", font_size=9)
        plotter.view_xy()

    plotter.subplot(1, 0)
    chart = pv.Chart2D(x_label="x", y_label="traction")
    chart.line(x, p, color="blue", width=2, label="pressure p")
    chart.line(x, q, color="red", width=2, label="shear q")
    chart.line(x, mu * p, color="gray", style="--", label="+mu p")
    chart.line(x, -mu * p, color="gray", style="--", label="-mu p")
    plotter.add_chart(chart)

    plotter.subplot(2, 0)
    chart = pv.Chart2D(x_label="x", y_label="slip / |V|")
    contact = p > 0
    chart.line(x[contact], slip[contact], color="green", width=2, label="slip (finite difference)")
    if "slip_hbem" in line.array_names:
        chart.scatter(x[contact], np.asarray(line["slip_hbem"])[contact], color="magenta", size=6, label="slip (boundary integral)")
    plotter.add_chart(chart)

    for interior in sorted(d.glob("interior_*.vt*")):
        print(f"note: {interior.name} present; open it in ParaView for the stress map")
    plotter.screenshot(str(out))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
