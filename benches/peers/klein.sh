#!/usr/bin/env bash
# Ours (benches/pga_timing.rs, cga-algebras' PGA) against klein (github.com/jeremyong/klein,
# header-only C++ with SSE, f32) on five operations, interleaved: klein.cpp built with
# -O3 -march=native, and our example in release, each run ROUNDS times in turn; prints the
# table of medians for benches/README.md with ours over klein's time (f32 and f64; klein has
# no f64): on values in arrays (the faster of one at a time and SIMD lanes), and on values
# stored packed (`simd::run_packed`); then the 1e6 points against a plain copy of them, the
# floor of the memory path.
#
#   KLEIN_DIR=/path/to/klein benches/peers/klein.sh
#
# Only klein.cpp is ours: klein's headers are read from the checkout, never copied here.
set -euo pipefail
: "${KLEIN_DIR:?set KLEIN_DIR to a checkout of github.com/jeremyong/klein}"
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${OUT:-$(mktemp -d)}
rounds=${ROUNDS:-5}
mkdir -p "$out"
cxx=${CXX:-g++}

"$cxx" -O3 -march=native -std=c++17 -I"$KLEIN_DIR/public" "$here/klein.cpp" -o "$out/klein"
cargo build --quiet --release -p cga-benches --example pga_timing --manifest-path "$root/Cargo.toml"
ours="${CARGO_TARGET_DIR:-$root/target}/release/examples/pga_timing"

: > "$out/raw.txt"
for _ in $(seq "$rounds"); do
    "$ours" >> "$out/raw.txt"
    "$out/klein" >> "$out/raw.txt"
done
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, $("$cxx" --version | head -1), $(rustc --version)"
python3 - "$out/raw.txt" "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from medians import read
ops, m = read(sys.argv[1])
print("| operation | klein f32 | ours f32 | ours f32 lanes | ours f32 packed | ours f64 | ours f64 lanes | ours f64 packed "
      "| f32 / klein | f32 packed / klein | f64 / klein | f64 packed / klein |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
fmt = lambda v: f"{v:.3f}" if v is not None else "–"
ratio = lambda v, k: f"{v / k:.2f}×" if v is not None else "–"
for op in ops:
    k = m[(op, "klein")]
    a, al, ap, b, bl, bp = (m.get((op, f)) for f in ("f32", "f32-lanes", "f32-packed", "f64", "f64-lanes", "f64-packed"))
    best32 = min(v for v in (a, al) if v is not None)
    best64 = min(v for v in (b, bl) if v is not None)
    print(f"| {op} | {k:.3f} | {fmt(a)} | {fmt(al)} | {fmt(ap)} | {fmt(b)} | {fmt(bl)} | {fmt(bp)} "
          f"| {ratio(best32, k)} | {ratio(ap, k)} | {ratio(best64, k)} | {ratio(bp, k)} |")
# The 1e6 points against the floor of the memory path: a plain copy of the same points.
kc, c32, c64 = (m.get(("motor_points", f)) for f in ("klein-copy", "f32-copy", "f64-copy"))
if None not in (kc, c32, c64):
    k, best32, best64 = m[("motor_points", "klein")], *(
        min(m[("motor_points", f)] for f in fs) for fs in (("f32", "f32-lanes"), ("f64", "f64-lanes")))
    print()
    print("| 1e6 points | klein | ours f32 | ours f64 |")
    print("|---|---|---|---|")
    print(f"| moved, ns a point | {k:.3f} | {best32:.3f} | {best64:.3f} |")
    print(f"| copied, ns a point | {kc:.3f} | {c32:.3f} | {c64:.3f} |")
    print(f"| moved / copied | {k / kc:.2f}× | {best32 / c32:.2f}× | {best64 / c64:.2f}× |")
    print(f"| copied / klein copied | 1.00× | {c32 / kc:.2f}× | {c64 / kc:.2f}× |")
PY
