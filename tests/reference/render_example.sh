#!/usr/bin/env bash
# Renders the reference frames of one example, the one recipe shared by the reference test and
# update.sh: a copy of the scene at 160×90, preview quality (no antialiasing, so no jitter) and
# frames 1..N, exported with `raintrace export`, rendered by plain `povray scene.ini` in the
# output folder (the folder renders without raintrace: scene-linear EXRs), then developed by
# `raintrace render OUT`, which finds the EXRs rendered and develops each into the PNG a render
# makes. Leaves WORKDIR/out/images/ (frame_NNNN.exr and the developed frame_NNNN.png).
# Usage: render_example.sh RAINTRACE EXAMPLE.toml WORKDIR [FRAMES=2]
set -euo pipefail
raintrace=$1
example=$2
work=$3
frames=${4:-2}
rm -rf "$work"
mkdir -p "$work"

# Replace width/height/frames/quality in [output] (or add the table), keep everything else.
awk -v frames="$frames" '
  function emit() { print "width = 160"; print "height = 90"; print "frames = " frames;
                    print "quality = \"preview\""; done = 1 }
  /^[[:space:]]*\[/ { section = $0; gsub(/[[:space:]]/, "", section) }
  section == "[output]" && /^[[:space:]]*(width|height|frames|quality)[[:space:]]*=/ { next }
  { print }
  /^[[:space:]]*\[output\][[:space:]]*(#.*)?$/ { emit() }
  END { if (!done) { print ""; print "[output]"; emit() } }
' "$example" > "$work/scene.toml"

"$raintrace" export "$work/scene.toml" -o "$work/out" > "$work/export.log" 2>&1 || {
  cat "$work/export.log" >&2
  echo "render_example.sh: 'raintrace export' failed for $example (log: $work/export.log)" >&2
  exit 1
}
# -D: no display; one thread, so even jittered effects would repeat (POVRAY-NOTES).
(cd "$work/out" && povray scene.ini -D +WT1 > "$work/povray.log" 2>&1) || {
  tail -20 "$work/povray.log" >&2
  echo "render_example.sh: povray failed in $work/out (log: $work/povray.log)" >&2
  exit 1
}
"$raintrace" render "$work/out" --no-movie > "$work/develop.log" 2>&1 || {
  cat "$work/develop.log" >&2
  echo "render_example.sh: 'raintrace render' could not develop $work/out (log: $work/develop.log)" >&2
  exit 1
}
grep -q "^render: 0 frames rendered" "$work/develop.log" || {
  cat "$work/develop.log" >&2
  echo "render_example.sh: raintrace rendered frames POV-Ray had rendered (log: $work/develop.log)" >&2
  exit 1
}
ls "$work/out/images/"*.png > /dev/null
