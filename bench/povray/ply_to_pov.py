#!/usr/bin/env python3
"""Writes a binary little-endian PLY (float x, y, z vertices; uchar-count int-index faces)
as a POV-Ray mesh2 declaration, so that POV-Ray renders the same triangles Glint does.

    ply_to_pov.py MESH.ply NAME > mesh.inc      (then: object { NAME ... } in a .pov file)
"""
import struct
import sys


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        sys.exit(f"{path}: expected a binary little-endian PLY")
    vertices = faces = 0
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            vertices = int(words[2])
        elif words[:2] == ["element", "face"]:
            faces = int(words[2])
    positions = struct.unpack_from(f"<{3 * vertices}f", data, end)
    at = end + 12 * vertices
    triangles = []
    for _ in range(faces):
        count = data[at]
        if count != 3:
            sys.exit(f"{path}: expected triangles, found a face of {count} vertices")
        triangles.append(struct.unpack_from("<3i", data, at + 1))
        at += 13
    return positions, triangles


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    positions, triangles = read_ply(sys.argv[1])
    out = sys.stdout
    lo = [min(positions[a::3]) for a in range(3)]
    hi = [max(positions[a::3]) for a in range(3)]
    out.write(f"// {sys.argv[1]}: {len(positions) // 3} vertices, {len(triangles)} triangles\n")
    out.write(f"// bounds <{lo[0]:g}, {lo[1]:g}, {lo[2]:g}> to <{hi[0]:g}, {hi[1]:g}, {hi[2]:g}>\n")
    out.write(f"#declare {sys.argv[2]} = mesh2 {{\n  vertex_vectors {{ {len(positions) // 3}")
    for i in range(0, len(positions), 3):
        out.write(f",\n    <{positions[i]:.7g}, {positions[i + 1]:.7g}, {positions[i + 2]:.7g}>")
    out.write(f"\n  }}\n  face_indices {{ {len(triangles)}")
    for a, b, c in triangles:
        out.write(f",\n    <{a}, {b}, {c}>")
    out.write("\n  }\n}\n")


if __name__ == "__main__":
    main()
