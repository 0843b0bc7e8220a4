#!/usr/bin/env python3
"""Print the benchmarks as markdown tables, from criterion's saved estimates.

Run after `cargo bench --bench products`, `--bench render` and/or `--bench peers --features peers`:
python3 benches/report.py
Products: criterion medians per batch divided by the batch size (256), ns per op.
Render: median ms per frame (one thread), rays/s, and the back ends' ratios.
"""
import json
import os
import platform
import sys

BATCH = 256
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "target", "criterion")
OPS = [
    ("line_meet_sphere", "Line ∨ Sphere → PointPair", 8.0),
    ("circle_from_3_points", "X1 ∧ X2 ∧ X3 → Circle", 10.0),
    ("motor_on_point", "M X M̃ (Motor on a point)", 16.0),
    ("circle_times_circle", "Circle · Circle → Even (Σ)", None),
    ("dense_gp_32x32", "dense 32×32 geometric product", None),
]


def median_ns(group, variant):
    path = os.path.join(ROOT, group, variant, "new", "estimates.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)["median"]["point_estimate"] / BATCH


def cpu():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def fmt(x):
    return "–" if x is None else (f"{x:.1f}" if x < 100 else f"{x:.0f}")


def estimate(group, variant):
    """Median and throughput-free path lookup: criterion writes `group/variant`."""
    for g in (group, group.replace("/", "_")):
        path = os.path.join(ROOT, g, variant, "new", "estimates.json")
        if os.path.exists(path):
            with open(path) as f:
                median = json.load(f)["median"]["point_estimate"]
            bench = os.path.join(ROOT, g, variant, "new", "benchmark.json")
            elements = None
            if os.path.exists(bench):
                with open(bench) as f:
                    throughput = json.load(f).get("throughput") or {}
                    elements = throughput.get("Elements")
            return median, elements
    return None, None


def render_table():
    rows = []
    for scene in ("primitives", "combined"):
        times = {b: estimate(f"render/{scene}", b) for b in ("sparse", "plain", "dense")}
        if all(t[0] is None for t in times.values()):
            continue
        ms = {b: (t[0] / 1e6 if t[0] else None) for b, t in times.items()}
        rays = next((t[1] for t in times.values() if t[1]), None)
        for b in ("sparse", "plain", "dense"):
            if ms[b] is None:
                continue
            rate = f"{rays / (ms[b] / 1e3):.3g}" if rays else "–"
            rows.append(f"| {scene} | {b} | {ms[b]:.1f} | {rate} |")
        ratio = lambda a, b: f"{ms[a] / ms[b]:.2f}×" if ms[a] and ms[b] else "–"
        rows.append(f"| {scene} | sparse / plain | {ratio('sparse', 'plain')} | |")
        rows.append(f"| {scene} | dense / sparse | {ratio('dense', 'sparse')} | |")
    if rows:
        print("\nRender, 160×120, one thread: median ms per frame and rays/s.\n")
        print("| scene | back end | ms / frame | rays/s |")
        print("|---|---|---|---|")
        print("\n".join(rows))


PEERS = ["line_meet_sphere", "circle_from_3_points", "motor_on_point", "circle_times_circle",
         "motor_times_motor", "rotor_times_rotor"]


def peers_table():
    """`cargo bench --bench peers --features peers`: ns per operation, ours against clifford and hisab."""
    rows = []
    for op in PEERS:
        t = {lib: median_ns(f"peers_{op}", lib) or median_ns(f"peers/{op}", lib)
             for lib in ("cga", "cga-packets", "clifford", "hisab")}
        if t["cga"] is None:
            continue
        ratio = lambda lib: f"{t[lib] / t['cga']:.2f}×" if t[lib] else "–"
        rows.append(f"| {op} | {fmt(t['cga'])} | {fmt(t['cga-packets'])} | {fmt(t['clifford'])} | "
                    f"{fmt(t['hisab'])} | {ratio('clifford')} | {ratio('hisab')} |")
    if rows:
        print("\nPeers, ns per operation (batches of 256):\n")
        print("| operation | cga | cga packets | clifford 0.3.0 | hisab 1.4 | clifford / cga | hisab / cga |")
        print("|---|---|---|---|---|---|---|")
        print("\n".join(rows))


def main():
    if not os.path.isdir(ROOT):
        sys.exit("no criterion results: run `cargo bench --bench products` (or render) first")
    print(f"Machine: {cpu()}, {os.cpu_count()} cores. Medians, ns per operation "
          f"(batches of {BATCH}).\n")
    print("| operation | scalar | sparse ns | dense ns | dense / sparse | target (f64) |")
    print("|---|---|---|---|---|---|")
    for group, label, target in OPS:
        for scalar in ("f64", "f32"):
            sparse = median_ns(f"{group}_{scalar}", "sparse")
            dense = median_ns(f"{group}_{scalar}", "dense")
            ratio = f"{dense / sparse:.0f}×" if sparse and dense else "–"
            goal = f"≈{target:.0f} ns" if target and scalar == "f64" else ""
            print(f"| {label} | {scalar} | {fmt(sparse)} | {fmt(dense)} | {ratio} | {goal} |")

    render_table()
    peers_table()


if __name__ == "__main__":
    main()
