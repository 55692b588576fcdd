#!/bin/bash
# Map once, localize later (doc/evaluation.md). In each home of a vslam-batch
# output: a map from the home's loop run; then its random run localized in
# that map (localization_only) from the true start and from an unknown start
# (initial_pose_unknown), continued from it (the map extended), and run
# without a map; and, where the batch has it, the random run with people,
# light changes, a dark spell and slips (random_disturbed) localized in it.
#
#   scripts/map_reuse.sh BATCH_OUT "SEEDS" [OUT] [VSLAM_INI]
#
# BATCH_OUT holds loop/data_seedN/, random/data_seedN/ (and random_disturbed/)
# as `vslam-batch config_ini/batches/test.ini` writes them. Prints one row per
# home (ATE means in metres; the unknown start: seconds from the first
# measurement of a mapped landmark until the pose was found, and until the
# estimate was within 0.3 m of the truth for 5 s; the error when found).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BATCH="$(cd "$1" && pwd)"; SEEDS="$2"; OUT="${3:-/tmp/vslam_map_reuse}"; INI="${4:-$ROOT/config_ini/demo_rendered.ini}"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
mkdir -p "$OUT"

# vslam on DATA (a batch data folder) into OUT/NAME with more --set arguments.
run() {
  local data="$1" name="$2"; shift 2
  "$BIN/vslam" "$INI" --quiet --out "$OUT/$name" --set vslam.rawlog_file="$data/sim.rawlog" \
    --set vslam.ground_truth_file="$data/sim_groundtruth.tum" "$@" > "$OUT/$name.log" 2>&1
}
# A number of run_summary.yaml: ate NAME -> the vslam ATE mean; key NAME SECTION KEY.
key() { awk -v s="$2:" -v k="$3:" '$1 == s && /^[a-z]/ {in_s = 1; next} /^[a-z]/ {in_s = 0} in_s && $1 == k {print $2}' "$OUT/$1/run_summary.yaml"; }
ate() { awk '/^error_vs_ground_truth_m:/ {e = 1} e && /^  vslam:/ {v = 1; next} e && /^  [a-z]/ {v = 0} v && $1 == "mean:" {printf "%.3f", $2; exit}' "$OUT/$1/run_summary.yaml"; }

# New landmarks of a continued map, and those of them within 0.3 m and 15 deg of
# one of the map's (a landmark frame is the robot pose that made it: the same
# place looked at the same way, most likely the same texture made again).
newLandmarks() {
  awk '!/^%/ && $2 == "pose" {if (FNR == NR) {n++; x[n] = $3; y[n] = $4; p[n] = $5; id[$1] = 1; next}
    if ($1 in id) next; added++; for (i = 1; i <= n; i++) {d = $5 - p[i]; while (d > 3.14159) d -= 6.28319;
      while (d < -3.14159) d += 6.28319; if (($3 - x[i])^2 + ($4 - y[i])^2 < 0.09 && d * d < 0.0685) {near++; break}}}
    END {printf "%d (%d)", added, near}' "$1" "$2"
}

echo "| home | map run (loop) | random: no map | random: continued (new landmarks, near an old one) | random: localization only | random with people, lights, dark spell, slips: localization only | unknown start: found after [s] | within 0.3 m after [s] | error when found [m] |"
echo "|---|---|---|---|---|---|---|---|---|"
for s in $SEEDS; do
  loop="$BATCH/loop/data_seed$s" random="$BATCH/random/data_seed$s" disturbed="$BATCH/random_disturbed/data_seed$s"
  map="$OUT/map_$s/final_map.vslam"
  run "$loop" "map_$s" --set vslam.initial_pose_from_ground_truth=true
  run "$random" "none_$s" &
  run "$random" "continued_$s" --set vslam.prior_map_file="$map" &
  wait
  run "$random" "localized_$s" --set vslam.prior_map_file="$map" --set vslam.localization_only=true &
  run "$random" "unknown_$s" --set vslam.prior_map_file="$map" --set vslam.localization_only=true \
    --set vslam.initial_pose_unknown=true --set vslam.initial_pose_from_ground_truth=false &
  wait
  disturbedAte="not run"
  if [[ -f "$disturbed/sim.rawlog" ]]; then
    run "$disturbed" "disturbed_$s" --set vslam.prior_map_file="$map" --set vslam.localization_only=true
    disturbedAte="$(ate "disturbed_$s")"
  fi
  first="$(key "unknown_$s" unknown_start_pose first_mapped_landmark_measured_at_s)"
  found="$(key "unknown_$s" unknown_start_pose found_at_s)"
  "$BIN/vslam-eval" "$OUT/unknown_$s/estimated_path.tum" "$random/sim_groundtruth.tum" \
    --csv "$OUT/unknown_$s/error.csv" > /dev/null
  # Times in the summary count from the run's first step (the odometry's first row).
  start="$(awk '!/^#/ {print $1; exit}' "$OUT/unknown_$s/odometry_path.tum")"
  # The first time from `first` on after which the error stays within 0.3 m for 5 s.
  within="$(awk -F, -v t0="$first" -v start="$start" 'NR > 1 && $1 == "estimate" {n++; t[n] = $2; e[n] = $3}
    END {for (i = 1; i <= n; i++) { if (t[i] - start < t0) continue; ok = 1;
      for (j = i; j <= n && t[j] < t[i] + 5; j++) if (e[j] > 0.3) {ok = 0; break}
      if (ok && j <= n) {printf "%.1f", t[i] - start - t0; exit} } print "never"}' "$OUT/unknown_$s/error.csv")"
  atFound="$(awk -F, -v t0="$found" -v start="$start" 'NR > 1 && $1 == "estimate" && $2 - start >= t0 - 1e-6 {printf "%.2f", $3; exit}' "$OUT/unknown_$s/error.csv")"
  foundAfter="never"; [[ "$found" != "" && "$found" != "~" && "$found" != "null" ]] && foundAfter="$(awk -v a="$found" -v b="$first" 'BEGIN {printf "%.1f", a - b}')"
  echo "| $s | $(ate "map_$s") | $(ate "none_$s") | $(ate "continued_$s") $(newLandmarks "$OUT/map_$s/final_map.txt" "$OUT/continued_$s/final_map.txt") | $(ate "localized_$s") | $disturbedAte | $foundAfter | $within | ${atFound:-} |"
done
