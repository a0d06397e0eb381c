# Failures of evgrid build: truncated, damaged or foreign input, bad config,
# an output folder that cannot be written, an interrupted run. Each exits 1
# naming the file, and leaves the outputs of an earlier run byte for byte.
source "$(dirname "$0")/lib.sh"

out="$T/out"
run 0 "$EVGRID" build -i "$SENA" -o "$out" --every 100
good=$(fingerprint "$out")

# expect_failure TEXT ARGS...: `evgrid build ARGS -o $out` exits 1, its error
# contains TEXT, and the output folder is as the good run left it.
expect_failure() {
  local text=$1
  shift
  run 1 "$EVGRID" build "$@" -o "$out"
  contains "$ERR" "evgrid build: error: $text"
  [ "$(fingerprint "$out")" = "$good" ] || fail "the failed run changed $out"
}

# Compressed rawlog cut at several lengths: in the gzip header, inside an
# entry near the start, in the middle, before the gzip trailer.
size=$(stat -c %s "$SENA")
for length in 10 20000 $((size / 2)) $((size - 4)); do
  head -c "$length" "$SENA" >"$T/cut.rawlog"
  expect_failure "$T/cut.rawlog: entry " -i "$T/cut.rawlog"
  contains "$ERR" " at byte "
  contains "$ERR" "truncated file?"
done
# Plain (uncompressed) rawlog cut inside an entry: the entry and its offset.
gzip -dc "$SENA" >"$T/plain.rawlog"
head -c 250000 "$T/plain.rawlog" >"$T/cut-plain.rawlog"
expect_failure "$T/cut-plain.rawlog: entry 224 at byte 248416: the file ends inside this entry (truncated file?)" \
  -i "$T/cut-plain.rawlog"
# Damaged bytes: in an entry's class name, and in its data (a sensor pose
# that is no longer a number).
cp "$T/plain.rawlog" "$T/damaged-name.rawlog"
printf '\377\377\377\377' | dd of="$T/damaged-name.rawlog" bs=1 seek=248420 conv=notrunc status=none
expect_failure "$T/damaged-name.rawlog: entry 224 at byte 248416: an object of a class evgrid does not know (Stored object has class 'CSe????yFrame'" \
  -i "$T/damaged-name.rawlog"
cp "$T/plain.rawlog" "$T/damaged.rawlog"
printf '\377\377\377\377\377\377\377\377' | dd of="$T/damaged.rawlog" bs=1 seek=248500 conv=notrunc status=none
expect_failure "$T/damaged.rawlog: entry 224: cannot insert the scan" -i "$T/damaged.rawlog"
# Scans that claim 2^31 - 1 and 2^28 rays (SENA's first ray count, 361,
# overwritten): MRPT allocates 13 bytes per claimed ray before it reads one,
# 28 GB and 3.5 GB here. evgrid refuses them within the memory a file of this
# size can justify, and the whole run stays far below a 512 MB budget.
count_at=$(LC_ALL=C grep -obUaP '\x69\x01\x00\x00' "$T/plain.rawlog" | head -1 | cut -d: -f1)
[ "$count_at" -lt 300 ] || fail "the first ray count is not where expected (byte $count_at)"
for claimed in '\377\377\377\177' '\000\000\000\020'; do
  cp "$T/plain.rawlog" "$T/huge-scan.rawlog"
  printf "$claimed" | dd of="$T/huge-scan.rawlog" bs=1 seek="$count_at" conv=notrunc status=none
  run 1 "$MEMORY_BUDGET" --budget-mb 512 -- "$EVGRID" build -i "$T/huge-scan.rawlog" -o "$out"
  lacks "$ERR" "memory_budget:"
  contains "$ERR" "evgrid build: error: $T/huge-scan.rawlog: entry 0 at byte 0: reading it took more memory than a file of"
  contains "$ERR" "a size in it is corrupted"
  [ "$(fingerprint "$out")" = "$good" ] || fail "the failed run changed $out"
done
# An object in a newer format of its class (as MRPT 2.14 writes simplemaps
# that 2.5.8 cannot read): the message says so, not "not a rawlog".
cp "$T/plain.rawlog" "$T/newer.rawlog"
name_length=$(( $(od -An -tu1 -N1 "$T/plain.rawlog") & 127 ))
printf '\143' | dd of="$T/newer.rawlog" bs=1 seek=$((1 + name_length)) conv=notrunc status=none
expect_failure "$T/newer.rawlog: entry 0 at byte 0: an object in a format that MRPT " -i "$T/newer.rawlog"
contains "$ERR" "unknown serialization version number: '99'): written by a newer MRPT?"
# Not a rawlog at all.
printf 'time x y phi\n0 0 0 0\n' >"$T/text.rawlog"
expect_failure "$T/text.rawlog: entry 0 at byte 0: not a rawlog, simplemap or map saved by MRPT" -i "$T/text.rawlog"
: >"$T/empty.rawlog"
expect_failure "$T/empty.rawlog: the file is empty" -i "$T/empty.rawlog"
expect_failure "$T/missing.rawlog: cannot open: No such file or directory" -i "$T/missing.rawlog"
expect_failure "$T: is a directory" -i "$T"
expect_failure "$out/map.evgrid: entry 0 is a mrpt_evidential::CEvidentialGridMap2D, which has no place in a rawlog" \
  -i "$out/map.evgrid"
