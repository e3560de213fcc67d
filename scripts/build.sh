#!/usr/bin/env bash
# Configures and builds raintrace into a build folder (default build/). Quick when up to date.
# Usage: scripts/build.sh [BUILD_DIR] [--target NAME] [-DOPTION=VALUE…]
#   --target NAME   build only NAME and what it needs (e.g. raintrace); default: everything
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
if [[ $# -gt 0 && $1 != -* ]]; then build=$1; shift; fi
targets=()
options=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --target) targets+=(--target "$2"); shift 2 ;;
    *) options+=("$1"); shift ;;
  esac
done
generator=()
command -v ninja >/dev/null && [[ ! -f $build/Makefile ]] && generator=(-G Ninja)
cmake -S "$root" -B "$build" "${generator[@]}" "${options[@]}" >/dev/null
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
