#!/usr/bin/env python3
"""Draw a rollbem run folder as one PNG, off-screen: what an engineer looks at first.

The files are read with pyvista (VTK's own reader), the figure is drawn with matplotlib.

Panels, top to bottom (each only when the run has the data):
  * bodies (bem runs, boundary_*.vtu): the whole body, its boundary deformed by its displacement
    (magnified, factor printed) and coloured by |u|; the contact marked; next to it
  * contact zoom: both surfaces along the contact, undeformed (dashed) and deformed (solid), the
    loaded part coloured by state (stick / slip);
  * sub-surface stress maps (interior_*.vtu, `output.interior` of the case): von Mises stress
    and maximum shear stress, filled with contour lines, each maximum marked and given in the
    stress unit and as a fraction of the peak pressure;
  * pressure p along x; shear q with the friction bounds +-mu p, stick and slip zones shaded,
    slip directions and the rolling direction marked;
  * slip velocity over |V| (finite difference; boundary-integral slip_hbem where present), with
    its zero line.
Units come from summary.json (`units`, else the case's `units`, else mm and N).

Example: python tools/inspect.py out/carter_051_block -o carter_block.png
"""
import os
import sys

# This file is named like the standard library's `inspect`, which numpy and pyvista import:
# drop its own folder from the module path before importing them.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import argparse  # noqa: E402
import json  # noqa: E402
from pathlib import Path  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402
import pyvista as pv  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

STICK, SLIP = "#9ecae1", "#fdae6b"  # zone shading (light blue, light orange)
STICK_LINE, SLIP_LINE = "#2171b5", "#e6550d"


def units(summary):
    """(length, force per length, stress) labels."""
    u = summary.get("units")
    case = summary.get("case", {}).get("units") or {}
    length = force = None
    if isinstance(u, dict):
        length, force = u.get("length"), u.get("force")
    length = length or case.get("length") or "mm"
    force = force or case.get("force") or "N"
    stress = u.get("stress") if isinstance(u, dict) and isinstance(u.get("stress"), str) else None
    return length, f"{force}/{length}", stress or f"{force}/{length}²"


def read_line(d):
    line = pv.read(d / "contact.vtu")
    cols = {k: np.asarray(line[k]) for k in line.array_names}
    cols["x"] = np.asarray(line.points)[:, 0]
    return cols


def edges(mesh):
    """Polyline segments of a boundary of quadratic edges (VTK order: end, end, middle)."""
    pts = np.asarray(mesh.points)[:, :2]
    cells = mesh.cells.reshape(-1, 4)[:, 1:]
    return pts, [np.array([c[0], c[2], c[1]]) for c in cells]


def segments(points, cells):
    return [points[c] for c in cells]


def draw_bodies(ax, bodies, length_unit, summary):
    width, height = np.ptp(np.vstack([np.asarray(b.points)[:, :2] for b in bodies]), axis=0)
    to_scale = height > 0.1 * width  # a thin layer or strip drawn to scale is a line
    umax = max(np.abs(np.asarray(b["displacement"])).max() for b in bodies)
    # The largest displacement drawn as 3 % of the picture (of its height when not to scale).
    factor = (0.03 * max(width, height) if to_scale else 0.3 * height) / max(umax, 1e-300)
    collections = []
    for b in bodies:
        pts, cells = edges(b)
        u = np.asarray(b["displacement"])[:, :2]
        ax.add_collection(LineCollection(segments(pts, cells), colors="0.75", linewidths=0.8, linestyles="--"))
        mag = np.linalg.norm(u, axis=1)
        lc = LineCollection(segments(pts + factor * u, cells), cmap="viridis", linewidths=2.2)
        lc.set_array(np.array([mag[c].mean() for c in cells]))
        collections.append(lc)
    vmax = max(np.nanmax(c.get_array()) for c in collections)
    for lc in collections:
        lc.set_clim(0.0, vmax)
        ax.add_collection(lc)
    ax.autoscale()
    if to_scale:
        ax.set_aspect("equal")
    a = summary["contact"]["half_width"] if summary.get("contact") else 0.0
    ax.plot([0], [0], marker="o", ms=14, mfc="none", mec="red", mew=2)
    ax.annotate(
        f"contact, 2a = {2 * a:.3g} {length_unit}\n(zoom on the right)",
        (0, 0),
        xytext=(0.62, 0.55),
        textcoords="axes fraction",
        color="red",
        fontsize=9,
        arrowprops={"arrowstyle": "->", "color": "red"},
    )
    ax.set_xlabel(f"x [{length_unit}]")
    ax.set_ylabel(f"y [{length_unit}]" + ("" if to_scale else " (not to scale with x)"))
    shown = f"{factor:.0f}" if factor >= 10 else f"{factor:.3g}"
    ax.set_title(f"bodies: boundary deformed by u × {shown} (dashed: undeformed)", fontsize=10)
    cb = plt.colorbar(collections[0], ax=ax, shrink=0.85, pad=0.02)
    cb.set_label(f"|u| [{length_unit}]")


