#!/bin/bash
# vslam set-up on Debian 12: installs the Debian packages the project needs
# (idempotent), builds, then runs the main job or the tests.
#
#   scripts/setup.sh demo     install, build, render the demo rawlog with
#                             vslam-simul, run the full visual vslam on it,
#                             plot the paths (outputs in vslam_out_demo/)
#   scripts/setup.sh test     install, build, run every test (ctest; the
#                             Slurm test starts a one-node cluster here),
#                             install the .deb and run it, then build the
#                             library's modules up to the front-end (core,
#                             config, obs, io, models, filter, graph,
#                             frontend) with ASan + UBSan and run their unit
#                             tests under the sanitizers (any report fails);
#                             CI runs this
#   scripts/setup.sh sanitize install, build everything with ASan + UBSan and
#                             run the whole suite under the sanitizers but
#                             for a few long tests listed below (about 40
#                             minutes on two cores: before a release)
#   scripts/setup.sh build    install and build only
#
# Run as root, or as a user with sudo. Environment:
#   VSLAM_BUILD_DIR   build folder (default: build)
#   VSLAM_JOBS        parallel build jobs (default: number of cores)
#   VSLAM_SKIP_APT=1  do not touch packages (e.g. no network)
#   VSLAM_SKIP_SANITIZED=1  test: skip the sanitized build and run
#   VSLAM_CMAKE_ARGS  more CMake options (e.g. -DVSLAM_BUILD_TESTS=OFF, as
#                     scripts/Dockerfile builds)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${VSLAM_BUILD_DIR:-$ROOT/build}"
JOBS="${VSLAM_JOBS:-$(nproc)}"
MODE="${1:-}"

usage() {
  sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | grep '^#' | sed 's/^# \{0,1\}//'
  exit 1
}
case "$MODE" in demo | test | sanitize | build) ;; *) usage ;; esac

# Debian 12 packages: compiler and build tools, MRPT 2.5.8 (libraries, the
# apps rawlog-edit / kf-slam / rbpf-slam, and mrpt-common's demo datasets),
# OpenCV 4.6, Eigen 3.4, Boost (Math), GoogleTest, Google
# Benchmark, zlib;
# Mesa's EGL and software rasterizer (vslam-simul renders headless through
# MRPT's CFBORender); photographs for the simulated worlds' textures and
# Sweet Home 3D's materials and furniture models, read from the packages'
# archives with libzip (licences in doc/textures.md).
PACKAGES=(
  g++ make cmake pkg-config
  libmrpt-dev mrpt-apps mrpt-common
  libegl1 libegl-mesa0 libgl1-mesa-dri libgbm1
  mate-backgrounds plasma-workspace-wallpapers
  sweethome3d sweethome3d-furniture libzip-dev
  libopencv-dev libeigen3-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  zlib1g-dev
  time
)

