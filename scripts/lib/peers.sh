# Shared by the comparison scripts (sourced, not run): MRPT's own SLAM apps
# as peers of vslam on one rawlog, each leaving a TUM trajectory, and the
# wall time and peak memory of any command.
#
# Needs ROOT (the repository) set by the caller.

# timed OUT_PREFIX COMMAND...: runs COMMAND (output to OUT_PREFIX.log) and
# writes "seconds peak_kib" to OUT_PREFIX.time; returns its exit code.
timed() {
  local prefix="$1"
  shift
  /usr/bin/time -f "%e %M" -o "$prefix.time" "$@" > "$prefix.log" 2>&1
}

# wall_seconds / peak_mib OUT_PREFIX: from OUT_PREFIX.time.
wall_seconds() { awk 'END {printf "%.1f", $1}' "$1.time"; }
peak_mib() { awk 'END {printf "%.0f", $2 / 1024}' "$1.time"; }

# rbpf_slam RAWLOG OUT_DIR: MRPT's rbpf-slam, grid mapping with the laser,
# with config_ini/peers/rbpf-slam_gridmapping.ini; leaves OUT_DIR/rbpf-slam.tum
# (its path starts at its own origin: compare after alignment) and
# OUT_DIR/rbpf-slam.{log,time}.
rbpf_slam() {
  local rawlog="$1" out="$2"
  (cd "$out" && timed "$out/rbpf-slam" rbpf-slam "$ROOT/config_ini/peers/rbpf-slam_gridmapping.ini" "$rawlog") ||
    return 1
  awk '{printf "%s %s %s 0 0 0 %.9f %.9f\n", $8, $2, $3, sin($5/2), cos($5/2)}' \
    "$out/rbpf-slam_out/log_estimated_path.txt" > "$out/rbpf-slam.tum"
}

# kf_slam RAWLOG OUT_DIR STEP_TIMES: MRPT's kf-slam (EKF, range-bearing,
# landmark IDs known) with config_ini/peers/kf-slam_mrclam.ini; it writes a
# pose file per step and no times, so the times come from STEP_TIMES (one per
# line per rawlog step, e.g. column 8 of vslam's log_estimated_path.txt).
# Leaves OUT_DIR/kf-slam.tum and OUT_DIR/kf-slam.{log,time}.
kf_slam() {
  local rawlog="$1" out="$2" times="$3" k="$2/kf-slam_out"
  rm -rf "$k" && mkdir -p "$k"
  sed -e "s|^rawlog_file = .*|rawlog_file = $rawlog|" -e "s|^logOutput_dir = .*|logOutput_dir = $k|" \
    "$ROOT/config_ini/peers/kf-slam_mrclam.ini" > "$out/kf-slam.ini"
  timed "$out/kf-slam" kf-slam "$out/kf-slam.ini" < /dev/null || true
  # robot_pose_NNNNN.txt: x, y, phi on three lines.
  ls "$k"/robot_pose_*.txt 2> /dev/null | sort |
    xargs -r awk 'FNR==1 && NR>1 {print l; l=""} {l = l (l=="" ? "" : " ") $1} END {if (l!="") print l}' > "$k.poses"
  paste -d' ' "$times" "$k.poses" |
    awk 'NF==4 {printf "%s %s %s 0 0 0 %.9f %.9f\n", $1, $2, $3, sin($4/2), cos($4/2)}' > "$out/kf-slam.tum"
  rm -rf "$k"  # thousands of per-step files; the TUM path is kept
  [[ -s "$out/kf-slam.tum" ]]
}
