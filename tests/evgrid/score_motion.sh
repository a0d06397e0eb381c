# evgrid score-motion: the motion layer against evgrid-simulate's ground truth
# on the committed room_door_box, a one-lap people scene and the static scene.
# Checks that every key is there, that the counts and ratios agree with each
# other and with stdout, that more tolerance never matches less, that the
# static scene has no truth event under either dating of the truth (and that
# its walls' flags are located, without a clearance), that the
# two datings differ on people and change the truth only, that the motion
# read in each scan's frame is the world's at exact poses and leaves the truth
# and the walls' share alone, that the default tolerance is one map cell, that a map that
# keeps conflict flags nothing,
# that a truth of another input, a shifted or a truncated one is an error
# that leaves an earlier --output as it was, and the usage errors. The F1
# scores are printed, not judged: the motion layer is still being tuned.
source "$(dirname "$0")/lib.sh"

RAWLOGS=$(dirname "$EVGRID_INI")
room="$RAWLOGS/room_door_box"
# The motion layer needs a map that does not keep conflict.
sed 's/^conflictHandling=.*/conflictHandling=Normalize/' "$EVGRID_INI" >"$T/normalize.ini"
grep -qx "conflictHandling=Normalize" "$T/normalize.ini" || fail "no conflictHandling line in $EVGRID_INI"
run 0 "$EVGRID_SIMULATE" --scene people --laps 1 "$T/people"
run 0 "$EVGRID_SIMULATE" --scene static --laps 1 "$T/static"
# The simulator's files appear together once complete: a run stopped
# halfway leaves an earlier run's files as they were, and nothing else.
mkdir -p "$T/sim" && cp "$T"/static.* "$T/sim/"
interrupt INT "$T/sim" "$EVGRID_SIMULATE" --scene people --laps 20 "$T/sim/static"
contains "$ERR" "interrupted by signal 2; no file was written"
run 1 "$EVGRID_SIMULATE" --scene people "$T/sim/"
contains "$ERR" "OUTPUT_PREFIX needs a file name (DIR/NAME), not a folder"
run 0 "$EVGRID_SIMULATE" --scene street --duration 0.3 "$T/sim/street"
[ "$(ls "$T"/sim | tr '\n' ' ')" = "static.gt.txt static.motion.gz static.rawlog static.slam.txt street.footprint.gz street.gt.txt street.gt3d.txt street.motion.gz street.rawlog street.slam.txt " ] ||
  fail "evgrid-simulate wrote $(ls -A "$T/sim")"

# value KEY FILE: the value of a `key value` line; fails if the key is absent.
value() {
  awk -v k="$1" '$1 == k { sub(/^[^ ]+ /, ""); print; found = 1 } END { exit !found }' "$2" ||
    fail "$2 has no key $1"
}

# check CONDITION WHAT VALUES...: an awk condition on the values $1, $2...
check() {
  local condition=$1 what=$2
  shift 2
  echo "$*" | awk "{ exit !($condition) }" || fail "$what: $*"
}

# ratio_of PART WHOLE: the ratio as the report writes it.
ratio_of() {
  if [ "$2" -eq 0 ]; then echo n/a; else awk -v p="$1" -v w="$2" 'BEGIN { printf "%.4f", p / w }'; fi
}

# check_worst_cells FILE: the worst scan's flagged static cells are "none",
# on a scan that flagged none, or "x,y" centres inside the truth grid.
check_worst_cells() {
  local f=$1 cells grid
  cells=$(value static_worst_cells "$f")
  grid=$(value truth_grid "$f")
  if [ "$cells" = none ]; then
    [ "$(value static_worst_pct "$f")" = 0.00 ] || fail "$f: no cell listed for the worst scan"
    return
  fi
  echo "$grid $cells" | awk '{ x0 = $1; y0 = $2; r = $3; x1 = x0 + r * $4; y1 = y0 + r * $5
    if (NF < 6) exit 1
    for (i = 6; i <= NF; ++i) { n = split($i, c, ","); if (n != 2 || c[1] < x0 || c[1] > x1 || c[2] < y0 || c[2] > y1) exit 1 } }' ||
    fail "$f: worst cells $cells not centres in the truth grid $grid"
}

