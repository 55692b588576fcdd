#!/bin/bash
# Bounded resources (doc/reliability.md): generates simulated runs of growing
# length in the same room with the same settings, runs vslam on each, and
# prints peak memory against run length. Memory should level off: the map is
# bounded by the room, path histories share their common ancestry, and every
# per-step output goes to disk as it is produced.
#
#   scripts/long_run_memory.sh [DURATIONS_S] [SIM_INI] [VSLAM_INI] [-- --set KEY=VALUE ...]
#
# Defaults: "600 1200 1800 3600", config_ini/simul_demo_visual.ini (kidnaps
# removed), config_ini/demo_visual.ini. A SIM_INI with a [vslam_simul]
# section is rendered by vslam-simul (camera images, JPEG to save disk) and
# vslam then runs the visual front-end too, e.g.
#   scripts/long_run_memory.sh "600 3600" config_ini/simul_living_room.ini \
#       config_ini/demo_rendered.ini -- --set vslam_landmark_database.max_landmarks=100
# Keys after -- go to vslam. Work files go to /tmp/vslam_long_run.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
ARGS=()
while [[ $# -gt 0 && "$1" != "--" ]]; do ARGS+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
DURATIONS="${ARGS[0]:-600 1200 1800 3600}"
SIM_INI="${ARGS[1]:-$ROOT/config_ini/simul_demo_visual.ini}"
VSLAM_INI="${ARGS[2]:-$ROOT/config_ini/demo_visual.ini}"
VSLAM_SET=("$@")
WORK=/tmp/vslam_long_run
[[ -x "$BIN/vslam" ]] || { echo "error: $BIN/vslam not built (scripts/setup.sh build)" >&2; exit 1; }
mkdir -p "$WORK"

echo "| simulated time [s] | steps | landmarks in map | ATE RMSE [m] | wall time [s] | peak memory [MiB] | vs the first |"
echo "|---|---|---|---|---|---|---|"
first=""
# FIELD of path NAME in run_summary.yaml's error_vs_ground_truth_m block.
summary_error() {
  awk -v name="$1" -v field="$2" '/^[^ ]/ { e = ($1 == "error_vs_ground_truth_m:") }
    e && /^  [^ ]/ { p = ($1 == name ":") } e && p && $1 == field ":" { print $2; exit }' "$3"
}
for d in $DURATIONS; do
  rawlog="$WORK/run_$d.rawlog"
  if grep -q '^\[vslam_simul\]' "$SIM_INI"; then
    "$BIN/vslam-simul" "$SIM_INI" "$rawlog" --quiet --set vslam_simul.duration="$d" \
      --set vslam_simul.kidnap_times= --set vslam_simul.image_format=jpg > /dev/null
  else
    "$BIN/vslam-simul-measurements" "$SIM_INI" "$rawlog" --set vslam_sim.duration="$d" \
      --set vslam_sim.kidnap_times= > /dev/null
  fi
  out="$WORK/out_$d"
  start=$(date +%s.%N)
  "$BIN/vslam" "$VSLAM_INI" "$rawlog" --out "$out" --quiet \
    --set vslam.ground_truth_file="$WORK/run_${d}_groundtruth.tum" "${VSLAM_SET[@]}" 2> /dev/null
  end=$(date +%s.%N)
  summary="$out/run_summary.yaml"
  steps=$(awk '$1 == "steps:" {print $2; exit}' "$summary")
  peak=$(awk '$1 == "peak_memory_MiB:" {print $2; exit}' "$summary")
  ate=$(summary_error vslam rmse "$summary")
  landmarks=$(grep -vc '^%' "$out/final_map.txt" || true)
  [[ -z "$first" ]] && first="$peak"
  awk -v d="$d" -v s="$steps" -v l="$landmarks" -v a="$ate" -v t0="$start" -v t1="$end" \
    -v p="$peak" -v f="$first" 'BEGIN {
      printf "| %s | %s | %s | %.3f | %.1f | %.1f | %.2fx |\n", d, s, l, a, t1 - t0, p, p / f }'
done
