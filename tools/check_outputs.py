#!/usr/bin/env python3
"""Check rollbem outputs with the real clients (meshio and pyvista).

Each DIR is a run folder (summary.json, contact.csv, contact.vtu, result.pvd), a sweep folder
(sweep.csv, sweep.pvd, run_NNNN/) or a stability-study folder (stability.csv, img/*.svg). For
every file: it opens in meshio and in pyvista, carries the documented arrays with the right
shapes, and its values equal contact.csv / summary.json to 1e-12 relative. Prints one line per defect and exits 1 if there is any, 0 otherwise.
"""
import os
import sys

# tools/inspect.py is named like the standard library's `inspect`, which numpy and pyvista
# import: keep this folder off the module path.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import argparse
import csv
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import meshio
import numpy as np
import pyvista as pv

SCALARS = ["pressure", "shear", "gap", "slip", "state", "u_n_A", "u_t_A", "u_n_B", "u_t_B"]
VECTORS = ["traction", "displacement_A", "displacement_B"]
STATE_CODE = {"open": 0, "stick": 1, "slip": 2}
RTOL = 1e-12

errors = []


def fail(where, message):
    errors.append(f"{where}: {message}")


def close(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(np.max(np.abs(b)) if b.size else 0.0, 1e-300)
    return a.shape == b.shape and np.max(np.abs(a - b)) <= RTOL * scale


def read_contact_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    cols = {}
    for key in rows[0]:
        if key == "state":
            cols[key] = np.array([STATE_CODE[r[key]] for r in rows], float)
        elif all(r[key] != "" for r in rows):
            cols[key] = np.array([float(r[key]) for r in rows])
    return cols


def check_vtu(path, cols):
    expected = SCALARS + VECTORS + (["slip_hbem"] if "slip_hbem" in cols else [])
    m = meshio.read(path)
    g = pv.read(path)
    n = len(cols["x"])
    for reader, points, data in [("meshio", m.points, m.point_data), ("pyvista", np.asarray(g.points), g.point_data)]:
        where = f"{path} ({reader})"
        if sorted(data.keys()) != sorted(expected):
            fail(where, f"arrays {sorted(data.keys())}, expected {sorted(expected)}")
            continue
        if points.shape != (n, 3) or not close(points[:, 0], cols["x"]):
            fail(where, "points do not match contact.csv x")
        for name in SCALARS + (["slip_hbem"] if "slip_hbem" in cols else []):
            arr = np.asarray(data[name]).reshape(-1)
            if arr.shape != (n,) or not close(arr, cols[name]):
                fail(where, f"`{name}` differs from contact.csv")
        for name in VECTORS:
            if np.asarray(data[name]).shape != (n, 3):
                fail(where, f"`{name}` has shape {np.asarray(data[name]).shape}, expected ({n}, 3)")
        t = np.asarray(data["traction"])
        if not (close(t[:, 0], cols["shear"]) and close(t[:, 1], cols["pressure"]) and np.all(t[:, 2] == 0)):
            fail(where, "`traction` is not (shear, pressure, 0)")
        d = np.asarray(data["displacement_B"])
        if not (close(d[:, 0], cols["u_t_B"]) and close(d[:, 1], -cols["u_n_B"])):
            fail(where, "`displacement_B` is not (u_t_B, -u_n_B, 0)")
    if len(m.cells) != 1 or m.cells[0].type != "line" or len(m.cells[0].data) != n - 1:
        fail(path, f"cells {m.cells}, expected {n - 1} lines")


def check_boundary(path, cols, summary):
    """A bem body's boundary: quadratic edges, documented arrays, finite values, and on the
    contact group the traction's normal component equals the pressure of contact.csv (the body
    carries the nodal contact tractions through its condensed response; 1e-3 of the peak pressure),
    turned into the global axes by the summary's `contact_frame` when there is one."""
    m = meshio.read(path)
    g = pv.read(path)
    if [c.type for c in m.cells] != ["line3"]:
        fail(path, f"cells {[c.type for c in m.cells]}, expected line3 (VTK quadratic edges)")
    n = len(m.points)
    for reader, data in [("meshio", m.point_data), ("pyvista", g.point_data)]:
        for name in ["displacement", "traction"]:
            arr = np.asarray(data.get(name, np.empty(0)))
            if arr.shape != (n, 3) or not np.all(np.isfinite(arr)):
                fail(f"{path} ({reader})", f"`{name}` has shape {arr.shape}, expected ({n}, 3), finite")
    if "group" not in g.cell_data or len(g.cell_data["group"]) != len(m.cells[0].data):
        fail(path, "cell data `group` missing or of the wrong length")
        return
    t = np.asarray(g.point_data["traction"])
    pts = np.asarray(g.points)
    side = 0 if path.name.endswith("_A.vtu") else 1
    sign = 1.0 if side == 0 else -1.0
    pmax = cols["pressure"].max()
    # With the tractions along the contact (summary `contact_frame`), the body carries the
    # nodal (p, q) turned by the interface angle psi and scaled by its arc factor s: its y
    # traction is s (p cos psi + q sin psi) (docs/theory.md, "Tractions along the contact").
    frame = summary.get("contact_frame")
    if frame:
        psi = np.asarray(frame["normal_angle"])
        scale = np.asarray(frame["arc_scale"][side])
        normal = scale * (cols["pressure"] * np.cos(psi) + cols["shear"] * np.sin(psi))
    else:
        normal = cols["pressure"]
    span = cols["x"].max() - cols["x"].min()
    # Element mid points at a contact node's x, near the contact (|y| small); where several
    # lie at the same x (a thin layer's bonded face under its contact), the one facing the other
    # body: the highest on B (below the contact), the lowest on A.
    on_contact = {}
    for k in np.arange(2, len(pts), 3):
        near = np.flatnonzero(np.abs(cols["x"] - pts[k, 0]) <= 1e-6 * span)
        if abs(pts[k, 1]) > 0.05 * span or near.size == 0:
            continue  # not on the contact segment, or not at a contact node
        j = int(near[0])
        facing = pts[k, 1] if side == 1 else -pts[k, 1]
        if j not in on_contact or facing > on_contact[j][0]:
            on_contact[j] = (facing, k)
    for j, (_, k) in sorted(on_contact.items()):
        p = normal[j]
        if abs(sign * t[k, 1] - p) > 1e-3 * pmax:
            fail(path, f"normal traction {sign * t[k, 1]:.6g} at x = {pts[k, 0]:.6g} differs from contact.csv pressure {p:.6g}")
            break


INTERIOR_STATUS = {"outside": 0, "inside": 1, "boundary": 2}


def check_interior(vtu, csv_path, summary):
    """Interior grid: `stress` (4 components), `von_mises`, `max_shear`, `displacement` (3-vector,
    z = 0) and `status` (0 outside, 1 inside, 2 boundary) equal the CSV's; every value is finite,
    points not evaluated carry zeros, the quad cells join evaluated points only, and
    summary.json's `interior` counts and maxima agree with the CSV."""
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    expected_cols = ["x", "y", "sxx", "syy", "szz", "txy", "von_mises", "max_shear", "ux", "uy", "status"]
    if list(rows[0].keys()) != expected_cols:
        fail(csv_path, f"columns {list(rows[0].keys())}, expected {expected_cols}")
        return
    status_names = [r["status"] for r in rows]
    if not set(status_names) <= set(INTERIOR_STATUS):
        fail(csv_path, f"unknown status values {sorted(set(status_names) - set(INTERIOR_STATUS))}")
        return
    status = np.array([INTERIOR_STATUS[s] for s in status_names])
    cols = {k: np.array([float(r[k]) for r in rows]) for k in expected_cols if k != "status"}
    for name, arr in cols.items():
        if not np.all(np.isfinite(arr)):
            fail(csv_path, f"non-finite values in `{name}`")
        if name not in ("x", "y") and np.any(arr[status != 1] != 0.0):
            fail(csv_path, f"`{name}` is not 0 at points that were not evaluated")
    m = meshio.read(vtu)
    g = pv.read(vtu)
    n = len(rows)
    for reader, points, data in [("meshio", m.points, m.point_data), ("pyvista", np.asarray(g.points), g.point_data)]:
        where = f"{vtu} ({reader})"
        st = np.asarray(data.get("stress", np.empty(0)))
        if st.shape != (n, 4):
            fail(where, f"`stress` has shape {st.shape}, expected ({n}, 4)")
            continue
        for k, name in enumerate(["sxx", "syy", "szz", "txy"]):
            if not close(st[:, k], cols[name]):
                fail(where, f"stress component {name} differs from {csv_path.name}")
        for name in ["von_mises", "max_shear"]:
            if not close(np.asarray(data[name]).reshape(-1), cols[name]):
                fail(where, f"`{name}` differs from {csv_path.name}")
        u = np.asarray(data.get("displacement", np.empty(0)))
        if u.shape != (n, 3) or not (close(u[:, 0], cols["ux"]) and close(u[:, 1], cols["uy"]) and np.all(u[:, 2] == 0)):
            fail(where, f"`displacement` is not (ux, uy, 0) of {csv_path.name} (shape {u.shape})")
        code = np.asarray(data.get("status", np.empty(0))).reshape(-1)
        if code.shape != (n,) or np.any(code != status):
            fail(where, f"`status` differs from {csv_path.name}")
        if not (close(points[:, 0], cols["x"]) and close(points[:, 1], cols["y"])):
            fail(where, "points differ from the CSV's x, y")
    types = [c.type for c in m.cells]
    quads = np.concatenate([np.asarray(c.data, dtype=np.int64).reshape(-1) for c in m.cells]) if types else np.empty(0, int)
    if set(types) - {"quad"} or np.any(status[quads] != 1):
        fail(vtu, f"cells must be quads joining evaluated (status 1) points only (types {types})")
    info = summary.get("interior")
    if info is None:
        fail(Path(vtu).parent / "summary.json", "`interior` missing although interior files were written")
        return
    counts = [int(np.sum(status == INTERIOR_STATUS[k])) for k in ("inside", "outside", "boundary")]
    if [info["inside"], info["outside"], info["boundary"]] != counts or info["points"] != n:
        fail(Path(vtu).parent / "summary.json", f"interior counts {info} differ from the CSV's {counts}")
    for key, col in [("max_shear", "max_shear"), ("max_von_mises", "von_mises")]:
        peak = info.get(key)
        if counts[0] and (peak is None or not np.isclose(peak["value"], cols[col][status == 1].max(), rtol=RTOL, atol=0)):
            fail(Path(vtu).parent / "summary.json", f"interior `{key}` differs from the CSV's maximum")


def pvd_files(path):
    root = ET.parse(path).getroot()
    return [ds.attrib["file"] for ds in root.iter("DataSet")]


def check_pvd(path, expected_count=None):
    files = pvd_files(path)
    if expected_count is not None and len(files) != expected_count:
        fail(path, f"{len(files)} datasets, expected {expected_count}")
    for f in files:
        if not (path.parent / f).exists():
            fail(path, f"lists missing file {f}")
    # pyvista's PVD reader exposes the time steps (what ParaView steps through); datasets of
    # one step are its parts.
    root = ET.parse(path).getroot()
    steps = sorted({float(ds.attrib["timestep"]) for ds in root.iter("DataSet")})
    reader = pv.get_reader(str(path))
    times = list(reader.time_values)
    if len(times) != len(steps):
        fail(path, f"pyvista sees {len(times)} time steps, the file lists {len(steps)}")
    for t in times:
        reader.set_active_time_value(t)
        block = reader.read()
        if sum(b.n_points for b in block if b is not None) == 0:
            fail(path, f"time step {t} reads as empty in pyvista")


def number_paths(value, path, out):
    """Every number of a JSON value, by path: `.` between keys, `[]` for array items."""
    if isinstance(value, bool) or value is None:
        return
    if isinstance(value, (int, float)):
        out.add(path)
    elif isinstance(value, list):
        for item in value:
            number_paths(item, path + "[]", out)
    elif isinstance(value, dict):
        for k, v in value.items():
            number_paths(v, f"{path}.{k}" if path else k, out)


def check_units(d, summary):
    """summary.json names the unit of every number it holds (outside the resolved case)."""
    units = summary.get("units")
    if not isinstance(units, dict):
        fail(d / "summary.json", "no `units` block")
        return
    paths = set()
    for key, value in summary.items():
        if key not in ("units", "case"):
            number_paths(value, key, paths)
    for p in sorted(paths - set(units)):
        fail(d / "summary.json", f"`{p}` has no unit in the units block")
    case_units = (summary.get("case") or {}).get("units") or {}
    length, force = case_units.get("length", "mm"), case_units.get("force", "N")
    for key, unit in [("normal_force", f"{force}/{length}"), ("max_pressure", f"{force}/{length}^2"),
                      ("overlap", length), ("creep", "-")]:
        if units.get(key) != unit:
            fail(d / "summary.json", f"unit of `{key}` is {units.get(key)!r}, expected {unit!r}")


def check_run(d):
    summary = json.loads((d / "summary.json").read_text())
    for key in ["version", "command", "converged", "iterations", "residual", "normal_force", "tangential_force",
                "overlap", "creep", "contact", "stick_zones", "slip_zones", "timings", "models", "units", "case"]:
        if key not in summary:
            fail(d / "summary.json", f"missing `{key}`")
    check_units(d, summary)
    if not summary.get("converged"):
        return
    cols = read_contact_csv(d / "contact.csv")
    for name, arr in cols.items():
        if not np.all(np.isfinite(arr)):
            fail(d / "contact.csv", f"non-finite values in `{name}`")
    # max_pressure is the peak of the pressure's interpolant: at or above the largest nodal value,
    # and above it only by the curvature between nodes (2.9e-4 at most on the shipped cases and
    # their error-controlled runs: 1e-3 leaves a margin of three).
    nodal = cols["pressure"].max()
    if not nodal * (1 - RTOL) <= summary["max_pressure"] <= nodal * (1 + 1e-3):
        fail(d / "summary.json", f"max_pressure {summary['max_pressure']} is not the peak of contact.csv's {nodal}")
    if summary.get("vtk", True):
        check_vtu(d / "contact.vtu", cols)
        bodies = sorted(d.glob("boundary_*.vtu"))
        expected = [f"boundary_{s}.vtu" for s, key in (("A", "A"), ("B", "B")) if summary["models"][key] == "bem"]
        if [b.name for b in bodies] != expected:
            fail(d, f"boundary files {[b.name for b in bodies]}, expected {expected}")
        for b in bodies:
            check_boundary(b, cols, summary)
        interiors = sorted(d.glob("interior_*.vtu"))
        for v in interiors:
            check_interior(v, v.with_suffix(".csv"), summary)
        check_pvd(d / "result.pvd", expected_count=1 + len(bodies) + len(interiors))


def check_sweep(d):
    with open(d / "sweep.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    ok = [r for r in rows if r["status"] == "ok"]
    check_pvd(d / "sweep.pvd", expected_count=len(ok))
    for r in ok:
        run = (d / r["folder"]).resolve()
        summary = json.loads((run / "summary.json").read_text())
        for key in ["normal_force", "tangential_force", "overlap", "creep", "residual"]:
            if not np.isclose(float(r[key]), summary[key], rtol=RTOL, atol=0):
                fail(d / "sweep.csv", f"run {r['run']}: `{key}` {r[key]} differs from {run}/summary.json")
        check_run(run)


STUDY_STATUS = {"converged", "not_converged", "out_of_domain", "error"}


def check_stability(d):
    """A stability map: known statuses; out-of-domain exactly where |Q/muP| >= 1; the default
    method converged in every other cell; finite numbers; one heat map per slice and method."""
    with open(d / "stability.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail(d / "stability.csv", "no rows")
        return
    for r in rows:
        where = f"{d / 'stability.csv'} {r['slice']} {r['method']} ({r['x']}, {r['y']})"
        if r["status"] not in STUDY_STATUS:
            fail(where, f"unknown status {r['status']}")
        ratio = [float(r[k]) for k in ("x", "y") if r[k + "_key"] == "loadratio"]
        outside = any(abs(v) >= 1 for v in ratio)
        if outside != (r["status"] == "out_of_domain"):
            fail(where, "out_of_domain does not match |Q/muP| >= 1")
        if r["method"] == "newton" and not outside and r["status"] != "converged":
            fail(where, f"default method: {r['status']} {r['message']}")
        for key in ("residual", "solve_s", "ripple", "creep"):
            if r[key] != "" and not np.isfinite(float(r[key])):
                fail(where, f"`{key}` is not finite")
        if r["status"] == "converged" and float(r["residual"]) > 1e-10:
            fail(where, f"converged with residual {r['residual']}")
    for s in sorted({r["slice"] for r in rows}):
        for m in sorted({r["method"] for r in rows}):
            svg = d / "img" / f"{s}__{m}.svg"
            if not svg.exists() or not svg.read_text().startswith("<svg"):
                fail(svg, "missing or not an SVG")
        if not (d / "img" / f"{s}.svg").exists():
            fail(d / "img" / f"{s}.svg", "overview missing")


def main(argv=None):
    ap = argparse.ArgumentParser(
        prog="check_outputs.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("dirs", nargs="+", metavar="DIR", help="run, sweep or stability-study folder written by rollbem")
    dirs = ap.parse_args(argv).dirs
    for name in dirs:
        d = Path(name)
        if (d / "sweep.csv").exists():
            check_sweep(d)
        elif (d / "stability.csv").exists():
            check_stability(d)
        elif (d / "summary.json").exists():
            check_run(d)
        else:
            fail(d, "neither a run folder (summary.json), a sweep folder (sweep.csv) nor a study folder (stability.csv)")
    for e in errors:
        print("FAIL", e)
    print(f"check_outputs: {len(dirs)} folder(s), {len(errors)} defect(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
