# evgrid export of the SENA map of build_sena: pictures, a .gridmap that MRPT
# reads back, a ROS map_server pair, and a failed export that leaves the
# earlier files alone.
source "$(dirname "$0")/lib.sh"

built="$SCRATCH/build_sena/out"
map="$built/map.evgrid"
[ -s "$map" ] || fail "no map from evgrid_build_sena in $built"
cells=$(awk '$1 == "cells:" { print $2, $4 }' "$built/summary.txt")

run 0 "$EVGRID_CHECK" odometry-path "$SENA" "$T/odometry.txt"
run 0 "$EVGRID" export "$map" --png "$T/png" --gridmap "$T/grid/sena.gridmap" --ros "$T/ros/sena" \
  --scene "$T/scene/sena.3Dscene" --path "$T/odometry.txt"
for f in png/map.png png/evidential.png png/betp.png png/conflict.png png/motion.png grid/sena.gridmap \
  ros/sena.pgm ros/sena.yaml scene/sena.3Dscene; do
  [ -s "$T/$f" ] || fail "missing or empty: $T/$f"
  contains "$OUT" "wrote $T/$f"
done
[ -z "$(find "$T" -name '.*.tmp-*')" ] || fail "temporary files left in $T"

# The pictures are those of the build; --bare leaves out the legend.
for picture in map evidential betp conflict motion; do
  cmp -s "$T/png/$picture.png" "$built/$picture.png" || fail "$picture.png differs from the build's"
done
run 0 "$EVGRID" export "$map" --png "$T/bare" --bare
run 0 "$EVGRID_CHECK" image "$T/bare/map.png"
[ "$(cat "$OUT")" = "$cells" ] || fail "bare map.png is $(cat "$OUT") pixels, the map $cells cells"
run 2 "$EVGRID" export "$map" --gridmap "$T/x.gridmap" --bare
contains "$ERR" "--bare needs --png"
run 2 "$EVGRID" export "$map" --gridmap "$T/x.gridmap" --path "$T/odometry.txt"
contains "$ERR" "--path needs --scene"

# The scene, read as SceneViewer3D reads it: the map's planes and the path,
# one line between each two of SENA's scans.
run 0 "$EVGRID_CHECK" scene "$T/scene/sena.3Dscene"
for name in evidentialGrid "  evidentialGrid.free" "  evidentialGrid.occupied" "path ($(( $(grep -vc "^#" "$T/odometry.txt") - 1 )) lines)"; do
  grep -qxF "$name" "$OUT" || fail "the scene has no '$name': $(cat "$OUT")"
done
grep -q "unknown" "$OUT" && fail "unknown cells drawn in the scene: $(cat "$OUT")"

# The .gridmap, read as pf-localization reads its map_file: same resolution,
# the same cells (give or take the one MRPT adds when it snaps the bounds).
run 0 "$EVGRID_CHECK" gridmap "$T/grid/sena.gridmap"
read -r gx gy gres <"$OUT"
read -r mx my <<<"$cells"
[ "$gres" = "0.05" ] || fail "gridmap resolution $gres"
[ $((gx - mx)) -ge 0 ] && [ $((gx - mx)) -le 1 ] && [ $((gy - my)) -ge 0 ] && [ $((gy - my)) -le 1 ] ||
  fail "gridmap of $gx x $gy cells for a map of $mx x $my"

# ROS map_server: binary PGM of the map's size, and its YAML.
[ "$(head -c 3 "$T/ros/sena.pgm")" = "P5" ] || fail "sena.pgm is not a binary PGM"
[ "$(sed -n 3p "$T/ros/sena.pgm")" = "$cells" ] || fail "sena.pgm is not $cells pixels"
contains "$T/ros/sena.yaml" "image: sena.pgm"
contains "$T/ros/sena.yaml" "resolution: 0.05"
contains "$T/ros/sena.yaml" "origin: ["

