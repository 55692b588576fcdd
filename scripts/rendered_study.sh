#!/bin/bash
# The rendered scenarios end to end (doc/results.md section 7): for each
# vslam-simul INI, render the rawlog, measure the images (vslam-image-stats),
# run the visual front-end and score its measurements against the ground
# truth (vslam-frontend --ground-truth), run the filter on them (vslam, as
# one run would: tested to give the same path), run MRPT's rbpf-slam with
# the laser of the same rawlog, and print one table row per scenario.
#
#   scripts/rendered_study.sh OUT_DIR SIMUL_INI... [-- --set KEY=VALUE ...]
#
# Keys after -- go to every program that owns them: vslam_simul.* to the
# simulator, vslam_frontend.* to the front-end, the rest to vslam.
# Example: scripts/rendered_study.sh /tmp/rendered config_ini/simul_living_room.ini \
#              config_ini/simul_apartment.ini config_ini/simul_kidnap.ini config_ini/simul_dynamic.ini
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
source "$ROOT/scripts/lib/peers.sh"
OUT="${1:?usage: rendered_study.sh OUT_DIR SIMUL_INI... [-- --set ...]}"
shift
INIS=()
while [[ $# -gt 0 && "$1" != "--" ]]; do INIS+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
SIM_SET=() FE_SET=() VSLAM_SET=()
while [[ $# -gt 0 ]]; do
  [[ "$1" == "--set" && $# -ge 2 ]] || { echo "error: expected --set KEY=VALUE after --, got '$1'" >&2; exit 1; }
  case "$2" in
    vslam_simul.*) SIM_SET+=(--set "$2") ;;
    vslam_frontend.*) FE_SET+=(--set "$2") ;;
    *) VSLAM_SET+=(--set "$2") ;;
  esac
  shift 2
done
mkdir -p "$OUT"
VSLAM_INI="$ROOT/config_ini/demo_rendered.ini"

rmse() { grep "  $1: " "$2" | sed 's/.* rmse: \([0-9.e-]*\),.*/\1/'; }
echo "| scenario | images | SIFT per image (median) | inliers consecutive / revisit (median) | measurements accepted | beyond 3 sigma | vslam ATE RMSE [m] | dead reckoning [m] | rbpf-slam (laser, aligned) [m] | front-end + filter [s] | rbpf-slam [s] |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for ini in "${INIS[@]}"; do
  name="$(basename "$ini" .ini)"
  d="$OUT/$name"
  mkdir -p "$d"
  log="$d/log.txt"
  : > "$log"
  "$BIN/vslam-simul" "$ini" "$d/sim.rawlog" --quiet "${SIM_SET[@]}" >> "$log" 2>&1 || { cat "$log" >&2; exit 1; }
  gt="$d/sim_groundtruth.tum"
  stats="$("$BIN/vslam-image-stats" "$d/sim.rawlog" "$gt" "${FE_SET[@]}" 2>&1)" || { echo "$stats" >&2; exit 1; }
  echo "$stats" >> "$log"
  images="$(echo "$stats" | sed -n 's/.*: \([0-9]*\) images;.*/\1/p')"
  sift="$(echo "$stats" | sed -n 's/.*median \([0-9]*\), min.*/\1/p')"
  cin="$(echo "$stats" | grep consecutive | sed 's/.*median *\([0-9]*\) inliers.*/\1/')"
  rin="$(echo "$stats" | grep revisits | sed 's/.*median *\([0-9]*\) inliers.*/\1/')"
  rpairs="$(echo "$stats" | grep revisits | sed 's/.*revisits *\([0-9]*\) pairs.*/\1/')"
  start=$(date +%s.%N)
  fe="$("$BIN/vslam-frontend" "$d/sim.rawlog" "$d/measurements.rawlog" --config "$VSLAM_INI" "${FE_SET[@]}" \
        --ground-truth "$gt" --accuracy-csv "$d/measurement_errors.csv" 2>&1)" || { echo "$fe" >&2; exit 1; }
  echo "$fe" >> "$log"
  "$BIN/vslam" "$VSLAM_INI" "$d/measurements.rawlog" --out "$d/vslam" --quiet \
    --set vslam.ground_truth_file="$gt" "${VSLAM_SET[@]}" >> "$log" 2>&1 || { cat "$log" >&2; exit 1; }
  vslam_s="$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN{printf "%.0f", b-a}')"
  acc="$(echo "$fe" | grep "vslam-frontend: accepted")"
  naccepted="$(echo "$acc" | awk '{print $3}')"
  beyond="$(echo "$acc" | sed 's/.*deg *\([0-9]*\) (\(.*\))$/\1 (\2)/')"
  v="$(rmse vslam "$d/vslam/run_summary.yaml")" dr="$(rmse dead_reckoning "$d/vslam/run_summary.yaml")"
  rbpf_slam "$d/sim.rawlog" "$d" || { tail -20 "$d/rbpf-slam.log" >&2; exit 1; }
  rbpf_s="$(wall_seconds "$d/rbpf-slam")"
  r="$("$BIN/vslam-eval" "$d/rbpf-slam.tum" "$gt" --align | head -n 1 | sed 's/.*rmse \([0-9.]*\).*/\1/')"
  "$BIN/vslam-eval" "$d/vslam/estimated_path.tum" "$gt" --odometry "$d/sim_odometry.tum" \
    --world "$(grep -m1 '^world_file' "$ini" | sed 's/.*= *//' | sed "s|^|$(dirname "$ini")/|")" \
    --plot "$d/paths.png" > /dev/null
  printf "| %s | %s | %s | %s / %s (%s pairs) | %s | %s | %.3f | %.3f | %.3f | %s | %s |\n" "$name" "$images" "$sift" \
    "$cin" "$rin" "$rpairs" "$naccepted" "$beyond" "$v" "$dr" "$r" "$vslam_s" "$rbpf_s"
done
