#!/usr/bin/env bash
# build_tree.sh SOURCE BUILD JOBS TARGETS CMAKE_ARGS...
# Configures BUILD from SOURCE with CMAKE_ARGS and builds TARGETS (targets
# separated by commas; all: every target) with JOBS jobs.
set -euo pipefail
source_dir=$1 build_dir=$2 jobs=$3
IFS=, read -ra targets <<<"$4"
shift 4
cmake -S "$source_dir" -B "$build_dir" "$@"
cmake --build "$build_dir" -j"$jobs" --target "${targets[@]}"
