#!/usr/bin/env python3
"""Print the products benchmark as a markdown table, from criterion's saved estimates.

Run after `cargo bench --bench products`:  python3 benches/report.py
Times are criterion medians per batch, divided by the batch size (256) to give ns per op.
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


def main():
    if not os.path.isdir(ROOT):
        sys.exit("no criterion results: run `cargo bench --bench products` first")
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


if __name__ == "__main__":
    main()
