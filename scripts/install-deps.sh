#!/usr/bin/env bash
# Installs the Debian packages raintrace needs, only those missing. Idempotent and quick when
# everything is there. Usage: scripts/install-deps.sh [--test]   (--test adds what tests need)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  povray                                   # the ray tracer
  povray-includes                          # its standard include files and fonts (the shop
                                           # signs' letters use cyrvetic.ttf)
  libglm-dev                               # vector maths (sim/)
  libopenimageio-dev openimageio-tools     # textures, image checks, compare/
  libtomlplusplus-dev                      # scene files
  libcli11-dev libfmt-dev                  # command line, formatting
  nlohmann-json3-dev                       # stats, manifest.json, compare reports
  libgtest-dev libgmock-dev libbenchmark-dev
  ffmpeg                                   # MP4 and GIF of a rendered animation
  blender-data                             # Blender's Filmic OpenColorIO configuration, which
                                           # develops HDR frames (film/); only its data, not
                                           # Blender (~100 MB installed)
  time                                     # /usr/bin/time in bench/*.sh
)
if [[ ${1:-} == --test ]]; then
  packages+=(
    clang-14 libclang-rt-14-dev            # libFuzzer target
    clang-format                           # the style check (.clang-format)
    chromium                               # checks the HTML compare report in a real browser
    slurmctld slurmd slurm-client munge    # one-node cluster for the Slurm backend tests
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if ((EUID != 0)); then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq -o DPkg::Lock::Timeout=600 --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
