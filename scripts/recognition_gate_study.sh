#!/bin/bash
# What a gate of each recognition against the same landmark's last one
# would do (doc/results.md 9.43), offline, from `vslam-frontend
# --accuracy-csv` files and the odometry the front-end had (a rendered
# run's sim_odometry.tum). A recognition of landmark L at time t is
# predicted from L's last recognition that passed, at t' >= t - HORIZON
# seconds, carried by the odometry from t' to t; it passes if its position
# is within POS + REL x its distance of the prediction and its heading
# within DEG degrees (a recognition with no such predecessor passes).
# Prints, per CSV and over all, the accepted measurements and those beyond
# 3 sigma, without and with the gate.
#
#   HORIZON=5 POS=0.3 REL=0.1 DEG=10 scripts/recognition_gate_study.sh ODOMETRY.tum ACCURACY.csv [...]
set -euo pipefail
[[ $# -ge 2 && $(($# % 2)) -eq 0 ]] || {
  echo "usage: [HORIZON=s POS=m REL=share DEG=deg] recognition_gate_study.sh ODOMETRY.tum ACCURACY.csv [...]" >&2; exit 1; }
HORIZON="${HORIZON:-5}" POS="${POS:-0.3}" REL="${REL:-0.1}" DEG="${DEG:-10}"
total=""
while [[ $# -gt 0 ]]; do
  odometry="$1" csv="$2"; shift 2
  for f in "$odometry" "$csv"; do [[ -r "$f" ]] || { echo "error: cannot read '$f'" >&2; exit 1; }; done
  line="$(awk -v H="$HORIZON" -v P="$POS" -v R="$REL" -v D="$DEG" '
    function absAngle(a) { while (a > pi) a -= 2 * pi; while (a < -pi) a += 2 * pi; return a < 0 ? -a : a }
    # The odometry pose at time t: the sample nearest t (binary search).
    function pose(t,   lo, hi, mid, k) {
      lo = 1; hi = n
      while (hi - lo > 1) { mid = int((lo + hi) / 2); if (ot[mid] < t) lo = mid; else hi = mid }
      k = (t - ot[lo] <= ot[hi] - t) ? lo : hi; px = ox[k]; py = oy[k]; pa = oa[k] }
    BEGIN { pi = atan2(0, -1) }
    FNR == NR { if ($1 !~ /^#/ && NF >= 8) { n++; ot[n] = $1; ox[n] = $2; oy[n] = $3; oa[n] = 2 * atan2($7, $8) } next }
    FNR == 1 { FS = ","; $0 = $0; for (i = 1; i <= NF; i++) c[$i] = i; next }
    {
      t = $c["t"]; L = $c["landmark"]; zx = $c["dx"]; zy = $c["dy"]; za = $c["dphi_deg"] * pi / 180
      pose(t); pass = 1
      if ((L in lt) && t - lt[L] <= H) {
        # The earlier robot pose in the current robot frame, then its measurement.
        dx = lx[L] - px; dy = ly[L] - py; cc = cos(pa); ss = sin(pa)
        rx = cc * dx + ss * dy; ry = -ss * dx + cc * dy; ra = la[L] - pa
        ex = rx + cos(ra) * mx[L] - sin(ra) * my[L]; ey = ry + sin(ra) * mx[L] + cos(ra) * my[L]
        pass = sqrt((ex - zx)^2 + (ey - zy)^2) <= P + R * sqrt(zx^2 + zy^2) && absAngle(ra + ma[L] - za) <= D * pi / 180
      }
      if (pass) { lt[L] = t; lx[L] = px; ly[L] = py; la[L] = pa; mx[L] = zx; my[L] = zy; ma[L] = za }
      if ($c["accepted"] == 1) { a++; b += $c["beyond_3_sigma"]; if (pass) { ag++; bg += $c["beyond_3_sigma"] } }
    }
    END { print a + 0, b + 0, ag + 0, bg + 0 }' "$odometry" "$csv")"
  read -r a b ag bg <<< "$line"
  awk -v f="$csv" -v a="$a" -v b="$b" -v ag="$ag" -v bg="$bg" 'BEGIN {
    printf "%s: accepted %d, beyond 3 sigma %d (%.2f%%); gated: accepted %d, beyond 3 sigma %d (%.2f%%)\n",
      f, a, b, a ? 100 * b / a : 0, ag, bg, ag ? 100 * bg / ag : 0 }'
  total+="$line"$'\n'
done
awk 'NF == 4 {a += $1; b += $2; ag += $3; bg += $4} END {
  printf "all: accepted %d, beyond 3 sigma %d (%.2f%%); gated: accepted %d, beyond 3 sigma %d (%.2f%%)\n",
    a, b, a ? 100 * b / a : 0, ag, bg, ag ? 100 * bg / ag : 0 }' <<< "$total"