# A rawlog of observations the map does not read (MRPT's landmark demo):
# the message says what it reads and counts what it found.
expect_failure "$DATASETS/kf-slam_demo.rawlog: no scan was inserted (the input holds no 2-D scan and no 3-D cloud the map reads: CObservation2DRangeScan, CObservationPointCloud, CObservationVelodyneScan, CObservation3DRangeScan; not inserted: " \
  -i "$DATASETS/kf-slam_demo.rawlog"
contains "$ERR" " mrpt::obs::CObservationBearingRange)"

# Every scan beyond the cell budget: nothing of the map seen, an error.
room=$(dirname "$EVGRID_INI")/room_door_box
awk '/^%/ { print; next } { printf "%s %.6f %.6f %s\n", $1, $2 + 50000, $3 + 50000, $4 }' \
  "$room.gt.txt" >"$T/far.txt"
expect_failure "$room.rawlog: no cell of the map was seen: all " -i "$room.rawlog" -p "$T/far.txt"

# Config files: missing, without an evidential grid, with a bad value, or a
# section that is not there.
expect_failure "$T/none.ini: cannot open the config file" -i "$SENA" -c "$T/none.ini"
printf '[MappingApplication]\noccupancyGrid_count=1\n' >"$T/no-grid.ini"
expect_failure "$T/no-grid.ini: section [MappingApplication] creates no evidential grid" -i "$SENA" -c "$T/no-grid.ini"
sed 's/^muF=0.7/muF=1.7/' "$EVGRID_INI" >"$T/bad-value.ini"
expect_failure "$T/bad-value.ini: " -i "$SENA" -c "$T/bad-value.ini"
contains "$ERR" "muF"
# A decimal comma, in the second of two maps: the message names its section
# (which MRPT's exception moved to its "Location:" line).
sed 's/^evidentialGrid_count=1/evidentialGrid_count=2/' "$EVGRID_INI" >"$T/two-maps.ini"
printf '[MappingApplication_evidentialGrid_01_insertOpts]\nmuO=0,95\n' >>"$T/two-maps.ini"
expect_failure "$T/two-maps.ini: [MappingApplication_evidentialGrid_01_insertOpts] muO = '0,95': not a finite number (the decimal mark is a point)" \
  -i "$SENA" -c "$T/two-maps.ini"
expect_failure "$EVGRID_INI: no section [Elsewhere]" -i "$SENA" -c "$EVGRID_INI" -s Elsewhere
expect_failure "$T: is a directory, not a config file" -i "$SENA" -c "$T"
# A pipe cannot be read twice (checked in a child, then read).
run 1 "$EVGRID" build -i <(cat "$SENA") -o "$out"
contains "$ERR" ": not a regular file (a pipe or a device); evgrid reads its input twice"
[ "$(fingerprint "$out")" = "$good" ] || fail "the failed run changed $out"

# An interrupted run (SIGTERM, as `timeout` sends) cleans up and changes nothing.
rc=0
"$EVGRID" build -c "$EVGRID_INI" -i "$SENA" -o "$out" --animation </dev/null >"$OUT" 2>"$ERR" &
pid=$!
for _ in $(seq 100); do
  [ -n "$(find "$out" -maxdepth 1 -name '.evgrid-build-*')" ] && break
  sleep 0.05
done
kill -TERM "$pid"
wait "$pid" || rc=$?
[ "$rc" -eq 1 ] || fail "interrupted run exited $rc"
contains "$ERR" "interrupted by signal 15; the output folder is unchanged"
[ "$(fingerprint "$out")" = "$good" ] || fail "the interrupted run changed $out"

# Output folders that cannot be written are reported before the input is
# even opened (the input here does not exist).
touch "$T/a-file"
run 1 "$EVGRID" build -i "$T/missing.rawlog" -o "$T/a-file"
contains "$ERR" "evgrid build: error: $T/a-file: the output folder cannot be written: it exists and is not a folder"
run 1 "$EVGRID" build -i "$T/missing.rawlog" -o "$T/a-file/sub"
contains "$ERR" "evgrid build: error: $T/a-file/sub: the output folder cannot be written"
# A folder without write permission. Root writes anywhere, so as root (CI)
# evgrid runs as nobody, when nobody can reach it from here.
mkdir "$T/read-only" && chmod 555 "$T/read-only"
as_user=()
[ "$(id -u)" -ne 0 ] || as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
if "${as_user[@]}" "$EVGRID" --help >/dev/null 2>&1; then
  run 1 "${as_user[@]}" "$EVGRID" build -i "$T/missing.rawlog" -o "$T/read-only"
  contains "$ERR" "$T/read-only: the output folder cannot be written: Permission denied"
else
  echo "note: nobody cannot run $EVGRID from here; the read-only folder is not tried"
fi
chmod 755 "$T/read-only"
echo "evgrid_bad_input: OK"
