# evgrid build --every and --animation: frame pictures, a readable MJPG video
# of a fixed size, and frames/ replaced as a whole by a later run.
source "$(dirname "$0")/lib.sh"

out="$T/out"
run 0 "$EVGRID" build -i "$SENA" -o "$out" --every 50 --animation --animation-every 10 \
  --animation-size 320x240 --animation-fps 10
frames=$(cd "$out/frames" && ls)
[ "$frames" = "$(printf 'frame_%06d_map.png\n' 50 100 150 200)" ] ||
  fail "frames: $frames"
contains "$out/summary.txt" "frames: 4 pictures in frames/, one every 50 scans"
# 22 frames every 10 scans of 224, and the final map.
contains "$out/summary.txt" "animation: growth.avi, 23 frames of 320 x 240 at 10 frames/s"

# Frames grow with the map: each covers at least the cells of the one before,
# and the final picture at least those of the last frame.
area() {
  run 0 "$EVGRID_CHECK" image "$1"
  read -r w h <"$OUT" || fail "$1 unreadable"
  echo $((w * h))
}
previous=0
for picture in "$out"/frames/frame_{000050,000100,000150,000200}_map.png "$out/map.png"; do
  current=$(area "$picture")
  [ "$current" -ge "$previous" ] || fail "$picture covers $current cells, less than $previous before it"
  previous=$current
done

# The video: MJPG in AVI, read back by OpenCV, every frame of the fixed size.
[ "$(head -c 4 "$out/growth.avi")" = "RIFF" ] || fail "growth.avi is not an AVI file"
run 0 "$EVGRID_CHECK" video "$out/growth.avi"
[ "$(cat "$OUT")" = "23 320 240" ] || fail "growth.avi: $(cat "$OUT") (frames width height)"
# A frame every more scans than the input holds: the final map alone.
run 0 "$EVGRID" build -i "$SENA" -o "$T/one-frame" --animation --animation-every 1000 \
  --animation-size 64x64
contains "$T/one-frame/summary.txt" "animation: growth.avi, 1 frames of 64 x 64"
run 0 "$EVGRID_CHECK" video "$T/one-frame/growth.avi"
[ "$(cat "$OUT")" = "1 64 64" ] || fail "one-frame growth.avi: $(cat "$OUT")"

# A new run with --every replaces frames/: no frame of the old run remains.
run 0 "$EVGRID" build -i "$SENA" -o "$out" --every 100
frames=$(cd "$out/frames" && ls)
[ "$frames" = "$(printf 'frame_%06d_map.png\n' 100 200)" ] ||
  fail "frames after the rerun: $frames"
[ -z "$(find "$out" -name '.evgrid-build-*')" ] || fail "temporary folder left in $out"
# --every beyond the scans: no frame falls due, and frames/ is replaced by an
# empty one (not left with the earlier run's), which the summary says.
run 0 "$EVGRID" build -i "$SENA" -o "$out" --every 100000
[ -d "$out/frames" ] && [ -z "$(ls -A "$out/frames")" ] || fail "frames/ kept the earlier run's: $(ls "$out/frames")"
contains "$out/summary.txt" "frames: 0 pictures in frames/, one every 100000 scans (fewer scans were inserted: frames/ is empty)"
# A grid at its cell budget: the scans it could hold only in part are counted,
# on the console and in the summary (and a run within the budget says nothing).
sed 's/^maxCells=.*/maxCells=500000/' "$EVGRID_INI" >"$T/budget.ini"
run 0 "$EVGRID" build -i "$SENA" -c "$T/budget.ini" -o "$T/budget"
contains "$OUT" "scans reached beyond the cell budget (creationOpts maxCells)"
contains "$T/budget/summary.txt" "  partly inserted: "
lacks "$out/summary.txt" "partly inserted"
echo "evgrid_growth: OK"
