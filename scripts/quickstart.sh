#!/usr/bin/env bash
# Set-up and entry points of mrpt-evidential on Debian bookworm (MRPT 2.5.8)
# and trixie (MRPT 2.14), as root.
#   scripts/quickstart.sh demo   install dependencies, build, map MRPT's SENA dataset
#   scripts/quickstart.sh test   install dependencies, build, run every test
#   scripts/quickstart.sh build  install dependencies and build only
# BUILD_DIR (default: build), JOBS (default: 2) and DEMO_DIR (default:
# BUILD_DIR/demo) may be set in the environment.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# Absolute: the demo runs icp-slam from another folder.
build_dir=$(realpath -m "${BUILD_DIR:-$here/build}")
jobs=${JOBS:-2}

# The release decides the clang runtime's package: clang 14 on bookworm,
# clang 19 on trixie.
codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
case "$codename" in
  bookworm) clang_runtime=libclang-rt-14-dev ;;
  trixie) clang_runtime=libclang-rt-19-dev ;;
  *)
    echo "quickstart: made for Debian bookworm and trixie, not '${codename:-unknown}': trying Debian's default clang runtime" >&2
    clang_runtime=libclang-rt-dev
    ;;
esac

packages=(
  g++ cmake make
  # compiles each source once per flags: the Debian packages' tree, which
  # the package test builds with the main build's flags, is then mostly
  # cache hits (README.md, the Debian packages)
  ccache
  libmrpt-obs-dev libmrpt-maps-dev libmrpt-slam-dev libmrpt-apps-dev libmrpt-gui-dev
  libmrpt-tclap-dev zlib1g-dev
  mrpt-apps mrpt-common
  libeigen3-dev libopencv-dev libgtest-dev libbenchmark-dev
  # the GUI tests: a virtual display, driven with xdotool (clicks) and
  # xclip (pastes), screenshots read with ImageMagick
  xvfb xauth x11-utils xdotool xclip imagemagick
  # the fleet recipe (doc/recipes/fleet.md)
  parallel
  # the Debian packages (scripts/build-deb.sh): dpkg-shlibdeps, and file,
  # with which CPack finds the binaries to give it
  dpkg-dev file
  # the sanitizer and fuzzing builds of the tests (doc/reliability.md):
  # clang, its runtimes (libFuzzer, ASan, UBSan, TSan) and llvm-symbolizer
  clang "$clang_runtime" llvm
)

install_dependencies() {
  if [ "$(id -u)" -ne 0 ]; then
    echo "quickstart: run as root (it installs Debian packages with apt-get)" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${packages[@]}"
}

build() {
  # Through ccache where its cache can be written: a compilation fails
  # when it cannot.
  local launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=) cache
  if command -v ccache >/dev/null && cache=$(ccache -k cache_dir) &&
    mkdir -p "$cache" 2>/dev/null && [ -w "$cache" ]; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
  cmake --build "$build_dir" -j"$jobs"
}

# evgrid on MRPT's SENA rawlog (real SICK, 224 scans) with rawlogs/evgrid.ini.
# Odometry drifts by metres over the loop, so the poses come from a headless
# run of stock icp-slam on the same rawlog (MRPT's own demo config).
demo() {
  local out=${DEMO_DIR:-$build_dir/demo}
  local sena="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
  local icp="$build_dir/demo-icp-slam"
  rm -rf "$icp" && mkdir -p "$icp"
  sed -e 's/^SHOW_PROGRESS_3D_REAL_TIME *=.*/SHOW_PROGRESS_3D_REAL_TIME=0/' \
    -e 's/^SAVE_3D_SCENE *=.*/SAVE_3D_SCENE=0/' -e 's/^LOG_FREQUENCY *=.*/LOG_FREQUENCY=0/' \
    -e "s#^logOutput_dir *=.*#logOutput_dir=$icp/out#" \
    /usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini >"$icp/icp-slam.ini"
  echo "Estimating the robot's path with icp-slam (log: $icp/icp-slam.log)..."
  (cd "$icp" && timeout 600 icp-slam "$icp/icp-slam.ini" "$sena" </dev/null >"$icp/icp-slam.log" 2>&1)
  "$build_dir/apps/evgrid/evgrid" build -c "$here/rawlogs/evgrid.ini" -i "$sena" \
    -p "$icp/out/log_estimated_path.txt" -o "$out" </dev/null
  echo
  echo "Demo done. The pictures of the map are in $out:"
  echo "  $out/map.png         (light free, dark occupied, grey unknown, orange appeared, teal left)"
  echo "  $out/evidential.png  (the masses: red occupied, green free, blue unknown)"
  echo "  $out/betp.png        (probability of occupancy: white free, black occupied)"
  echo "  $out/conflict.png    (conflict kept in the cells: black unless conflictHandling=Keep)"
  echo "  $out/motion.png      (the motion layer: orange appeared, teal left, over the static map)"
  echo "  $out/map.3Dscene     (the map and the path in 3-D: SceneViewer3D $out/map.3Dscene)"
  echo "$out/summary.txt describes the run; doc/evgrid.md explains evgrid."
}

# The tests with the largest peak resident memory, as the memory budget
# launcher recorded them (tests/support/memory_budget.cpp): the ten largest
# of the build, the five largest of the sanitizer tree.
print_memory_peaks() {
  print_peaks "$build_dir/test-memory" 10 "budget 2048 MB each"
  print_peaks "$build_dir/tests/reliability/asan/test-memory" 5 \
    "under AddressSanitizer, budget 6144 MB each"
}
print_peaks() {
  local peaks=("$1"/*.peak)
  [ -e "${peaks[0]}" ] || return 0
  echo
  echo "Largest peak resident memory of a test, MB ($3):"
  # awk reads to the end: `head` would leave sort writing into a closed pipe,
  # and SIGPIPE fails the script under pipefail once the list is long.
  cat "${peaks[@]}" | sort -rn |
    awk -v n="$2" 'NR <= n { kb = $1; $1 = ""; printf "  %8.1f %s\n", kb / 1024, $0 }'
}

case "${1:-}" in
  demo)
    install_dependencies
    build
    demo
    ;;
  build)
    install_dependencies
    build
    ;;
  test)
    install_dependencies
    build
    rm -f "$build_dir"/test-memory/*.peak "$build_dir"/tests/reliability/asan/test-memory/*.peak
    status=0
    ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" || status=$?
    print_memory_peaks
    exit $status
    ;;
  *)
    echo "usage: $0 demo|test|build" >&2
    exit 2
    ;;
esac
