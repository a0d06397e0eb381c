#!/usr/bin/env bash
# Stock observations2map with rawlogs/observations2map.ini on MRPT's Malaga
# simplemap: with the plugin preloaded it writes the evidential map; without
# it, it silently skips the map and still exits 0 (why every test checks the
# files and not only the exit code).
# Usage: observations2map.sh <plugin.so> <observations2map> <rawlogs dir> <datasets dir> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 5 ] || fail "usage: $0 <plugin.so> <observations2map> <rawlogs dir> <datasets dir> <scratch dir>"
plugin=$1 observations2map=$2 rawlogs=$3 datasets=$4 scratch=$5
simplemap=$datasets/malaga-cs-fac-building.simplemap.gz

rm -rf "$scratch"
# observations2map does not create the output folder.
mkdir -p "$scratch/with_plugin" "$scratch/without_plugin"
run_stock "$scratch/with_plugin.log" 300 "$plugin" \
	"$observations2map" "$rawlogs/observations2map.ini" "$simplemap" "$scratch/with_plugin/malaga"
# 99 scans of the Malaga building at 0.05 m: about 608,000 free and 10,600
# occupied cells.
check_evidential_files "$scratch/with_plugin/malaga_mrpt_evidential__CEvidentialGridMap2D_00" 200000 2000
grep -q '^insertions: 99$' "$scratch/with_plugin/malaga_mrpt_evidential__CEvidentialGridMap2D_00_info.txt" ||
	fail "the evidential map did not receive the simplemap's 99 scans"

run_stock_without_plugin "$scratch/without_plugin.log" 300 evidentialGrid \
	"$observations2map" "$rawlogs/observations2map.ini" "$simplemap" "$scratch/without_plugin/malaga"
if compgen -G "$scratch/without_plugin/*CEvidentialGridMap2D*" >/dev/null; then
	fail "evidential files written without the plugin"
fi
ok "without the plugin, observations2map writes no evidential map"
