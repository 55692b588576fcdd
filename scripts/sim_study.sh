#!/bin/bash
# Accuracy on simulated runs: for each seed, simulate a run
# with vslam-simul-measurements, run vslam on it (starting at the true first
# pose), and print ATE RMSE of vslam and of dead reckoning per seed and the
# means.
#
#   scripts/sim_study.sh SIM_INI VSLAM_INI [SEEDS] [OUT_DIR] [-- --set ... (simulator and vslam keys)]
#
# Keys after -- go to both programs: vslam_sim.* to the simulator, the rest
# to vslam. Example:
#   scripts/sim_study.sh config_ini/simul_measurements_example.ini config_ini/demo_visual.ini \
#       "1 2 3 4 5 6 7 8 9 10" /tmp/vslam_sim -- --set vslam_sim.duration=600 \
#       --set vslam_sim.odo_scale_bias=0.02 --set vslam_sim.odo_turn_bias=0.03
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
ARGS=()
while [[ $# -gt 0 && "$1" != "--" ]]; do ARGS+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
SIM_INI="${ARGS[0]:?usage: sim_study.sh SIM_INI VSLAM_INI [SEEDS] [OUT_DIR] [-- --set ...]}"
VSLAM_INI="${ARGS[1]:?usage: sim_study.sh SIM_INI VSLAM_INI [SEEDS] [OUT_DIR] [-- --set ...]}"
SEEDS="${ARGS[2]:-1 2 3 4 5 6 7 8 9 10}"
OUT="${ARGS[3]:-/tmp/vslam_sim}"
SIM_SET=() VSLAM_SET=()
while [[ $# -gt 0 ]]; do
  [[ "$1" == "--set" && $# -ge 2 ]] || { echo "error: expected --set SECTION.KEY=VALUE after --, got '$1'" >&2; exit 1; }
  if [[ "$2" == vslam_sim.* ]]; then SIM_SET+=(--set "$2"); else VSLAM_SET+=(--set "$2"); fi
  shift 2
done
mkdir -p "$OUT"

# FIELD of path NAME in run_summary.yaml's error_vs_ground_truth_m block.
summary_error() {
  awk -v name="$1" -v field="$2" '/^[^ ]/ { e = ($1 == "error_vs_ground_truth_m:") }
    e && /^  [^ ]/ { p = ($1 == name ":") } e && p && $1 == field ":" { print $2; exit }' "$3"
}
rmse() { summary_error "$1" rmse "$2"; }
echo "| seed | vslam ATE RMSE [m] | dead reckoning [m] | kidnaps detected |"
echo "|---|---|---|---|"
sumV=0 sumD=0 n=0
for s in $SEEDS; do
  rawlog="$OUT/sim_s$s.rawlog"
  log="$OUT/seed_$s.log"
  "$BIN/vslam-simul-measurements" "$SIM_INI" "$rawlog" --set vslam_sim.seed="$s" "${SIM_SET[@]}" \
    > "$log" 2>&1 || { cat "$log" >&2; exit 1; }
  "$BIN/vslam" "$VSLAM_INI" "$rawlog" --out "$OUT/vslam_s$s" --quiet --set vslam.RANDOM_SEED="$s" \
    --set vslam.ground_truth_file="$OUT/sim_s${s}_groundtruth.tum" \
    --set vslam.initial_pose_from_ground_truth=true "${VSLAM_SET[@]}" >> "$log" 2>&1 ||
    { cat "$log" >&2; exit 1; }
  summary="$OUT/vslam_s$s/run_summary.yaml"
  v="$(rmse vslam "$summary")" d="$(rmse dead_reckoning "$summary")"
  k="$(awk '$1 == "kidnaps_detected:" {print $2; exit}' "$summary")"
  printf "| %s | %.3f | %.3f | %s |\n" "$s" "$v" "$d" "$k"
  sumV="$(awk -v a="$sumV" -v b="$v" 'BEGIN{print a+b}')"
  sumD="$(awk -v a="$sumD" -v b="$d" 'BEGIN{print a+b}')"
  n=$((n + 1))
done
awk -v v="$sumV" -v d="$sumD" -v n="$n" 'BEGIN{printf "| mean | %.3f | %.3f | |\n", v/n, d/n}'
