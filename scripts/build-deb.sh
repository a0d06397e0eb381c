#!/usr/bin/env bash
# Builds the Debian packages of mrpt-evidential and prints their paths.
#   scripts/build-deb.sh [BUILD_DIR [CMAKE_ARGS...]]
# BUILD_DIR (default: build-deb) is a tree of its own, configured for the
# prefix /usr (the library in lib/<multiarch>, the programs without RPATH)
# and without the tests, which are not packaged; CMAKE_ARGS go to its
# configuration. JOBS (default: 2) build jobs. Needs cmake, g++, the MRPT -dev
# packages and dpkg-dev (scripts/quickstart.sh installs them); not root.
# The packages land in BUILD_DIR/packages/.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=$(realpath -m "${1:-$here/build-deb}")
shift $(($# > 0 ? 1 : 0))
jobs=${JOBS:-2}

cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
	-DMRPT_EVIDENTIAL_BUILD_TESTS=OFF "$@"
cmake --build "$build_dir" -j"$jobs"
# Only this version's packages: an earlier version's would be installed too.
rm -f "$build_dir"/packages/*.deb
(cd "$build_dir" && cpack -G DEB)

echo
echo "Debian packages:"
for deb in "$build_dir"/packages/*.deb; do
	echo "  $deb ($(du -h "$deb" | cut -f1))"
done
echo "Install them all with: apt-get install $build_dir/packages/*.deb"
