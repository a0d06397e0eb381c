#!/usr/bin/env bash
# rawlogs/rawlogviewer-rawmap.ini, as RawLogViewer's Raw-map dialog uses it
# (replayed by rawmap_dialog.cpp on the synthetic room, plugin loaded at run
# time): it creates the evidential map next to the points map and fills it;
# the saved files are checked, and the rawlog holding the map is left in the
# scratch folder for the rawlog-edit and RawLogViewer tests, with the map's
# scene as `evgrid export --scene` writes it (the odometry as its path), for
# SceneViewer3D in the GUI test.
# Usage: rawmap_dialog.sh <plugin.so> <rawmap_dialog> <rawlogs dir> <scratch dir> <evgrid> <evgrid_check>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 6 ] || fail "usage: $0 <plugin.so> <rawmap_dialog> <rawlogs dir> <scratch dir> <evgrid> <evgrid_check>"
plugin=$1 rawmap_dialog=$2 rawlogs=$3 scratch=$4 evgrid=$5 evgrid_check=$6

rm -rf "$scratch"
mkdir -p "$scratch"
run_stock "$scratch/rawmap_dialog.log" 120 "" "$rawmap_dialog" "$plugin" \
	"$rawlogs/rawlogviewer-rawmap.ini" "$rawlogs/room_door_box.rawlog" \
	"$scratch/map.rawlog" "$scratch/rawmap" 20
cat "$scratch/rawmap_dialog.log"

grep -q '^evidential map: .*, 800 observations;' "$scratch/rawmap_dialog.log" ||
	fail "the evidential map did not receive the rawlog's 800 scans"
info=$(only_file "$scratch/rawmap_mrpt_evidential__CEvidentialGridMap2D_*_info.txt")
# The room along the drifting odometry at 0.05 m: about 30,000 free and 1,500
# occupied cells.
check_evidential_files "${info%_info.txt}" 20000 800
only_file "$scratch/rawmap_mrpt__maps__CSimplePointsMap_*.txt" >/dev/null
[ -s "$scratch/map.rawlog" ] || fail "no rawlog written"
ok "the Raw-map .ini builds the evidential map; $scratch/map.rawlog holds it"

"$evgrid_check" odometry-path "$rawlogs/room_door_box.rawlog" "$scratch/odometry.txt" ||
	fail "cannot write the odometry path"
"$evgrid" export -q "${info%_info.txt}.evgrid" --scene "$scratch/map.3Dscene" --path "$scratch/odometry.txt" ||
	fail "evgrid export --scene failed"
[ -s "$scratch/map.3Dscene" ] || fail "no scene written"
ok "evgrid export wrote $scratch/map.3Dscene"
