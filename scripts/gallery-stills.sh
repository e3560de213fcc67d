#!/usr/bin/env bash
# Renders the stills of docs/gallery.md: one frame of each example at 640×360 and final quality
# with `raintrace render` (developed as every rendered frame is), saved as a JPEG small enough
# for the repository (quality 85, ~30–120 KB each). Final quality whatever the example asks for:
# a still is one frame, and the gallery shows what the renderer makes, antialiased, with its
# windows' reflections (most examples preview for speed).
# Usage: scripts/gallery-stills.sh [RAINTRACE] [OUT_DIR] [EXAMPLE…]
#   RAINTRACE  the raintrace binary (default build/cli/raintrace)
#   OUT_DIR    where the JPEGs go (default docs/images/gallery)
#   EXAMPLE…   names in examples/ (default: all)
# Scratch render folders go to ${TMPDIR:-/tmp}/raintrace-gallery and are kept for a re-run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
raintrace=${1:-$root/build/cli/raintrace}
out=${2:-$root/docs/images/gallery}
shift $(( $# > 2 ? 2 : $# ))
examples=("$@")
if (( ${#examples[@]} == 0 )); then
  examples=(default night_street thunderstorm no_fog little_fog heavy_fog closeup streaks
            light_rain heavy_rain)
fi
scratch=${TMPDIR:-/tmp}/raintrace-gallery
mkdir -p "$out" "$scratch"

# The frame each still shows: frame 16 (two thirds of a second in, the rain well developed),
# but the thunderstorm's frame 13, the peak of its first return stroke, whose flash lights the
# sky behind the channel (first_strike_s = 0.5 s at 24 fps; at the example's first exposure
# blind viewers chose frame 14, the stroke's tail, over its "twilight" sky, and at the
# exposure it has now, 1.5 stops under, both viewers of a pair chose frame 13: BENCHMARKS.md,
# 2026-12-07), and the closeup's first frame (its drops are beaded, the frames differ only by
# the far rain).
frame_of() {
  case $1 in
    thunderstorm) echo 13 ;;
    closeup) echo 1 ;;
    *) echo 16 ;;
  esac
}

for name in "${examples[@]}"; do
  frame=$(frame_of "$name")
  folder=$scratch/$name
  echo "== $name: frame $frame"
  "$raintrace" render "$root/examples/$name.toml" -o "$folder" --frames "$frame" \
    --width 640 --height 360 --quality final --no-movie --force
  image=$(printf '%s/images/frame_%04d.png' "$folder" "$frame")
  # Without the command line oiiotool would record in the JPEG: it names this machine's paths.
  oiiotool --nosoftwareattrib "$image" --compression jpeg:85 -o "$out/$name.jpg"
  echo "   $out/$name.jpg: $(( $(stat -c %s "$out/$name.jpg") / 1024 )) KB"
done
