# 3-D clouds: evgrid build on MRPT's one-scan VLP-16 and RGB-D datasets, read
# in place, and on the committed street sample of evgrid-simulate against its
# footprint truth; stock observations2map with the plugin on the street's
# clouds; the rotating scan, which the map cannot read.
source "$(dirname "$0")/lib.sh"

# 1. The VLP-16 scan (raw packets, decoded with their calibration): ground
#    around the car free, obstacles occupied, most of the grid unseen.
run 0 "$EVGRID" build -c "$EVGRID_INI" -i "$DATASETS/test_velodyne_VLP16.rawlog" -o "$T/vlp16"
s="$T/vlp16/summary.txt"
contains "$s" "clouds: 1 3-D clouds: 1 inserted, 0 without a pose, 0 refused by the map (1 mrpt::obs::CObservationVelodyneScan)"
contains "$s" "poses: the origin (the rawlog has no odometry)"
[ "$(count free "$s")" -gt 50000 ] || fail "VLP-16: only $(count free "$s") free cells"
[ "$(count occupied "$s")" -gt 3000 ] || fail "VLP-16: only $(count occupied "$s") occupied cells"
[ "$(count unknown "$s")" -gt "$(count free "$s")" ] || fail "VLP-16: more free than unknown cells"
[ "$(count conflict "$s")" -eq 0 ] || fail "VLP-16: conflict in a map without it"
# Without ground removal the ground itself reads occupied around the car.
sed 's/^groundRemoval=.*/groundRemoval=None/' "$EVGRID_INI" >"$T/none.ini"
grep -q '^groundRemoval=None' "$T/none.ini" || fail "evgrid.ini has no groundRemoval key"
run 0 "$EVGRID" build -c "$T/none.ini" -i "$DATASETS/test_velodyne_VLP16.rawlog" -o "$T/vlp16-none"
[ "$(count occupied "$T/vlp16-none/summary.txt")" -gt $((2 * $(count occupied "$s"))) ] ||
  fail "VLP-16: ground removal changed little"

# 2. The RGB-D frame: a frustum ahead of the camera, free then occupied.
run 0 "$EVGRID" build -c "$EVGRID_INI" -i "$DATASETS/tests_rgbd.rawlog" -o "$T/rgbd"
s="$T/rgbd/summary.txt"
contains "$s" "clouds: 1 3-D clouds: 1 inserted, 0 without a pose, 0 refused by the map (1 mrpt::obs::CObservation3DRangeScan)"
[ "$(count free "$s")" -gt 300 ] || fail "RGB-D: only $(count free "$s") free cells"
[ "$(count occupied "$s")" -gt 100 ] || fail "RGB-D: only $(count occupied "$s") occupied cells"

# 3. The committed street sample of evgrid-simulate (a VLP-16 driving 3 s down
#    a street with a hill, kerbs, parked cars, posts, a gantry over the road,
#    people and a car), at the SLAM-like poses, against its footprint truth:
#    obstacles read occupied, the ground, the kerbs and the gantry do not (the
#    ground's share holds the cells the people and the car crossed).
street="$(dirname "$EVGRID_INI")/street_vlp16"
# Each ground removal that fits a plane: evgrid.ini's (Terrain, the ground
# followed over the hill) and Plane.
for removal in Plane Terrain; do
  sed "s/^groundRemoval=.*/groundRemoval=$removal/" "$EVGRID_INI" >"$T/$removal.ini"
  grep -q "^groundRemoval=$removal\$" "$T/$removal.ini" || fail "evgrid.ini has no groundRemoval key"
