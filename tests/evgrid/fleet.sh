# The fleet recipes of doc/recipes/fleet.md: scripts/fleet/evgrid-parallel.sh
# builds three simulated rawlogs with GNU parallel and merges them; the Slurm
# array script, run as one of its tasks would be, builds the same map; odd
# paths are used as given and rawlogs that would share a folder refused; a
# failed build stops the fleet before the merge.
source "$(dirname "$0")/lib.sh"
fleet="$(dirname "$EVGRID_INI")/../scripts/fleet"
command -v parallel >/dev/null || fail "GNU parallel is not installed (Debian package parallel)"
export EVGRID

mkdir -p "$T/logs"
for seed in 1 2 3; do
  "$EVGRID_SIMULATE" --scene room_before --seed "$seed" --laps 1 "$T/logs/run$seed" >/dev/null ||
    fail "evgrid-simulate failed"
done

# 1. GNU parallel, two jobs at once: three maps, their poses found beside each
#    rawlog, and the merge of the three.
run 0 env JOBS=2 bash "$fleet/evgrid-parallel.sh" "$EVGRID_INI" "$T/out" "$T"/logs/run*.rawlog
for n in 1 2 3; do
  [ -s "$T/out/run$n/map.evgrid" ] || fail "no map for run$n"
  contains "$T/out/run$n/summary.txt" "poses: $T/logs/run$n.slam.txt"
done
[ "$(awk 'NR > 1 && $7 == 0' "$T/out/joblog.txt" | wc -l)" -eq 3 ] || fail "the job log has not three successful jobs"
contains "$T/out/merged/summary.txt" "inputs:"
for n in 1 2 3; do contains "$T/out/merged/summary.txt" "$T/out/run$n/map.evgrid"; done
[ "$(count occupied "$T/out/merged/summary.txt")" -gt 1000 ] || fail "the merged map has few occupied cells"

# 2. The Slurm array script as task 1 (the second line of the list) builds
#    the same map.
printf '%s\n' "$T"/logs/run*.rawlog >"$T/list.txt"
run 0 env SLURM_ARRAY_TASK_ID=1 bash "$fleet/evgrid-slurm-array.sh" "$EVGRID_INI" "$T/list.txt" "$T/slurm"
cmp -s "$T/slurm/run2/map.evgrid" "$T/out/run2/map.evgrid" || fail "the Slurm task built another map than parallel"
run 1 env SLURM_ARRAY_TASK_ID=7 bash "$fleet/evgrid-slurm-array.sh" "$EVGRID_INI" "$T/list.txt" "$T/slurm"
contains "$ERR" "has no line 8"
run 1 bash "$fleet/evgrid-slurm-array.sh" "$EVGRID_INI" "$T/list.txt" "$T/slurm"
contains "$ERR" "not a Slurm array task"

# 3. Rawlogs in folders whose names hold a space and shell characters, an
#    output folder too: used as given (parallel joins a command's words into
#    one shell line). Two rawlogs that would build one folder are refused
#    before any build, by both scripts. One rawlog: no stale merge is left.
odd="$T/logs a \$(touch $T/ran) 'b"
mkdir -p "$odd/one" "$odd/two"
cp "$T/logs/run1.rawlog" "$odd/one/run.rawlog"
cp "$T/logs/run1.slam.txt" "$odd/one/run.slam.txt"
cp "$T/logs/run2.rawlog" "$odd/two/other.rawlog"
cp "$T/logs/run2.slam.txt" "$odd/two/other.slam.txt"
run 0 env JOBS=2 bash "$fleet/evgrid-parallel.sh" "$EVGRID_INI" "$odd/out" "$odd/one/run.rawlog" "$odd/two/other.rawlog"
[ ! -e "$T/ran" ] || fail "a path's shell characters were run"
cmp -s "$odd/out/run/map.evgrid" "$T/out/run1/map.evgrid" || fail "one/run.rawlog did not build run1's map"
cmp -s "$odd/out/other/map.evgrid" "$T/out/run2/map.evgrid" || fail "two/other.rawlog did not build run2's map"
for name in run other; do contains "$odd/out/merged/summary.txt" "$odd/out/$name/map.evgrid"; done
cp "$T/logs/run2.rawlog" "$odd/two/run.rawlog"
run 2 env JOBS=1 bash "$fleet/evgrid-parallel.sh" "$EVGRID_INI" "$T/twice" "$odd/one/run.rawlog" "$odd/two/run.rawlog"
contains "$ERR" "would both build $T/twice/run/"
[ ! -e "$T/twice/run" ] || fail "a refused fleet built"
printf '%s\n' "$odd/one/run.rawlog" "$odd/two/run.rawlog" >"$T/twice.txt"
run 1 env SLURM_ARRAY_TASK_ID=0 bash "$fleet/evgrid-slurm-array.sh" "$EVGRID_INI" "$T/twice.txt" "$T/twice"
contains "$ERR" "would both build $T/twice/run/"
run 0 env JOBS=1 bash "$fleet/evgrid-parallel.sh" "$EVGRID_INI" "$odd/out" "$odd/two/other.rawlog"
[ ! -e "$odd/out/merged" ] || fail "a fleet of one rawlog left the merge of an earlier run"

# 4. A damaged rawlog fails its job: the fleet exits non-zero, no merge.
head -c 5000 "$T/logs/run2.rawlog" >"$T/logs/cut.rawlog"
run 1 env JOBS=1 bash "$fleet/evgrid-parallel.sh" "$EVGRID_INI" "$T/bad" "$T/logs/cut.rawlog" "$T/logs/run1.rawlog"
[ ! -e "$T/bad/merged" ] || fail "a failed fleet merged"

echo "evgrid_fleet: OK"
