#!/usr/bin/env bash
# Configures and builds raintrace into a build folder (default build/). Quick when up to date.
# Usage: scripts/build.sh [BUILD_DIR] [extra cmake -D options…]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift $(( $# > 0 ? 1 : 0 ))
generator=()
command -v ninja >/dev/null && [[ ! -f $build/Makefile ]] && generator=(-G Ninja)
cmake -S "$root" -B "$build" "${generator[@]}" "$@" >/dev/null
cmake --build "$build" -j "$(nproc)"
