#!/bin/bash
# Fuzzing (doc/reliability.md): builds the libFuzzer targets with clang
# (ASan + UBSan) in build-fuzz/, makes seed corpora from real files, runs
# each target for SECONDS, and prints a table of executions and findings.
#
#   scripts/fuzz.sh [SECONDS] [TARGETS]
#
# Defaults: 60 s; "fuzz_rawlog fuzz_observations fuzz_config fuzz_mrclam fuzz_landmark_map fuzz_frontend".
# Needs clang and libclang-rt-14-dev (installed here if missing) and a normal
# build for the seed rawlogs (scripts/setup.sh build). Findings are saved as
# build-fuzz/findings/<target>/{crash,timeout,oom}-*; reproduce one with
# build-fuzz/bin/<target> FILE, and turn each into a regression test.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SECONDS_PER_TARGET="${1:-60}"
TARGETS="${2:-fuzz_rawlog fuzz_observations fuzz_config fuzz_mrclam fuzz_landmark_map fuzz_frontend fuzz_scenario}"
BUILD="$ROOT/build-fuzz"
# Any UBSan report stops the target; the one alignment report MRPT's opengl
# headers make is suppressed (scripts/ubsan.supp, CMakeLists.txt).
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$ROOT/scripts/ubsan.supp"
BIN="$ROOT/build/bin"

if ! command -v clang++ > /dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2> /dev/null | grep -q "ok installed"; then
  SUDO=""; [[ $EUID -ne 0 ]] && SUDO=sudo
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends clang libclang-rt-14-dev
fi
[[ -x "$BIN/vslam-simul-measurements" ]] || "$ROOT/scripts/setup.sh" build

mkdir -p "$BUILD"
CXX=clang++ cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVSLAM_FUZZ=ON \
  -DVSLAM_BUILD_TESTS=OFF -DVSLAM_BUILD_BENCHMARKS=OFF > "$BUILD/configure.log"
cmake --build "$BUILD" -j "$(nproc)" --target $TARGETS > "$BUILD/build.log" ||
  { tail -n 30 "$BUILD/build.log" >&2; exit 1; }

# Seed corpora from real files.
SEEDS="$BUILD/seeds"
rm -rf "$SEEDS" && mkdir -p "$SEEDS"/{fuzz_rawlog,fuzz_observations,fuzz_config,fuzz_mrclam,fuzz_landmark_map,fuzz_frontend,fuzz_scenario}
for ini in simul_demo_visual simul_range_bearing; do
  "$BIN/vslam-simul-measurements" "$ROOT/config_ini/$ini.ini" "$SEEDS/$ini.rawlog" \
    --set vslam_sim.duration=15 --set vslam_sim.mapping_duration=0 --set vslam_sim.kidnap_times= > /dev/null
  cp "$SEEDS/$ini.rawlog" "$SEEDS/fuzz_rawlog/"
  cp "$SEEDS/${ini}_landmarks.txt" "$SEEDS/fuzz_landmark_map/"
  # Plain copy of a gzip rawlog (the reader takes both).
  if gzip -t "$SEEDS/$ini.rawlog" 2> /dev/null; then
    gzip -dc "$SEEDS/$ini.rawlog" > "$SEEDS/fuzz_rawlog/$ini.plain.rawlog"
  fi