# check_report FILE STDOUT: every key is there, the numbers agree, and stdout
# shows the very numbers of FILE.
check_report() {
  local f=$1 s=$2 key kind t r p tp m pr rc f1
  for key in input poses config truth truth_scene truth_scans truth_grid motion_window_s \
    tolerance_cells truth_times traced_at motion_frame scans_total scans_without_pose scans_refused scans_scored \
    observed_hit_cells observed_crossed_cells static_cells static_observed static_flagged \
    static_flagged_pct static_scans static_mean_pct static_worst_pct static_worst_scan \
    static_worst_time_s static_worst_cells; do
    value "$key" "$f" >/dev/null
  done
  [ "$(value scans_total "$f")" -eq $(($(value scans_without_pose "$f") + \
    $(value scans_refused "$f") + $(value scans_scored "$f"))) ] || fail "$f: the scans do not add up"
  [ "$(value scans_total "$f")" -eq "$(value truth_scans "$f")" ] || fail "$f: not one truth record a scan"
  for kind in appeared disappeared; do
    t=$(value "${kind}_truth" "$f")
    r=$(value "${kind}_recalled" "$f")
    p=$(value "${kind}_predicted" "$f")
    tp=$(value "${kind}_true_positives" "$f")
    m=$(value "${kind}_map_cells" "$f")
    pr=$(value "${kind}_precision" "$f")
    rc=$(value "${kind}_recall" "$f")
    f1=$(value "${kind}_f1" "$f")
    [ "$r" -le "$t" ] && [ "$tp" -le "$p" ] && [ "$p" -le "$m" ] ||
      fail "$f: $kind counts out of order (truth $t recalled $r predicted $p tp $tp map $m)"
    [ "$pr" = "$(ratio_of "$tp" "$p")" ] || fail "$f: ${kind}_precision $pr is not $tp / $p"
    [ "$rc" = "$(ratio_of "$r" "$t")" ] || fail "$f: ${kind}_recall $rc is not $r / $t"
    if [ "$pr" = n/a ] || [ "$rc" = n/a ]; then
      [ "$f1" = n/a ] || fail "$f: ${kind}_f1 $f1 of an undefined ratio"
    else
      check '$1 >= 0 && $1 <= 1 && $2 >= 0 && $2 <= 1 && $3 >= 0 && $3 <= 1' "$f: $kind ratios outside [0, 1]" "$pr" "$rc" "$f1"
      # F1 from the rounded P and R, within their rounding.
      check '($1 + $2 == 0) ? $3 == 0 : ($3 - 2 * $1 * $2 / ($1 + $2))^2 < 9e-8' "$f: ${kind}_f1 is not 2PR/(P+R)" "$pr" "$rc" "$f1"
    fi
  done
  # The table on stdout: the label, then appeared, then disappeared.
  for row in "truth cells:truth" "recalled:recalled" "recall:recall" \
    "predicted (observed):predicted" "true positives:true_positives" "precision:precision" \
    "F1:f1" "map's cells (all):map_cells"; do
    local label=${row%%:*} key=${row#*:}
    [ "$(grep -F -- "  $label  " "$s" | head -n 1 | awk '{ print $(NF - 1), $NF }')" = \
      "$(value "appeared_$key" "$f") $(value "disappeared_$key" "$f")" ] ||
      fail "$s does not show ${key} as $f does"
  done
  [ "$(value static_flagged "$f")" -le "$(value static_observed "$f")" ] || fail "$f: more static cells flagged than observed"
  [ "$(value static_flagged_pct "$f")" = "$(awk -v a="$(value static_flagged "$f")" -v b="$(value static_observed "$f")" \
    'BEGIN { if (b == 0) print "n/a"; else printf "%.2f", 100 * a / b }')" ] || fail "$f: static_flagged_pct"
  if [ "$(value static_scans "$f")" -gt 0 ]; then
    check '$2 >= $1 && $2 <= 100 && $3 < $4' "$f: the worst static scan" \
      "$(value static_mean_pct "$f")" "$(value static_worst_pct "$f")" "$(value static_worst_scan "$f")" "$(value scans_total "$f")"
    check_worst_cells "$f"
  else
    [ "$(value static_worst_cells "$f")" = n/a ] || fail "$f: worst cells without a scan"
  fi
  contains "$s" "motion window: $(value motion_window_s "$f") s (the map's motionWindow); tolerance: $(value tolerance_cells "$f") cell"
  contains "$s" "truth times: $(value truth_times "$f") (each event from "
  contains "$s" "observed cells, summed over the scans: $(value observed_hit_cells "$f") hit (a beam's end), $(value observed_crossed_cells "$f") crossed"
  contains "$s" "  observed, summed over the scans: $(value static_observed "$f") cells, $(value static_flagged "$f") flagged"
  contains "$s" "  overall share %: $(value static_flagged_pct "$f")"
  contains "$s" "  mean share per scan %: $(value static_mean_pct "$f") over $(value static_scans "$f") scans"
  contains "$s" "  worst scan %: $(value static_worst_pct "$f") at scan $(value static_worst_scan "$f") ($(value static_worst_time_s "$f") s), flagged cells (x,y m): $(value static_worst_cells "$f")"
}

# score NAME PREFIX [OPTIONS...]: a run with the Normalize map, its report
# checked and its F1 scores printed for the log.
score() {
  local name=$1 prefix=$2
  shift 2
  run 0 "$EVGRID" score-motion -c "$T/normalize.ini" -i "$prefix.rawlog" -p "$prefix.slam.txt" \
    --truth "$prefix.motion.gz" --output "$T/$name.txt" "$@"
  cp "$OUT" "$T/$name.stdout"
  check_report "$T/$name.txt" "$T/$name.stdout"
  echo "$name: F1 appeared $(value appeared_f1 "$T/$name.txt"), disappeared $(value disappeared_f1 "$T/$name.txt");" \
    "static flagged $(value static_flagged_pct "$T/$name.txt")% (worst scan $(value static_worst_pct "$T/$name.txt")%)"
}

# 1. The room, one lap of people, the static scene.
score room "$room"
[ "$(value scans_scored "$T/room.txt") $(value truth_scene "$T/room.txt") $(value tolerance_cells "$T/room.txt")" = \
  "800 room_door_box 1" ] || fail "room: not 800 scans of room_door_box scored with tolerance 1"
[ "$(value motion_window_s "$T/room.txt")" = 2 ] || fail "room: the map's motionWindow is not the default 2 s"
score people "$T/people"
[ "$(value scans_scored "$T/people.txt")" -eq 400 ] || fail "people: not 400 scans scored"
for kind in appeared disappeared; do
  [ "$(value "${kind}_truth" "$T/people.txt")" -gt 0 ] || fail "people: no $kind truth among the observed cells"
done
score static "$T/static"
for key in appeared_truth:0 disappeared_truth:0 appeared_recalled:0 appeared_recall:n/a \
  disappeared_recall:n/a appeared_f1:n/a disappeared_f1:n/a; do
  [ "$(value "${key%%:*}" "$T/static.txt")" = "${key#*:}" ] || fail "static: ${key%%:*} is not ${key#*:}"
done

# Without a clearance for the pose's error, the static scene's walls are
# flagged, and the report says where.
sed 's/^motionClearance=.*/motionClearance=0/' "$T/normalize.ini" >"$T/no-clearance.ini"
grep -qx "motionClearance=0" "$T/no-clearance.ini" || fail "no motionClearance line in $EVGRID_INI"
run 0 "$EVGRID" score-motion -c "$T/no-clearance.ini" -i "$T/static.rawlog" -p "$T/static.slam.txt" \
  --truth "$T/static.motion.gz" --output "$T/static-no-clearance.txt"
cp "$OUT" "$T/static-no-clearance.stdout"
check_report "$T/static-no-clearance.txt" "$T/static-no-clearance.stdout"
[ "$(value static_worst_cells "$T/static-no-clearance.txt")" != none ] ||
  fail "static without a clearance: no wall cell flagged"

# 2. The datings of the truth: observed by default, physical on demand. The
#    static scene has no event under either; on people they give other truth
#    and the same predictions.
[ "$(value truth_times "$T/people.txt")" = observed ] || fail "people: the default dating is not observed"
score people-observed "$T/people" --truth-times observed
cmp -s "$T/people.txt" "$T/people-observed.txt" || fail "--truth-times observed is not the default"
score people-physical "$T/people" --truth-times physical
[ "$(value truth_times "$T/people-physical.txt")" = physical ] || fail "people: --truth-times physical not reported"
for kind in appeared disappeared; do
  [ "$(value "${kind}_truth" "$T/people-physical.txt")" -gt 0 ] || fail "people, physical: no $kind truth"
  for key in predicted map_cells; do
    [ "$(value "${kind}_$key" "$T/people.txt")" = "$(value "${kind}_$key" "$T/people-physical.txt")" ] ||
      fail "the dating changed ${kind}_$key"
  done
done
[ "$(value appeared_truth "$T/people.txt") $(value disappeared_truth "$T/people.txt")" != \
  "$(value appeared_truth "$T/people-physical.txt") $(value disappeared_truth "$T/people-physical.txt")" ] ||
  fail "people: the observed and physical truths have the same counts"
score static-physical "$T/static" --truth-times physical
for key in appeared_truth:0 disappeared_truth:0; do
  [ "$(value "${key%%:*}" "$T/static-physical.txt")" = "${key#*:}" ] || fail "static, physical: ${key%%:*} is not ${key#*:}"
done

# 3. More tolerance matches at least as much, and counts the same cells.
score people-t0 "$T/people" --tolerance 0
score people-t3 "$T/people" --tolerance 3
for kind in appeared disappeared; do
  for key in truth predicted map_cells; do
    [ "$(value "${kind}_$key" "$T/people-t0.txt")" = "$(value "${kind}_$key" "$T/people-t3.txt")" ] ||
      fail "the tolerance changed ${kind}_$key"
  done
  for key in true_positives recalled; do
    [ "$(value "${kind}_$key" "$T/people-t0.txt")" -le "$(value "${kind}_$key" "$T/people.txt")" ] &&
      [ "$(value "${kind}_$key" "$T/people.txt")" -le "$(value "${kind}_$key" "$T/people-t3.txt")" ] ||
      fail "more tolerance matched fewer ${kind}_$key"
  done
done

# 3b. The observed cells traced at the true poses. Traced at the poses the
#     map is built at, they say the same as tracing at the map's poses; a file
#     without the input's times is an error.
[ "$(value traced_at "$T/room.txt")" = "the map's poses" ] || fail "room: not traced at the map's poses by default"
run 0 "$EVGRID" score-motion -c "$T/normalize.ini" -i "$room.rawlog" -p "$room.gt.txt" \
  --truth "$room.motion.gz" --output "$T/room-gt.txt"
run 0 "$EVGRID" score-motion -c "$T/normalize.ini" -i "$room.rawlog" -p "$room.gt.txt" \
  --truth "$room.motion.gz" --truth-poses "$room.gt.txt" --output "$T/room-gt-traced.txt"
[ "$(value traced_at "$T/room-gt-traced.txt")" = "true poses, $room.gt.txt" ] || fail "--truth-poses not reported"
diff <(grep -v '^traced_at ' "$T/room-gt.txt") <(grep -v '^traced_at ' "$T/room-gt-traced.txt") >/dev/null ||
  fail "tracing at the map's own poses through --truth-poses changed the scores"
score room-true "$room" --truth-poses "$room.gt.txt"
[ "$(value appeared_truth "$T/room-true.txt")" != "$(value appeared_truth "$T/room.txt")" ] ||
  fail "tracing at the true poses did not change the truth of the slam-posed run"

# 3c. The motion read where each scan's pose estimate puts the truth's cells:
#     at the true poses that is the cells themselves; at the SLAM-like poses
#     the truth and the walls' share stay as they were, the predictions move.
[ "$(value motion_frame "$T/room.txt")" = world ] || fail "room: motion not read in the world frame by default"
run 0 "$EVGRID" score-motion -c "$T/normalize.ini" -i "$room.rawlog" -p "$room.gt.txt" \
  --truth "$room.motion.gz" --truth-poses "$room.gt.txt" --motion-frame scan --output "$T/room-gt-scan.txt"
diff <(grep -v '^motion_frame ' "$T/room-gt-traced.txt") <(grep -v '^motion_frame ' "$T/room-gt-scan.txt") >/dev/null ||
  fail "reading the motion in the frame of exact poses changed the scores"
score room-scan "$room" --truth-poses "$room.gt.txt" --motion-frame scan
contains "$T/room-scan.stdout" "motion read at: scan (each truth cell where the scan's pose estimate puts it"
for key in appeared_truth disappeared_truth static_observed static_flagged static_worst_pct; do
  [ "$(value $key "$T/room-scan.txt")" = "$(value $key "$T/room-true.txt")" ] ||
    fail "the scan frame changed $key"
done
[ "$(value appeared_predicted "$T/room-scan.txt") $(value appeared_true_positives "$T/room-scan.txt")" != \
  "$(value appeared_predicted "$T/room-true.txt") $(value appeared_true_positives "$T/room-true.txt")" ] ||
  fail "the scan frame read the same predictions as the world frame at SLAM-like poses"
run 2 "$EVGRID" score-motion -i "$room.rawlog" --truth "$room.motion.gz" --motion-frame scan --output "$T/x.txt"
contains "$ERR" "--motion-frame scan needs the true poses: --truth-poses PREFIX.gt.txt"
run 2 "$EVGRID" score-motion -i "$room.rawlog" --truth "$room.motion.gz" --motion-frame robot --output "$T/x.txt"
contains "$ERR" "--motion-frame must be world or scan, got 'robot'"

# 3d. The default tolerance is one cell of the map: two of the truth's 0.05 m
#     cells for a map of 0.10 m; --tolerance still sets it.
sed 's/^resolution=.*/resolution=0.10/' "$T/normalize.ini" >"$T/coarse.ini"
grep -qx "resolution=0.10" "$T/coarse.ini" || fail "no resolution line in $EVGRID_INI"
run 0 "$EVGRID" score-motion -c "$T/coarse.ini" -i "$room.rawlog" -p "$room.slam.txt" \
  --truth "$room.motion.gz" --output "$T/coarse.txt"
[ "$(value tolerance_cells "$T/coarse.txt")" = 2 ] || fail "a 0.10 m map: tolerance not two truth cells"
contains "$OUT" "tolerance: 2 cells (Chebyshev), one map cell"
run 0 "$EVGRID" score-motion -c "$T/coarse.ini" -i "$room.rawlog" -p "$room.slam.txt" \
  --truth "$room.motion.gz" --tolerance 1 --output "$T/coarse-t1.txt"
[ "$(value tolerance_cells "$T/coarse-t1.txt")" = 1 ] || fail "--tolerance 1 not kept for a 0.10 m map"
[ "$(value appeared_recalled "$T/coarse-t1.txt")" -le "$(value appeared_recalled "$T/coarse.txt")" ] ||
  fail "a 0.10 m map: one truth cell of tolerance recalled more than two"

awk 'NR <= 100' "$room.gt.txt" >"$T/short.gt.txt"
run 1 "$EVGRID" score-motion -c "$T/normalize.ini" -i "$room.rawlog" -p "$room.slam.txt" \
  --truth "$room.motion.gz" --truth-poses "$T/short.gt.txt" --output "$T/x.txt"
contains "$ERR" "evgrid score-motion: error: $T/short.gt.txt: no pose at the time of 2-D scan 99"
[ ! -e "$T/x.txt" ] || fail "a failed run wrote its output"

# The map in another frame than the truth (the odometry, without -p): a
# warning, not scores that read as a layer that flags wrong. Poses far
# beyond the cell budget: the map saw nothing, an error as in build.
run 0 "$EVGRID" score-motion -q -c "$T/normalize.ini" -i "$room.rawlog" --truth "$room.motion.gz"
contains "$ERR" "warning: no truth cell lay where the scans looked"
awk '/^%/ { print; next } { printf "%s %.6f %.6f %s\n", $1, $2 + 50000, $3 + 50000, $4 }' "$room.gt.txt" >"$T/far.gt.txt"
run 1 "$EVGRID" score-motion -q -c "$T/normalize.ini" -i "$room.rawlog" -p "$T/far.gt.txt" \
  --truth "$room.motion.gz" --output "$T/far.txt"
contains "$ERR" ": no cell of the map was seen: all "
[ ! -e "$T/far.txt" ] || fail "a failed run wrote its output"
run 0 "$EVGRID" score-motion -q -c "$T/normalize.ini" -i "$room.rawlog" -p "$room.slam.txt" --truth "$room.motion.gz"
lacks "$ERR" "warning"

# 4. Deterministic, and quiet with -q.
run 0 "$EVGRID" score-motion -q -c "$T/normalize.ini" -i "$room.rawlog" -p "$room.slam.txt" \
  --truth "$room.motion.gz" --output "$T/again.txt"
[ ! -s "$OUT" ] || fail "--quiet printed the report"
cmp -s "$T/room.txt" "$T/again.txt" || fail "a second run wrote other numbers"

# 5. A map that keeps conflict has no motion layer: it flags nothing.
sed 's/^conflictHandling=.*/conflictHandling=Keep/' "$EVGRID_INI" >"$T/keep.ini"
run 0 "$EVGRID" score-motion -c "$T/keep.ini" -i "$room.rawlog" -p "$room.slam.txt" \
  --truth "$room.motion.gz" --output "$T/keep.txt"
for key in appeared_predicted:0 appeared_map_cells:0 disappeared_predicted:0 \
  disappeared_map_cells:0 static_flagged:0 appeared_precision:n/a appeared_recall:0.0000; do
  [ "$(value "${key%%:*}" "$T/keep.txt")" = "${key#*:}" ] || fail "Keep: ${key%%:*} is not ${key#*:}"
done
[ "$(value appeared_truth "$T/keep.txt")" = "$(value appeared_truth "$T/room.txt")" ] ||
  fail "the truth depends on the map's conflict handling"

# 6. A truth that is not the input's, or is damaged: exit 1 naming the file,
#    and an earlier --output stays as it was.
mkdir "$T/kept"
cp "$T/room.txt" "$T/kept/report.txt"
before=$(fingerprint "$T/kept")
fails_with() {
  local truth=$1 message=$2
  run 1 "$EVGRID" score-motion -c "$T/normalize.ini" -i "$room.rawlog" --truth "$truth" --output "$T/kept/report.txt"
  contains "$ERR" "evgrid score-motion: error: $truth: $message"
  [ "$(fingerprint "$T/kept")" = "$before" ] || fail "a failed run changed $T/kept"
}
fails_with "$T/people.motion.gz" "holds 400 scans, but $room.rawlog: entry 801 is 2-D scan 400: not the truth of this input"
gzip -dc "$room.motion.gz" | sed 's/^start 1700000000.050$/start 1700000000.150/' | gzip >"$T/shifted.motion.gz"
fails_with "$T/shifted.motion.gz" "scan 0 is at 1700000000.150 s but $room.rawlog: entry 1 (2-D scan 0) at 1700000000.050 s"
run 1 "$EVGRID" score-motion -i "$T/people.rawlog" --truth "$room.motion.gz"
contains "$ERR" "evgrid score-motion: error: $room.motion.gz: holds 800 scans, but $T/people.rawlog has 400 2-D scans"
head -c 6000 "$room.motion.gz" >"$T/cut.motion.gz"
fails_with "$T/cut.motion.gz" "the compressed data stops early (truncated file?)"
gzip -dc "$room.motion.gz" | awk 'NR <= 1000' | gzip >"$T/short.motion.gz"
fails_with "$T/short.motion.gz" "line 1000: the file ends after 331 of its 800 scans (truncated?)"
gzip -dc "$room.motion.gz" | sed '501s/^occupied [0-9]*/occupied 5/' | gzip >"$T/miscounted.motion.gz"
fails_with "$T/miscounted.motion.gz" "line 501: more cells than the line's count"
fails_with "$room.rawlog" "line 1: not an evgrid-simulate motion file of version 1"
# Grids that would take gigabytes or minutes to score, and a bad number.
for grid in "-5.50 -4.50 0.05 100000 1000:a grid of more than 2e7 cells" \
  "-5.50 -4.50 1e300 270 180:RES must be in [0.001, 10] m" "nan -4.50 0.05 270 180:X0 'nan' is not a finite number"; do
  gzip -dc "$room.motion.gz" | sed "s/^grid .*/grid ${grid%%:*}/" | gzip >"$T/grid.motion.gz"
  fails_with "$T/grid.motion.gz" "line 4: ${grid#*:}"
done
fails_with "$T/none.motion.gz" "cannot open: No such file or directory"

# 7. Usage errors: exit 2 before any work.
run 2 "$EVGRID" score-motion -i "$room.rawlog" --output "$T/x.txt"
contains "$ERR" "missing the truth: --truth PREFIX.motion.gz"
run 2 "$EVGRID" score-motion --truth "$room.motion.gz" --output "$T/x.txt"
contains "$ERR" "missing the input"
run 2 "$EVGRID" score-motion -i "$room.rawlog" --truth "$room.motion.gz" --tolerance -1 --output "$T/x.txt"
contains "$ERR" "--tolerance must be at least 0, got -1"
run 2 "$EVGRID" score-motion -i "$room.rawlog" --truth "$room.motion.gz" --tolerance one
contains "$ERR" "bad value 'one' for --tolerance"
run 2 "$EVGRID" score-motion -i "$room.rawlog" --truth "$room.motion.gz" --truth-times seen --output "$T/x.txt"
contains "$ERR" "--truth-times must be observed or physical, got 'seen'"
run 2 "$EVGRID" score-motion -i "$room.rawlog" --truth "$room.motion.gz" --output ""
contains "$ERR" "--output needs a non-empty value"
[ ! -e "$T/x.txt" ] || fail "a usage error wrote the output"
echo "evgrid_score_motion: OK"
