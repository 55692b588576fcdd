#!/bin/bash
# Side by side on one rawlog: vslam, odometry alone, and
# MRPT's own SLAM with its documented best settings (config_ini/peers/):
# rbpf-slam grid mapping when the rawlog has laser scans, kf-slam when it has
# range-bearing observations. Prints one Markdown table: ATE (raw, and after
# SE(2) alignment: MRPT's apps start at their own origin), RPE over 1 s,
# wall time and peak memory of each program.
#
#   scripts/side_by_side.sh RAWLOG GROUND_TRUTH OUT_DIR [VSLAM_INI] [-- --set KEY=VALUE ...]
#
# VSLAM_INI defaults to config_ini/demo_rendered.ini (camera images); for
# range-bearing rawlogs use e.g. config_ini/mrclam_range_bearing.ini. The
# --set options go to vslam. Example, on the demo rawlog:
#   scripts/side_by_side.sh rawlogs/demo_rendered.rawlog rawlogs/demo_rendered_groundtruth.tum /tmp/sbs
# Needs a build (scripts/setup.sh build) and MRPT's apps (mrpt-apps).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
source "$ROOT/scripts/lib/peers.sh"
usage="usage: side_by_side.sh RAWLOG GROUND_TRUTH OUT_DIR [VSLAM_INI] [-- --set KEY=VALUE ...]"
ARGS=()
while [[ $# -gt 0 && "$1" != "--" ]]; do ARGS+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
[[ ${#ARGS[@]} -ge 3 && ${#ARGS[@]} -le 4 ]] || { echo "$usage" >&2; exit 1; }
RAWLOG="$(realpath "${ARGS[0]}")" GT="$(realpath "${ARGS[1]}")" OUT="${ARGS[2]}"
VSLAM_INI="$(realpath "${ARGS[3]:-$ROOT/config_ini/demo_rendered.ini}")"
[[ -f "$RAWLOG" ]] || { echo "error: no rawlog '$RAWLOG'" >&2; exit 1; }
[[ -f "$GT" ]] || { echo "error: no ground truth '$GT'" >&2; exit 1; }
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

# One table row from vslam-eval's output: ATE raw / aligned, RPE 1 s.
row() { # NAME TRAJECTORY TIME_PREFIX(or "")
  local e
  e="$("$BIN/vslam-eval" "$2" "$GT")" || { echo "error: vslam-eval failed on $2" >&2; exit 1; }
  local raw aligned median rpe rot
  raw="$(grep '^ate:' <<< "$e" | sed 's/.* rmse \([0-9.]*\) .*/\1/')"
  aligned="$(grep '^ate_se2_aligned:' <<< "$e" | sed 's/.* rmse \([0-9.]*\) .*/\1/')"
  median="$(grep '^ate_se2_aligned:' <<< "$e" | sed 's/.* median \([0-9.]*\) .*/\1/')"
  rpe="$(grep '^rpe_1s:' <<< "$e" | sed 's/.* trans_rmse \([0-9.]*\) .*/\1/')"
  rot="$(grep '^rpe_1s:' <<< "$e" | sed 's/.* rot_rmse_deg \([0-9.]*\) .*/\1/')"
  local wall="-" mem="-"
  [[ -n "$3" ]] && wall="$(wall_seconds "$3")" mem="$(peak_mib "$3")"
  printf "| %s | %.3f | %.3f | %.3f | %.3f | %.2f | %s | %s |\n" "$1" "$raw" "$aligned" "$median" "$rpe" "$rot" \
    "$wall" "$mem"
}

data_seconds() { awk 'NR==2 {t0=$1} NF>1 && $1!~/^#/ {t=$1} END {printf "%.0f", t-t0}' "$GT"; }
echo "Rawlog: $RAWLOG ($(data_seconds) s of data); vslam: $VSLAM_INI"
echo
echo "| method | ATE RMSE [m] | ATE RMSE, SE(2)-aligned [m] | ATE median, aligned [m] | RPE 1 s RMSE [m] | RPE 1 s rotation RMSE [deg] | wall time [s] | peak memory [MiB] |"
echo "|---|---|---|---|---|---|---|---|"
timed "$OUT/vslam" "$BIN/vslam" "$VSLAM_INI" "$RAWLOG" --out "$OUT/vslam" --quiet "$@" ||
  { tail -n 20 "$OUT/vslam.log" >&2; exit 1; }
row vslam "$OUT/vslam/estimated_path.tum" "$OUT/vslam"
row "odometry alone" "$OUT/vslam/odometry_path.tum" ""

classes="$(zcat -f "$RAWLOG" | head -c 50000000 | grep -a -o -E 'CObservation2DRangeScan|CObservationBearingRange' | sort -u)"
if grep -q CObservation2DRangeScan <<< "$classes"; then
  if command -v rbpf-slam > /dev/null && rbpf_slam "$RAWLOG" "$OUT"; then
    row "rbpf-slam (laser grid mapping)" "$OUT/rbpf-slam.tum" "$OUT/rbpf-slam"
  else
    echo "| rbpf-slam | failed or not installed: see $OUT/rbpf-slam.log | | | | | | |"
  fi
fi
if grep -q CObservationBearingRange <<< "$classes"; then
  awk '{print $8}' "$OUT/vslam/log_estimated_path.txt" > "$OUT/step_times.txt"
  if command -v kf-slam > /dev/null && kf_slam "$RAWLOG" "$OUT" "$OUT/step_times.txt"; then
    row "kf-slam (EKF, range-bearing)" "$OUT/kf-slam.tum" "$OUT/kf-slam"
  else
    echo "| kf-slam | failed or not installed: see $OUT/kf-slam.log | | | | | | |"
  fi
fi
