#!/usr/bin/env bash
# Stock rbpf-slam with the plugin preloaded and rawlogs/rbpf-slam.ini (the
# evidential grid is the only map, hence the only likelihood source), on the
# project's synthetic room: it runs to the end, saves its final evidential map,
# and its path follows the ground truth better than the odometry does.
# Without the plugin, rbpf-slam runs to the end with no map and exits 0.
# Usage: rbpf_slam.sh <plugin.so> <rbpf-slam> <rawlogs dir> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 4 ] || fail "usage: $0 <plugin.so> <rbpf-slam> <rawlogs dir> <scratch dir>"
plugin=$1 rbpf_slam=$2 rawlogs=$3 scratch=$4
rawlog=$rawlogs/room_door_box.rawlog truth=$rawlogs/room_door_box.gt.txt

rm -rf "$scratch"
mkdir -p "$scratch"
cp "$rawlogs/rbpf-slam.ini" "$scratch/"
(cd "$scratch" && run_stock "$scratch/rbpf-slam.log" 500 "$plugin" "$rbpf_slam" rbpf-slam.ini "$rawlog")
out=$scratch/rbpf-slam-out

info=$(only_file "$out/finalMap_mrpt_evidential__CEvidentialGridMap2D_*_info.txt")
# The 10 x 8 m room at 0.1 m: about 7,500 free and 500 occupied cells.
check_evidential_files "${info%_info.txt}" 5000 300
[ -s "$out/most_likely_path.txt" ] || fail "rbpf-slam wrote no most_likely_path.txt"

# Position errors along a path (step x y ... per line) against the ground
# truth (time x y phi per line), which starts at the first true pose where
# the path starts at the origin: "mean max steps".
path_errors() {
	awk '
		FNR == NR { if ($1 !~ /^%/) truth[n++] = $0; next }
		$1 !~ /^%/ {
			split(truth[$1], t, " ")
			if (!started) { x0 = t[2]; y0 = t[3]; c = cos(t[4]); s = sin(t[4]); started = 1 }
			dx = t[2] - x0; dy = t[3] - y0
			e = sqrt(($2 - (c * dx + s * dy)) ^ 2 + ($3 - (c * dy - s * dx)) ^ 2)
			sum += e; if (e > max) max = e; ++steps
		}
		END { printf "%.3f %.3f %d\n", sum / steps, max, steps }' "$truth" "$1"
}
read -r mean max steps <<<"$(path_errors "$out/log_estimated_path.txt")"
read -r odo_mean odo_max odo_steps <<<"$(path_errors "$out/log_odometry_path.txt")"
echo "position error along $steps steps: rbpf-slam mean $mean m, max $max m; odometry mean $odo_mean m, max $odo_max m"
[ "$steps" -eq 800 ] && [ "$odo_steps" -eq 800 ] || fail "expected 800 steps in both paths"
awk -v m="$mean" -v x="$max" -v o="$odo_mean" 'BEGIN { exit !(m <= 0.2 && x <= 0.4 && m <= 0.5 * o) }' ||
	fail "rbpf-slam's path is not close to the ground truth (limits: mean 0.2 m, max 0.4 m, half the odometry's mean)"
ok "rbpf-slam with the evidential map follows the ground truth"

mkdir -p "$scratch/without_plugin"
cp "$rawlogs/rbpf-slam.ini" "$scratch/without_plugin/"
(cd "$scratch/without_plugin" &&
	run_stock_without_plugin "$scratch/without_plugin.log" 120 evidentialGrid "$rbpf_slam" rbpf-slam.ini "$rawlog")
if compgen -G "$scratch/without_plugin/rbpf-slam-out/finalMap*" >/dev/null; then
	fail "final map files written without the plugin"
fi
ok "without the plugin, rbpf-slam writes no final map"