def body_radius(summary, body, boundary, half_length):
    """Profile radius of a body near the contact: the case's radius, else a fit of its mesh."""
    spec = summary.get("case", {}).get("bodies", {}).get(body, {})
    if spec.get("radius"):
        return float(spec["radius"])
    if boundary is not None:
        # The contact face: the mesh points within the contact's reach of the x-axis.
        p = np.asarray(boundary.points)[:, :2]
        near = (np.abs(p[:, 0]) <= half_length) & (np.abs(p[:, 1]) <= 0.05 * half_length)
        x, y = p[near, 0], np.abs(p[near, 1])
        if near.sum() >= 3:
            moment = np.sum(x**2 * y)
            if moment <= 1e-9 * np.sum(x**4) / half_length:
                return np.inf  # flat (a block or a layer)
            return float(np.sum(x**4) / (2 * moment))  # least squares of y = x²/(2R)
    return None


def draw_zoom(ax, line, summary, boundaries, length_unit):
    x = line["x"]
    half = 0.5 * (x.max() - x.min())
    overlap = summary.get("overlap", 0.0)
    h = line["u_n_A"] + line["u_n_B"]
    h0 = line["gap"] + overlap - h  # the undeformed gap, g = h0 - delta0 + h
    curv = {}
    for body in "AB":
        r = body_radius(summary, body, boundaries.get(body), half)
        curv[body] = 1.0 / r if r else None  # 1/inf = 0: flat
    if curv["A"] is None or curv["B"] is None:
        share_a = 0.5
    else:
        share_a = curv["A"] / (curv["A"] + curv["B"]) if curv["A"] + curv["B"] > 0 else 0.5
    # Rigid positions: the profiles overlap by delta0, shared like the curvatures. The normal
    # displacements carry a datum (half-space logarithm, shaft of a bem body) that cancels in the
    # gap: shift them by opposite constants so that the surfaces meet near y = 0 at the centre.
    ya0 = share_a * h0 - share_a * overlap
    yb0 = -(1 - share_a) * h0 + (1 - share_a) * overlap
    centre = np.argmin(np.abs(x - summary.get("contact", {}).get("centre", 0.0)))
    shift = line["u_n_A"][centre] - share_a * overlap
    ya, yb = ya0 + line["u_n_A"] - shift, yb0 - line["u_n_B"] - shift
    ax.plot(x, ya0, "--", color="0.55", lw=1, label="undeformed (overlapping by δ0)")
    ax.plot(x, yb0, "--", color="0.55", lw=1)
    ax.plot(x, ya, color="black", lw=1.5, label="deformed")
    ax.plot(x, yb, color="black", lw=1.5)
    state = line["state"]
    for code, colour, name in [(1, STICK_LINE, "stick"), (2, SLIP_LINE, "slip")]:
        yy = np.where(state == code, ya, np.nan)
        ax.plot(x, yy, color=colour, lw=4, solid_capstyle="butt", label=name)
    for y, name, va in [(ya0, "A undeformed", "top"), (yb0, "B undeformed", "bottom"), (ya, "A", "bottom"), (yb, "B", "top")]:
        ax.annotate(name, (x[-1], y[-1]), xytext=(-4, 0), textcoords="offset points", ha="right", va=va, fontsize=8)
    ax.set_xlim(x.min(), x.max())
    ax.set_xlabel(f"x [{length_unit}]")
    ax.set_ylabel(f"y [{length_unit}] (not to scale with x)")
    ax.set_title(f"contact zoom: overlap δ0 = {overlap:.4g} {length_unit}", fontsize=10)
    ax.legend(loc="center", fontsize=8, ncol=2)


