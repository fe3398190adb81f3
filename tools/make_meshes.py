#!/usr/bin/env python3
"""Regenerate meshes/*.msh from meshes/*.geo with the gmsh wheel (MSH 4.1, quadratic lines).

Usage:
  make_meshes.py            regenerate every .msh next to its .geo
  make_meshes.py --check    regenerate into a temporary folder and compare with the committed
                            .msh files: same node count, element count and physical groups
                            (exit 1 on a difference)
"""
import os
import sys

# tools/inspect.py is named like the standard library's `inspect`, which numpy and pyvista
# import: keep this folder off the module path.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != os.path.dirname(os.path.abspath(__file__))]

import sys
import tempfile
from pathlib import Path

import gmsh

MESHES = Path(__file__).resolve().parent.parent / "meshes"


def generate(geo: Path, msh: Path):
    gmsh.initialize()
    gmsh.option.setNumber("General.Verbosity", 1)
    try:
        gmsh.open(str(geo))
        gmsh.model.mesh.generate(1)
        gmsh.model.mesh.setOrder(2)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.option.setNumber("Mesh.Binary", 0)
        gmsh.write(str(msh))
    finally:
        gmsh.finalize()


def describe(msh: Path):
    gmsh.initialize()
    gmsh.option.setNumber("General.Verbosity", 1)
    try:
        gmsh.open(str(msh))
        nodes = len(gmsh.model.mesh.getNodes()[0])
        groups = {}
        for dim, tag in gmsh.model.getPhysicalGroups():
            name = gmsh.model.getPhysicalName(dim, tag)
            count = 0
            for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
                types, tags, _ = gmsh.model.mesh.getElements(dim, entity)
                count += sum(len(t) for t in tags)
            groups[name] = count
        return nodes, groups
    finally:
        gmsh.finalize()


def main():
    check = "--check" in sys.argv[1:]
    geos = sorted(MESHES.glob("*.geo"))
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for geo in geos:
            target = MESHES / (geo.stem + ".msh")
            out = Path(tmp) / target.name if check else target
            generate(geo, out)
            if check:
                if not target.exists():
                    print(f"FAIL {target.name}: not committed")
                    bad += 1
                    continue
                new, old = describe(out), describe(target)
                status = "ok" if new == old else "FAIL"
                bad += status == "FAIL"
                print(f"{status} {target.name}: nodes {new[0]} (committed {old[0]}), groups {new[1]}")
            else:
                print(f"wrote {target.relative_to(MESHES.parent)}: nodes and groups {describe(target)}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
