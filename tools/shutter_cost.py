#!/usr/bin/env python3
"""What a shutter costs beside a still picture of the same samples: a 180,000-triangle mesh
(a 300 × 300 sphere grid, written here) that stands and a ball that moves, 160 × 120 pixels,
256 samples a pixel, rendered still and through a shutter of 256 instants; CPU time, wall
time and peak memory of each (GNU time), and whether the two builds' pictures are the same.

    python3 tools/shutter_cost.py target/release/cga-trace [OTHER_BUILD]

With a second build (an older commit's), both render each scene and the pictures are
compared byte for byte (a shuttered picture of a build from before 3c81c49 differs: every
pixel then shared the shutter's instants).
"""

import math
import os
import subprocess
import sys
import tempfile

N = 300
CAMERA = """[camera]
position = [0.0, -6.0, 1.0]
look_at = [0.0, 0.0, 0.0]
fov = 45.0
width = 160
height = 120
"""
REST = """[render]
spp = 256
[[lights]]
position = [-4.0, -6.0, 10.0]
[[objects]]
name = "m"
type = "mesh"
file = "m.obj"
material = { colour = [0.8, 0.8, 0.8] }
[[objects]]
name = "ball"
type = "sphere"
centre = [1.5, 0.0, 0.0]
radius = 0.5
material = { colour = [0.8, 0.2, 0.2] }
motion = [[1, 0, 0, 0, 0, 0, 0, 0], [1, 0, 0, 0, 0, 1.5, 0, 0]]
"""


def write_mesh(path):
    with open(path, "w") as f:
        for i in range(N + 1):
            for j in range(N + 1):
                u, v = i / N * math.pi, j / N * 2 * math.pi
                f.write(f"v {math.sin(u) * math.cos(v):.6f} {math.sin(u) * math.sin(v):.6f} {math.cos(u):.6f}\n")
        for i in range(N):
            for j in range(N):
                a = i * (N + 1) + j + 1
                b, c = a + 1, a + N + 1
                f.write(f"f {a} {c} {c + 1}\nf {a} {c + 1} {b}\n")


def run(binary, scene, out, folder):
    timed = ["/usr/bin/time", "-f", "%U %S %e %M", binary, "render", scene, "-o", out]
    p = subprocess.run(timed, cwd=folder, capture_output=True, text=True, check=True)
    user, system, wall, kib = p.stderr.strip().splitlines()[-1].split()
    return float(user) + float(system), float(wall), int(kib) / 1024


def main():
    builds = [os.path.abspath(b) for b in sys.argv[1:3]]
    if not builds:
        sys.exit(__doc__)
    with tempfile.TemporaryDirectory() as folder:
        write_mesh(os.path.join(folder, "m.obj"))
        open(os.path.join(folder, "still.toml"), "w").write(CAMERA + REST)
        open(os.path.join(folder, "shutter.toml"), "w").write(CAMERA + "shutter = [0.0, 1.0]\ntime_samples = 256\n" + REST)
        print("| build | scene | CPU s | wall s | peak MiB |")
        print("|---|---|---|---|---|")
        for scene in ["still", "shutter"]:
            pictures = []
            for k, binary in enumerate(builds):
                out = f"{scene}-{k}.png"
                cpu, wall, mib = run(binary, f"{scene}.toml", out, folder)
                print(f"| {binary} | {scene} | {cpu:.2f} | {wall:.2f} | {mib:.0f} |")
                pictures.append(open(os.path.join(folder, out), "rb").read())
            if len(pictures) == 2:
                print(f"{scene}: the pictures are {'the same' if pictures[0] == pictures[1] else 'DIFFERENT'}")


if __name__ == "__main__":
    main()
