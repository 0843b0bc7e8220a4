#!/usr/bin/env python3
"""Writes FOLDER/vase_mesh.inc, mesh.pov's `Vase`: the vertices, vertex normals and triangles of
cga-trace/scenes/meshes/vase.obj (polygons cut into fans, as cga-trace reads them) as a POV-Ray
mesh2, so that POV-Ray and cga-trace trace the same triangles. mesh.pov finds it with +LFOLDER.

    python3 benches/povray/features/vase_mesh.py FOLDER

adaptive.py and retime.py call it; time.sh runs it. Standard library only.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MESH_OBJ = os.path.normpath(os.path.join(HERE, "../../../cga-trace/scenes/meshes/vase.obj"))


def write(folder):
    """Writes folder/vase_mesh.inc from MESH_OBJ."""
    v, n, faces = [], [], []
    with open(MESH_OBJ) as f:
        for line in f:
            p = line.split()
            if p and p[0] == "v":
                v.append(p[1:4])
            elif p and p[0] == "vn":
                n.append(p[1:4])
            elif p and p[0] == "f":
                corners = [[int(x) - 1 for x in q.split("/")[::2]] for q in p[1:]]
                faces += [(corners[0], corners[k], corners[k + 1]) for k in range(1, len(corners) - 1)]
    vec = ",\n".join
    with open(os.path.join(folder, "vase_mesh.inc"), "w") as out:
        out.write(f"// {MESH_OBJ} by vase_mesh.py\n#declare Vase = mesh2 {{\n")
        out.write(f" vertex_vectors {{ {len(v)},\n" + vec(f"<{x},{y},{z}>" for x, y, z in v) + " }\n")
        out.write(f" normal_vectors {{ {len(n)},\n" + vec(f"<{x},{y},{z}>" for x, y, z in n) + " }\n")
        out.write(f" face_indices {{ {len(faces)},\n" + vec(f"<{a[0]},{b[0]},{c[0]}>" for a, b, c in faces) + " }\n")
        out.write(f" normal_indices {{ {len(faces)},\n" + vec(f"<{a[1]},{b[1]},{c[1]}>" for a, b, c in faces) + " }\n}\n")


if __name__ == "__main__":
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit(__doc__)
    write(sys.argv[1])
