#!/usr/bin/env bash
# Regenerates the reference stills in tests/reference/<example>/ from examples/*.toml. Only ever
# run on purpose (CMake target `update-references`), never by a test: a reference changes when a
# human decides the new pictures are right. Review the change with
#   raintrace compare <old reference> <new reference> --html /tmp/ref.html
# Usage: update.sh RAINTRACE WORKDIR [EXAMPLE...]   (no EXAMPLE = all of examples/*.toml)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
raintrace=$1
work=$2
shift 2
if [[ $# -eq 0 ]]; then
  set -- $(cd "$root/examples" && ls *.toml | sed 's/\.toml$//')
fi
for name in "$@"; do
  frames=$(python3 -c 'import json,sys; t=json.load(open(sys.argv[1])); print({**t["default"], **t["examples"].get(sys.argv[2], {})}["frames"])' \
           "$here/thresholds.json" "$name")
  echo "== $name: frames 1-$frames at 160x90"
  "$here/render_example.sh" "$raintrace" "$root/examples/$name.toml" "$work/$name" "$frames"
  rm -rf "$here/$name"
  mkdir -p "$here/$name"
  cp "$work/$name/out/images/frame_"*.png "$here/$name/"   # the developed frames
done
echo "updated: $*  (commit tests/reference/ after reviewing the pictures)"
