#!/usr/bin/env bash
# POV-Ray 3.7 against cga-trace on the scenes of the shapes POV-Ray also has (here: the
# torus, the box, the cylinder and cone), one thread, CPU time (user + sys), interleaved rounds, medians, 1280x960, no
# anti-aliasing; as ../../../shared/anchors/povray/time.sh does for the paper's scenes.
#
#   benches/povray/time.sh PATH/TO/cga-trace [ROUNDS]     (from the project's root)
set -euo pipefail
bin=$(realpath "$1"); rounds=${2:-5}
here=$(cd "$(dirname "$0")" && pwd)
root=$(pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpu() { /usr/bin/time -f '%U %S' -o "$work/t" "$@" >/dev/null 2>&1; awk '{print $1 + $2}' "$work/t"; }
med() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
printf '%-12s %10s %10s %10s\n' scene povray cga-trace 'povray/ours'
for name in torus box cylinder; do
  : > "$work/p"; : > "$work/o"
  for _ in $(seq "$rounds"); do
    cpu povray "+I$here/$name.pov" "+O$work/p.png" +W1280 +H960 -D +WT1 -A >> "$work/p"
    cpu "$bin" render "$root/cga-trace/scenes/$name.toml" -o "$work/o.png" --width 1280 --height 960 --threads 1 >> "$work/o"
  done
  p=$(med < "$work/p"); o=$(med < "$work/o")
  printf '%-12s %10s %10s %10s\n' "$name" "$p" "$o" "$(awk -v p="$p" -v o="$o" 'BEGIN { printf "%.2f", p / o }')"
done