install_packages() {
  if [[ "${VSLAM_SKIP_APT:-0}" == 1 ]]; then
    echo "[setup] VSLAM_SKIP_APT=1: not installing packages"
    return
  fi
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [[ ${#missing[@]} -eq 0 ]]; then
    echo "[setup] all ${#PACKAGES[@]} Debian packages already installed"
    return
  fi
  local SUDO=""
  if [[ $EUID -ne 0 ]]; then
    command -v sudo > /dev/null || { echo "[setup] error: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    SUDO="sudo"
  fi
  echo "[setup] installing: ${missing[*]}"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${PACKAGES[@]}"
}

build() {
  echo "[setup] configuring and building in $BUILD ($JOBS jobs)"
  # shellcheck disable=SC2086 # the options are separate words
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release ${VSLAM_CMAKE_ARGS:-}
  cmake --build "$BUILD" -j "$JOBS"
}

# The Debian package as a user installs it: built with CPack, installed
# with apt-get install ./vslam_*.deb (its dependencies are there: the
# build needed them), and the installed vslam run on the installed demo
# from another folder. Root only (CI is); the package stays installed.
check_debian_package() {
  if [[ $EUID -ne 0 ]]; then
    echo "[setup] not root: not installing the .deb"
    return
  fi
  echo "[setup] building and installing the Debian package"
  (cd "$BUILD" && rm -f vslam_*.deb && cpack -G DEB > cpack.log)
  local deb
  deb="$(ls "$BUILD"/vslam_*.deb)"
  apt-get install -y --no-install-recommends "$deb" > "$BUILD/apt-install-deb.log" ||
    { cat "$BUILD/apt-install-deb.log"; echo "[setup] error: apt-get install $deb failed" >&2; exit 1; }
  local out
  out="$(mktemp -d)"
  (cd "$out" && /usr/bin/vslam /usr/share/vslam/config_ini/demo_visual.ini --out run --quiet \
    --set vslam.max_steps=300)
  grep -q '^status: completed' "$out/run/run_summary.yaml" ||
    { echo "[setup] error: the installed vslam did not complete the installed demo" >&2; exit 1; }
  echo "[setup] $(basename "$deb"): installed, /usr/bin/vslam ran the installed demo"
  rm -rf "$out"
}

# The modules CI checks under the sanitizers: every file reader, the filter
# and the front-end's parts, whose unit tests are short. The front-end's
# multi-frame runs (CVisualFrontEnd.*, 30-110 s each under ASan) are left to
# the whole sanitized suite. About 12 minutes on two cores against the whole
# suite's 40 (scripts/setup.sh sanitize): CI stays within its time this way.
SANITIZED_MODULES=(core config obs io models filter graph frontend)

# A build folder beside $BUILD with AddressSanitizer + UndefinedBehaviorSanitizer.
# -O2 without debug info (with -g it takes far longer to build); reports
# still name the functions. At -O2 our code inlines MRPT's opengl headers,
# whose objects MRPT allocates below their declared 32-byte alignment: that
# one report is suppressed (scripts/ubsan.supp), any other stops the test.
SANITIZED="$BUILD-sanitized"
configure_sanitized() {
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$ROOT/scripts/ubsan.supp"
  cmake -S "$ROOT" -B "$SANITIZED" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O2 \
    -DVSLAM_SANITIZE=ON -DVSLAM_BUILD_BENCHMARKS=OFF
}

sanitized_module_tests() {
  echo "[setup] building ${SANITIZED_MODULES[*]} with ASan + UBSan in $SANITIZED"
  configure_sanitized
  cmake --build "$SANITIZED" -j "$JOBS" --target "${SANITIZED_MODULES[@]/#/test_}"
  echo "[setup] running the tests of ${SANITIZED_MODULES[*]} under ASan + UBSan"
  local labels
  labels="$(IFS='|'; echo "${SANITIZED_MODULES[*]}")"
  ctest --test-dir "$SANITIZED" --output-on-failure -j "$JOBS" -L "^($labels)\$" -E '^CVisualFrontEnd\.'
}

# All but the accuracy scenarios (label "accuracy": long runs for a figure
# whose code the unit and app tests run too), the Slurm test (a cluster
# running the same programs) and a few long tests of the same kind: the
# front-end's multi-lap tests and the simulator's full rendering. The plain
# run's test times go first, so that the longest start first.
sanitized_suite() {
  echo "[setup] building everything with ASan + UBSan in $SANITIZED"
  configure_sanitized
  cmake --build "$SANITIZED" -j "$JOBS"
  echo "[setup] running all tests under ASan + UBSan"
  mkdir -p "$SANITIZED/Testing/Temporary"
  cp "$BUILD/Testing/Temporary/CTestCostData.txt" "$SANITIZED/Testing/Temporary/" 2> /dev/null || true
  ctest --test-dir "$SANITIZED" --output-on-failure -j "$JOBS" -LE 'slurm|accuracy' \
    -E '^(CVisualFrontEnd\.(LaterSightingsCorrectTheScaleOfLandmarksBuiltOnNoisyOdometry|ARecognitionTheOdometryRulesOutCountsAsRecognizedButIsNotReported)|VslamSimul\.WritesARawlogThatVslamAndRbpfSlamBothRun)$'
}

install_packages
if [[ "$MODE" == sanitize ]]; then
  sanitized_suite
  exit 0
fi
build
case "$MODE" in
  demo)
    cd "$ROOT"
    echo "[setup] rendering the demo rawlog: build/bin/vslam-simul config_ini/simul_demo.ini rawlogs/demo_rendered.rawlog"
    "$BUILD/bin/vslam-simul" config_ini/simul_demo.ini rawlogs/demo_rendered.rawlog --quiet
    echo "[setup] running: build/bin/vslam config_ini/demo_rendered.ini"
    "$BUILD/bin/vslam" config_ini/demo_rendered.ini
    echo "[setup] errors and figures: build/bin/vslam-eval --run vslam_out_demo rawlogs/demo_rendered_groundtruth.tum"
    "$BUILD/bin/vslam-eval" --run vslam_out_demo rawlogs/demo_rendered_groundtruth.tum \
      --world rawlogs/demo_rendered_world.world --plot vslam_out_demo/paths.png | grep -v '^figure:'
    cp rawlogs/demo_rendered_preview.png vslam_out_demo/simulation_preview.png
    echo "[setup] outputs in $ROOT/vslam_out_demo/: run_summary.yaml (errors against the ground truth),"
    echo "[setup]   estimated_path.tum, log_estimated_path.txt, final_map.txt, paths.png (estimate, truth,"
    echo "[setup]   odometry over the floor plan), figures/ (the paper's figures: paths with landmarks, error"
    echo "[setup]   over time, measurements per landmark, particle spread, dual ratio),"
    echo "[setup]   simulation_preview.png; the rendered rawlog and its"
    echo "[setup]   images are in rawlogs/demo_rendered.rawlog and rawlogs/demo_rendered_Images/"
    ;;
  test)
    echo "[setup] running all tests"
    ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS"
    # What the Slurm test did (its sacct table), also when it passed.
    sed -n '/^[0-9]*\/[0-9]* Test: SlurmCluster/,/^Test time/p' "$BUILD/Testing/Temporary/LastTest.log"
    check_debian_package
    if [[ "${VSLAM_SKIP_SANITIZED:-0}" == 1 ]]; then
      echo "[setup] VSLAM_SKIP_SANITIZED=1: not running the tests under ASan + UBSan"
      exit 0
    fi
    sanitized_module_tests
    ;;
esac
