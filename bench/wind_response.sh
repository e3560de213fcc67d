#!/usr/bin/env bash
# What each [wind] setting does to the drops: the figures in docs/scene-format.md ([wind]).
# Simulates (no rendering) the default camera at 5 mm/h with one wind setting at a time and
# reports, from `raintrace simulate --stats` (horizontal_motion_by_frame, docs/statistics.md):
# the drops' mean horizontal velocity over time (mean, min, max, RMS about the mean), its
# spread across drops at one instant, the wind at look_at, and the streak tilt from vertical
# that velocity gives a drop falling at the mean fall speed. About 2.5 CPU minutes.
# Usage: bench/wind_response.sh [RAINTRACE]      (default build/cli/raintrace)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$root/build/cli/raintrace}
work=$(mktemp -d /tmp/raintrace_wind.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work"
base='seed = 1
[output]
frames = FRAMES
fps = 24
[camera]
position = [0, 1.6, -5]
look_at = [0, 1.3, 0]
[rain]
rate_mm_per_h = 5
far_m = 6
[splashes]
enabled = false
[wind]'
run() {  # name frames extra-wind-lines
  printf '%s\n%s\n' "${base/FRAMES/$2}" "$3" > "$1.toml"
  nice "$exe" simulate "$1.toml" --stats "$1.json" >/dev/null 2>&1
  python3 - "$1" <<'PY'
import json, sys, math
j = json.load(open(sys.argv[1] + ".json"))
m = j["horizontal_motion_by_frame"]
vx = [f["drop_velocity_m_per_s"][0] for f in m]; vz = [f["drop_velocity_m_per_s"][1] for f in m]
wx = [f["wind_m_per_s"][0] for f in m]
sd = sum(f["drop_velocity_sd_m_per_s"][0] for f in m) / len(m)
mean = sum(vx) / len(vx); rms = math.sqrt(sum((v - mean) ** 2 for v in vx) / len(vx))
# fall speed of the mean drop: weight bins by samples
b = j["fall_speed_by_diameter"]; n = sum(x["samples"] for x in b)
vf = sum(x["speed_m_per_s"] * x["samples"] for x in b) / n
tilt = lambda v: math.degrees(math.atan2(abs(v), vf))
print(f"{sys.argv[1]:28s} drops vx mean {mean:6.3f} min {min(vx):6.3f} max {max(vx):6.3f} rms {rms:5.3f} | across-drop sd {sd:5.3f} | wind x {min(wx):6.2f}..{max(wx):6.2f} | vz mean {sum(vz)/len(vz):6.3f} | mean fall {vf:4.2f} tilt mean {tilt(mean):4.1f} max {tilt(max(vx,key=abs)):4.1f} deg")
PY
}
run still 48 ''
run steady_2 48 'velocity_m_per_s = [2, 0, 0]'
run steady_5 48 'velocity_m_per_s = [5, 0, 0]'
run gust_printed 96 'gusts = true
gust_strength = 20
gust_period_s = 2'
run gust_default 480 'gusts = true
gust_strength = 20'
run gust_8_period_20 480 'gusts = true
gust_strength = 8'
run gust_20_period_60 1440 'gusts = true
gust_strength = 20
gust_period_s = 60'
run gust_20_period_5 240 'gusts = true
gust_strength = 20
gust_period_s = 5'
run turb_0.8 96 'turbulence_m_per_s = 0.8'
run turb_2_scale_1 96 'turbulence_m_per_s = 2
turbulence_scale_m = 1'
run turb_2_scale_10 96 'turbulence_m_per_s = 2
turbulence_scale_m = 10'
