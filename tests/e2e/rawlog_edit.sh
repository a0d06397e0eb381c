#!/usr/bin/env bash
# Stock rawlog-edit -p <plugin> reads a rawlog whose first object is a
# serialized evidential map (written by the rawmap_dialog test: the map, then
# 10 odometry actions and 10 sensory frames of the synthetic room) to its end;
# without -p it stops at the map, whose class it does not know.
# Usage: rawlog_edit.sh <plugin.so> <rawlog-edit> <map rawlog> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 4 ] || fail "usage: $0 <plugin.so> <rawlog-edit> <map rawlog> <scratch dir>"
plugin=$1 rawlog_edit=$2 rawlog=$3 scratch=$4
[ -s "$rawlog" ] || fail "$rawlog is missing: the e2e_rawmap_dialog test writes it"

rm -rf "$scratch"
mkdir -p "$scratch"
info_value() { grep "^$1 *:" "$2" | sed 's/^[^:]*: *//'; }

run_stock "$scratch/with_plugin.log" 120 "" "$rawlog_edit" -p "$plugin" -i "$rawlog" --info
cat "$scratch/with_plugin.log"
if grep -q 'Found exception' "$scratch/with_plugin.log"; then
	fail "rawlog-edit -p could not read the rawlog"
fi
objects=$(info_value 'Overall number of objects' "$scratch/with_plugin.log")
[ "$objects" = 21 ] || fail "rawlog-edit -p read $objects objects, expected 21"
info_value 'Sensor (Label/Occurs/Rate/Durat.)' "$scratch/with_plugin.log" | grep -q '^LASER */ *10 ' ||
	fail "rawlog-edit -p did not find the 10 scans behind the map"
ok "rawlog-edit -p reads the evidential map and the 20 entries behind it"

run_stock "$scratch/without_plugin.log" 120 "" "$rawlog_edit" -i "$rawlog" --info
grep -q "class 'mrpt_evidential::CEvidentialGridMap2D' which is not registered" "$scratch/without_plugin.log" ||
	fail "without -p, rawlog-edit did not stop at the evidential map"
ok "without -p, rawlog-edit stops at the map: the plugin is what makes it readable"
