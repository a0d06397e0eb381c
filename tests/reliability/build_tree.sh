#!/usr/bin/env bash
# build_tree.sh SOURCE BUILD JOBS TARGET CMAKE_ARGS...
# Configures BUILD from SOURCE with CMAKE_ARGS and builds TARGET (all: every
# target) with JOBS jobs.
set -euo pipefail
source_dir=$1 build_dir=$2 jobs=$3 target=$4
shift 4
cmake -S "$source_dir" -B "$build_dir" "$@"
cmake --build "$build_dir" -j"$jobs" --target "$target"
