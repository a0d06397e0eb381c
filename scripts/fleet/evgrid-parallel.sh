#!/usr/bin/env bash
# evgrid-parallel.sh CONFIG.ini OUT RAWLOG...: one map per rawlog, built by
# GNU parallel, then all merged into OUT/merged/ (doc/recipes/fleet.md).
#   JOBS              jobs at once (default: one per core)
#   PARALLEL_OPTIONS  more options for parallel, e.g. "--sshlogin 4/host1,4/:"
#                     (the hosts need evgrid and the same paths: a shared file
#                     system, or see the recipe for --transferfile/--return)
#   EVGRID            the program (default: evgrid on PATH)
# The job log is OUT/joblog.txt. A failed build stops the others and skips the
# merge; the script then exits non-zero.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 CONFIG.ini OUT RAWLOG..." >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
config=$1 out=$2
shift 2
mkdir -p "$out"
# shellcheck disable=SC2086  # PARALLEL_OPTIONS is a list of options
parallel --jobs "${JOBS:-100%}" --halt now,fail=1 --joblog "$out/joblog.txt" \
  ${PARALLEL_OPTIONS:-} bash "$here/build-one.sh" "$config" "$out" {} ::: "$@"
maps=()
for rawlog in "$@"; do
  name=$(basename "$rawlog")
  name=${name%.gz}
  maps+=("$out/${name%.rawlog}/map.evgrid")
done
if [ ${#maps[@]} -ge 2 ]; then
  "${EVGRID:-evgrid}" merge "${maps[@]}" -o "$out/merged"
fi
