#!/usr/bin/env bash
# evgrid-simulate's scene "people" and its ground truth: the same seed writes
# the same files, the motion file (rawlogs/README.md) agrees with the scene's
# known paths and with itself, the SLAM-like poses stay within their bounds,
# and evgrid builds a map from the rawlog with them. The scene "static" lists
# nothing moving.
# Usage: simulate_scenes.sh <evgrid-simulate> <evgrid> <rawlogs dir> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 4 ] || fail "usage: $0 <evgrid-simulate> <evgrid> <rawlogs dir> <scratch dir>"
simulate=$1 evgrid=$2 rawlogs=$3 scratch=$4

rm -rf "$scratch"
mkdir -p "$scratch/a" "$scratch/b" "$scratch/seed2"
help_has "$simulate" '--scene' 'left C ITEMS'
if "$simulate" --scene nowhere "$scratch/x" 2>"$scratch/bad.log"; then fail "--scene nowhere was accepted"; fi
grep -q 'people' "$scratch/bad.log" || fail "--scene nowhere does not list the scenes"

for run in a b; do
	run_stock "$scratch/$run.log" 60 "" "$simulate" --scene people --seed 1 "$scratch/$run/people"
done
for suffix in .rawlog .gt.txt .slam.txt .motion.gz; do
	cmp "$scratch/a/people$suffix" "$scratch/b/people$suffix" ||
		fail "two runs with the same seed differ: people$suffix"
done
ok "two runs of the scene people with the same seed write the same files"
run_stock "$scratch/seed2.log" 60 "" "$simulate" --scene people --seed 2 "$scratch/seed2/people"
! cmp -s <(zcat "$scratch/a/people.rawlog") <(zcat "$scratch/seed2/people.rawlog") ||
	fail "seeds 1 and 2 write the same rawlog"
cmp <(zcat "$scratch/a/people.motion.gz") <(zcat "$scratch/seed2/people.motion.gz") ||
	fail "the motion ground truth depends on the seed"
ok "another seed changes the noise and not the ground truth"

prefix=$scratch/a/people
motion=$scratch/motion.txt
zcat "$prefix.motion.gz" >"$motion"
read -r x0 y0 res nx ny < <(sed -n 's/^grid //p' "$motion")
[ "$res" = 0.05 ] || fail "the motion grid's resolution is $res, not 0.05"
# The index of the cell holding point (x, y).
cell_of() {
	awk -v x="$1" -v y="$2" -v x0="$x0" -v y0="$y0" -v r="$res" -v nx="$nx" \
		'BEGIN { print int((x - x0) / r) + nx * int((y - y0) / r) }'
}

# Consistency of the whole file, and where the probe cells are listed:
# "occupied K CELL" and "left K CELL TL" lines for every probe.
# Person 2 stands at (-0.2, 1.3) from 9.25 to 14.25 s and is elsewhere at 5 s.
person2=$(cell_of -0.175 1.325)
# Person 3 stands at (1.2, -1.0) with radius 0.3 until 24 s, then walks
# towards (4.4, 0) at 1.118 m/s: the cell x in [1.2, 1.25], y in [-1, -0.95]
# is uncovered once its far corner is 0.3 m behind, at 24.323 s.
person3=$(cell_of 1.225 -0.975)
# The cart's south edge is at y = -3.7 until 52 s, then moves north at
# 0.825 m/s: it clears the row y in [-3.7, -3.65] at 52.061 s, so the first
# sample after it (every 0.02 s) is 52.08.
cart=$(cell_of 3.8 -3.675)
# The closed door, x in [5.03, 5.12], until 15 s.
door=$(cell_of 5.075 0.025)
awk -v probes="$person2 $person3 $cart $door" '
	function fail(msg) { print "FAILED: " msg > "/dev/stderr"; bad = 1; exit 1 }
	# Expands the items of fields 3.. into cells[]; returns the count.
	function expand(    i, item, range, n, c, tl) {
		delete cells; delete when; n = 0
		for (i = 3; i <= NF; ++i) {
			item = $i; tl = ""
			if (split(item, parts, ":") == 2) { item = parts[1]; tl = parts[2] }
			if (split(item, range, "-") == 1) range[2] = range[1]
			for (c = range[1] + 0; c <= range[2] + 0; ++c) { cells[c] = 1; when[c] = tl; ++n }
		}
		return n
	}
	BEGIN { split(probes, p, " "); for (i in p) probe[p[i]] = 1; k = -1 }
	$1 == "scans" { scans = $2 }
	$1 == "static" {
		if (expand() != $2) fail("static: " $2 " cells announced")
		for (c in cells) static[c] = 1
		nstatic = $2
	}
	$1 == "scan" {
		if ($2 != k + 1) fail("scan " $2 " after scan " k)
		k = $2; previous = t; t = $3
		if (t != sprintf("%.2f", k / 10)) fail("scan " k " at time " t)
	}
	$1 == "occupied" || $1 == "left" {
		if (expand() != $2) fail("scan " k ": " $1 " lists not " $2 " cells")
		for (c in cells) {
			if (c in static) fail("scan " k ": static cell " c " listed " $1)
			if ($1 == "left" && !(when[c] > previous && when[c] <= t))
				fail("scan " k ": cell " c " left at " when[c])
			if ($1 == "occupied") occupied[c] = k
			else if (occupied[c] == k "") fail("scan " k ": cell " c " both occupied and left")
			if (c in probe) print $1, k, c, when[c]
		}
	}
	END {
		if (bad) exit 1
		if (k + 1 != scans) fail("the file has " k + 1 " scans, its header " scans)
		print "checked", scans, "scans,", nstatic, "static cells" > "/dev/stderr"
	}' "$motion" >"$scratch/probes.txt" || fail "the motion file of people is inconsistent"
