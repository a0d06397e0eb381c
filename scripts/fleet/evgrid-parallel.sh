#!/usr/bin/env bash
# evgrid-parallel.sh CONFIG.ini OUT RAWLOG...: one map per rawlog, built by
# GNU parallel, then all merged into OUT/merged/ (doc/recipes/fleet.md).
#   JOBS              jobs at once (default: one per core)
#   PARALLEL_OPTIONS  more options for parallel, e.g. "--sshlogin 4/host1,4/:"
#                     (the hosts need evgrid and the same paths: a shared file
#                     system, or see the recipe for --transferfile/--return)
#   EVGRID            the program (default: evgrid on PATH)
# The job log is OUT/joblog.txt. A failed build stops the others and skips the
# merge; the script then exits non-zero. Two rawlogs whose maps would share a
# folder (robot1/run.rawlog and robot2/run.rawlog) are refused before any
# build. With one rawlog there is nothing to merge: an OUT/merged/ of an
# earlier run is removed, so that it is not taken for this one's.
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 CONFIG.ini OUT RAWLOG..." >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
config=$1 out=$2
shift 2
declare -A rawlog_of
maps=()
for rawlog in "$@"; do
  name=$(bash "$here/build-one.sh" --name "$rawlog")
  if [ "$name" = merged ]; then
    echo "$0: $rawlog: its map would go to $out/merged/, the merged map's folder; rename it" >&2
    exit 2
  fi
  if [ -n "${rawlog_of[$name]:-}" ]; then
    echo "$0: $rawlog and ${rawlog_of[$name]} would both build $out/$name/; give them different file names" >&2
    exit 2
  fi
  rawlog_of[$name]=$rawlog
  maps+=("$out/$name/map.evgrid")
done
mkdir -p "$out"
# -q: parallel quotes each word of the command, so that paths with spaces or
# shell characters reach build-one.sh as they are.
# shellcheck disable=SC2086  # PARALLEL_OPTIONS is a list of options
parallel -q --jobs "${JOBS:-100%}" --halt now,fail=1 --joblog "$out/joblog.txt" \
  ${PARALLEL_OPTIONS:-} bash "$here/build-one.sh" "$config" "$out" {} ::: "$@"
if [ ${#maps[@]} -ge 2 ]; then
  "${EVGRID:-evgrid}" merge "${maps[@]}" -o "$out/merged"
else
  rm -rf "$out/merged"
fi
