#!/usr/bin/env bash
# Stock RawLogViewer -l <plugin>, in an Xvfb of its own, opens a rawlog whose first
# object is a serialized evidential map (written by the rawmap_dialog test):
# its window shows up and a screenshot of the screen is not blank, and no
# "Zero entries loaded" message appears. Without -l that message does appear
# (the map's class is unknown, so the load stops at the first object): the
# plugin is what makes the rawlog readable. RawLogViewer never exits by itself:
# it is ended by its process id.
# Usage: rawlogviewer.sh <plugin.so> <RawLogViewer> <map rawlog> <scratch dir>
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
IMPORT=/usr/bin/import
MAIN_WINDOW="RawlogViewer - Part of the MRPT project"
NOTHING_LOADED="Zero entries loaded"

# window_exists NAME: a window has this title. (ImageMagick's import is no
# probe: given a name no window has, it waits for a click.)
window_exists() {
	xwininfo -root -tree | grep -F "\"$1\": (" >/dev/null
}

# wait_for_window NAME SECONDS: false if it never shows up.
wait_for_window() {
	local deadline=$((SECONDS + $2))
	until window_exists "$1"; do
		[ $SECONDS -lt $deadline ] || return 1
		sleep 0.5
	done
}

# In the virtual display: run RawLogViewer (with -l if a plugin is given),
# check what it shows, end it.
session() {
	local plugin=$1 viewer=$2 rawlog=$3 run=$4
	local args=()
	[ -n "$plugin" ] && args=(-l "$plugin")
	"$viewer" "${args[@]}" "$rawlog" </dev/null >"$scratch/$run.log" 2>&1 &
	viewer_pid=$!
	trap 'kill "$viewer_pid" 2>/dev/null || true; wait "$viewer_pid" 2>/dev/null || true' EXIT
	check_$run "$viewer_pid" "$plugin"
}

check_with_plugin() {
	# Two minutes: a full ctest run, both cores busy with the sanitizer
	# trees' builds, once failed here after a minute.
	wait_for_window "$MAIN_WINDOW" 120 || fail "RawLogViewer's window never showed up"
	# The rawlog is loaded by a timer once the window is up; a failed load
	# shows its message at once.
	sleep 5
	kill -0 "$1" 2>/dev/null || fail "RawLogViewer ended by itself"
	grep -qF "$(basename "$2")" "/proc/$1/maps" || fail "the plugin is not loaded in RawLogViewer"
	window_exists "$NOTHING_LOADED" && fail "RawLogViewer -l loaded nothing from the rawlog"
	"$IMPORT" -window root "$scratch/screen.png"
	"$IMPORT" -window "$MAIN_WINDOW" "$scratch/window.png"
	local colours mean
	read -r colours mean <<<"$("$IDENTIFY" -format '%k %[fx:mean]' "$scratch/screen.png")"
	echo "screenshot: $colours colours, mean level $mean ($("$IDENTIFY" -format '%w x %h' "$scratch/window.png") window)"
	[ "$colours" -ge 100 ] && awk -v m="$mean" 'BEGIN { exit !(m > 0.05) }' ||
		fail "the screenshot is blank"
	ok "RawLogViewer -l shows the rawlog holding the evidential map (screenshot: $scratch/screen.png)"
}

check_without_plugin() {
	wait_for_window "$NOTHING_LOADED" 120 || fail "without -l, RawLogViewer did not report an empty load"
	ok "without -l, RawLogViewer loads nothing: the plugin is what makes the rawlog readable"
}

if [ "${1:-}" = --in-display ]; then
	shift
	scratch=$5
	session "$1" "$2" "$3" "$4"
	exit
fi

[ $# -eq 4 ] || fail "usage: $0 <plugin.so> <RawLogViewer> <map rawlog> <scratch dir>"
plugin=$1 viewer=$2 rawlog=$3 scratch=$4
[ -s "$rawlog" ] || fail "$rawlog is missing: the e2e_rawmap_dialog test writes it"
command -v xwininfo >/dev/null || fail "xwininfo is missing: install x11-utils"
rm -rf "$scratch"
# RawLogViewer keeps its settings in $HOME/.RawLogViewer: a home of its own,
# without the tip-of-the-day window that would cover the main one.
mkdir -p "$scratch/home/.RawLogViewer"
printf '[tips]\nshow=false\n' >"$scratch/home/.RawLogViewer/config.cfg"
XVFB_PID=
trap '[ -z "$XVFB_PID" ] || stop_process "$XVFB_PID"' EXIT
for run in with_plugin without_plugin; do
	[ $run = with_plugin ] && use=$plugin || use=
	start_xvfb "$scratch" 1280x1024x24
	status=0
	HOME=$scratch/home timeout 140 \
		bash "${BASH_SOURCE[0]}" --in-display "$use" "$viewer" "$rawlog" "$run" "$scratch" </dev/null ||
		status=$?
	stop_process "$XVFB_PID"
	XVFB_PID=
	if [ $status -ne 0 ]; then
		show_log "$scratch/$run.log"
		fail "RawLogViewer session $run failed"
	fi
done
