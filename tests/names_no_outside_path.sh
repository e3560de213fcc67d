#!/usr/bin/env bash
# A clone of the repository is all a user gets, so no file in it may point outside it: not to
# the development machine's folders, not to the design notes kept beside the repository (by
# folder or by their file names; what the code needs from them is in docs/). Binary files are
# searched too (image metadata keeps the command lines of the tools that wrote them).
# Usage: tests/names_no_outside_path.sh [SOURCE_DIR]   (exit 1 and the lines found, if any)
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
# The patterns are bracketed so that this file does not match itself.
patterns=(-e '/wor[k]/' -e '/hom[e]/' -e '\.\./share[d]' -e 'POVRAY-NOTE[S]' -e 'BUILD-NOTE[S]'
          -e 'DESIGN\.m[d]' -e 'STYLE\.m[d]')
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  found=$(git ls-files -z | xargs -0 -r grep -a -n -o -E "${patterns[@]}" -- 2>/dev/null || true)
else  # an unpacked archive: every file but build folders
  found=$(find . -path './build*' -prune -o -path './.git' -prune -o -type f -print0 |
            xargs -0 -r grep -a -n -o -E "${patterns[@]}" -- 2>/dev/null || true)
fi
if [[ -n $found ]]; then
  echo "files that name a path outside the repository (file:line:match):"
  echo "$found" | head -40
  exit 1
fi
echo "no file names a path outside the repository"
