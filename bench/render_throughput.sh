#!/usr/bin/env bash
# Render throughput of `raintrace render` (simulate + export + POV-Ray), the paper's Table 1:
#   1. frames/s at 2k/5k/10k/15k drops, 320×240 preview, for --jobs 1, 2, 3, 4 (best marked);
#   2. the top row again without the environment plate ([export] environment_plate = false);
#   3. frames/hour for examples/default.toml at 640×360 preview and 1280×720 final, best --jobs.
# Each row also gives the run's own CPU share: user + system seconds of raintrace and every
# POV-Ray it ran, over wall seconds × cores (100 % = all cores busy with this run alone).
# Run it on a quiet machine: other work on the cores shows up directly in the numbers.
# Usage: bench/render_throughput.sh [RAINTRACE] [--quick]
#   RAINTRACE defaults to build/cli/raintrace; --quick renders 8 frames and only 2k and 15k.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build/cli/raintrace}
quick=${2:-}
[[ -x $exe ]] || { echo "render_throughput: no raintrace at $exe (build first)" >&2; exit 2; }
work=$(mktemp -d -t raintrace_render_bench.XXXXXX)
trap 'rm -rf "$work"' EXIT

frames=48; counts=(2000 5000 10000 15000); hd_frames=24; final_frames=6
if [[ $quick == --quick ]]; then frames=8; counts=(2000 15000); hd_frames=4; final_frames=2; fi

# Drops in view = density × frustum volume. At 5 mm/h Marshall-Palmer the density is ~630 /m³
# (docs/scene-format.md); a 60° (horizontal) 4:3 frustum from 0.3 m to F holds
# 4/3·tan30°·(0.75·tan30°)·F³ ≈ 0.333·F³ m³, so F = (N / (630·0.333))^(1/3).
far_for() { awk -v n="$1" 'BEGIN { printf "%.3f", (n / (630 * 0.3333)) ^ (1 / 3) }'; }

scene_for() {  # $1 drops → prints a scene file path
  local f="$work/drops_$1.toml"
  cat >"$f" <<TOML
seed = 1
[output]
frames = $frames
fps = 24
width = 320
height = 240
quality = "preview"
[camera]
position = [0, 1.6, -5]
look_at = [0, 1.3, 0]
fov_deg = 60
exposure_s = 0.02
[rain]
rate_mm_per_h = 5
distribution = "marshall-palmer"
near_m = 0.3
far_m = $(far_for "$1")
[wind]
velocity_m_per_s = [0.8, 0, 0]
[environment]
name = "night_street"
TOML
  echo "$f"
}

# run LABEL FRAMES -- raintrace args… ; prints seconds, frames/s, frames/h, CPU share
run() {
  local label=$1 n=$2; shift 3
  /usr/bin/time -f "%e %U %S" -o "$work/time.txt" "$exe" render "$@" --no-movie \
    >"$work/last.log" 2>&1 || {
    echo "render_throughput: '$label' failed, see below" >&2; tail -20 "$work/last.log" >&2; exit 1; }
  read -r wall user sys <"$work/time.txt"
  awk -v l="$label" -v n="$n" -v d="$wall" -v u="$user" -v s="$sys" -v cores="$(nproc)" \
    'BEGIN { printf "%-34s %6d %9.1f %9.2f %10.0f %7.0f%%\n", l, n, d, n / d, 3600 * n / d,
             100 * (u + s) / (d * cores) }'
}

header() { printf "%-34s %6s %9s %9s %10s %8s\n" "case" "frames" "seconds" "frames/s" "frames/h" "CPU"; }

echo "raintrace render throughput — $(nproc) cores, $(povray --version 2>&1 | head -1 | tr -s ' ')"
echo "(wall time of simulate + export + POV-Ray + contact sheet; no video)"
header
best_jobs=2; best_fps=0
for n in "${counts[@]}"; do
  scene=$(scene_for "$n")
  actual=$("$exe" simulate "$scene" --frames 1 --stats - 2>/dev/null |
           sed -n 's/.*"count": *\([0-9]*\).*/\1/p' | head -1)
  for jobs in 1 2 3 4; do
    line=$(run "${n} drops (${actual:-?} sim), --jobs $jobs" "$frames" -- "$scene" \
               -o "$work/out_${n}_$jobs" --jobs "$jobs")
    echo "$line"
    if [[ $n == "${counts[-1]}" ]]; then
      fps=$(awk '{ print $(NF-2) }' <<<"$line")
      if awk -v a="$fps" -v b="$best_fps" 'BEGIN { exit !(a > b) }'; then best_fps=$fps; best_jobs=$jobs; fi
    fi
  done
done
echo "best --jobs at ${counts[-1]} drops: $best_jobs ($best_fps frames/s; target >= 5)"

# The same top row with every frame tracing the whole environment ([export] environment_plate =
# false): what the preview's environment plate is worth.
n=${counts[-1]}
noplate=$work/drops_${n}_noplate.toml
{ cat "$(scene_for "$n")"; printf '[export]\nenvironment_plate = false\n'; } >"$noplate"
run "${n} drops, no plate, --jobs $best_jobs" "$frames" -- "$noplate" -o "$work/out_noplate" \
  --jobs "$best_jobs"

# The default example as users render it: its own 640×360 preview, then 1280×720 final.
default=$root/examples/default.toml
run "default 640x360 preview, --jobs $best_jobs" "$hd_frames" -- "$default" -o "$work/out_360" \
  --jobs "$best_jobs" --frames "1-$hd_frames"
run "default 1280x720 final, --jobs $best_jobs" "$final_frames" -- "$default" -o "$work/out_720" \
  --jobs "$best_jobs" --width 1280 --height 720 --quality final --frames "1-$final_frames"
