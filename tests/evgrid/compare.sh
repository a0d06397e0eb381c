# evgrid compare: our map against MRPT's occupancy grid on the simulated room
# with its true poses, on MRPT's Malaga simplemap and on SENA along its
# odometry. Checks the report's numbers add up, that MRPT's grid localizes the
# held-out scans of the room, what the count of walls within one cell reads,
# that MRPT's grid takes its options from the .ini when it lists one,
# that --output holds the numbers stdout shows and is written atomically, and
# the usage errors.
source "$(dirname "$0")/lib.sh"

RAWLOGS=$(dirname "$EVGRID_INI")
room="$RAWLOGS/room_door_box.rawlog"
gt="$RAWLOGS/room_door_box.gt.txt"

# value KEY FILE: the value of a `key value` line; fails if the key is absent.
value() {
  awk -v k="$1" '$1 == k { sub(/^[^ ]+ /, ""); print; found = 1 } END { exit !found }' "$2" ||
    fail "$2 has no key $1"
}

# check_report FILE STDOUT: the keys exist, the counts and percentages add up,
# and stdout shows the very numbers of FILE.
check_report() {
  local file=$1 stdout=$2 prefix decision n sum pct
  [ "$(value scans_total "$file")" -eq $(($(value scans_without_pose "$file") + \
    $(value scans_held_out "$file") + $(value scans_given_to_maps "$file"))) ] ||
    fail "$file: the scans do not add up"
  [ "$(value mrpt_cells "$file")" -eq $(($(value mrpt_occupied_cells "$file") + \
    $(value mrpt_free_cells "$file") + $(value mrpt_neither_cells "$file"))) ] ||
    fail "$file: MRPT's cells do not add up"
  contains "$stdout" "MRPT occupied (getCell < $(value mrpt_occupied_below "$file")): $(value mrpt_occupied_cells "$file") cells"
  contains "$stdout" "MRPT free (getCell > $(value mrpt_free_above "$file")): $(value mrpt_free_cells "$file") cells"
  for prefix in mrpt_occupied mrpt_free; do
    # No cells in this state: stdout says so (checked by the caller) and
    # shows no rows.
    [ "$(value "${prefix}_cells" "$file")" -gt 0 ] || continue
    sum=0
    pct=""
    for decision in occupied free unknown conflict; do
      n=$(value "${prefix}_ours_$decision" "$file")
      sum=$((sum + n))
      pct="$pct $(value "${prefix}_ours_${decision}_pct" "$file")"
      # The row of this decision in the block of this MRPT state on stdout.
      [ "$(awk -v block="MRPT ${prefix#mrpt_}" -v d="$decision" '
          /^  MRPT / { inside = index($0, block " ") == 3 }
          inside && $1 == d && NF == 3 { print $2, $3 }' "$stdout")" = \
        "$n $(value "${prefix}_ours_${decision}_pct" "$file")%" ] ||
        fail "$stdout does not show ${prefix}_ours_$decision as $file does"
    done
    [ "$sum" -eq "$(value "${prefix}_cells" "$file")" ] || fail "$file: $prefix does not add up"
    echo "$pct" | awk '{ s = $1 + $2 + $3 + $4; exit !(s > 99.97 && s < 100.03) }' ||
      fail "$file: the shares of $prefix sum to other than 100:$pct"
  done
  # MRPT's occupied cells occupied in ours within one cell: at least those
  # occupied at their centre, at most all of them, on stdout as in FILE.
  n=$(value mrpt_occupied_near_ours_occupied "$file")
  [ "$n" -ge "$(value mrpt_occupied_ours_occupied "$file")" ] &&
    [ "$n" -le "$(value mrpt_occupied_cells "$file")" ] ||
    fail "$file: $n of MRPT's occupied cells near ours' is out of bounds"
  if [ "$(value mrpt_occupied_cells "$file")" -gt 0 ]; then
    contains "$stdout" "occupied in ours within one cell (the cell or a neighbour): $n  $(value mrpt_occupied_near_ours_occupied_pct "$file")%"
  fi
  # The localization table: "hits  20  21" and so on, ours then MRPT.
  for row in "held-out scans:localization_scans" "hits:hits" "hit rate %:hit_rate_pct" \
    "mean position error m:mean_position_error_m" "mean heading error deg:mean_heading_error_deg"; do
    local label=${row%%:*} key=${row#*:}
    [ "$(grep -E "^  $label +" "$stdout" | awk '{ print $(NF - 1), $NF }')" = \
      "$(value "ours_$key" "$file") $(value "mrpt_$key" "$file")" ] ||
      fail "$stdout does not show ${key} as $file does"
  done
}

# 1. The simulated room with its ground truth: 800 scans, 80 held out.
run 0 "$EVGRID" compare -c "$EVGRID_INI" -i "$room" -p "$gt" --poses-format time --output "$T/room.txt"
cp "$OUT" "$T/room.stdout"
check_report "$T/room.txt" "$T/room.stdout"
for key in scans_total:800 scans_held_out:80 scans_given_to_maps:720 scans_inserted_ours:720 \
  scans_inserted_mrpt:720 holdout:10 resolution:0.05 ours_localization_scans:80 mrpt_localization_scans:80; do
  [ "$(value "${key%%:*}" "$T/room.txt")" = "${key#*:}" ] || fail "${key%%:*} is not ${key#*:}"
done
# True poses, a simulated lidar: MRPT's grid finds the held-out scans' poses
# (all 80 when measured; 90% leaves room for changes of MRPT's defaults). Its
# occupied cells lie on walls our map also holds (occupied or conflict), and
# our map calls few of its free cells occupied: those beside the walls, which
# the default imprecision (0.1 m, for the pose error of real runs) covers.
awk '{ exit !($1 >= 90) }' <<<"$(value mrpt_hit_rate_pct "$T/room.txt")" ||
  fail "MRPT's hit rate on the room is $(value mrpt_hit_rate_pct "$T/room.txt")%"
awk '{ exit !($1 + $2 >= 85) }' <<<"$(value mrpt_occupied_ours_occupied_pct "$T/room.txt") $(value mrpt_occupied_ours_conflict_pct "$T/room.txt")" ||
  fail "our map sees few of MRPT's occupied cells as occupied or conflict"
awk '{ exit !($1 < 10) }' <<<"$(value mrpt_free_ours_occupied_pct "$T/room.txt")" ||
  fail "our map calls many of MRPT's free cells occupied"
# Every occupied cell of MRPT's is occupied in ours within one cell (all
# 1717 when measured).
awk '{ exit !($1 >= 99) }' <<<"$(value mrpt_occupied_near_ours_occupied_pct "$T/room.txt")" ||
  fail "our map has few of MRPT's occupied cells within one cell"
# The same run gives the same numbers.
run 0 "$EVGRID" compare -q -c "$EVGRID_INI" -i "$room" -p "$gt" --output "$T/again.txt"
[ ! -s "$OUT" ] || fail "--quiet printed the report"
cmp -s "$T/room.txt" "$T/again.txt" || fail "a second run wrote other numbers"
# MRPT's grid takes MRPT's defaults unless the .ini lists an occupancyGrid
# too (as icp-slam's do): then its insertion and likelihood options, at our
# map's cells. Inserting up to 2 m instead of MRPT's default 15 m leaves it
# fewer occupied cells; its own resolution (0.25 m) is not used.
contains "$T/room.stdout" "MRPT's options: MRPT's defaults"
[ "$(value mrpt_options "$T/room.txt")" = "MRPT's defaults" ] || fail "not MRPT's defaults"
sed 's/^evidentialGrid_count=1$/&\noccupancyGrid_count=1/' "$EVGRID_INI" >"$T/both.ini"
printf '%s\n' "[MappingApplication_occupancyGrid_00_creationOpts]" "resolution=0.25" \
  "[MappingApplication_occupancyGrid_00_insertOpts]" "maxDistanceInsertion=2" >>"$T/both.ini"
run 0 "$EVGRID" compare -c "$T/both.ini" -i "$room" -p "$gt" --poses-format time --output "$T/both.txt"
cp "$OUT" "$T/both.stdout"
# MRPT's own options, which MRPT reads unchecked: a zero decimation would
# make its likelihood loop forever.
printf '%s\n' "[MappingApplication_occupancyGrid_00_likelihoodOpts]" "LF_decimation=0" \
  | cat "$T/both.ini" - >"$T/decimation.ini"
run 1 "$EVGRID" compare -c "$T/decimation.ini" -i "$room" -p "$gt" --poses-format time
contains "$ERR" "the occupancyGrid's LF_decimation must be at least 1"
check_report "$T/both.txt" "$T/both.stdout"
contains "$T/both.stdout" "MRPT's options: the .ini's first occupancyGrid (its insertOpts and likelihoodOpts; our map's cells)"
# MRPT's grid at our 0.05 m cells, as with its defaults (0.25 m would make
# it 25 times fewer).
[ "$(value mrpt_cells "$T/both.txt")" = "$(value mrpt_cells "$T/room.txt")" ] ||
  fail "MRPT's grid took the .ini's resolution"
[ "$(value mrpt_occupied_cells "$T/both.txt")" -lt "$(value mrpt_occupied_cells "$T/room.txt")" ] ||
  fail "MRPT's grid did not take the .ini's maxDistanceInsertion"

# 2. A failed run leaves the earlier file as it was, and no temporary file.
mkdir "$T/kept"
cp "$T/room.txt" "$T/kept/room.txt"
before=$(fingerprint "$T/kept")
run 1 "$EVGRID" compare -i "$T/none.rawlog" --output "$T/kept/room.txt"
contains "$ERR" "evgrid compare: error: $T/none.rawlog: cannot open"
[ "$(fingerprint "$T/kept")" = "$before" ] || fail "a failed run changed $T/kept"
head -c 300000 "$room" >"$T/cut.rawlog"
run 1 "$EVGRID" compare -i "$T/cut.rawlog" --output "$T/kept/room.txt"
contains "$ERR" "$T/cut.rawlog: entry "
contains "$ERR" "truncated file?"
[ "$(fingerprint "$T/kept")" = "$before" ] || fail "a failed run changed $T/kept"
#    The report's path is an input's: refused before the work, the input kept.
cp "$room" "$T/victim.rawlog"
run 1 "$EVGRID" compare -i "$T/victim.rawlog" -p "$gt" --output "$T/victim.rawlog"
contains "$ERR" "$T/victim.rawlog: is also an input ($T/victim.rawlog): writing it would destroy it"
cmp -s "$room" "$T/victim.rawlog" || fail "the rawlog was overwritten"
#    An input without 2-D scans: the error says what it held instead.
run 1 "$EVGRID" compare -i "$DATASETS/test_velodyne_VLP16.rawlog" --output "$T/kept/room.txt"
contains "$ERR" "a map took no scan (0 2-D scans"
contains "$ERR" "not inserted: 1 mrpt::obs::CObservationVelodyneScan)"
[ "$(fingerprint "$T/kept")" = "$before" ] || fail "a failed run changed $T/kept"

# 3. MRPT's Malaga simplemap: real SICK scans, the keyframes' poses.
run 0 "$EVGRID" compare -c "$EVGRID_INI" -i "$DATASETS/malaga-cs-fac-building.simplemap.gz" --output "$T/malaga.txt"
cp "$OUT" "$T/malaga.stdout"
check_report "$T/malaga.txt" "$T/malaga.stdout"
contains "$T/malaga.stdout" "poses: the simplemap's"
[ "$(value scans_total "$T/malaga.txt") $(value scans_held_out "$T/malaga.txt")" = "99 9" ] ||
  fail "Malaga: not 99 scans with 9 held out"
# Its walls: nearly all of MRPT's occupied cells are occupied in ours within
# one cell (98.5 % when measured, 92.9 % at their very centre).
awk '{ exit !($1 >= 95) }' <<<"$(value mrpt_occupied_near_ours_occupied_pct "$T/malaga.txt")" ||
  fail "Malaga: $(value mrpt_occupied_near_ours_occupied_pct "$T/malaga.txt")% of MRPT's occupied cells near ours'"

#    SENA along its odometry, which drifts by metres: walls seen twice a
#    cell or more apart. The count within one cell lies strictly between the
#    count at the centre and all of MRPT's occupied cells (75.6 % and 84.5 %
#    when measured): it reads the neighbours, and only those ours calls
#    occupied.
run 0 "$EVGRID" compare -c "$EVGRID_INI" -i "$SENA" --output "$T/sena.txt"
cp "$OUT" "$T/sena.stdout"
check_report "$T/sena.txt" "$T/sena.stdout"
near=$(value mrpt_occupied_near_ours_occupied "$T/sena.txt")
[ "$(value mrpt_occupied_ours_occupied "$T/sena.txt")" -lt "$near" ] &&
  [ "$near" -lt "$(value mrpt_occupied_cells "$T/sena.txt")" ] ||
  fail "SENA: $near of MRPT's occupied cells near ours' is not between the two counts"

# 4. Nothing to share: every range 16 m longer, beyond MRPT's 15 m insertion
#    limit, leaves its grid without an occupied cell; on that empty grid every
#    perturbation scores the same, and the first, (-0.30, -0.30, -5 deg),
#    wins. More scans than --holdout N: none held out.
run 0 "$EVGRID_CHECK" farther "$room" 16 "$T/far.rawlog.gz"
run 0 "$EVGRID" compare -i "$T/far.rawlog.gz" -p "$gt" --output "$T/far.txt"
cp "$OUT" "$T/far.stdout"
check_report "$T/far.txt" "$T/far.stdout"
contains "$T/far.stdout" "MRPT occupied (getCell < 0.4): 0 cells, none to compare"
[ "$(value mrpt_occupied_ours_occupied_pct "$T/far.txt") $(value mrpt_occupied_near_ours_occupied_pct "$T/far.txt")" = "n/a n/a" ] ||
  fail "a share of no cells"
[ "$(value mrpt_hits "$T/far.txt") $(value mrpt_mean_position_error_m "$T/far.txt") $(value mrpt_mean_heading_error_deg "$T/far.txt")" = \
  "0 0.4243 5.00" ] || fail "ties on an empty grid do not go to the first perturbation"
run 0 "$EVGRID" compare -i "$room" --holdout 1000 --output "$T/none-held.txt"
contains "$OUT" "no scan was held out (fewer than 1000 scans with a pose)"
[ "$(value scans_held_out "$T/none-held.txt") $(value ours_hit_rate_pct "$T/none-held.txt")" = "0 n/a" ] ||
  fail "no held-out scan: not 0 and n/a"

# Poses kilometres from the grid: our map stops at its cell budget, and
# compare stops there too (MRPT's grid, which has no budget, would grow until
# it exhausted the memory and crashed).
awk '/^%/ { print; next } { printf "%s %.6f %.6f %s\n", $1, $2 + 500000, $3 - 4200000, $4 }' "$gt" >"$T/utm.txt"
run 1 "$EVGRID" compare -q -c "$EVGRID_INI" -i "$room" -p "$T/utm.txt"
contains "$ERR" "lets our map grow to, and MRPT's grid has no such limit: compare stops"

# 5. Usage errors: exit 2 before any work.
run 2 "$EVGRID" compare -i "$room" --holdout 1
contains "$ERR" "--holdout must be at least 2, got 1"
run 2 "$EVGRID" compare -i "$room" --holdout some
contains "$ERR" "bad value 'some' for --holdout"
run 2 "$EVGRID" compare --output "$T/x.txt"
contains "$ERR" "missing the input"
run 2 "$EVGRID" compare -i "$room" --output ""
contains "$ERR" "--output needs a non-empty value"
run 2 "$EVGRID" compare -i "$room" --poses-format time
contains "$ERR" "--poses-format needs --poses"
[ ! -e "$T/x.txt" ] || fail "a usage error wrote the output"
echo "evgrid_compare: OK"
