#!/usr/bin/env bash
# How far a render's ETA was from the time really left: reads the progress lines `raintrace
# render` writes to a log or pipe ("render: D/T frames done, [X/T exported,] F failed, E s
# elapsed, ETA N s") and its last line ("… failed in S s"), and prints, for each progress line,
# the ETA, what the plain rate of finished pictures (E ÷ (D + F) × (T − D − F)) would have said
# at that moment, and the time really left (S − E); then, for both, when the first estimate
# came and the median and worst of |estimate − left| ÷ left.
# Usage: raintrace render SCENE -o OUT … 2> progress.txt; bench/eta_error.sh progress.txt
set -euo pipefail
[[ $# == 1 ]] || { echo "usage: $0 PROGRESS_LOG" >&2; exit 2; }

tr '\r' '\n' < "$1" | awk '
  function median(a, n,   i, j, t) {
    for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  # A local render also counts the frames exported ("…, 30/48 exported, …"): left out.
  match($0, /[0-9]+\/[0-9]+ frames done, ([0-9]+\/[0-9]+ exported, )?[0-9]+ failed, [0-9.]+ s elapsed, ETA [0-9a-z]+/) {
    line = substr($0, RSTART, RLENGTH); sub(/[0-9]+\/[0-9]+ exported, /, "", line)
    split(line, w, /[\/ ,]+/)
    n++; done_[n] = w[1] + w[5]; total[n] = w[2]; elapsed[n] = w[7]
    eta[n] = (w[11] == "unknown") ? -1 : w[11]
  }
  match($0, /failed in [0-9.]+ s/) { split(substr($0, RSTART, RLENGTH), f, " "); seconds = f[3] }
  END {
    if (seconds == "") { print "no final line (\"… failed in S s\") in the log" > "/dev/stderr"; exit 1 }
    printf "%9s %6s %8s %8s %8s\n", "elapsed", "done", "ETA", "plain", "left"
    for (i = 1; i <= n; i++) {
      left = seconds - elapsed[i]
      plain = done_[i] > 0 ? elapsed[i] / done_[i] * (total[i] - done_[i]) : -1
      printf "%9.1f %6d %8s %8s %8.1f\n", elapsed[i], done_[i], eta[i] < 0 ? "-" : eta[i],
             plain < 0 ? "-" : sprintf("%.0f", plain), left
      if (left <= 0) continue
      if (eta[i] >= 0) { if (ne == 0) first_eta = elapsed[i]; e[++ne] = (eta[i] > left ? eta[i] - left : left - eta[i]) / left; if (e[ne] > we) we = e[ne] }
      if (plain >= 0) { if (np == 0) first_plain = elapsed[i]; p[++np] = (plain > left ? plain - left : left - plain) / left; if (p[np] > wp) wp = p[np] }
    }
    printf "render %.1f s\n", seconds
    if (ne) printf "ETA:        first at %.1f s, %d lines, median error %.2f, worst %.2f\n", first_eta, ne, median(e, ne), we
    if (np) printf "plain rate: first at %.1f s, %d lines, median error %.2f, worst %.2f\n", first_plain, np, median(p, np), wp
  }'
