#!/usr/bin/env bash
# Times POV-Ray on the peer rain scene (bench/peer/peer_rain.pov: SDL #while + rand(), the way
# POV-Ray users make rain today) against frame 1 of raintrace's heavy_rain example, at the same
# size, in the same night_street environment. Prints wall time, peak memory and POV-Ray's own
# parse/trace times for each. The lead runs it on a quiet machine; it takes about a minute.
#   usage: bench/render_compare.sh [path/to/raintrace] [WIDTHxHEIGHT]   (from the source root)
set -euo pipefail
raintrace=${1:-build/cli/raintrace}
size=${2:-640x360}
width=${size%x*}
height=${size#*x}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$raintrace" export "$root/examples/heavy_rain.toml" -o "$work/heavy" --frames 1 >/dev/null 2>&1
spheres=$(grep -c '^sphere{' "$work/heavy/frames/frame_0001.pov" || true)
streaks=$(grep -o 'vertex_vectors{[0-9]*' "$work/heavy/frames/frame_0001.pov" | grep -o '[0-9]*$' || echo 0)
echo "raintrace heavy_rain frame 1: $spheres sphere lines, $((${streaks:-0} / 4)) streak quads"

run() {  # name, folder, scene file, extra args
  local name=$1 dir=$2 scene=$3
  shift 3
  (cd "$dir" && /usr/bin/time -f "%e %M" -o "$work/$name.time" \
     povray "$scene" "$@" +W"$width" +H"$height" -D -A +FN +O"$work/$name.png" >"$work/$name.log" 2>&1)
  read -r wall rss <"$work/$name.time"
  local parse trace
  parse=$(grep -m1 'Parse Time' "$work/$name.log" | grep -o '([0-9.]* seconds)' || true)
  trace=$(grep -m1 'Trace Time' "$work/$name.log" | grep -o '([0-9.]* seconds)' || true)
  printf '%-10s %5sx%-5s wall %7.2f s  peak %6d MB  parse %s  trace %s\n' "$name" "$width" \
    "$height" "$wall" "$((rss / 1024))" "$parse" "$trace"
}

run raintrace "$work/heavy" frames/frame_0001.pov +L.
run peer "$root/bench/peer" peer_rain.pov +L"$work/heavy"
