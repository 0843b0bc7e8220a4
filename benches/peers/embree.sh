#!/usr/bin/env bash
# Our swept surfaces against Embree (the library the `embreex` wheel bundles) on primary
# visibility: for fig3c, fig3b, catmull-rom and surface.toml, our example surface_rays
# (benches/surface_rays.rs) forms the camera ray through every pixel centre, times meeting
# them with the one surface and with our exported mesh of it (2·RINGS·SEGMENTS triangles, 1M
# by default), and writes them; embree.py traces the same rays against that mesh. Both one thread,
# median of ROUNDS interleaved rounds, ns per ray; prints the table for benches/README.md.
#
#   python3 -m venv /tmp/embree && /tmp/embree/bin/pip install embreex numpy
#   PYTHON=/tmp/embree/bin/python benches/peers/embree.sh PATH/TO/cga-trace [ROUNDS]
#
# WIDTH (1280; the height follows the scenes' 4:3), RINGS (512), SEGMENTS (1024): smaller
# for a quick run. PASSES (1): run both sides that many times in turn, the table taking the
# median of the passes. OUT: where the rays, meshes and raw output go (a temporary folder).
set -euo pipefail
cga_trace=$(realpath "${1:?usage: benches/peers/embree.sh PATH/TO/cga-trace [ROUNDS]}")
rounds=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=${OUT:-$(mktemp -d)}
py=${PYTHON:-python3}
width=${WIDTH:-1280}
mkdir -p "$out"

cargo build --quiet --release -p cga-benches --example surface_rays --manifest-path "$root/Cargo.toml"
ours="${CARGO_TARGET_DIR:-$root/target}/release/examples/surface_rays"

: > "$out/raw.txt"
for scene in fig3c fig3b catmull-rom surface; do
    object=surface
    [ "$scene" = surface ] && object="evolved surface"
    file="$root/cga-trace/scenes/$scene.toml"
    # The mesh first: our side times it too (`ours-mesh`), and embree.py reads it.
    [ -e "$out/$scene.ply" ] || "$cga_trace" mesh "$file" --object "$object" -o "$out/$scene.ply" \
        --rings "${RINGS:-512}" --segments "${SEGMENTS:-1024}" > /dev/null
    for _ in $(seq "${PASSES:-1}"); do
        "$ours" "$file" --object "$object" --width "$width" --rounds "$rounds" --rays "$out/$scene.bin" \
            --mesh "$out/$scene.ply" | sed "s/^/$scene /" >> "$out/raw.txt"
        "$py" "$here/embree.py" --cga-trace "$cga_trace" --scene "$file" --object "$object" \
            --rays "$out/$scene.bin" --mesh "$out/$scene.ply" --rounds "$rounds" \
            --rings "${RINGS:-512}" --segments "${SEGMENTS:-1024}" | sed "s/^/$scene /" >> "$out/raw.txt"
    done
done
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, $(rustc --version)," \
    "$(grep -m1 'Embree version' "$out/raw.txt" | cut -d' ' -f2- | cut -d, -f1-2); raw output in $out/raw.txt"
"$py" - "$out/raw.txt" <<'PY'
import statistics, sys
rows = {}
for line in open(sys.argv[1]):
    scene, tag, *pairs = line.split()
    if pairs and "=" in pairs[0]:
        rows.setdefault(scene, {}).setdefault(tag, []).append(dict(p.split("=", 1) for p in pairs))
med = lambda r, tag, k: statistics.median(float(f[k]) for f in r[tag])
first = lambda r, tag, k: r[tag][0][k]
print("| scene | rays (hit) | triangles | Embree hit | ours hit | ratio | Embree miss | ours miss | ratio | Embree per ray | ours per ray | ratio | mismatched pixels |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for scene, r in rows.items():
    cells = [f"{first(r, 'ours', 'rays')} ({first(r, 'ours', 'hits')})", first(r, "embree", "triangles")]
    for k in ("hit", "miss", "all"):
        e, o = med(r, "embree", k), med(r, "ours-surface", k)
        cells += [f"{e:.0f}", f"{o:.0f}", f"{o / e:.2f}×"]
    a = r["agree"][0]
    cells.append(f"{int(a['embree_only']) + int(a['ours_only'])} ({a['embree_only']} Embree only)")
    print(f"| {scene} | " + " | ".join(cells) + " |")
print()
print("| scene | ours via Renderer::nearest: all / hit / miss | ours on the mesh: all / hit / miss | over Embree | Embree BVH build | median abs(t_Embree - t_ours) | run() call overhead |")
print("|---|---|---|---|---|---|---|")
for scene, r in rows.items():
    nearest = " / ".join(f"{med(r, 'ours-renderer', k):.0f}" for k in ("all", "hit", "miss"))
    mesh = " / ".join(f"{med(r, 'ours-mesh', k):.0f}" for k in ("all", "hit", "miss"))
    over = " / ".join(f"{med(r, 'ours-mesh', k) / med(r, 'embree', k):.2f}×" for k in ("all", "hit", "miss"))
    build, dt, call = med(r, "embree", "build_ms"), first(r, "agree", "dt_median"), med(r, "embree", "call_us")
    print(f"| {scene} | {nearest} ns | {mesh} ns | {over} | {build:.0f} ms | {dt} | {call:.1f} µs |")
PY
