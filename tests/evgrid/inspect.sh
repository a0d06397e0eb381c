# evgrid inspect on the SENA map of build_sena: geometry, counts, options,
# single cells, and the errors of a file that is not a map.
source "$(dirname "$0")/lib.sh"

built="$SCRATCH/build_sena/out"
map="$built/map.evgrid"
[ -s "$map" ] || fail "no map from evgrid_build_sena in $built"

run 0 "$EVGRID" inspect "$map"
contains "$OUT" "map: $map"
contains "$OUT" "resolution: 0.05 m"
contains "$OUT" "insertions: 225"
contains "$OUT" "latest time: 1137834284."
contains "$OUT" "(2006/01/21,"
contains "$OUT" "$(grep -F '  x: [' "$built/summary.txt" | sed 's/^  //')"
contains "$OUT" "$(grep -F '  y: [' "$built/summary.txt" | sed 's/^  //')"
contains "$OUT" "[insertOpts]"
contains "$OUT" "[likelihoodOpts]"
contains "$OUT" "[renderOpts]"
contains "$OUT" "muO = 0.9"
# The same counts as the summary of the run that built it.
[ "$(decisions "$OUT")" = "$(decisions "$built/summary.txt")" ] ||
  fail "counts differ from the summary: $(decisions "$OUT") / $(decisions "$built/summary.txt")"

# The cells of largest free and occupied mass decide so; 2 m ahead of the
# robot's start lies the corridor it first drives along.
run 0 "$EVGRID_CHECK" cells "$map"
read -r _ fx fy <<<"$(grep '^free' "$OUT")"
read -r _ ox oy <<<"$(grep '^occupied' "$OUT")"
run 0 "$EVGRID" inspect "$map" --cell "$fx,$fy" --cell "$ox,$oy" --cell 2,0
[ "$(grep -c '^cell at' "$OUT")" -eq 3 ] || fail "expected three cells"
lacks "$OUT" "cells by decision"
[ "$(grep -c 'decision Free' "$OUT")" -eq 2 ] || fail "the free cells do not read Free"
[ "$(grep -c 'decision Occupied' "$OUT")" -eq 1 ] || fail "the occupied cell does not read Occupied"
[ "$(grep -c "^  motion None$" "$OUT")" -eq 3 ] || fail "a static map read with motion: $(cat "$OUT")"
contains "$OUT" "m(empty) "
contains "$OUT" "m(Omega) "
contains "$OUT" "BetP 0.0"
run 0 "$EVGRID" inspect "$map" --cell -1e6,0
contains "$OUT" "outside the map"
contains "$OUT" "m(Omega) 1.000000"
contains "$OUT" "BetP 0.500000  decision Unknown"

# A compressed copy reads the same.
gzip -c "$map" >"$T/map.evgrid.gz"
run 0 "$EVGRID" inspect "$T/map.evgrid.gz"
[ "$(decisions "$OUT")" = "$(decisions "$built/summary.txt")" ] || fail "the .gz copy reads differently"

# The .evgrid a stock MRPT program writes (saveMetricMapRepresentationToFile):
# observations2map with the library preloaded and rawlogs/evgrid.ini.
LD_PRELOAD="$EVGRID_LIB" run 0 observations2map "$EVGRID_INI" \
  "$DATASETS/malaga-cs-fac-building.simplemap.gz" "$T/o2m"
run 0 "$EVGRID" inspect "$T/o2m_mrpt_evidential__CEvidentialGridMap2D_00.evgrid"
contains "$OUT" "insertions: 99"
contains "$OUT" "resolution: 0.05 m"

# Not a map: a rawlog, a text file, a truncated map, no file.
run 1 "$EVGRID" inspect "$SENA"
contains "$ERR" "$SENA: holds a mrpt::obs::CSensoryFrame, not an evidential grid map"
echo "not a map" >"$T/text.evgrid"
run 1 "$EVGRID" inspect "$T/text.evgrid"
contains "$ERR" "$T/text.evgrid: entry 0 at byte 0: not a rawlog, simplemap or map saved by MRPT"
head -c 100000 "$map" >"$T/truncated.evgrid"
run 1 "$EVGRID" inspect "$T/truncated.evgrid"
contains "$ERR" "$T/truncated.evgrid: entry 0 at byte 0: the file ends inside this entry"
# One byte of the cells changed: the map's own reason, not "not a map".
cp "$map" "$T/damaged.evgrid"
at=$(($(stat -c %s "$map") / 2))
byte=$(od -An -tu1 -j "$at" -N1 "$map" | tr -d ' ')
printf "\\$(printf %03o $((byte ^ 255)))" |
  dd of="$T/damaged.evgrid" bs=1 seek="$at" conv=notrunc status=none
cmp -s "$map" "$T/damaged.evgrid" && fail "the byte was not changed"
run 1 "$EVGRID" inspect "$T/damaged.evgrid"
contains "$ERR" "$T/damaged.evgrid: entry 0 at byte 0: CEvidentialGridMap2D: corrupted or invalid"
contains "$ERR" "serialized map: checksum mismatch"
run 1 "$EVGRID" inspect "$T/none.evgrid"
contains "$ERR" "$T/none.evgrid: cannot open"
# Two maps joined into one file: not read as the first alone.
cat "$map" "$map" >"$T/joined.evgrid"
run 1 "$EVGRID" inspect "$T/joined.evgrid"
contains "$ERR" "$T/joined.evgrid: holds more than the map (another object after it: files joined?)"
echo "evgrid_inspect: OK"
