"""Time and memory of the renderer on hostile inputs, for two builds side by side.

    python3 tools/hostile_figures.py OLD_BINARY NEW_BINARY [--rounds N]

Each case is a scene (and the files it reads) made in a scratch folder: one image under
three spellings, a PLY mesh of 4 million vertices, a shutter of 256 instants over a
180,000-triangle mesh, 20,000 instances of a mesh of a million vertices, 1,024 area lights of
4,096 samples, a texture that names a pipe without a writer. Each binary renders each case
(interleaved, `rounds` times, one thread); the table gives the median wall time, the peak
resident memory (`/usr/bin/time`'s maximum resident set) and the first line of what it said.
A run is stopped after `LIMIT` seconds.
Needs numpy and Pillow (`pip install numpy pillow`).
"""

import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from PIL import Image

CAMERA = """[camera]
position = [0.0, -6.0, 3.0]
look_at = [0.0, 0.0, 0.0]
fov = 50.0
width = 64
height = 48
"""
WHITE = 'material = { colour = [1.0, 1.0, 1.0] }'
# Seconds a run may take before it is stopped.
LIMIT = 240


def ply(path, vertices, faces):
    """A binary little-endian PLY of float x y z vertices and triangle faces."""
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n"
        f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    face = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
    face["n"], face["i"] = 3, faces
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(np.asarray(vertices, dtype="<f4").tobytes())
        f.write(face.tobytes())


def grid(n):
    """An n × n grid of squares in the unit square at z = 0: vertices and triangles."""
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1))
    vertices = np.stack([i.ravel() / n - 0.5, j.ravel() / n - 0.5, np.zeros(i.size)], axis=1)
    k = (j[:-1, :-1] * (n + 1) + i[:-1, :-1]).ravel()
    faces = np.concatenate([np.stack([k, k + 1, k + n + 2], 1), np.stack([k, k + n + 2, k + n + 1], 1)])
    return vertices, faces


def cases(folder):
    """(name, scene file) for each case, its files written into `folder`."""
    out = []
    def scene(name, text):
        path = os.path.join(folder, name + ".toml")
        with open(path, "w") as f:
            f.write(text)
        out.append((name, path))

    ramp = np.linspace(0, 255, 8192, dtype=np.uint8)
    Image.fromarray(np.stack([np.tile(ramp, (8192, 1))] * 3, axis=2)).save(os.path.join(folder, "big.png"))
    os.makedirs(os.path.join(folder, "sub"), exist_ok=True)
    balls = "".join(
        f'[[objects]]\ntype = "sphere"\ncentre = [{k}.0, 0.0, 0.0]\nradius = 0.4\n'
        f'material = {{ colour = [1.0, 1.0, 1.0], texture = {{ image = "{name}" }} }}\n'
        for k, name in enumerate(["big.png", "./big.png", "sub/../big.png"])
    )
    scene("image-three-spellings", CAMERA + balls)

    # Four million vertices, a million small triangles among them (cheap to render).
    rng = np.random.default_rng(1)
    corners = (rng.random((1_000_000, 1, 3)) + 0.002 * rng.random((1_000_000, 4, 3))).reshape(-1, 3)
    ply(os.path.join(folder, "cloud.ply"), corners, np.arange(4_000_000).reshape(-1, 4)[:, :3])
    scene("ply-4M-vertices", CAMERA + f'[[objects]]\ntype = "mesh"\nfile = "cloud.ply"\n{WHITE}\n')

    ply(os.path.join(folder, "sheet.ply"), *grid(300))
    scene(
        "shutter-256-over-180k-triangles",
        CAMERA.replace("width = 64\nheight = 48", "width = 32\nheight = 24")
        + "shutter = [0.0, 1.0]\ntime_samples = 256\n[render]\nspp = 256\n"
        + f'[[objects]]\ntype = "mesh"\nfile = "sheet.ply"\n{WHITE}\n'
        + "motion = [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0, -0.5, 0.0, 0.0, 0.0]]\n",
    )

    ply(os.path.join(folder, "million.ply"), rng.random((1_000_000, 3)), np.array([[0, 1, 2]]))
    instance = '[[objects]]\ntype = "instance"\nof = "cloud"\ntransform = [{ translate = [0.0, 0.0, 0.001] }]\n'
    scene(
        "20000-instances-of-1M-vertices",
        CAMERA + f'[[objects]]\nname = "cloud"\ntemplate = true\ntype = "mesh"\nfile = "million.ply"\n{WHITE}\n'
        + instance * 20_000,
    )

    lights = '[[lights]]\nposition = [0.0, 0.0, 5.0]\nsphere = 0.5\nsamples = 4096\n' * 1024
    scene("1024-area-lights-of-4096", CAMERA + lights + f'[[objects]]\ntype = "plane"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n{WHITE}\n')

    os.mkfifo(os.path.join(folder, "pipe.png"))
    scene(
        "texture-names-a-pipe",
        CAMERA + '[[objects]]\ntype = "sphere"\ncentre = [0.0, 0.0, 0.0]\nradius = 1.0\n'
        'material = { colour = [1.0, 1.0, 1.0], texture = { image = "pipe.png" } }\n',
    )
    return out


def run(binary, scene, folder):
    """(wall seconds, peak resident MiB, first line said) of one render."""
    start = time.perf_counter()
    # A fresh process per run measures its own peak: run through /usr/bin/time.
    command = ["/usr/bin/time", "-f", "%M", binary, "render", scene, "-o", os.path.join(folder, "out.png"), "--threads", "1"]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=LIMIT)
        seconds = time.perf_counter() - start
        lines = done.stderr.strip().splitlines()
        peak = int(lines[-1]) / 1024 if lines and lines[-1].isdigit() else float("nan")
        said = next((l for l in lines[:-1] if not l.startswith("note")), "")
    except subprocess.TimeoutExpired:
        seconds, peak, said = float("inf"), float("nan"), f"(stopped after {LIMIT} s)"
    return seconds, peak, said[:110]


def main():
    old, new = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 1
    with tempfile.TemporaryDirectory() as folder:
        print("| case | build | median s | peak MiB | said |\n|---|---|---:|---:|---|")
        for name, scene in cases(folder):
            figures = {old: [], new: []}
            for _ in range(rounds):
                for binary in (old, new):
                    figures[binary].append(run(binary, scene, folder))
            for label, binary in (("before", old), ("after", new)):
                runs = figures[binary]
                seconds = statistics.median(r[0] for r in runs)
                peak = max(r[1] for r in runs)
                print(f"| {name} | {label} | {seconds:.2f} | {peak:.0f} | {runs[-1][2]} |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
