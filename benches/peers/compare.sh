#!/usr/bin/env bash
# Ours against Versor (github.com/wolftype/versor) on six operations, interleaved: the
# harness versor.cpp built for baseline x86-64 and with -march=native, in double precision
# like ours (-DVSR_PRECISION_DOUBLE: Versor's scalar is float unless that is defined, though
# its header's comment says double), the native build also in Versor's default float for
# reference, and our
# examples/batch_timing (baseline build; the packets dispatch to AVX2 at run time), each run
# ROUNDS times in turn; prints the table of medians for benches/README.md, with each
# operation's floor (its multiplications at the core's peak rate, from batch_timing) and the
# ratio to Versor native that the floor allows at most.
#
#   VERSOR_DIR=/path/to/versor benches/peers/compare.sh
#
# Only versor.cpp is ours: Versor's headers are read from the checkout, never copied here.
set -euo pipefail
: "${VERSOR_DIR:?set VERSOR_DIR to a checkout of github.com/wolftype/versor}"
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${OUT:-$(mktemp -d)}
rounds=${ROUNDS:-5}
mkdir -p "$out"
cxx=${CXX:-g++}

"$cxx" -O3 -std=c++14 -DVSR_PRECISION_DOUBLE -I"$VERSOR_DIR/include" "$here/versor.cpp" -o "$out/versor-baseline"
"$cxx" -O3 -std=c++14 -DVSR_PRECISION_DOUBLE -march=native -I"$VERSOR_DIR/include" "$here/versor.cpp" -o "$out/versor-native"
"$cxx" -O3 -std=c++14 -march=native -I"$VERSOR_DIR/include" "$here/versor.cpp" -o "$out/versor-native-f32"
cargo build --quiet --release -p cga-benches --example batch_timing --manifest-path "$root/Cargo.toml"
ours="${CARGO_TARGET_DIR:-$root/target}/release/examples/batch_timing"

: > "$out/raw.txt"
for _ in $(seq "$rounds"); do
    "$ours" >> "$out/raw.txt"
    "$out/versor-baseline" | sed 's/ / versor-baseline /' >> "$out/raw.txt"
    "$out/versor-native" | sed 's/ / versor-native /' >> "$out/raw.txt"
    "$out/versor-native-f32" | sed 's/ / versor-native-f32 /' >> "$out/raw.txt"
done
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, $("$cxx" --version | head -1), $(rustc --version)"
python3 - "$out/raw.txt" "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from medians import read
ops, m = read(sys.argv[1])
ops = [op for op in ops if op != "multiply"]
print("| operation | ours scalar | ours batch | ours packets | Versor x86-64 | Versor native | native / packets | native / batch | multiplications | floor | native / floor | Versor native f32 |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for op in ops:
    g = lambda f: m[(op, f)]
    print(f"| {op} | {g('scalar'):.2f} | {g('batch'):.2f} | {g('packets'):.2f} | {g('versor-baseline'):.2f} | "
          f"{g('versor-native'):.2f} | {g('versor-native') / g('packets'):.2f}× | {g('versor-native') / g('batch'):.2f}× | "
          f"{g('multiplications'):.0f} | {g('floor'):.2f} | {g('versor-native') / g('floor'):.2f}× | {g('versor-native-f32'):.2f} |")
print(f"\nfloor: the multiplications at this core's peak rate, {m[('multiply', 'peak')]:.4f} ns each "
      "(batch_timing); native / floor is the most any code doing those multiplications can reach against Versor native; "
      "Versor native f32: Versor's default float scalar, half the bytes per value, not comparable with ours")
PY
