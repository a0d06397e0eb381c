#!/usr/bin/env bash
# Stock icp-slam with the plugin preloaded, on MRPT's real SENA rawlog, with
# rawlogs/icp-slam.ini as it is and with its evidential map removed: the
# evidential grid must not change the path icp-slam estimates, must be saved
# with plausible content, and must be drawn into the saved 3-D scenes.
# Usage: icp_slam.sh <plugin.so> <icp-slam> <rawlogs dir> <datasets dir> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 5 ] || fail "usage: $0 <plugin.so> <icp-slam> <rawlogs dir> <datasets dir> <scratch dir>"
plugin=$1 icp_slam=$2 rawlogs=$3 datasets=$4 scratch=$5
rawlog="$datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"

rm -rf "$scratch"
mkdir -p "$scratch/with_map" "$scratch/without_map"
cp "$rawlogs/icp-slam.ini" "$scratch/with_map/icp-slam.ini"
sed 's/^evidentialGrid_count=1$/evidentialGrid_count=0/' "$rawlogs/icp-slam.ini" >"$scratch/without_map/icp-slam.ini"
grep -q '^evidentialGrid_count=0$' "$scratch/without_map/icp-slam.ini" ||
	fail "icp-slam.ini has no line evidentialGrid_count=1 to remove"

for run in with_map without_map; do
	(cd "$scratch/$run" && run_stock "$scratch/$run.log" 300 "$plugin" "$icp_slam" icp-slam.ini "$rawlog")
done

# The same path, step by step (icp-slam prints 6 decimals).
with=$scratch/with_map/icp-slam-out/log_estimated_path.txt
without=$scratch/without_map/icp-slam-out/log_estimated_path.txt
steps=$(wc -l <"$with")
[ "$steps" -eq 224 ] || fail "$with has $steps steps, expected one per action-observation pair of the rawlog: 224"
[ "$steps" -eq "$(wc -l <"$without")" ] || fail "the paths with and without the map differ in length"
difference=$(paste -d ' ' "$with" "$without" | awk '
	{ for (i = 1; i <= 4; ++i) { d = $i - $(i + 4); if (d < 0) d = -d; if (d > m) m = d } }
	END { printf "%.3g", m + 0 }')
echo "largest difference between the paths (step, x, y, phi): $difference"
awk -v d="$difference" 'BEGIN { exit !(d <= 1e-6) }' ||
	fail "the evidential map changed icp-slam's path (difference $difference)"
ok "icp-slam's path is the same with and without the evidential map ($steps steps, end: $(tail -n 1 "$with"))"

info=$(only_file "$scratch/with_map/icp-slam-out/_finalmaps_.txt_mrpt_evidential__CEvidentialGridMap2D_*_info.txt")
# SENA's corridors at 0.05 m: about 584,000 free and 8,600 occupied cells.
check_evidential_files "${info%_info.txt}" 200000 2000
if compgen -G "$scratch/without_map/icp-slam-out/*CEvidentialGridMap2D*" >/dev/null; then
	fail "evidential files written without the evidential map"
fi

# The map's 3-D view (its objects, by name) is in icp-slam's scenes. (grep -c
# reads everything: with -q, zcat could die of SIGPIPE and fail the pipe.)
map_objects() { zcat "$1" | grep -ac 'evidentialGrid\.\(free\|occupied\)' || true; }
scenes=("$scratch"/with_map/icp-slam-out/buildingmap_*.3Dscene)
[ -s "${scenes[-1]}" ] || fail "icp-slam saved no 3-D scene"
[ "$(map_objects "${scenes[-1]}")" -gt 0 ] || fail "${scenes[-1]} holds none of the map's objects"
without_scene="$scratch/without_map/icp-slam-out/$(basename "${scenes[-1]}")"
[ -s "$without_scene" ] || fail "the run without the evidential map saved no $(basename "$without_scene")"
[ "$(map_objects "$without_scene")" -eq 0 ] ||
	fail "the map's objects without the evidential map: the check above proves nothing"
ok "the evidential map is drawn in $(basename "${scenes[-1]}")"
