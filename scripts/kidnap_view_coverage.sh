#!/bin/bash
# Did the map cover what a kidnapped robot saw? (doc/results.md 9.17)
#
# For each rendered kidnap rawlog of a batch (BATCH_OUT/SCENARIO/data_seed*/),
# runs the front-end with --ground-truth once, places every landmark built
# before the kidnap at its true frame (the robot's true pose at its first
# measurement composed with that measurement's true relative pose), and
# prints, over the robot's true poses in the 10 s after the kidnap:
#   - the least heading difference to a landmark frame within 1.5 m, and
#   - the least distance to a landmark frame within 20 deg of heading
# (a landmark is a view: it is recognized from near its frame, looking the
# way it looked). Both are 999 where no landmark qualifies.
#
# With VIEWS=recognitions, every pose from which a landmark was recognized
# before the kidnap (a measurement the pre-filter accepted) counts as a
# view too, not only its frame: what the map would cover if each landmark
# also kept the appearance of the views it was recognized from.
#
# usage: scripts/kidnap_view_coverage.sh BATCH_OUT WORK_DIR [KIDNAP_TIME_S=240] [SCENARIO=kidnap] [VIEWS=frames]
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 BATCH_OUT WORK_DIR [KIDNAP_TIME_S] [SCENARIO] [VIEWS=frames|recognitions]" >&2; exit 2; }
out=$1 work=$2 kidnap=${3:-240} scenario=${4:-kidnap} views=${5:-frames}
case $views in frames | recognitions) ;; *) echo "VIEWS must be frames or recognitions, not '$views'" >&2; exit 2 ;; esac
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
for d in "$out/$scenario"/data_seed*; do
  seed=${d##*data_seed}
  csv=$work/seed$seed.csv
  [ -s "$csv" ] || "$root/build/bin/vslam-frontend" "$d/sim.rawlog" "$work/seed$seed.rawlog" \
    --config "$root/config_ini/demo_rendered.ini" --ground-truth "$d/sim_groundtruth.tum" \
    --accuracy-csv "$csv" > "$work/seed$seed.log"
  t0=$(awk '!/^#/ { print int($1); exit }' "$d/sim_groundtruth.tum")
  printf 'seed %s: ' "$seed"
  awk -v T0="$t0" -v TK="$kidnap" -v ALL="$([ "$views" = recognitions ] && echo 1 || echo 0)" '
    function wrap(a) { while (a > 180) a -= 360; while (a < -180) a += 360; return a }
    BEGIN { FS = "[ ,]+"; pi = atan2(0, -1) }
    FNR == 1 { file++ }
    file == 1 && !/^#/ { t = sprintf("%.1f", $1 - T0); X[t] = $2; Y[t] = $3; H[t] = 2 * atan2($7, $8) * 180 / pi; next }
    file == 2 && FNR > 1 {  # t,landmark,dx,dy,dphi_deg,true_dx,true_dy,true_dphi_deg,...
      t = sprintf("%.1f", $1 - T0); id = $2
      if (t + 0 >= TK || !(t in X)) next
      if (ALL && (id in LX) && $12 == 1) { v++; LX[id "/" v] = X[t]; LY[id "/" v] = Y[t]; LH[id "/" v] = H[t] }
      if (id in LX) next
      c = cos(H[t] * pi / 180); s = sin(H[t] * pi / 180)
      LX[id] = X[t] + c * $6 - s * $7; LY[id] = Y[t] + s * $6 + c * $7; LH[id] = wrap(H[t] + $8); n++
    }
    END {
      bestH = 999; bestD = 999
      for (t in X) {
        if (t + 0 <= TK || t + 0 > TK + 10) continue
        for (id in LX) {
          d = sqrt((X[t] - LX[id])^2 + (Y[t] - LY[id])^2); dh = wrap(H[t] - LH[id]); if (dh < 0) dh = -dh
          if (d <= 1.5 && dh < bestH) bestH = dh
          if (dh <= 20 && d < bestD) bestD = d
        }
      }
      printf "%d landmarks before the kidnap; least heading difference within 1.5 m: %.0f deg; least distance within 20 deg: %.2f m\n", n, bestH, bestD
    }' "$d/sim_groundtruth.tum" "$csv"
done
