#!/usr/bin/env bash
# run_fuzzer.sh FUZZ_DIR TARGET SECONDS WORK_DIR CORPUS_DIR
# Runs FUZZ_DIR/fuzz_TARGET for SECONDS on the committed seeds
# (CORPUS_DIR/TARGET) and on fresh ones from fuzz_seeds; new inputs go to
# WORK_DIR/corpus, a finding to WORK_DIR/crash-*, leak-*, timeout-* or oom-*.
# Exits non-zero on a finding.
set -euo pipefail
fuzz_dir=$1 target=$2 seconds=$3 work=$4 corpus=$5

mkdir -p "$work/corpus" "$work/seeds"
# Stack traces with UBSan findings also when run by hand.
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
"$fuzz_dir/fuzz_seeds" "$work/seeds"
# -timeout: seconds per input; -rss_limit_mb and -malloc_limit_mb: memory of
# the process and of one allocation (an input that needs more is a finding).
exec "$fuzz_dir/fuzz_$target" -max_total_time="$seconds" -timeout=20 \
  -rss_limit_mb=2048 -malloc_limit_mb=1024 \
  -print_final_stats=1 -artifact_prefix="$work/" \
  "$work/corpus" "$corpus/$target" "$work/seeds/$target"
