#!/usr/bin/env bash
# build-one.sh CONFIG.ini OUT RAWLOG: one `evgrid build` of a fleet
# (doc/recipes/fleet.md), the job GNU parallel and Slurm run. The map goes to
# OUT/NAME/, NAME being the rawlog's file name without .gz and .rawlog; a pose
# file NAME.slam.txt or NAME.poses.txt beside the rawlog is used with -p.
# build-one.sh --name RAWLOG prints NAME (the fleet scripts check with it
# that no two rawlogs share a folder).
# EVGRID: the program (default: evgrid on PATH).
set -euo pipefail
name_of() {
  local name
  name=$(basename "$1")
  name=${name%.gz}
  printf '%s\n' "${name%.rawlog}"
}
if [ $# -eq 2 ] && [ "$1" = --name ]; then
  name_of "$2"
  exit 0
fi
[ $# -eq 3 ] || { echo "usage: $0 CONFIG.ini OUT RAWLOG, or $0 --name RAWLOG" >&2; exit 2; }
config=$1 out=$2 rawlog=$3
name=$(name_of "$rawlog")
stem=${rawlog%.gz}
stem=${stem%.rawlog}
poses=()
for suffix in .slam.txt .poses.txt; do
  if [ -f "$stem$suffix" ]; then poses=(-p "$stem$suffix"); break; fi
done
exec "${EVGRID:-evgrid}" build -q -c "$config" -i "$rawlog" "${poses[@]}" -o "$out/$name"
