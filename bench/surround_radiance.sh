#!/usr/bin/env bash
# The light of the surroundings a raindrop refracts, for an environment's RT_RainSurround
# (docs/rain-appearance.md). A drop shows a blurred image of what lies behind it: each
# direction ω weighted by the drop's phase function P(θ) at the angle θ between ω and the line
# of sight (sim/drop_optics.h; here Henyey-Greenstein with its asymmetry g = 0.769). This
# renders the environment of an exported folder around a few points of the rain with POV-Ray's
# spherical camera and averages it with that weight (oiiotool). Lights are left out: they are
# scattered by the drops' finish from the light_sources, so radiance above CLAMP (default 1.5,
# more than any lit surface at night or overcast sky by day; a lamp's lens is hundreds) is
# clamped to it before averaging.
# Usage: [CLAMP=1.5] [CAMERA="X Y Z"] bench/surround_radiance.sh FOLDER [X Y Z]...
#   FOLDER: a folder `raintrace export` wrote (its scene.inc, environment.inc); points in metres,
#   default three points 2, 5 and 8 m in front of the default camera at heights 0.8, 1.6, 2.6.
#   Each point is seen along +z unless CAMERA is given: then along the line from the camera
#   through it, as the camera sees a drop there (a drop toward a near wall refracts more of the
#   wall than one down the street does), and the environment faces its glows to that camera.
# Prints the mean rgb and each point's.
set -euo pipefail
folder=$(cd "$1" && pwd); shift
points=("$@")
if ((${#points[@]} == 0)); then points=(0.4 0.8 -3  -0.5 1.6 0  0.6 2.6 3); fi
work=$(mktemp -d /tmp/raintrace_surround.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$folder"/*.inc "$work/"
if [[ -d "$folder/textures" ]]; then cp -r "$folder/textures" "$work/"; fi
cd "$work"
g=0.769
# Weight: P(θ)·cos(latitude) (equirectangular pixels cover solid angle ∝ cos(latitude)), with
# cos θ = z for a line of sight along +z. Scaled into [0, 1] by the peak (1+g)/(1−g)²; the scale
# cancels.
cat > weight.pov <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical angle 360 180 location 0 look_at z }
#declare P = function(c) { (1 - $g * $g) / pow(1 + $g * $g - 2 * $g * c, 1.5) * (1 - $g) * (1 - $g) / (1 + $g) }
sky_sphere { pigment { function { P(z) * sqrt(max(0, 1 - y * y)) } color_map { [0 rgb 0] [1 rgb 1] } } }
POV
povray weight.pov +W360 +H180 +FE +Oweight.exr -D -V -GA >/dev/null 2>&1
# The camera, once: the line of sight of every point runs from it, and the environment faces it.
camera=""
camera_line=""
if [[ -n "${CAMERA:-}" ]]; then
  read -r cx cy cz <<<"$CAMERA"
  camera="<$cx,$cy,$cz>"
  camera_line="#declare RT_CameraPosition = $camera;"
fi
sum=(0 0 0); n=0
for ((i = 0; i < ${#points[@]}; i += 3)); do
  p="<${points[i]},${points[i+1]},${points[i+2]}>"
  sight="z"
  if [[ -n "$camera" ]]; then sight="($p - $camera)"; fi
  cat > env.pov <<POV
#version 3.7;
#declare RT_Mask = 0;
#declare RT_Preview = 0;
#declare RT_LightsOnly = 0;
#declare RT_Flash = 0;
$camera_line
global_settings { assumed_gamma 1.0 max_trace_level 32 }
camera { spherical angle 360 180 location $p look_at $p + $sight }
#include "environment.inc"
POV
  if ! povray env.pov +W360 +H180 +FE +Oenv.exr -D -V -GA +L. >/dev/null 2>env.log; then
    tail -5 env.log >&2
    exit 1
  fi
  oiiotool env.exr --clamp:max="${CLAMP:-1.5}" weight.exr --mul -o product.exr
  num=$(oiiotool product.exr --printstats | sed -n 's/.*Stats Avg: *\([0-9.e+-]*\) \([0-9.e+-]*\) \([0-9.e+-]*\).*/\1 \2 \3/p' | head -1)
  den=$(oiiotool weight.exr --printstats | sed -n 's/.*Stats Avg: *\([0-9.e+-]*\).*/\1/p' | head -1)
  rgb=$(awk -v n="$num" -v d="$den" 'BEGIN { split(n, a, " "); printf "%.4f %.4f %.4f", a[1]/d, a[2]/d, a[3]/d }')
  echo "point $p: rgb $rgb"
  read -r r gg b <<<"$rgb"
  read -r -a sum < <(awk -v a="${sum[0]}" -v b="${sum[1]}" -v c="${sum[2]}" -v r="$r" -v g2="$gg" -v bl="$b" 'BEGIN { print a + r, b + g2, c + bl }')
  n=$((n + 1))
done
awk -v a="${sum[0]}" -v b="${sum[1]}" -v c="${sum[2]}" -v n="$n" \
  'BEGIN { printf "RT_RainSurround = rgb <%.4f, %.4f, %.4f>  (mean of %d points)\n", a/n, b/n, c/n, n }'