done
share() { awk -v c="$1" '$1 == c { print $3 }' "$T/street.footprint.txt"; }
seen() { awk -v c="$1" '$1 == c { print $2 }' "$T/street.footprint.txt"; }
for removal in Plane Terrain; do
  run 0 "$EVGRID" build -c "$T/$removal.ini" -i "$street.rawlog" -p "$street.slam.txt" -o "$T/street-$removal"
  contains "$T/street-$removal/summary.txt" "clouds: 30 3-D clouds: 30 inserted, 0 without a pose, 0 refused by the map (30 mrpt::obs::CObservationPointCloud)"
  contains "$T/street-$removal/summary.txt" "groundRemoval = $removal "
  run 0 "$EVGRID_CHECK" footprint "$T/street-$removal/map.evgrid" "$street.footprint.gz"
  cp "$OUT" "$T/street.footprint.txt"
  echo "$removal:"
  cat "$T/street.footprint.txt"
  for cls in ground obstacle low overhang; do
    [ "$(seen $cls)" -gt 1000 ] || fail "street ($removal): only $(seen $cls) $cls cells seen"
  done
  awk -v s="$(share obstacle)" 'BEGIN { exit !(s >= 95) }' || fail "street ($removal): $(share obstacle)% of obstacle cells occupied"
  for cls in ground:5 low:3 overhang:3; do
    awk -v s="$(share ${cls%%:*})" -v m="${cls#*:}" 'BEGIN { exit !(s <= m) }' ||
      fail "street ($removal): $(share ${cls%%:*})% of ${cls%%:*} cells occupied"
  done
done

# 4. Stock observations2map with the plugin builds the same kind of map from
#    a simplemap of the street's clouds (at their true poses).
"$EVGRID_CHECK" to-simplemap "$street.rawlog" "$street.gt.txt" "$T/street.simplemap.gz" ||
  fail "cannot make the street's simplemap"
mkdir -p "$T/o2m"
run 0 env LD_PRELOAD="$EVGRID_LIB" observations2map "$(dirname "$EVGRID_INI")/observations2map.ini" \
  "$T/street.simplemap.gz" "$T/o2m/street"
base="$T/o2m/street_mrpt_evidential__CEvidentialGridMap2D_00"
contains "$base"_info.txt "insertions: 30"
run 0 "$EVGRID_CHECK" footprint "$base.evgrid" "$street.footprint.gz"
cp "$OUT" "$T/street.footprint.txt"
awk -v s="$(share obstacle)" 'BEGIN { exit !(s >= 95) }' || fail "observations2map: $(share obstacle)% of obstacle cells occupied"
awk -v s="$(share ground)" 'BEGIN { exit !(s <= 5) }' || fail "observations2map: $(share ground)% of ground cells occupied"

# 5. A rotating scan has no elevations in MRPT: counted, not inserted. One
#    made with the MRPT at hand, beside a 2-D scan that is inserted.
"$EVGRID_CHECK" rotating-scan "$T/rot.rawlog" || fail "cannot write a rotating scan"
run 0 "$EVGRID" build -c "$EVGRID_INI" -i "$T/rot.rawlog" -o "$T/rot"
contains "$T/rot/summary.txt" "other observations: 1 mrpt::obs::CObservationRotatingScan (not inserted)"
contains "$T/rot/summary.txt" "scans: 1 2-D scans: 1 inserted"
#    A file cut inside the rotating scan fails there as one of the other
#    release does (MRPT changed the class's stream in 2.11.4, under the same
#    version): the message says which class and why that may be.
gzip -dc "$T/rot.rawlog" >"$T/rot-plain.rawlog"
head -c 60 "$T/rot-plain.rawlog" >"$T/rot-cut.rawlog"
run 1 "$EVGRID" build -i "$T/rot-cut.rawlog" -o "$T/rot-cut"
contains "$ERR" "$T/rot-cut.rawlog: entry 0 at byte 0: the file ends inside this entry (truncated file?) (a CObservationRotatingScan, whose stream differs between MRPT 2.5.8 and 2.14: written by the other one?)"
#    MRPT's own dataset, with an MRPT that reads it: since 2.11.4 (the class
#    changed) MRPT cannot read the version that file holds (rawlog-edit of
#    Debian 13 stops on it, after allocating gigabytes).
rot="$DATASETS/rot_scan_velodyne.rawlog"
mrpt=$("$EVGRID_CHECK" mrpt-version) || fail "cannot tell MRPT's version"
if [ "$(printf '%s\n2.11.4\n' "$mrpt" | sort -V | head -n 1)" = 2.11.4 ]; then
  echo "MRPT $mrpt cannot read $rot: not fed to evgrid"
else
  run 1 "$EVGRID" build -c "$EVGRID_INI" -i "$rot" -o "$T/rot-dataset"
  contains "$ERR" "no scan was inserted"
  contains "$ERR" "not inserted: 1 mrpt::obs::CObservationRotatingScan"
  [ ! -e "$T/rot-dataset/summary.txt" ] || fail "a failed run wrote $T/rot-dataset/summary.txt"
fi

echo "evgrid_clouds: OK"