def quad_triangles(mesh):
    quads = mesh.cells.reshape(-1, 5)[:, 1:]
    return np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])


def draw_stress(fig, ax, interior, name, label, stress_unit, length_unit, p_ref, surface):
    pts = np.asarray(interior.points)[:, :2]
    values = np.asarray(interior[name])
    tri = mtri.Triangulation(pts[:, 0], pts[:, 1], quad_triangles(interior))
    levels = np.linspace(0.0, values[np.asarray(interior["status"]) == 1].max(), 13)
    filled = ax.tricontourf(tri, values, levels=levels, cmap="magma_r")
    lines = ax.tricontour(tri, values, levels=levels[2::2], colors="black", linewidths=0.6)
    ax.clabel(lines, fmt=lambda v: f"{v:.0f}", fontsize=7)
    inside = np.asarray(interior["status"]) == 1
    k = np.argmax(np.where(inside, values, -np.inf))
    ax.plot(*pts[k], marker="x", color="cyan", ms=10, mew=2.5)
    ax.set_title(
        f"{label}: max {values[k]:.4g} {stress_unit} = {values[k] / p_ref:.3f} p_max\n"
        f"at x = {pts[k, 0]:.3g}, y = {pts[k, 1]:.3g} {length_unit}",
        fontsize=10,
    )
    if surface is not None:
        ax.plot(*surface, color="black", lw=2)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x [{length_unit}]")
    ax.set_ylabel(f"y [{length_unit}]")
    cb = fig.colorbar(filled, ax=ax, shrink=0.9, pad=0.02)
    cb.set_label(f"{label} [{stress_unit}]")
    cb.locator = matplotlib.ticker.MaxNLocator(6)
    cb.update_ticks()


def shade_zones(ax, summary):
    for z in summary.get("zones", []):
        if z["state"] in ("stick", "slip"):
            ax.axvspan(z["x0"], z["x1"], color=STICK if z["state"] == "stick" else SLIP, alpha=0.45, lw=0)


def mark_zones(ax, summary, width):
    """Zone names and slip directions along the top of an axis (zones wider than 6 % of it)."""
    for z in summary.get("zones", []):
        if z["state"] not in ("stick", "slip") or z["x1"] - z["x0"] < 0.06 * width:
            continue
        mid = 0.5 * (z["x0"] + z["x1"])
        text = "stick" if z["state"] == "stick" else ("slip →" if z["direction"] > 0 else "← slip")
        ax.text(mid, 0.04, text, transform=ax.get_xaxis_transform(), ha="center", va="bottom", fontsize=9)


