#!/usr/bin/env bash
# evgrid-simulate's scene "street" (issue 12): the command of rawlogs/README.md
# writes the committed sample again (rawlog and gzip files compared
# decompressed, since another zlib may compress the same bytes differently),
# the same seed writes the same files and another seed other noise only,
# rawlog-edit reads the point clouds, the footprint truth puts the street's
# things in their classes, and the options of one kind of scene are refused
# for the other.
# Usage: simulate_street.sh <evgrid-simulate> <rawlog-edit> <rawlogs dir> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 4 ] || fail "usage: $0 <evgrid-simulate> <rawlog-edit> <rawlogs dir> <scratch dir>"
simulate=$1 rawlog_edit=$2 rawlogs=$3 scratch=$4

rm -rf "$scratch"
mkdir -p "$scratch/a" "$scratch/b" "$scratch/seed2"
help_has "$simulate" '--azimuth-step' 'overhang C ITEMS'

# Options of the other kind of scene, and out of their bounds, are refused.
refused() {
	if "$simulate" "$@" "$scratch/x" 2>"$scratch/refused.log"; then fail "accepted: $*"; fi
	grep -q -- "$1" "$scratch/refused.log" || fail "the refusal of $* does not name $1"
}
refused --laps 2 --scene street
refused --layers 8
refused --duration 3 --scene people
refused --layers 0 --scene street
refused --layers 129 --scene street
refused --azimuth-step 0 --scene street
refused --duration 25 --scene street
ok "options for the other kind of scene, or out of bounds, are refused"

name=street_vlp16
sample=(--scene street --seed 1 --duration 3 --azimuth-step 1)
suffixes=(.rawlog .gt.txt .gt3d.txt .slam.txt .motion.gz .footprint.gz)
for run in a b; do
	(cd "$scratch" && run_stock "$scratch/$run.log" 60 "" "$simulate" "${sample[@]}" "$run/$name")
done
for suffix in "${suffixes[@]}"; do
	cmp "$scratch/a/$name$suffix" "$scratch/b/$name$suffix" ||
		fail "two runs with the same seed differ: $name$suffix"
done
ok "two runs with the same seed write the same files"

committed=$rawlogs/$name
total=0
for suffix in "${suffixes[@]}"; do
	total=$((total + $(stat -c %s "$committed$suffix")))
	case $suffix in
	*.txt) cmp "$committed$suffix" "$scratch/a/$name$suffix" ;;
	*) cmp <(zcat "$committed$suffix") <(zcat "$scratch/a/$name$suffix") ;;
	esac || fail "$committed$suffix is not what evgrid-simulate writes: regenerate it (rawlogs/README.md)"
done
[ "$total" -lt 3000000 ] || fail "the committed $name files take $total bytes, over 3 MB"
[ "$(grep -vc '^%' "$committed.gt.txt")" -eq 30 ] || fail "$committed.gt.txt has not 30 poses"
ok "the committed $name files are reproduced ($total bytes)"

run_stock "$scratch/seed2.log" 60 "" "$simulate" --scene street --seed 2 --duration 3 --azimuth-step 1 "$scratch/seed2/$name"
! cmp -s <(zcat "$scratch/a/$name.rawlog") <(zcat "$scratch/seed2/$name.rawlog") ||
	fail "seeds 1 and 2 write the same rawlog"
for suffix in .gt.txt .gt3d.txt; do
	cmp "$scratch/a/$name$suffix" "$scratch/seed2/$name$suffix" || fail "$name$suffix depends on the seed"
done
for suffix in .motion.gz .footprint.gz; do
	cmp <(zcat "$scratch/a/$name$suffix") <(zcat "$scratch/seed2/$name$suffix") ||
		fail "$name$suffix depends on the seed"
done
ok "another seed changes the noise and not the ground truth"

# MRPT's own reader: 30 point clouds labelled VELODYNE at 10 Hz (MRPT 2.14
# puts a space before the rate).
run_stock "$scratch/info.log" 60 "" "$rawlog_edit" --info -i "$committed.rawlog"
grep -Eq 'VELODYNE / +30 / *10\.000' "$scratch/info.log" ||
	{ show_log "$scratch/info.log"; fail "rawlog-edit does not list 30 VELODYNE observations at 10 Hz"; }
grep -Eq 'Overall number of objects +: 60$' "$scratch/info.log" ||
	{ show_log "$scratch/info.log"; fail "rawlog-edit does not count 30 actions and 30 sensory frames"; }
ok "rawlog-edit reads $name.rawlog"

# The footprint truth: the class of the cell holding each probe point.
footprint=$scratch/footprint.txt
zcat "$committed.footprint.gz" >"$footprint"
head -n 4 "$footprint" | tr '\n' '|' | grep -qx 'evgrid-simulate footprint 1|scene street|grid -16.00 -9.00 0.05 1840 360|heights 0.20 2.00|' ||
	fail "the footprint file's header is not as documented: $(head -n 4 "$footprint" | tr '\n' '|')"
zcat "$committed.motion.gz" | sed -n 4p | grep -qx 'grid -16.00 -9.00 0.05 1840 360' ||
	fail "the motion file's grid is not the footprint's"
class_at() {
	awk -v x="$1" -v y="$2" '
		$1 == "grid" { cell = int((x - $2) / $4) + $5 * int((y - $3) / $4) }
		$1 == "obstacle" || $1 == "low" || $1 == "overhang" {
			n = 0
			for (i = 3; i <= NF; ++i) {
				if (split($i, r, "-") == 1) r[2] = r[1]
				n += r[2] - r[1] + 1
				if (cell >= r[1] + 0 && cell <= r[2] + 0) found = $1
			}
			if (n != $2) { print "count"; exit }
		}
		END { print found ? found : "ground" }' "$footprint"
}
expect_class() {
	local got
	got=$(class_at "$1" "$2")
	[ "$got" = "$3" ] || fail "the footprint cell at ($1, $2), $4, is $got, not $3"
}
expect_class 2.0 3.0 obstacle "a parked car"
expect_class -3.0 8.15 obstacle "a house front"
expect_class 0.0 -4.6 obstacle "a lamp post"
expect_class -3.0 -4.075 low "the kerb"
expect_class 14.0 0.0 overhang "the gantry's beam"
expect_class 45.0 7.0 overhang "the tree's crown"
expect_class -3.0 0.0 ground "the road"
expect_class 17.0 -5.0 ground "the crossing person's start (moving, not static)"
ok "the footprint truth classes the street's things"
