# The fleet recipes of doc/recipes/fleet.md: scripts/fleet/evgrid-parallel.sh
# builds three simulated rawlogs with GNU parallel and merges them; the Slurm
# array script, run as one of its tasks would be, builds the same map; a
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

# 3. A damaged rawlog fails its job: the fleet exits non-zero, no merge.
head -c 5000 "$T/logs/run2.rawlog" >"$T/logs/cut.rawlog"
run 1 env JOBS=1 bash "$fleet/evgrid-parallel.sh" "$EVGRID_INI" "$T/bad" "$T/logs/cut.rawlog" "$T/logs/run1.rawlog"
[ ! -e "$T/bad/merged" ] || fail "a failed fleet merged"

echo "evgrid_fleet: OK"
