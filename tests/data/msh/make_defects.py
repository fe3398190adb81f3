"""Makes the defective meshes of tests/mesh_defects.rs from valid ones, one defect per file.

    python3 tests/data/msh/make_defects.py

Plain Python (no gmsh needed): the ASCII MSH 4.1 files are edited section by section.

- roller_relabelled.msh   meshes/roller_r100_shaft10_A.msh with node tags 24 and 54 swapped in
                          $Nodes and $Elements: the same mesh, numbered differently (valid).
- duplicate_tag.msh       square_linear.msh whose node 6 is tagged 5, as node 5 already is.
- missing_tag.msh         square_linear.msh whose last element names node 99, which is not defined.
- nan_node.msh            square_linear.msh with node 3 at (nan, 1).
- nan_node_bin.msh        annulus_bin.msh with NaN for the x of its first node.
- bowtie.msh              square_linear.msh with corners 3 and 4 swapped: the outline crosses itself.
- hole_crossing.msh       annulus.msh with the hole (radius 10) moved to x = +15: it crosses the
                          outer circle (radius 20).
- hole_outside.msh        annulus.msh with the hole moved to x = +40: outside the body.
- mixed_order.msh         plate.msh whose last contact element (tag 21) is a 2-node line in a
                          block of its own: one loop of line3 and line2 elements.
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))


def read(path):
    with open(path) as f:
        return f.read().split("\n")


def write(name, lines):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("\n".join(lines))


def section(lines, name):
    """(first, last) line indices of the body of section $name."""
    start = lines.index("$" + name) + 1
    return start, lines.index("$End" + name)


def node_lines(lines):
    """{tag: index of its coordinate line} and the indices of the tag lines, by block."""
    start, end = section(lines, "Nodes")
    i = start + 1
    coords, tag_lines = {}, []
    while i < end:
        n = int(lines[i].split()[3])
        tags = list(range(i + 1, i + 1 + n))
        for k, t in enumerate(tags):
            coords[int(lines[t])] = i + 1 + n + k
        tag_lines += tags
        i += 1 + 2 * n
    return coords, tag_lines


def element_lines(lines):
    start, end = section(lines, "Elements")
    out, i = [], start + 1
    while i < end:
        n = int(lines[i].split()[3])
        out += list(range(i + 1, i + 1 + n))
        i += 1 + n
    return out


def swap_tags(lines, a, b):
    out = list(lines)
    swap = {str(a): str(b), str(b): str(a)}
    _, tag_lines = node_lines(lines)
    for t in tag_lines:
        out[t] = swap.get(out[t].strip(), out[t])
    for e in element_lines(lines):
        words = out[e].split()
        out[e] = " ".join([words[0]] + [swap.get(w, w) for w in words[1:]]) + " "
    return out


def move(lines, tags, dx):
    out = list(lines)
    coords, _ = node_lines(lines)
    for t in tags:
        x, y, z = (float(v) for v in out[coords[t]].split())
        out[coords[t]] = f"{x + dx!r} {y!r} {z!r}"
    return out


def group_nodes(lines, curves):
    """Node tags of the elements on the given curve entities."""
    start, end = section(lines, "Elements")
    tags, i = set(), start + 1
    while i < end:
        dim, entity, _, n = (int(v) for v in lines[i].split())
        if dim == 1 and entity in curves:
            for e in range(i + 1, i + 1 + n):
                tags.update(int(v) for v in lines[e].split()[1:])
        i += 1 + n
    return tags


roller = read(os.path.join(ROOT, "meshes", "roller_r100_shaft10_A.msh"))
write("roller_relabelled.msh", swap_tags(roller, 24, 54))

square = read(os.path.join(HERE, "square_linear.msh"))
coords, tag_lines = node_lines(square)
dup = list(square)
dup[[t for t in tag_lines if square[t].strip() == "6"][0]] = "5"
write("duplicate_tag.msh", dup)

missing = list(square)
last = element_lines(square)[-1]
missing[last] = "8 8 99 "
write("missing_tag.msh", missing)

nan = list(square)
nan[coords[3]] = "nan 1 0"
write("nan_node.msh", nan)

bowtie = list(square)
bowtie[coords[3]], bowtie[coords[4]] = square[coords[4]], square[coords[3]]
write("bowtie.msh", bowtie)

annulus = read(os.path.join(HERE, "annulus.msh"))
hole = group_nodes(annulus, {1, 2})
write("hole_crossing.msh", move(annulus, hole, 15.0))
write("hole_outside.msh", move(annulus, hole, 40.0))

plate = read(os.path.join(HERE, "plate.msh"))
start, end = section(plate, "Elements")
mixed = list(plate)
blocks, entities, first, last = (int(v) for v in plate[start].split())
mixed[start] = f"{blocks + 1} {entities} {first} {last}"
block = mixed.index("1 4 8 6")
mixed[block] = "1 4 8 5"
element = block + 6
tag, a, b, _mid = plate[element].split()
mixed[element:element + 1] = ["1 4 1 1", f"{tag} {a} {b} "]
write("mixed_order.msh", mixed)

with open(os.path.join(HERE, "annulus_bin.msh"), "rb") as f:
    data = bytearray(f.read())
body = data.index(b"\n$Nodes\n") + len(b"\n$Nodes\n")
# Section header: 4 size_t; first block: 3 int + 1 size_t, then one size_t tag, then x.
x_at = body + 4 * 8 + 3 * 4 + 8 + 8
data[x_at:x_at + 8] = struct.pack("<d", math.nan)
with open(os.path.join(HERE, "nan_node_bin.msh"), "wb") as f:
    f.write(data)
