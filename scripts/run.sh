#!/usr/bin/env bash
# The README's first command: installs whatever is missing, builds the raintrace program (only
# it: tests and benchmarks are scripts/test.sh's), and renders the default example into
# out/default (frames, MP4, GIF, contact sheet). Re-running resumes where it stopped.
# Usage: scripts/run.sh [SCENE.toml [OUT_DIR]]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scene=${1:-$root/examples/default.toml}
out=${2:-$root/out/$(basename "$scene" .toml)}
start=$SECONDS
stage() { printf '\n== run.sh %s: %s (%d s so far)\n' "$1" "$2" $((SECONDS - start)); }

stage 1/3 "Debian packages (only the missing ones)"
"$root/scripts/install-deps.sh"

stage 2/3 "building the raintrace program into build/"
"$root/scripts/build.sh" "$root/build" --target raintrace

stage 3/3 "rendering $scene into $out"
"$root/build/cli/raintrace" render "$scene" -o "$out"
printf '\n== run.sh done in %d s: %s/images/, animation.mp4, contact_sheet.png\n' \
  $((SECONDS - start)) "$out"
