#!/bin/bash
# MRCLAM comparison: for each robot of one data set,
#   - import it with mrclam2rawlog (rawlog + ground truth in the start frame),
#   - run vslam with config_ini/mrclam_range_bearing.ini for several seeds,
#   - run MRPT's kf-slam (CRangeBearingKFSLAM2D) with config_ini/peers/kf-slam_mrclam.ini,
# and print ATE RMSE (no alignment, all starting at the robot's first pose) of
# dead reckoning, kf-slam and vslam per robot as a Markdown table. vslam's
# figures are its online estimate (estimated_path.tum), its pose graph solved
# once more at the end (pose_graph_path.tum), and that graph with every
# keyframe kept (max_keyframes = 0, seed 1): a batch least squares over the
# whole run with known associations, the best a smoother could do here.
#
#   scripts/mrclam_compare.sh [DATASET_DIR] [OUT_DIR] [SEEDS] [ROBOTS] [-- vslam --set options]
#
# Defaults: ../shared/data/mrclam/MRCLAM_Dataset6, /tmp/vslam_mrclam, "1 2 3", "1 2 3 4 5".
# Needs a build (scripts/setup.sh build) and, for kf-slam, MRPT's apps (mrpt-apps).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
source "$ROOT/scripts/lib/peers.sh"
ARGS=()
while [[ $# -gt 0 && "$1" != "--" ]]; do ARGS+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
EXTRA=("$@")
DATASET="${ARGS[0]:-$ROOT/../shared/data/mrclam/MRCLAM_Dataset6}"
OUT="${ARGS[1]:-/tmp/vslam_mrclam}"
SEEDS="${ARGS[2]:-1 2 3}"
ROBOTS="${ARGS[3]:-1 2 3 4 5}"

[[ -f "$DATASET/Barcodes.dat" ]] || { echo "error: no MRCLAM data set in '$DATASET'" >&2; exit 1; }
mkdir -p "$OUT"
DATASET="$(cd "$DATASET" && pwd)"
OUT="$(cd "$OUT" && pwd)"
name="$(basename "$DATASET" | sed 's/MRCLAM_Dataset/d/')"

rmse() { # ESTIMATE GROUND_TRUTH -> RMSE
  "$BIN/vslam-eval" "$1" "$2" | head -n 1 | sed 's/.* rmse \([0-9.]*\) .*/\1/'
}
mean() { awk '{s=0; for(i=1;i<=NF;i++) s+=$i; printf "%.2f", s/NF}' <<< "$*"; }

printf "| robot | dead reckoning | kf-slam | vslam online (seeds %s) | mean | vslam smoothed (seeds %s) | mean | full batch |\n" "$SEEDS" "$SEEDS"
printf "|---|---|---|---|---|---|---|---|\n"
for r in $ROBOTS; do
  base="$OUT/${name}_r$r"
  "$BIN/mrclam2rawlog" "$DATASET" "$r" "$base.rawlog" > "$base.import.log"
  gt="${base}_groundtruth.tum"

  vals=(); smoothed=()
  for s in $SEEDS; do
    o="$base.vslam_s$s"
    "$BIN/vslam" "$ROOT/config_ini/mrclam_range_bearing.ini" "$base.rawlog" --out "$o" --quiet \
      --set vslam.RANDOM_SEED="$s" --set vslam.ground_truth_file="$gt" "${EXTRA[@]}" > "$o.log" 2>&1
    vals+=("$(rmse "$o/estimated_path.tum" "$gt")")
    smoothed+=("$(rmse "$o/pose_graph_path.tum" "$gt")")
  done
  o="$base.vslam_batch"
  "$BIN/vslam" "$ROOT/config_ini/mrclam_range_bearing.ini" "$base.rawlog" --out "$o" --quiet \
    --set vslam.RANDOM_SEED=1 --set vslam.ground_truth_file="$gt" --set vslam_loop_closure.max_keyframes=0 \
    "${EXTRA[@]}" > "$o.log" 2>&1
  batch="$(rmse "$o/pose_graph_path.tum" "$gt")"

  # Dead reckoning: vslam writes it beside its estimate, at the same steps.
  o="$base.vslam_s$(awk '{print $1}' <<< "$SEEDS")"
  dr="$(rmse "$o/odometry_path.tum" "$gt")"

  kf="n/a"
  if command -v kf-slam > /dev/null; then
    awk '{print $8}' "$o/log_estimated_path.txt" > "$base.step_times"
    mkdir -p "$base.peers"
    kf_slam "$base.rawlog" "$base.peers" "$base.step_times" && kf="$(rmse "$base.peers/kf-slam.tum" "$gt")"
  fi
  printf "| %s | %.2f | %s | %s | %s | %s | %s | %.2f |\n" "$r" "$dr" \
    "$([[ $kf == n/a ]] && echo n/a || printf %.2f "$kf")" \
    "$(printf "%.2f " "${vals[@]}" | sed 's/ $//')" "$(mean "${vals[@]}")" \
    "$(printf "%.2f " "${smoothed[@]}" | sed 's/ $//')" "$(mean "${smoothed[@]}")" "$batch"
done
