#!/usr/bin/env bash
# Set-up and entry points of mrpt-evidential on Debian bookworm, as root.
#   scripts/quickstart.sh test   install dependencies, build, run every test
#   scripts/quickstart.sh build  install dependencies and build only
# BUILD_DIR (default: build) and JOBS (default: 2) may be set in the environment.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$here/build}
jobs=${JOBS:-2}

packages=(
  g++ cmake make
  libmrpt-obs-dev libmrpt-maps-dev libmrpt-slam-dev libmrpt-apps-dev libmrpt-gui-dev
  mrpt-apps mrpt-common
  libeigen3-dev libopencv-dev libgtest-dev libbenchmark-dev
  xvfb xauth imagemagick
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
  cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build_dir" -j"$jobs"
}

case "${1:-}" in
  build)
    install_dependencies
    build
    ;;
  test)
    install_dependencies
    build
    ctest --test-dir "$build_dir" --output-on-failure -j"$jobs"
    ;;
  *)
    echo "usage: $0 test|build" >&2
    exit 2
    ;;
esac
