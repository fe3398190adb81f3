"""Regenerates the test meshes of tests/bem/msh_reader.rs with the gmsh Python wheel.

    pip install gmsh && python3 tests/data/msh/generate.py

Each `name.geo` gives `name.msh` (MSH 4.1 ASCII); annulus, plate and square_surface also give
`*_bin.msh` (MSH 4.1 binary); square_surface is meshed in 2D. annulus_meshio.msh and
plate_meshio_bin.msh are annulus.msh and plate.msh as `meshio` writes them (pip install meshio). A few bad files are made on purpose: a version 2.2 file, a file with an
untagged curve (Mesh.SaveAll), and a zero-length element built through the API.
"""
import os
import gmsh

HERE = os.path.dirname(os.path.abspath(__file__))


def mesh_geo(name, out, binary=False, version=4.1, save_all=False, dim=1):
    gmsh.clear()
    gmsh.open(os.path.join(HERE, name + ".geo"))
    gmsh.option.setNumber("Mesh.MshFileVersion", version)
    gmsh.option.setNumber("Mesh.Binary", 1 if binary else 0)
    if not save_all:
        gmsh.option.setNumber("Mesh.SaveAll", 0)
    gmsh.model.mesh.generate(dim)
    gmsh.write(os.path.join(HERE, out))


def zero_length():
    """A square of line2 elements in which one element joins two coincident nodes."""
    gmsh.clear()
    gmsh.model.add("zero_length")
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.option.setNumber("Mesh.SaveAll", 0)
    c = gmsh.model.addDiscreteEntity(1)
    xyz = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0]  # node 5 duplicates node 1
    gmsh.model.mesh.addNodes(1, c, [1, 2, 3, 4, 5], xyz)
    gmsh.model.mesh.addElementsByType(c, 1, [1, 2, 3, 4, 5], [1, 2, 2, 3, 3, 4, 4, 5, 5, 1])
    gmsh.model.addPhysicalGroup(1, [c], 1, "free")
    gmsh.write(os.path.join(HERE, "zero_length.msh"))


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
for name in ["annulus", "plate", "square_linear", "open_loop", "unnamed_group", "cubic"]:
    mesh_geo(name, name + ".msh")
mesh_geo("annulus", "annulus_bin.msh", binary=True)
mesh_geo("plate", "plate_bin.msh", binary=True)
mesh_geo("annulus", "annulus_v22.msh", version=2.2)
mesh_geo("open_loop", "untagged.msh", save_all=True)
# square_surface.geo sets Mesh.SaveAll and Mesh.SaveParametric itself.
mesh_geo("square_surface", "square_surface.msh", save_all=True, dim=2)
mesh_geo("square_surface", "square_surface_bin.msh", binary=True, save_all=True, dim=2)
zero_length()
gmsh.finalize()


def meshio_copies():
    """The annulus (line3) and the plate (line2) as `meshio` writes them
    (`meshio.write(..., file_format="gmsh")`, MSH 4.1), ASCII and binary: read back from the
    Gmsh files above, so they must read as the same meshes."""
    import meshio

    for source, out, binary in [("annulus.msh", "annulus_meshio.msh", False), ("plate.msh", "plate_meshio_bin.msh", True)]:
        mesh = meshio.read(os.path.join(HERE, source))
        meshio.write(os.path.join(HERE, out), mesh, file_format="gmsh", binary=binary)


meshio_copies()
