# Where the poses come from: MRPT ground truth by time stamp, icp-slam's
# estimated path by step, a path file that reproduces the odometry exactly,
# interpolation and tolerance, bad pose files; and the other input formats
# (observation-only rawlog, simplemap).
source "$(dirname "$0")/lib.sh"

# 1. MRPT's ground-truth file ("time x y phi") of its simulated dataset.
sim="$DATASETS/graphslam-engine-demos/action_observations_map/simul.rawlog"
run 0 "$EVGRID" build -i "$sim" -p "$sim.GT.txt" -o "$T/gt"
contains "$T/gt/summary.txt" "1734 poses, by time stamp (interpolated, tolerance 0.1 s)"
contains "$T/gt/summary.txt" "1733 2-D scans: 1733 inserted, 0 without a pose"
contains "$T/gt/summary.txt" "the last, an action, has no sensory frame after it"

# 2. icp-slam's estimated path ("step x y phi"): run the stock program headless
#    on SENA. Its reader skips SENA's first sensory frame, which has no action
#    before it: that scan gets no step, hence no pose.
sed -e 's/^SHOW_PROGRESS_3D_REAL_TIME *=.*/SHOW_PROGRESS_3D_REAL_TIME=0/' \
  -e 's/^SAVE_3D_SCENE *=.*/SAVE_3D_SCENE=0/' -e 's/^LOG_FREQUENCY *=.*/LOG_FREQUENCY=0/' \
  -e "s#^logOutput_dir *=.*#logOutput_dir=$T/icp-slam#" \
  /usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini >"$T/icp-slam.ini"
(cd "$T" && run 0 icp-slam "$T/icp-slam.ini" "$SENA")
path="$T/icp-slam/log_estimated_path.txt"
[ "$(wc -l <"$path")" -eq 224 ] || fail "icp-slam wrote $(wc -l <"$path") poses"
run 0 "$EVGRID" build -i "$SENA" -p "$path" -o "$T/icp"
contains "$T/icp/summary.txt" "224 poses, by step number (icp-slam path)"
contains "$T/icp/summary.txt" "225 2-D scans: 224 inserted, 1 without a pose"
run 1 "$EVGRID" build -i "$SENA" -p "$path" --poses-format time -o "$T/icp-as-time"
contains "$ERR" "$SENA: no scan was inserted (225 2-D scans: 0 inserted, 225 without a pose"

# 3. The odometry written out as a time file gives the very map odometry gives.
run 0 "$EVGRID_CHECK" odometry-path "$SENA" "$T/odometry.txt"
run 0 "$EVGRID" build -i "$SENA" -o "$T/odometry"
run 0 "$EVGRID" build -i "$SENA" -p "$T/odometry.txt" -o "$T/odometry-file"
contains "$T/odometry-file/summary.txt" "225 poses, by time stamp"
[ "$(decisions "$T/odometry-file/summary.txt")" = "$(decisions "$T/odometry/summary.txt")" ] ||
  fail "the odometry path file gives another map than the odometry"

# 4. One pose in two: the others are interpolated, every scan is placed; one
#    in ten with a tight tolerance: scans far from a pose are skipped.
awk '/^#/ || (++n % 2 == 1)' "$T/odometry.txt" >"$T/half.txt"
run 0 "$EVGRID" build -i "$SENA" -p "$T/half.txt" --pose-tolerance 1 -o "$T/half"
contains "$T/half/summary.txt" "225 inserted, 0 without a pose"
awk '/^#/ || (++n % 10 == 1)' "$T/odometry.txt" >"$T/tenth.txt"
run 0 "$EVGRID" build -i "$SENA" -p "$T/tenth.txt" --pose-tolerance 0.05 -o "$T/tenth"
without=$(grep -oE '[0-9]+ without a pose' "$T/tenth/summary.txt" | cut -d' ' -f1)
[ "$without" -ge 150 ] || fail "only $without scans without a pose at 0.05 s tolerance"

# 5. Bad pose files: exit 1 with the file and line.
printf '0 0 0 0\n1 2 3\n' >"$T/short.txt"
run 1 "$EVGRID" build -i "$SENA" -p "$T/short.txt" -o "$T/bad"
contains "$ERR" "$T/short.txt:2: expected 4 numbers"
printf '10.5 0 0 0\n10.4 1 1 0\n' >"$T/backwards.txt"
run 1 "$EVGRID" build -i "$SENA" -p "$T/backwards.txt" -o "$T/bad"
contains "$ERR" "$T/backwards.txt:2: time 10.4 does not follow 10.5"
printf '1 x 0 0\n' >"$T/word.txt"
run 1 "$EVGRID" build -i "$SENA" -p "$T/word.txt" -o "$T/bad"
contains "$ERR" "$T/word.txt:1: 'x' is not a number"
run 1 "$EVGRID" build -i "$SENA" -p "$T/none.txt" -o "$T/bad"
contains "$ERR" "$T/none.txt: cannot open the pose file"

# 6. The same rawlog in the observation-only format (odometry readings
#    before the scans), gzip-compressed: the same map.
run 0 "$EVGRID_CHECK" to-obs-only "$SENA" "$T/sena-obs.rawlog.gz"
run 0 "$EVGRID" build -i "$T/sena-obs.rawlog.gz" -o "$T/obs"
contains "$T/obs/summary.txt" "rawlog (observations), gzip-compressed"
contains "$T/obs/summary.txt" "poses: odometry (latest CObservationOdometry reading)"
contains "$T/obs/summary.txt" "225 mrpt::obs::CObservationOdometry (not inserted)"
[ "$(decisions "$T/obs/summary.txt")" = "$(decisions "$T/odometry/summary.txt")" ] ||
  fail "the observation-only copy gives another map"

# 7. A simplemap (keyframes with their SLAM poses); step files do not apply.
malaga="$DATASETS/malaga-cs-fac-building.simplemap.gz"
run 0 "$EVGRID" build -i "$malaga" -o "$T/malaga"
contains "$T/malaga/summary.txt" "  simplemap, gzip-compressed, 99 keyframes"
contains "$T/malaga/summary.txt" "poses: the simplemap's"
contains "$T/malaga/summary.txt" "99 2-D scans: 99 inserted"
run 1 "$EVGRID" build -i "$malaga" -p "$path" -o "$T/bad"
contains "$ERR" "$path: holds poses by step number"
echo "evgrid_poses: OK"
