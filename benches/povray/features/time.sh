#!/usr/bin/env bash
# POV-Ray 3.7 against cga-trace on the scenes of the features that cost more than one ray per
# pixel and light: a disk light's soft shadows (area: 16 shadow rays and 16 shading terms per
# hit on both sides), glass (glass: Fresnel-split reflected and refracted rays, depth 8 = POV's
# max_trace_level 9) and a thin lens (lens: 16 camera rays per pixel on both sides), and on
# textures (textures: a checker floor and an image-mapped ball, one ray per pixel), and on
# meshes (mesh: two 3,072-triangle vases and a ball, one ray per pixel). Each NAME.toml here
# and its twin NAME.pov (whose comments say what POV-Ray does; +L here, where textures.pov
# finds its image, and +L the work folder, where vase_mesh.py writes mesh.pov's mesh2 from the
# OBJ that mesh.toml reads); as ../time.sh: one thread, CPU time (user + sys), interleaved
# rounds, medians, 1280x960, no anti-aliasing.
#
#   benches/povray/features/time.sh PATH/TO/cga-trace [ROUNDS]     (from the project's root)
#
# SPP=16 anti-aliases both with 16 rays a pixel: POV-Ray's +A0.0 +AM1 +R4 (method 1 at
# threshold 0: every pixel that differs at all from a neighbour takes a 4x4 grid of rays, one
# of a flat area keeps its one) against --spp 16. lens keeps -A on POV-Ray's side: its focal
# blur already takes 16 rays a pixel, and +A would trace all 16 for each anti-aliasing sample.
# WIDTH and HEIGHT (1280, 960) shrink the pictures.
set -euo pipefail
bin=$(realpath "$1"); rounds=${2:-5}
w=${WIDTH:-1280}; h=${HEIGHT:-960}
if [ -n "${SPP:-}" ]; then
  r=$(awk -v n="$SPP" 'BEGIN { printf "%d", sqrt(n) }')
  pov_aa=(+A0.0 +AM1 "+R$r"); ours_aa=(--spp "$SPP")
else
  pov_aa=(-A); ours_aa=()
fi
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/vase_mesh.py" "$work"
cpu() { /usr/bin/time -f '%U %S' -o "$work/t" "$@" >/dev/null 2>&1; awk '{print $1 + $2}' "$work/t"; }
med() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
printf '%-12s %10s %10s %10s\n' scene povray cga-trace 'povray/ours'
for name in area glass lens textures mesh; do
  : > "$work/p"; : > "$work/o"
  for _ in $(seq "$rounds"); do
    aa=("${pov_aa[@]}"); [ "$name" = lens ] && aa=(-A)
    cpu povray "+I$here/$name.pov" "+L$here" "+L$work" "+O$work/p.png" "+W$w" "+H$h" -D +WT1 "${aa[@]}" >> "$work/p"
    cpu "$bin" render "$here/$name.toml" -o "$work/o.png" --width "$w" --height "$h" --threads 1 "${ours_aa[@]}" >> "$work/o"
  done
  p=$(med < "$work/p"); o=$(med < "$work/o")
  printf '%-12s %10s %10s %10s\n' "$name" "$p" "$o" "$(awk -v p="$p" -v o="$o" 'BEGIN { printf "%.2f", p / o }')"
done
