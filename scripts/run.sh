#!/usr/bin/env bash
# The README's first command: installs whatever is missing, builds raintrace, and renders the
# default example into out/default (frames, MP4, GIF, contact sheet). Re-running resumes.
# Usage: scripts/run.sh [SCENE.toml [OUT_DIR]]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scene=${1:-$root/examples/default.toml}
out=${2:-$root/out/$(basename "$scene" .toml)}
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build"
"$root/build/cli/raintrace" render "$scene" -o "$out"
