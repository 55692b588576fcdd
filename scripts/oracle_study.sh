#!/bin/bash
# How much of vslam's error is the front-end's and how much the filter's
# (doc/results.md section 9.6). For every rendered rawlog of a batch
# scenario (BATCH_OUT/SCENARIO/data_seed*/sim.rawlog, e.g. from
# config_ini/batches/paper_experiments.ini), the front-end runs once
# (vslam-frontend, cached in OUT_DIR) and writes two measurement rawlogs:
# its own measurements, and the same recognitions with the true measurement
# each (--oracle-rawlog). The filter then runs on both with filter seeds
# 1..FILTER_SEEDS (the filter alone takes about a second per run), and the
# table gives the ATE RMSE (raw and SE(2)-aligned) and median of the online
# estimate, the SE(2)-aligned ATE RMSE of the most-likely path and the ATE
# RMSE of the loop-closure graph's path at the end (pose_graph_path.tum; 0
# when the run has none), mean over the filter seeds, for each rawlog and
# over all. The front-end's log (accuracy against the truth) and, with
# heading changes on, their CSV (--heading-csv) stay in OUT_DIR.
#
#   [ORACLE_KIND=K] [ORACLE_SCALE_BIAS=B] scripts/oracle_study.sh BATCH_OUT SCENARIO OUT_DIR [FILTER_SEEDS] [-- --set KEY=VALUE ...]
#
# ORACLE_KIND (vslam-frontend --oracle-kind): all (default: every
# measurement replaced by its truth), outliers, inliers, drop-outliers,
# scale (each landmark's scale error taken out; ORACLE_SCALE_BIAS, the
# odometry's own scale error, is left in: --oracle-scale-bias).
#
# The --set options go to both the front-end and the filter runs (vslam
# section keys to vslam, vslam_frontend keys to both). FILTER_SEEDS: 4.
# Example:
#   scripts/oracle_study.sh batch_out/paper_experiments living_room /tmp/oracle
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
INI="$ROOT/config_ini/demo_rendered.ini"
usage="usage: oracle_study.sh BATCH_OUT SCENARIO OUT_DIR [FILTER_SEEDS] [-- --set KEY=VALUE ...]"
ARGS=()
while [[ $# -gt 0 && "$1" != "--" ]]; do ARGS+=("$1"); shift; done
[[ "${1:-}" == "--" ]] && shift
[[ ${#ARGS[@]} -ge 3 && ${#ARGS[@]} -le 4 ]] || { echo "$usage" >&2; exit 1; }
BATCH="${ARGS[0]}" SCENARIO="${ARGS[1]}" OUT="${ARGS[2]}" SEEDS="${ARGS[3]:-4}"
KIND="${ORACLE_KIND:-all}"
BIAS_ARGS=()
[[ -n "${ORACLE_SCALE_BIAS:-}" ]] && BIAS_ARGS=(--oracle-scale-bias "$ORACLE_SCALE_BIAS")
SETS=("$@")
FRONTEND_SETS=()
for ((i = 0; i < ${#SETS[@]}; i++)); do
  [[ "${SETS[$i]}" == "--set" && "${SETS[$((i + 1))]:-}" == vslam_frontend.* ]] &&
    FRONTEND_SETS+=(--set "${SETS[$((i + 1))]}")
done
shopt -s nullglob
DATA=("$BATCH/$SCENARIO"/data_seed*/sim.rawlog)
[[ ${#DATA[@]} -gt 0 ]] || { echo "error: no $BATCH/$SCENARIO/data_seed*/sim.rawlog" >&2; exit 1; }
mkdir -p "$OUT"
# A key for the front-end settings, so cached measurement rawlogs match them.
KEY="$(printf '%s ' "${FRONTEND_SETS[@]:-}" | md5sum | cut -c1-8)"

# Mean over the filter seeds: raw RMSE, aligned RMSE, raw median, and the
# most-likely path's aligned RMSE.
filter_runs() { # MEASUREMENT_RAWLOG GROUND_TRUTH
  for ((s = 1; s <= SEEDS; s++)); do
    local o="$OUT/run_$$"
    if ! "$BIN/vslam" "$INI" "$1" --quiet --out "$o" --set vslam.ground_truth_file="$2" \
      --set vslam.RANDOM_SEED="$s" "${SETS[@]}" > "$OUT/run_$$.log" 2>&1; then
      echo "error: vslam failed on $1 (seed $s):" >&2
      cat "$OUT/run_$$.log" >&2
      exit 1
    fi
    local raw aligned smoothed
    raw="$(grep '^  vslam:' "$o/run_summary.yaml")"
    aligned="$(grep '^  vslam_se2_aligned:' "$o/run_summary.yaml")"
    smoothed="$(grep '^  most_likely_path_se2_aligned:' "$o/run_summary.yaml")"
    graph="$(grep '^  pose_graph_path:' "$o/run_summary.yaml" || echo ' rmse: 0,')"
    echo "$(sed 's/.* rmse: \([0-9.]*\),.*/\1/' <<< "$raw") $(sed 's/.* rmse: \([0-9.]*\),.*/\1/' <<< "$aligned") $(sed 's/.* median: \([0-9.]*\),.*/\1/' <<< "$raw") $(sed 's/.* rmse: \([0-9.]*\),.*/\1/' <<< "$smoothed") $(sed 's/.* rmse: \([0-9.]*\),.*/\1/' <<< "$graph")"
    rm -rf "$o" "$OUT/run_$$.log"
  done | awk '{r += $1; a += $2; m += $3; s += $4; g += $5; n++} END {printf "%.3f %.3f %.3f %.3f %.3f\n", r / n, a / n, m / n, s / n, g / n}'
}

echo "| rawlog | measured: RMSE / aligned / median / most-likely path aligned / pose-graph path | oracle ($KIND): the same |"
echo "|---|---|---|"
TOTAL=""
for rawlog in "${DATA[@]}"; do
  dir="$(dirname "$rawlog")" name="$(basename "$(dirname "$rawlog")")"
  gt="$(realpath "$dir/sim_groundtruth.tum")"
  measured="$OUT/${SCENARIO}_${name}_$KEY.rawlog" oracle="$OUT/${SCENARIO}_${name}_${KEY}_oracle.rawlog"
  [[ "$KIND" == all ]] || oracle="$OUT/${SCENARIO}_${name}_${KEY}_oracle_$KIND${ORACLE_SCALE_BIAS:+_$ORACLE_SCALE_BIAS}.rawlog"
  if [[ ! -s "$oracle" ]]; then
    "$BIN/vslam-frontend" "$rawlog" "$measured" --config "$INI" "${FRONTEND_SETS[@]}" \
      --ground-truth "$gt" --oracle-rawlog "$oracle.part" --oracle-kind "$KIND" "${BIAS_ARGS[@]}" \
      --heading-csv "$OUT/${SCENARIO}_${name}_$KEY.heading.csv" > "$OUT/${SCENARIO}_${name}_$KEY.log"
    mv "$oracle.part" "$oracle"
  fi
  m="$(filter_runs "$measured" "$gt")" || exit 1
  t="$(filter_runs "$oracle" "$gt")" || exit 1
  echo "| $SCENARIO $name | $(tr ' ' '/' <<< "$m" | sed 's|/| / |g') | $(tr ' ' '/' <<< "$t" | sed 's|/| / |g') |"
  TOTAL+="$m $t"$'\n'
done
awk 'NF == 10 {for (i = 1; i <= 10; i++) s[i] += $i; n++}
  END {printf "| **mean** | **%.3f** / %.3f / %.3f / %.3f / %.3f | **%.3f** / %.3f / %.3f / %.3f / %.3f |\n", s[1]/n, s[2]/n, s[3]/n, s[4]/n, s[5]/n, s[6]/n, s[7]/n, s[8]/n, s[9]/n, s[10]/n}' <<< "$TOTAL"
