#!/usr/bin/env bash
# evgrid-simulate, run again with the command of rawlogs/README.md, writes what
# is committed: the same rawlog and motion ground truth content (compared
# decompressed, since another zlib may compress the same bytes differently)
# and the same pose files.
# Usage: simulate.sh <evgrid-simulate> <rawlogs dir> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 3 ] || fail "usage: $0 <evgrid-simulate> <rawlogs dir> <scratch dir>"
simulate=$1 rawlogs=$2 scratch=$3

rm -rf "$scratch"
mkdir -p "$scratch/a" "$scratch/b"
help_has "$simulate" '--seed'

for run in a b; do
	(cd "$scratch" && run_stock "$scratch/$run.log" 120 "" "$simulate" --seed 1 --laps 2 "$run/room_door_box")
done
for suffix in .rawlog .gt.txt .slam.txt .motion.gz; do
	cmp "$scratch/a/room_door_box$suffix" "$scratch/b/room_door_box$suffix" ||
		fail "two runs with the same seed differ: room_door_box$suffix"
done
ok "two runs with the same seed write the same files"

committed=$rawlogs/room_door_box
for suffix in .rawlog .gt.txt .slam.txt .motion.gz; do
	size=$(stat -c %s "$committed$suffix")
	[ "$size" -lt 1000000 ] || fail "$committed$suffix is $size bytes, over 1 MB"
done
cmp <(zcat "$committed.rawlog") <(zcat "$scratch/a/room_door_box.rawlog") ||
	fail "$committed.rawlog is not what evgrid-simulate writes: regenerate it (rawlogs/README.md)"
cmp <(zcat "$committed.motion.gz") <(zcat "$scratch/a/room_door_box.motion.gz") ||
	fail "$committed.motion.gz is not what evgrid-simulate writes: regenerate it (rawlogs/README.md)"
for suffix in .gt.txt .slam.txt; do
	cmp "$committed$suffix" "$scratch/a/room_door_box$suffix" ||
		fail "$committed$suffix is not what evgrid-simulate writes: regenerate it (rawlogs/README.md)"
done
[ "$(grep -vc '^%' "$committed.gt.txt")" -eq 800 ] || fail "$committed.gt.txt has not 800 poses"
ok "the committed room_door_box.rawlog, .gt.txt, .slam.txt and .motion.gz are reproduced ($(stat -c %s "$committed.rawlog") bytes)"
