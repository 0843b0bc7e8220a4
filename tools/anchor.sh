#!/usr/bin/env bash
# The whole tracer against the plain-vector anchor (../shared/anchors/glam-whitted), as
# docs/PERFORMANCE.md reports it: the anchor's scene at 1280×960, whole processes, CPU time
# (user + system), ROUNDS interleaved rounds (default 9), medians and ratios to the anchor.
#
#   tools/anchor.sh [path/to/glam-whitted]     (default ../shared/anchors/glam-whitted)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
anchor_dir=${1:-$root/../shared/anchors/glam-whitted}
rounds=${ROUNDS:-9}
out=$(mktemp -d)
cargo build --quiet --release --manifest-path "$anchor_dir/Cargo.toml" --target-dir "$out/anchor"
cargo build --quiet --release -p cga-trace --manifest-path "$root/Cargo.toml"
ours="${CARGO_TARGET_DIR:-$root/target}/release/cga-trace"
scene="$anchor_dir/primitives.toml"
cpu() { # name, command...: appends "name seconds" (user + system)
    local name=$1; shift
    /usr/bin/time -f "$name %U %S %e" "$@" > /dev/null 2>> "$out/raw" || true
}
for _ in $(seq "$rounds"); do
    cpu anchor "$out/anchor/release/glam-whitted" 1280 960 "$out/anchor.png" 1
    cpu sparse "$ours" render "$scene" -o "$out/sparse.png" --threads 1
    cpu sparse-no-packets "$ours" render "$scene" -o "$out/scalar.png" --threads 1 --no-packets
    cpu sparse-no-avx2 "$ours" render "$scene" -o "$out/arrays.png" --threads 1 --no-avx2
    cpu plain "$ours" render "$scene" -o "$out/plain.png" --threads 1 --backend plain
    cpu plain-no-packets "$ours" render "$scene" -o "$out/plain.png" --threads 1 --backend plain --no-packets
    cpu anchor-2 "$out/anchor/release/glam-whitted" 1280 960 "$out/anchor.png" 2
    cpu sparse-1-wall "$ours" render "$scene" -o "$out/sparse.png" --threads 1
    cpu sparse-2-wall "$ours" render "$scene" -o "$out/sparse.png" --threads 2
done
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, $rounds rounds"
python3 - "$out/raw" <<'PY'
import sys, statistics, collections
cpu, wall = collections.defaultdict(list), collections.defaultdict(list)
for line in open(sys.argv[1]):
    parts = line.split()
    if len(parts) == 4 and parts[0][0].isalpha() and parts[1][0].isdigit():
        cpu[parts[0]].append(float(parts[1]) + float(parts[2])); wall[parts[0]].append(float(parts[3]))
m = {k: statistics.median(v) for k, v in cpu.items()}
print("| program (1 thread) | CPU s | / anchor |\n|---|---:|---:|")
for k in ["anchor", "sparse", "sparse-no-avx2", "sparse-no-packets", "plain", "plain-no-packets"]:
    print(f"| {k} | {m[k]:.3f} | {m[k] / m['anchor']:.2f}× |")
w = {k: statistics.median(v) for k, v in wall.items()}
print(f"\nwall, 2 threads / 1 thread: cga-trace {w['sparse-1-wall'] / w['sparse-2-wall']:.2f}× "
      f"({w['sparse-1-wall']:.3f} → {w['sparse-2-wall']:.3f} s); anchor 1 → 2 threads CPU {m['anchor']:.3f} / {m['anchor-2']:.3f} s")
PY