def rolling_note(ax, summary):
    direction = summary.get("case", {}).get("contact", {}).get("rolling_direction", "+x")
    lead = "+a" if direction == "+x" else "−a"
    arrow = "→" if direction == "+x" else "←"
    ax.text(
        0.99, 1.02, f"rolling {arrow} ({direction}); leading edge at x = {lead}",
        transform=ax.transAxes, ha="right", va="bottom", fontsize=9,
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run_dir", type=Path, help="folder written by `rollbem run` (summary.json, contact.vtu, ...)")
    ap.add_argument("-o", "--output", type=Path, default=None, help="PNG file (default RUN_DIR.png beside the run folder: a file inside it would keep rollbem from replacing that result)")
    ap.add_argument("--dpi", type=int, default=100, help="resolution (default 100)")
    args = ap.parse_args()
    d = args.run_dir
    out = args.output or d.parent / (d.resolve().name + ".png")
    summary = json.loads((d / "summary.json").read_text())
    length_unit, _, stress_unit = units(summary)
    mu = summary["case"]["contact"]["friction"]
    line = read_line(d)
    boundaries = {p.stem.split("_")[-1]: pv.read(p) for p in sorted(d.glob("boundary_*.vtu"))}
    interiors = {p.stem.split("_")[-1]: pv.read(p) for p in sorted(d.glob("interior_*.vtu"))}

    rows = (["bodies"] if boundaries else []) + ["stress"] * len(interiors) + ["p", "q", "slip"]
    heights = {"bodies": 4.6, "stress": 4.2, "p": 2.4, "q": 2.4, "slip": 2.2}
    fig = plt.figure(figsize=(13, sum(heights[r] for r in rows) + 0.8), layout="constrained")
    grid = fig.add_gridspec(len(rows), 2, height_ratios=[heights[r] for r in rows])
    fig.suptitle(summary.get("title", d.name), fontsize=13)
    x = line["x"]
    p_ref = max(summary.get("max_pressure") or line["pressure"].max(), 1e-300)
    row = 0
    if boundaries:
        draw_bodies(fig.add_subplot(grid[row, 0]), list(boundaries.values()), length_unit, summary)
        draw_zoom(fig.add_subplot(grid[row, 1]), line, summary, boundaries, length_unit)
        row += 1
    for body, interior in interiors.items():
        h0 = None
        if body in "AB":
            r = body_radius(summary, body, boundaries.get(body), 0.5 * np.ptp(x))
            if r:
                xs = np.linspace(*np.asarray(interior.bounds[:2]), 200)
                sign = 1.0 if body == "A" else -1.0
                h0 = (xs, sign * (r - np.sqrt(np.maximum(r * r - xs * xs, 0.0))))
        for col, (name, label) in enumerate([("von_mises", "von Mises stress"), ("max_shear", "maximum shear stress")]):
            ax = fig.add_subplot(grid[row, col])
            draw_stress(fig, ax, interior, name, f"{label} ({body})", stress_unit, length_unit, p_ref, h0)
        row += 1

    ax_p = fig.add_subplot(grid[row, :])
    shade_zones(ax_p, summary)
    ax_p.plot(x, line["pressure"], color="navy", lw=2, label="pressure p")
    ax_p.set_ylabel(f"p [{stress_unit}]")
    ax_p.set_ylim(bottom=0)
    ax_p.legend(loc="upper left", fontsize=8)
    mark_zones(ax_p, summary, np.ptp(x))
    rolling_note(ax_p, summary)
    ax_q = fig.add_subplot(grid[row + 1, :], sharex=ax_p)
    shade_zones(ax_q, summary)
    ax_q.plot(x, mu * line["pressure"], "--", color="0.4", lw=1, label="±μp")
    ax_q.plot(x, -mu * line["pressure"], "--", color="0.4", lw=1)
    ax_q.plot(x, line["shear"], color="firebrick", lw=2, label="shear q (on A, +x)")
    ax_q.axhline(0, color="black", lw=0.6)
    ax_q.set_ylabel(f"q [{stress_unit}]")
    ax_q.legend(loc="best", fontsize=8, ncol=2)
    ax_s = fig.add_subplot(grid[row + 2, :], sharex=ax_p)
    shade_zones(ax_s, summary)
    contact = line["pressure"] > 0
    ax_s.axhline(0, color="black", lw=0.8)
    ax_s.plot(x[contact], line["slip"][contact], color="darkgreen", lw=2, marker=".", label="slip (finite difference)")
    if "slip_hbem" in line:
        ax_s.plot(x[contact], line["slip_hbem"][contact], "o", mfc="none", color="magenta", ms=5,
                  label="slip (boundary integral)")
    ax_s.set_ylabel("slip / |V| [-]")
    ax_s.set_xlabel(f"x [{length_unit}]")
    ax_s.legend(loc="best", fontsize=8, ncol=2)
    ax_s.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3))
    for ax in (ax_p, ax_q):
        plt.setp(ax.get_xticklabels(), visible=False)
    ax_p.set_xlim(x.min(), x.max())
    fig.savefig(out, dpi=args.dpi)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
