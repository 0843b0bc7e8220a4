#!/usr/bin/env python3
"""Embree on the rays of benches/surface_rays.rs, against our exported mesh of the surface.

The Embree library the `embreex` wheel bundles (Embree 4.4 in embreex 4.4.0.post1) traces
the very rays our example wrote (RAYS.bin: per ray seven little-endian f64, origin, unit
direction, our hit distance or +inf) against the triangle mesh `cga-trace mesh` exports of
the same surface. `EmbreeScene.run` loops `rtcIntersect1` over the rays in compiled code,
one thread, so each side traces one ray at a time. Prints, like our example, the median ns
per ray over interleaved rounds of all rays (in pixel order), the rays we hit and the rays
we miss (the same three sets of rays as ours), then how far the two agree.

    python embree.py --cga-trace PATH --scene SCENE.toml --object NAME --rays RAYS.bin \
        [--mesh MESH.ply] [--rings 512] [--segments 1024] [--rounds 5] [--robust]

The mesh (2 rings segments triangles) is exported to MESH.ply unless that file exists:
binary PLY, whose f64 vertices numpy reads as they are (OBJ would need a text parse).
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import time

import numpy as np
from embreex import rtcore_scene
from embreex.mesh_construction import TriangleMesh
from embreex.rtcore import EmbreeDevice

MISS = np.float32(1e37)  # the tfar embreex starts every ray with (as f32), left there by a miss


def export_mesh(args):
    command = [args.cga_trace, "mesh", args.scene, "--object", args.object, "-o", args.mesh,
               "--rings", str(args.rings), "--segments", str(args.segments)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode:
        sys.exit(f"{' '.join(command)}: {done.stderr.strip()}")


def read_ply(path):
    """Vertices (n, 3) f64 and triangles (m, 3) u32 of our binary PLY (x y z nx ny nz u v)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    nv = int(re.search(r"element vertex (\d+)", header)[1])
    nf = int(re.search(r"element face (\d+)", header)[1])
    vertices = np.frombuffer(data, "<f8", nv * 8, end).reshape(nv, 8)[:, :3]
    faces = np.frombuffer(data, np.dtype([("n", "u1"), ("i", "<u4", 3)]), nf, end + nv * 64)
    assert (faces["n"] == 3).all(), "triangles only"
    return vertices, faces["i"]


def read_rays(path):
    """Origins and directions as f32 (what Embree takes), and our t (f64, inf for a miss)."""
    records = np.fromfile(path, "<f8").reshape(-1, 7)
    f32 = lambda a: np.ascontiguousarray(a, dtype=np.float32)
    return f32(records[:, :3]), f32(records[:, 3:6]), records[:, 6]


def ns_per_ray(scene, batches, rounds):
    """The median over interleaved rounds of each batch's ns per ray (nan for an empty one)."""
    times = [[] for _ in batches]
    for _ in range(rounds):
        for (origins, dirs), t in zip(batches, times):
            start = time.perf_counter_ns()
            scene.run(origins, dirs, query="DISTANCE")
            t.append((time.perf_counter_ns() - start) / max(len(origins), 1))
    return [statistics.median(t) if len(o) else float("nan") for t, (o, _) in zip(times, batches)]


def call_overhead_us(scene, origins, dirs, calls=20000):
    """The median time of a call of `run` with one ray: what a call costs beyond its rays."""
    one = origins[:1], dirs[:1]
    times = []
    for _ in range(calls):
        start = time.perf_counter_ns()
        scene.run(*one, query="DISTANCE")
        times.append(time.perf_counter_ns() - start)
    return statistics.median(times) / 1e3


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--cga-trace", required=True, help="the cga-trace command, to export the mesh")
    p.add_argument("--scene", required=True)
    p.add_argument("--object", required=True)
    p.add_argument("--rays", required=True, help="written by surface_rays --rays")
    p.add_argument("--mesh", help="the mesh file (.ply), exported unless it exists")
    p.add_argument("--rings", type=int, default=512)
    p.add_argument("--segments", type=int, default=1024)
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--robust", action="store_true", help="RTC_SCENE_FLAG_ROBUST (off: Embree's fast path)")
    args = p.parse_args()
    args.mesh = args.mesh or os.path.splitext(args.rays)[0] + ".ply"
    if not os.path.exists(args.mesh):
        export_mesh(args)
    vertices, triangles = read_ply(args.mesh)
    origins, dirs, ours = read_rays(args.rays)

    device = EmbreeDevice()
    scene = rtcore_scene.EmbreeScene(device, robust=args.robust)
    start = time.perf_counter()
    TriangleMesh(scene, vertices.astype(np.float32), triangles.astype(np.int64))
    load_ms = (time.perf_counter() - start) * 1e3
    # The first `run` commits the scene: Embree builds its BVH (on all cores, with TBB).
    start = time.perf_counter()
    scene.run(origins[:1], dirs[:1], query="DISTANCE")
    build_ms = (time.perf_counter() - start) * 1e3

    hit = np.isfinite(ours)
    batches = [(origins, dirs), (origins[hit], dirs[hit]), (origins[~hit], dirs[~hit])]
    batches = [(np.ascontiguousarray(o), np.ascontiguousarray(d)) for o, d in batches]
    all_ns, hit_ns, miss_ns = ns_per_ray(scene, batches, args.rounds)
    call_us = call_overhead_us(scene, origins, dirs)

    t = scene.run(origins, dirs, query="DISTANCE")
    theirs = t < MISS
    both = theirs & hit
    dt = np.abs(t[both].astype(np.float64) - ours[both])
    print(f"{device!r}, robust={args.robust}, {len(triangles)} triangles, {len(vertices)} vertices")
    print(f"embree rays={len(ours)} hits={int(theirs.sum())} triangles={len(triangles)} "
          f"all={all_ns:.1f} hit={hit_ns:.1f} miss={miss_ns:.1f} "
          f"build_ms={build_ms:.0f} load_ms={load_ms:.0f} call_us={call_us:.2f}")
    print(f"agree embree_only={int((theirs & ~hit).sum())} ours_only={int((hit & ~theirs).sum())} "
          f"dt_median={np.median(dt) if len(dt) else float('nan'):.3g} "
          f"dt_max={dt.max() if len(dt) else float('nan'):.3g}")


if __name__ == "__main__":
    main()
