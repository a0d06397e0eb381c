# evgrid build on MRPT's SENA rawlog (real SICK, odometry) with
# rawlogs/evgrid.ini: the outputs, their sizes, plausible counts, timing, and
# the quiet mode. The map it leaves is read by the inspect and export tests.
source "$(dirname "$0")/lib.sh"

out="$T/out"
run 0 "$EVGRID" build -c "$EVGRID_INI" -i "$SENA" -o "$out"
for f in map.evgrid map.3Dscene map.png evidential.png betp.png conflict.png motion.png summary.txt; do
  [ -s "$out/$f" ] || fail "missing or empty: $out/$f"
done
[ -z "$(find "$out" -name '.evgrid-build-*')" ] || fail "temporary folder left in $out"

# The closing report on stdout; progress lines on stderr (not a terminal).
contains "$OUT" "evgrid build: 225 2-D scans: 225 inserted, 0 without a pose, 0 refused by the map"
contains "$OUT" "scans/s"
contains "$OUT" "time: reading "
contains "$OUT" "pictures: $out/map.png, $out/evidential.png, $out/betp.png, $out/conflict.png, $out/motion.png"
contains "$OUT" "scene: $out/map.3Dscene"
contains "$ERR" "evgrid build: 100%"
lacks "$ERR" $'\r'

summary="$out/summary.txt"
contains "$summary" "rawlog (actions/sensory frames), gzip-compressed, 449 entries"
contains "$summary" "poses: odometry"
contains "$summary" "config: $EVGRID_INI, section [MappingApplication]"
contains "$summary" "resolution: 0.05 m"
contains "$summary" "insertions: 225"
for phase in reading insertion writing; do contains "$summary" "  $phase: "; done
contains "$summary" "sensorModel = ImpreciseMultiEcho"

# A real building: much free space, walls occupied (the conflict of the
# odometry's drift goes to the motion layer, not into the cells), and no cell
# left uncounted.
read -r free occupied unknown conflict <<<"$(decisions "$summary")"
[ "$free" -gt 200000 ] || fail "only $free free cells"
[ "$occupied" -gt 5000 ] || fail "only $occupied occupied cells"
[ "$conflict" -eq 0 ] || fail "$conflict conflict cells in a map that normalizes conflict"
size=$(awk '$1 == "cells:" { print $2 * $4 }' "$summary")
[ $((free + occupied + unknown + conflict)) -eq "$size" ] || fail "counts do not add up to $size cells"

# One pixel per cell, above the legend strip.
read -r sx sy <<<"$(awk '$1 == "cells:" { print $2, $4 }' "$summary")"
for picture in map evidential betp conflict motion; do
  run 0 "$EVGRID_CHECK" image "$out/$picture.png"
  read -r w h <"$OUT"
  [ "$w" -eq "$sx" ] && [ "$h" -gt "$sy" ] && [ "$h" -lt $((sy + 100)) ] ||
    fail "$picture.png is $w x $h pixels, the map $sx x $sy cells above its legend"
done

# --quiet: nothing on either stream, same outputs.
run 0 "$EVGRID" build -q -i "$SENA" -o "$T/quiet"
[ ! -s "$OUT" ] && [ ! -s "$ERR" ] || fail "--quiet printed something"
[ -s "$T/quiet/map.evgrid" ] || fail "--quiet wrote no map"
echo "evgrid_build_sena: OK"