done
gzip -dc "$ROOT/rawlogs/demo_visual.rawlog" | head -c 2000000 > "$SEEDS/demo.plain" || true
python3 "$ROOT/tests/fuzz/make_observation_seeds.py" "$SEEDS/demo.plain" "$SEEDS/fuzz_observations"
python3 "$ROOT/tests/fuzz/make_frontend_seeds.py" "$SEEDS/fuzz_frontend"
head -c 20000 "$ROOT/rawlogs/demo_visual.rawlog" > "$SEEDS/fuzz_rawlog/demo_head.rawlog"
for ini in "$ROOT"/config_ini/*.ini "$ROOT"/config_ini/peers/*.ini; do
  cp "$ini" "$SEEDS/fuzz_config/$(basename "$ini")"
done
printf 'vslam_particle_filter.sampleSize=50\nvslam_motion_model.sigma_T=0.1\n%%%%%%%%\n' |
  cat - "$ROOT/config_ini/demo_visual.ini" > "$SEEDS/fuzz_config/with_overrides.ini"
"$BIN/vslam" "$ROOT/config_ini/demo_visual.ini" --quiet --out "$SEEDS/demo_out" --set vslam.max_steps=600 > /dev/null
cp "$SEEDS/demo_out/final_map.txt" "$SEEDS/fuzz_landmark_map/final_map.txt"
cp "$SEEDS/demo_out/final_map.vslam" "$SEEDS/fuzz_landmark_map/final_map.vslam"
MRCLAM="$ROOT/../shared/data/mrclam/MRCLAM_Dataset6"
if [[ -d "$MRCLAM" ]]; then
  for f in Barcodes Landmark_Groundtruth Robot1_Odometry Robot1_Measurement Robot1_Groundtruth; do
    head -n 60 "$MRCLAM/$f.dat"
    [[ $f != Robot1_Groundtruth ]] && printf '%%%%%%%%\n'
  done > "$SEEDS/fuzz_mrclam/d6_r1_head.txt"
fi
cp "$ROOT"/tests/fuzz/seeds/mrclam/* "$SEEDS/fuzz_mrclam/"
for ini in "$ROOT"/config_ini/simul_{example,demo,living_room,apartment,kidnap,dynamic}.ini; do
  world_file="$(grep -m1 '^world_file' "$ini" | sed 's/.*= *//' || true)"
  [[ -z "$world_file" ]] && continue  # a generated home (world_seed): no world file to pair it with
  world="$ROOT/config_ini/$world_file"
  { cat "$ini"; printf '%%%%%%%%\n'; cat "$world"; } > "$SEEDS/fuzz_scenario/$(basename "$ini" .ini).txt"
done

# Fork mode: a finding is saved and counted, and fuzzing goes on for the
# whole time (a run that stopped at the first finding would say nothing of
# the rest). Findings: crash-* / timeout-* / oom-* files per target.
echo "| target | seconds | executions | executions/s | corpus | crashes / timeouts / ooms |"
echo "|---|---|---|---|---|---|"
for t in $TARGETS; do
  corpus="$BUILD/corpus/$t" findings="$BUILD/findings/$t"
  mkdir -p "$corpus" "$findings"
  log="$BUILD/$t.log"
  # fuzz_rawlog's reader reads the file first in a child process that it
  # bounds itself (1 GiB there); libFuzzer's malloc hook, inherited by that
  # child, would save its bounded failures as findings, so the hook's limit
  # is lifted for this target (the parent's RSS limit still holds).
  malloc_limit=2048
  [[ "$t" == fuzz_rawlog ]] && malloc_limit=1048576
  set +e
  (cd "$findings" && ASAN_OPTIONS=detect_leaks=1 "$BUILD/bin/$t" -fork=1 -ignore_crashes=1 \
    -ignore_timeouts=1 -ignore_ooms=1 -max_total_time="$SECONDS_PER_TARGET" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb="$malloc_limit" -max_len=65536 -artifact_prefix="$findings/" \
    "$corpus" "$SEEDS/$t") > "$log" 2>&1
  set -e
  # The last status line: "#<execs>: cov: .. corp: <n> .. oom/timeout/crash: a/b/c ..".
  status="$(grep -E '^#[0-9]+: ' "$log" | tail -n 1)"
  execs="$(sed -E 's/^#([0-9]+):.*/\1/' <<< "$status")"
  triple="$(grep -oE 'oom/timeout/crash: [0-9]+/[0-9]+/[0-9]+' <<< "$status" | grep -oE '[0-9/]+$')"
  IFS=/ read -r ooms timeouts crashes <<< "${triple:-0/0/0}"
  printf "| %s | %s | %s | %s | %s | %s / %s / %s |\n" "$t" "$SECONDS_PER_TARGET" "${execs:-0}" \
    "$((${execs:-0} / SECONDS_PER_TARGET))" "$(ls "$corpus" | wc -l)" "$crashes" "$timeouts" "$ooms"
done
