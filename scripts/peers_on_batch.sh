#!/bin/bash
# MRPT's rbpf-slam (laser grid mapping, config_ini/peers/rbpf-slam_gridmapping.ini)
# on every rendered rawlog of a vslam-batch output folder (its
# <scenario>/data_seed<N>/ folders), scored like the batch's runs: one Markdown
# row per scenario with mean +- standard deviation over the seeds of the
# SE(2)-aligned ATE RMSE, median and mean (rbpf-slam starts at its own
# origin), wall time and peak memory. For doc/results.md section 9.
#
#   scripts/peers_on_batch.sh BATCH_OUTPUT_DIR
#
# Needs a build (scripts/setup.sh build) and MRPT's apps (mrpt-apps).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BIN="${VSLAM_BIN:-$ROOT/build/bin}"
source "$ROOT/scripts/lib/peers.sh"
OUT="$(cd "${1:?usage: peers_on_batch.sh BATCH_OUTPUT_DIR}" && pwd)"

# mean +- sample standard deviation of the arguments
stats() { # FORMAT VALUE...
  local f="$1"
  shift
  awk -v f="$f" '{for (i = 1; i <= NF; i++) {s += $i; q += $i * $i; n++}}
    END {m = s / n; v = n > 1 ? (q - n * m * m) / (n - 1) : 0; printf f " +- " f, m, (v > 0 ? sqrt(v) : 0)}' <<< "$*"
}

echo "| scenario | seeds | rbpf-slam ATE RMSE aligned [m] | ATE median aligned [m] | ATE mean aligned [m] | wall time [s] | peak memory [MiB] |"
echo "|---|---|---|---|---|---|---|"
for scenario in "$OUT"/*/; do
  rmse=() median=() mean=() wall=() mem=()
  for data in "$scenario"data_seed*/; do
    [[ -f "$data/sim.rawlog" ]] || continue
    peer="$data/peers"
    mkdir -p "$peer"
    rbpf_slam "$data/sim.rawlog" "$peer" || { echo "error: rbpf-slam failed, see $peer/rbpf-slam.log" >&2; exit 1; }
    line="$("$BIN/vslam-eval" "$peer/rbpf-slam.tum" "$data/sim_groundtruth.tum" --align | head -n 1)"
    rmse+=("$(sed 's/.* rmse \([0-9.]*\) .*/\1/' <<< "$line")")
    median+=("$(sed 's/.* median \([0-9.]*\) .*/\1/' <<< "$line")")
    mean+=("$(sed 's/.* mean \([0-9.]*\) .*/\1/' <<< "$line")")
    wall+=("$(wall_seconds "$peer/rbpf-slam")") mem+=("$(peak_mib "$peer/rbpf-slam")")
  done
  [[ ${#rmse[@]} -gt 0 ]] || continue
  printf "| %s | %d | %s | %s | %s | %s | %s |\n" "$(basename "$scenario")" "${#rmse[@]}" "$(stats %.3f "${rmse[@]}")" \
    "$(stats %.3f "${median[@]}")" "$(stats %.3f "${mean[@]}")" "$(stats %.1f "${wall[@]}")" "$(stats %.0f "${mem[@]}")"
done
