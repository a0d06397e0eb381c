#!/usr/bin/env bash
# evgrid-slurm-array.sh CONFIG.ini LIST OUT: task SLURM_ARRAY_TASK_ID of a
# Slurm job array builds the map of line SLURM_ARRAY_TASK_ID + 1 of LIST (one
# rawlog path per line) into OUT/NAME/ (doc/recipes/fleet.md):
#   n=$(wc -l <logs.txt)
#   job=$(sbatch --parsable --array=0-$((n - 1)) evgrid-slurm-array.sh evgrid.ini logs.txt out)
#   sbatch --dependency=afterok:$job --wrap "evgrid merge out/*/map.evgrid -o out/merged"
# The resources below suit one build of MRPT's datasets; raise --time for
# long logs.
#SBATCH --job-name=evgrid
#SBATCH --cpus-per-task=1
#SBATCH --mem=2G
#SBATCH --time=01:00:00
#SBATCH --output=evgrid-%A_%a.log
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 CONFIG.ini LIST OUT" >&2; exit 2; }
: "${SLURM_ARRAY_TASK_ID:?not a Slurm array task (sbatch --array=...)}"
config=$1 list=$2 out=$3
rawlog=$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" "$list")
[ -n "$rawlog" ] || { echo "$list has no line $((SLURM_ARRAY_TASK_ID + 1))" >&2; exit 1; }
# Slurm runs a copy of this script from its spool: the helper is found in
# EVGRID_FLEET_DIR, else in the submission folder's scripts/fleet (a
# checkout), else in the fleet folder of the installation that holds the
# evgrid on PATH (PREFIX/share/mrpt-evidential/fleet).
here=${EVGRID_FLEET_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)}
[ -f "$here/build-one.sh" ] || here=$SLURM_SUBMIT_DIR/scripts/fleet
if [ ! -f "$here/build-one.sh" ] && evgrid=$(command -v "${EVGRID:-evgrid}"); then
  here=$(cd "$(dirname "$evgrid")/.." && pwd)/share/mrpt-evidential/fleet
fi
[ -f "$here/build-one.sh" ] || {
  echo "$0: build-one.sh not found: set EVGRID_FLEET_DIR to the folder of the fleet scripts" >&2
  exit 1
}
# Each task checks that no other line of LIST builds the same folder (two
# robots' run.rawlog): one would replace the other's map.
name=$(bash "$here/build-one.sh" --name "$rawlog")
while IFS= read -r other; do
  [ -n "$other" ] && [ "$other" != "$rawlog" ] || continue
  if [ "$(bash "$here/build-one.sh" --name "$other")" = "$name" ]; then
    echo "$0: $rawlog and $other (in $list) would both build $out/$name/; give them different file names" >&2
    exit 1
  fi
done <"$list"
mkdir -p "$out"
exec bash "$here/build-one.sh" "$config" "$out" "$rawlog"