probe() { grep -qx "$1" "$scratch/probes.txt" || fail "$2 ($1 not in $scratch/probes.txt)"; }
probe "occupied 120 $person2 " "person 2 is not listed at (-0.2, 1.3) at 12 s"
! grep -q "^occupied 50 $person2 " "$scratch/probes.txt" || fail "person 2 is listed at (-0.2, 1.3) at 5 s"
probe "occupied 240 $person3 " "person 3 is not listed at (1.2, -1.0) at 24 s"
tl=$(awk -v c="$person3" '$1 == "left" && $3 == c { print $4 }' "$scratch/probes.txt")
awk -v t="$tl" 'BEGIN { exit !(t >= 24.32 && t <= 24.36) }' ||
	fail "person 3 leaves its cell at '$tl', not at 24.32 to 24.36 s"
probe "occupied 520 $cart " "the parked cart is not listed at 52 s"
probe "left 521 $cart 52.08" "the cart's cell is not left at 52.08 s"
probe "occupied 149 $door " "the closed door is not listed at 14.9 s"
probe "left 150 $door 15.00" "the door's cell is not left at 15 s"
ok "the motion ground truth agrees with the scene's paths (person 3 left at $tl s)"

# The poses: one a scan, the SLAM-like ones within 5 cm and 1 degree.
for suffix in gt.txt slam.txt; do
	[ "$(grep -vc '^%' "$prefix.$suffix")" -eq 800 ] || fail "people.$suffix has not 800 poses"
done
paste -d ' ' <(grep -v '^%' "$prefix.gt.txt") <(grep -v '^%' "$prefix.slam.txt") | awk '
	function abs(v) { return v < 0 ? -v : v }
	{
		if ($1 != $5) { print "time " $1 " against " $5; exit 1 }
		d = abs($8 - $4); if (d > 3.14159265) d = 2 * 3.14159265 - d
		e = abs($6 - $2) > abs($7 - $3) ? abs($6 - $2) : abs($7 - $3)
		if (e > 0.05 || d > 3.14159265 / 180) { print "off by " e " m, " d " rad at " $1; exit 1 }
		if (e > most) most = e
	}
	END { if (most < 0.005) { print "largest error " most " m"; exit 1 } }' ||
	fail "people.slam.txt is not the truth with a small error"
ok "people.slam.txt stays within 5 cm and 1 degree of people.gt.txt"

run_stock "$scratch/evgrid.log" 60 "" "$evgrid" build -i "$prefix.rawlog" -p "$prefix.slam.txt" \
	-c "$rawlogs/evgrid.ini" -o "$scratch/map" -q
grep -q '^scans: 800 2-D scans: 800 inserted' "$scratch/map/summary.txt" ||
	fail "evgrid did not insert the 800 scans of people.rawlog ($scratch/map/summary.txt)"
ok "evgrid builds a map from people.rawlog and people.slam.txt"

run_stock "$scratch/static.log" 60 "" "$simulate" --scene static --laps 1 "$scratch/a/static"
zcat "$scratch/a/static.motion.gz" | awk '
	$1 == "occupied" || $1 == "left" { if ($2 != 0) exit 1; ++records }
	END { exit records != 800 }' || fail "the scene static lists something moving"
ok "the scene static lists nothing moving"
