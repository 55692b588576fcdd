#!/bin/bash
# The systematic errors of each landmark's measurements (doc/results.md
# 9.29), from a `vslam-frontend --accuracy-csv` file, over the accepted
# measurements:
# - heading slope: a landmark whose depths are tilted (its creation views'
#   heading off) is measured with a heading error that grows in proportion
#   to how far ahead of or behind its frame the robot is. For every landmark
#   with at least 8 measurements spanning at least 0.5 m of true_dx, the
#   least-squares slope of the heading error against true_dx (deg per m);
#   the median |slope| and its RMS over those landmarks;
# - scale: a landmark built too large or too small is measured too far or
#   too near. For every landmark with at least 5 measurements more than
#   0.4 m from its frame, the least-squares ratio of the measured to the
#   true displacement (dx, dy); the median |ratio - 1| and the largest;
# - scale, later half: the same ratio over the second half (in time) of
#   those measurements, for every landmark with at least 10 of them (what
#   the scale track left after its first sightings); the median
#   |ratio - 1| and the mean of ratio - 1 (its sign: too large or small);
# - the median |heading error| of all accepted measurements.
#
#   scripts/landmark_bias.sh ACCURACY.csv [...]
set -euo pipefail
[[ $# -ge 1 ]] || { echo "usage: landmark_bias.sh ACCURACY.csv [...]" >&2; exit 1; }
median() { sort -g | awk '{v[NR] = $1} END {if (NR == 0) print "nan"; else if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
for csv in "$@"; do
  [[ -r "$csv" ]] || { echo "error: cannot read '$csv'" >&2; exit 1; }
  # Columns by name, so the script follows the CSV's header.
  rows="$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next}
    $c["accepted"] == 1 {
      e = $c["dphi_deg"] - $c["true_dphi_deg"]; while (e > 180) e -= 360; while (e < -180) e += 360
      print $c["landmark"], $c["true_dx"], e, $c["true_dy"], $c["dx"], $c["dy"] }' "$csv")"
  slopes="$(awk '{n[$1]++; sx[$1] += $2; sy[$1] += $3; sxx[$1] += $2 * $2; sxy[$1] += $2 * $3
      if (!($1 in lo) || $2 < lo[$1]) lo[$1] = $2; if (!($1 in hi) || $2 > hi[$1]) hi[$1] = $2}
    END {for (k in n) if (n[k] >= 8 && hi[k] - lo[k] >= 0.5) {
      d = n[k] * sxx[k] - sx[k] * sx[k]; print (n[k] * sxy[k] - sx[k] * sy[k]) / d }}' <<< "$rows")"
  count="$(grep -c . <<< "$slopes" || true)"
  if [[ "$count" -eq 0 ]]; then
    echo "$csv: no landmark with 8 accepted measurements over 0.5 m of true_dx"
    continue
  fi
  absMedian="$(awk '{print ($1 < 0 ? -$1 : $1)}' <<< "$slopes" | median)"
  rms="$(awk '{s += $1 * $1} END {printf "%.2f", NR ? sqrt(s / NR) : 0}' <<< "$slopes")"
  headingMedian="$(awk '{print ($3 < 0 ? -$3 : $3)}' <<< "$rows" | median)"
  scales="$(awk '$2 * $2 + $4 * $4 > 0.16 {n[$1]++; mt[$1] += $5 * $2 + $6 * $4; tt[$1] += $2 * $2 + $4 * $4}
    END {for (k in n) if (n[k] >= 5) {d = mt[k] / tt[k] - 1; print (d < 0 ? -d : d)}}' <<< "$rows")"
  scaleCount="$(grep -c . <<< "$scales" || true)"
  scaleMedian="$(median <<< "$scales")"
  scaleMax="$(sort -g <<< "$scales" | tail -n 1)"
  # The CSV is in time order: each landmark's far measurements are numbered
  # as they come, and the second half is taken once their count is known.
  laterScales="$(awk '$2 * $2 + $4 * $4 > 0.16 {i = ++n[$1]; mt[$1, i] = $5 * $2 + $6 * $4; tt[$1, i] = $2 * $2 + $4 * $4}
    END {for (k in n) if (n[k] >= 10) {a = b = 0; for (i = int(n[k] / 2) + 1; i <= n[k]; i++) {a += mt[k, i]; b += tt[k, i]}
      print a / b - 1 }}' <<< "$rows")"
  laterCount="$(grep -c . <<< "$laterScales" || true)"
  laterMedian="$(awk '{print ($1 < 0 ? -$1 : $1)}' <<< "$laterScales" | median)"
  laterMean="$(awk '{s += $1} END {print NR ? s / NR : "nan"}' <<< "$laterScales")"
  printf '%s: heading error slope over %s landmarks: median |.| %.2f deg/m, RMS %s deg/m; scale error over %s landmarks: median %.1f%%, largest %.1f%%; later half over %s landmarks: median |.| %.1f%%, mean %+.1f%%; accepted heading error median |.| %.3f deg\n' \
    "$csv" "$count" "$absMedian" "$rms" "$scaleCount" "$(awk '{print 100 * $1}' <<< "$scaleMedian")" \
    "$(awk '{print 100 * $1}' <<< "$scaleMax")" "$laterCount" "$(awk '{print 100 * $1}' <<< "$laterMedian")" \
    "$(awk '{print 100 * $1}' <<< "$laterMean")" "$headingMedian"
done