# -q lists nothing.
run 0 "$EVGRID" export -q "$map" --gridmap "$T/quiet.gridmap"
[ ! -s "$OUT" ] || fail "-q printed something"

# A destination that cannot be written: exit 1 naming it, nothing else touched.
before=$(fingerprint "$T/png" && fingerprint "$T/grid" && fingerprint "$T/ros")
touch "$T/not-a-folder"
run 1 "$EVGRID" export "$map" --gridmap "$T/not-a-folder/x.gridmap"
contains "$ERR" "$T/not-a-folder: cannot create the folder"
rm "$T/not-a-folder"
after=$(fingerprint "$T/png" && fingerprint "$T/grid" && fingerprint "$T/ros")
[ "$before" = "$after" ] || fail "a failed export changed $T"
run 1 "$EVGRID" export "$T/missing.evgrid" --png "$T/png"
contains "$ERR" "$T/missing.evgrid: cannot open"
# The map itself, a pipe or a device as a destination: refused before any
# write (a rename would replace them: /dev/null as root); a link: the file it
# leads to is written, the link stays; a --ros prefix that names a folder.
cp "$map" "$T/copy.evgrid"
run 1 "$EVGRID" export "$T/copy.evgrid" --png "$T/png2" --gridmap "$T/copy.evgrid"
contains "$ERR" "$T/copy.evgrid: is also an input ($T/copy.evgrid): writing it would destroy it"
cmp -s "$map" "$T/copy.evgrid" || fail "the map was overwritten"
[ ! -e "$T/png2" ] || fail "an export refused wrote pictures"
mkfifo "$T/fifo.gridmap"
run 1 "$EVGRID" export "$map" --gridmap "$T/fifo.gridmap"
contains "$ERR" "$T/fifo.gridmap: is not a regular file"
[ -p "$T/fifo.gridmap" ] || fail "the pipe was replaced"
run 1 "$EVGRID" export "$map" --scene /dev/null
contains "$ERR" "/dev/null: is not a regular file"
[ -c /dev/null ] || fail "/dev/null was replaced"
: >"$T/real.gridmap"
ln -s real.gridmap "$T/link.gridmap"
run 0 "$EVGRID" export "$map" --gridmap "$T/link.gridmap" -q
[ -L "$T/link.gridmap" ] || fail "the link was replaced"
[ -s "$T/real.gridmap" ] || fail "the file behind the link was not written"
run 2 "$EVGRID" export "$map" --ros "$T/ros/"
contains "$ERR" "--ros needs a file prefix (DIR/NAME), not a folder"

# Stopped (Ctrl-C) at any moment: each file written whole or not at all,
# never a temporary file left; a stopped export says so and exits 1.
for delay in 0.1 0.2 0.3 0.5 0.8; do
  rm -rf "$T/stop"
  rc=0
  timeout --preserve-status -s INT "$delay" "$EVGRID" export "$map" --png "$T/stop/png" \
    --gridmap "$T/stop/sena.gridmap" --ros "$T/stop/sena" </dev/null >"$OUT" 2>"$ERR" || rc=$?
  [ -z "$(find "$T/stop" -name '.*.tmp-*' 2>/dev/null)" ] || fail "temporary files left after $delay s"
  case "$rc" in
    0) ;;
    1) contains "$ERR" "evgrid export: error: interrupted by signal 2; " ;;
    # Killed before it caught the signal, which it does before writing.
    130) [ -z "$(find "$T/stop" -type f 2>/dev/null)" ] || fail "killed after writing" ;;
    *) fail "stopped after $delay s: exit code $rc" ;;
  esac
  # Whatever it listed is whole: the pictures read back.
  listed=$(awk '$1 == "wrote" && /\.png$/ { print $2 }' "$OUT")
  for file in $listed; do run 0 "$EVGRID_CHECK" image "$file"; done
done
echo "evgrid_export: OK"
