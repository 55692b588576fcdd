#!/bin/bash
# vslam-batch --slurm --submit on a real single-node Slurm cluster: the
# batch's tasks run as job arrays (sacct shows them), the summary equals
# the same batch run locally (every figure but time and memory), and a
# failed rendering cancels the runs that wait for it while the other
# scenario's runs finish.
#   slurm_batch_test.sh BIN_DIR SOURCE_DIR
set -euo pipefail
BIN="$1"
SRC="$2"
if [[ $EUID -ne 0 ]]; then
  echo "SKIPPED: starting a Slurm cluster needs root (scripts/slurm_local_cluster.sh)"
  exit 77
fi
T="$(mktemp -d /tmp/vslam_slurm_test.XXXXXX)"
CLUSTER="$T/cluster"
cleanup() { [[ -e "$CLUSTER/slurm.conf" ]] && "$SRC/scripts/slurm_local_cluster.sh" stop "$CLUSTER" || true; }
trap cleanup EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }

"$SRC/scripts/slurm_local_cluster.sh" start "$CLUSTER"
export SLURM_CONF="$CLUSTER/slurm.conf"

# A rendered scenario (its runs wait for its renderings) and a fixed rawlog,
# two seeds, two variations: 10 tasks, in arrays of at most 3 (chunking),
# 2 at a time.
write_batch() {  # $1 file, $2 extra simulator setting
  cat > "$1" << INI
[batch]
output_dir = local
seeds = 1 2
jobs = 2
vslam_ini = $SRC/config_ini/demo_rendered.ini
set = vslam.show_progress=false
[scenario:rendered]
simul_ini = $SRC/config_ini/simul_demo.ini
simul_set = vslam_simul.duration=12$2
[scenario:measured]
rawlog = $SRC/rawlogs/demo_visual.rawlog
ground_truth = $SRC/rawlogs/demo_visual_groundtruth.tum
vslam_ini = $SRC/config_ini/demo_visual.ini
set = vslam.max_steps=200
[grid]
vslam_particle_filter.sampleSize = 30 60
[slurm]
max_array_size = 3
throttle = 2
cpus_per_task = 1
INI
}

# Waits for every job of a submission (its jobs.txt) to leave the queue.
wait_for_jobs() {
  local ids
  ids=$(awk '{print $2}' "$1/jobs.txt" | paste -sd,)
  for ((i = 0; i < 600; i++)); do
    [[ -z "$(squeue -h -j "$ids" 2> /dev/null)" ]] && return 0
    sleep 1
  done
  squeue
  fail "the jobs $ids did not end within 600 s"
}

# The state of each job and array element (sacct -X): "JOBID NAME STATE".
# slurmctld hands finished jobs to the accounting daemon on its own time and
# in no set order: asked again (up to 30 s) until all $2 records are there.
job_states() {
  local ids states
  ids=$(awk '{print $2}' "$1/jobs.txt" | paste -sd,)
  for ((i = 0; i < 30; i++)); do
    states=$(sacct -X -n -P -j "$ids" --format=JobID,JobName,State | tr '|' ' ')
    [[ $(grep -c . <<< "$states") -ge $2 ]] && break
    sleep 1
  done
  echo "$states"
}

# summary.csv without the columns a machine's speed changes.
figures() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = $i !~ /^(wall_s|peak_mib|real_time_factor)$/ }
    { line = ""; for (i = 1; i <= NF; i++) if (keep[i]) line = line $i ","; print line }' "$1"
}

cd "$T"
write_batch batch.ini ""
echo "== the batch run locally"
"$BIN/vslam-batch" batch.ini > local.log || { cat local.log; fail "the local batch failed"; }

echo "== the batch as Slurm job arrays"
"$BIN/vslam-batch" batch.ini --set "batch.output_dir=$T/cluster_out" --slurm sub --submit
wait_for_jobs sub
echo "== sacct"
sacct -j "$(awk '{print $2}' sub/jobs.txt | paste -sd,)" --format=JobID%14,JobName%22,State,ExitCode,AllocCPUS,ReqMem,Elapsed
states="$(job_states sub 11)"  # 10 tasks and the summary
[[ $(grep -c ' COMPLETED$' <<< "$states") -eq 11 ]] || fail "not 10 tasks and the summary COMPLETED: $states"
grep -q "1 CPUs:" sub/logs/rendered-run_*_0.out || fail "a task did not see SLURM_CPUS_PER_TASK=1"
[[ -s cluster_out/summary.csv ]] || fail "the summary job wrote no summary.csv"
diff <(figures local/summary.csv) <(figures cluster_out/summary.csv) ||
  fail "the Slurm run's summary.csv differs from the local run's (above)"
echo "summary.csv: the $(($(wc -l < local/summary.csv) - 1)) runs' figures equal the local run's"

echo "== resources measured on the finished local tasks"
"$BIN/vslam-batch" batch.ini --slurm measured_sub | tee measured.log
grep -q "per rendering: .* (measured on 2 finished tasks)" measured.log || fail "renderings' needs not measured"
grep -q "per run: .* (measured on 8 finished tasks)" measured.log || fail "runs' needs not measured"

echo "== a failed rendering cancels its runs, not the other scenario's"
write_batch bad.ini "; vslam_simul.world_file=$T/no_such.world"
"$BIN/vslam-batch" bad.ini --set "batch.output_dir=$T/bad_out" --slurm bad_sub --submit
wait_for_jobs bad_sub
states="$(job_states bad_sub 9)"  # 2 renderings, 4 runs, 2 cancelled arrays, the summary
echo "$states"
[[ $(grep -c 'vslam-rendered-render FAILED$' <<< "$states") -eq 2 ]] || fail "the renderings did not fail"
grep 'vslam-rendered-run' <<< "$states" | grep -qv 'CANCELLED$' && fail "a run of the failed rendering was not cancelled"
[[ $(grep -c 'vslam-measured-run COMPLETED$' <<< "$states") -eq 4 ]] || fail "the other scenario's runs did not finish"
grep -q 'vslam-summary COMPLETED$' <<< "$states" || fail "the summary did not run"
echo "PASSED"
