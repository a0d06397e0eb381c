# Helpers of the evgrid tests, sourced by each script. CTest gives EVGRID (the
# program), EVGRID_SIMULATE (evgrid-simulate), EVGRID_CHECK (the helper),
# EVGRID_LIB (the library, for stock programs to preload), DATASETS (MRPT's
# datasets), EVGRID_INI (rawlogs/evgrid.ini), EVGRID_DOC (doc/evgrid.md),
# MEMORY_BUDGET (the test launcher, tests/support/memory_budget.cpp) and
# SCRATCH.
set -euo pipefail

SENA="$DATASETS/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
# This test's own folder, emptied first.
T="$SCRATCH/$(basename "$0" .sh)"
rm -rf "$T"
mkdir -p "$T"
OUT="$T/last.stdout"
ERR="$T/last.stderr"
: >"$OUT"
: >"$ERR"

fail() {
  echo "FAIL: $*" >&2
  echo "--- stdout of the last command:" >&2
  cat "$OUT" >&2
  echo "--- stderr of the last command:" >&2
  cat "$ERR" >&2
  exit 1
}

# run RC COMMAND...: runs COMMAND without input and with a time limit, its
# output into $OUT and $ERR, and fails unless it exits with RC.
run() {
  local expected=$1 rc=0
  shift
  timeout 120 "$@" </dev/null >"$OUT" 2>"$ERR" || rc=$?
  [ "$rc" -eq "$expected" ] || fail "exit code $rc instead of $expected: $*"
}

# contains FILE TEXT: FILE holds TEXT (a fixed string).
contains() {
  grep -qF -- "$2" "$1" || fail "$1 does not contain: $2"
}

# lacks FILE TEXT
lacks() {
  if grep -qF -- "$2" "$1"; then fail "$1 contains: $2"; fi
}

# count DECISION FILE: the number of cells of a decision in a summary.txt or
# `evgrid inspect` listing ("  free   12345   4.56%").
count() {
  awk -v d="$1" '$1 == d && NF == 3 { print $2 }' "$2"
}

# decisions FILE: the four counts on one line.
decisions() {
  echo "$(count free "$1") $(count occupied "$1") $(count unknown "$1") $(count conflict "$1")"
}

# fingerprint DIR: names, sizes and checksums of everything in DIR, hidden
# entries included, to compare a folder before and after a run.
fingerprint() {
  (cd "$1" && find . -print0 | sort -z | xargs -0 -r sh -c \
    'for f; do if [ -f "$f" ]; then echo "$f $(cksum <"$f")"; else echo "$f"; fi; done' sh)
}

# interrupt SIGNAL DIR COMMAND...: runs COMMAND, which writes into the output
# folder DIR (created if missing), in the background and sends it SIGNAL
# while its staging folder exists, frozen meanwhile (SIGSTOP, SIGCONT) so
# that the signal lands before it commits; a run that finishes before its
# staging folder is seen is tried again (DIR put back as it was). Fails
# unless the run exits 1 saying so and leaves DIR as it was.
interrupt() {
  local signal=$1 dir=$2 pid rc kept
  shift 2
  mkdir -p "$dir"
  kept=$(fingerprint "$dir")
  rm -rf "$T/.interrupt-kept" && cp -a "$dir" "$T/.interrupt-kept"
  for _ in $(seq 20); do
    rm -rf "$dir" && cp -a "$T/.interrupt-kept" "$dir"
    "$@" </dev/null >"$OUT" 2>"$ERR" &
    pid=$!
    while kill -0 "$pid" 2>/dev/null; do
      if [ -n "$(find "$dir" -maxdepth 1 -name '.evgrid-build-*')" ]; then
        kill -STOP "$pid" && kill "-$signal" "$pid" && kill -CONT "$pid"
        rc=0
        wait "$pid" || rc=$?
        [ "$rc" -eq 1 ] || fail "interrupted by SIG$signal, exit code $rc: $*"
        contains "$ERR" "interrupted by signal "
        [ "$(fingerprint "$dir")" = "$kept" ] || fail "the interrupted run changed $dir: $*"
        return 0
      fi
      sleep 0.01
    done
    wait "$pid" || true
  done
  fail "never caught the run with its staging folder: $*"
}
