# evgrid build with 3-D clouds: MRPT's one-scan VLP-16 and RGB-D datasets,
# read in place; the rotating scan, which the map cannot read; a stock MRPT
# program with the plugin on a point-cloud rawlog.
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

# 3. A rotating scan has no elevations in MRPT 2.5.8: counted, not inserted.
run 1 "$EVGRID" build -c "$EVGRID_INI" -i "$DATASETS/rot_scan_velodyne.rawlog" -o "$T/rot"
contains "$ERR" "no scan was inserted"
[ ! -e "$T/rot/summary.txt" ] || fail "a failed run wrote $T/rot/summary.txt"

echo "evgrid_clouds: OK"
