#!/usr/bin/env bash
# Drives the stock GUI programs as a user would, in a virtual display of the
# test's own, and checks the pixels of what they show:
#  1. RawLogViewer -l <plugin> on a rawlog with odometry: the toolbar's
#     "Raw-map" button, the .ini pasted over the dialog's options box (read
#     back from it), "Map from odometry", "Preview map in 3D"; the preview
#     window is checked.
#  2. RawLogViewer -l <plugin> on a rawlog whose first entry is an evidential
#     map: a click on that entry of the tree; the main window's 3-D view is
#     checked.
#  3. SceneViewer3D on a .3Dscene (skipped when no scene is given).
# A check passes when no colour covers 95 % of the picture and it holds at
# least MIN_PIXELS pixels within COLOUR_TOLERANCE (on each channel) of every
# colour of EXPECT_COLOURS, e.g. "free=EBEBEB occupied=1E1E1E".
# Without a window manager, windows open at the top left at the size the
# program asks for: each is moved and sized so that the clicks land on fixed
# offsets (found on RawLogViewer 2.5.8), and every step waits for its effect,
# with a deadline, before the next one.
# Screenshots, by stable names, stay in the scratch folder.
# Usage: rawlogviewer_gui.sh <plugin.so> <RawLogViewer> <SceneViewer3D>
#   <rawlog with odometry> <Raw-map .ini, '' for rawlogs/rawlogviewer-rawmap.ini>
#   <map rawlog> <scratch dir> [<.3Dscene>]
# (the scene last: CMake drops an empty argument).
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
IMPORT=/usr/bin/import
CONVERT=/usr/bin/convert
MAIN_WINDOW="RawlogViewer - Part of the MRPT project"
# The main window's size: large, so that its 3-D view shows the small motion
# cells by hundreds of pixels.
MAIN_WIDTH=2300 MAIN_HEIGHT=1250
RAWMAP_DIALOG='Creation of "raw map & paths" from scans & odometry'
PROGRESS="Creating raw map"
EMPTY_RAWLOG="Rawlog is empty"
PREVIEW="Raw-map 3D preview"
SCENE_VIEWER="SceneViewer3D - Part of the MRPT project"

[ $# -eq 7 ] || [ $# -eq 8 ] || fail "usage: $0 <plugin.so> <RawLogViewer> <SceneViewer3D> <rawlog with odometry> <.ini or ''> <map rawlog> <scratch dir> [<.3Dscene>]"
plugin=$1 viewer=$2 scene_viewer=$3 odometry_rawlog=$4 ini=${5:-$(dirname "${BASH_SOURCE[0]}")/../../rawlogs/rawlogviewer-rawmap.ini}
map_rawlog=$6 scratch=$7 scene=${8:-}
: "${EXPECT_COLOURS:?EXPECT_COLOURS is not set: name=RRGGBB ... (tests/e2e/CMakeLists.txt sets it)}"
# CTexturedPlane draws unlit: in Xvfb a flat colour of the map comes through
# exactly, and only the pixels where texture filtering blends two cells are a
# few units off. 16 leaves room for another rasteriser's rounding while
# keeping apart colours a picture would use for different decisions; the
# minimum count keeps the blends along cell borders from passing for a colour.
COLOUR_TOLERANCE=${COLOUR_TOLERANCE:-16}
MIN_PIXELS=${MIN_PIXELS:-200}
for tool in xdotool:xdotool xclip:xclip xwininfo:x11-utils; do
	command -v "${tool%%:*}" >/dev/null || fail "${tool%%:*} is missing: install ${tool#*:}"
done
for file in "$plugin" "$odometry_rawlog" "$ini" "$map_rawlog"; do
	[ -s "$file" ] || fail "$file is missing or empty"
done
[ -z "$scene" ] || [ -s "$scene" ] || fail "$scene is missing or empty"

# Everything this script starts, ended by its process id on the way out.
started=()
stop_all() {
	local i
	for ((i = ${#started[@]} - 1; i >= 0; i--)); do
		stop_process "${started[i]}"
	done
}
trap stop_all EXIT

rm -rf "$scratch"
mkdir -p "$scratch/home/.RawLogViewer"
# RawLogViewer keeps its settings in $HOME/.RawLogViewer: a home of its own,
# without the tip-of-the-day window that would cover the main one.
printf '[tips]\nshow=false\n' >"$scratch/home/.RawLogViewer/config.cfg"
export HOME=$scratch/home

# The display, wide enough for the preview beside the dialog.
start_xvfb "$scratch" 2400x1300x24
started+=("$XVFB_PID")
echo "display $DISPLAY"

# window_id TITLE SECONDS: the id of the shown window with exactly this
# title, polled until the deadline. A program may title a window before it
# maps it, and size it again when it does: an unmapped window is not yet
# worth placing.
window_id() {
	local pattern deadline=$((SECONDS + $2)) id
	pattern="^$(sed 's/[][\\.^$*+?(){}|]/\\&/g' <<<"$1")\$"
	until id=$(xdotool search --onlyvisible --name "$pattern" 2>/dev/null | head -n 1) && [ -n "$id" ]; do
		[ $SECONDS -lt $deadline ] || return 1
		sleep 0.5
	done
	echo "$id"
}

window_exists() {
	window_id "$1" 0 >/dev/null
}

# geometry ID: the window's WxH+X+Y on the screen.
geometry() {
	xwininfo -id "$1" | awk -F: '
		/Absolute upper-left X/ { x = $2 + 0 } /Absolute upper-left Y/ { y = $2 + 0 }
		/^ *Width/ { w = $2 + 0 } /^ *Height/ { h = $2 + 0 }
		END { printf "%dx%d+%d+%d\n", w, h, x, y }'
}

# place ID X Y W H: moves and sizes a window until the X server reports the
# new geometry. There is no window manager, but a program may size its own
# window again (RawLogViewer does once its rawlog has loaded, late on a busy
# machine): the request is repeated until the geometry holds.
place() {
	local id=$1 wanted="$4x$5+$2+$3" deadline=$((SECONDS + 60)) i
	while :; do
		xdotool windowmove "$id" "$2" "$3" windowsize "$id" "$4" "$5"
		for i in 1 2 3 4 5; do
			[ "$(geometry "$id")" = "$wanted" ] && return 0
			sleep 0.2
		done
		[ $SECONDS -lt $deadline ] || fail "window $id did not become $wanted: $(geometry "$id")"
	done
}

# click ID X Y: a left click at this offset in the window.
click() {
	xdotool mousemove --window "$1" "$2" "$3" click 1
}

# Prints a picture's largest share of one colour and, per expected colour,
# the pixels near it; returns 1 unless every check passes. With SHADED=1, a
# pixel also counts when it is the colour darkened by lighting: within the
# tolerance of k times it, k from 0.6 to 1 (a scene file does not keep the
# map's "unlit" flag in MRPT 2.5.8, and SceneViewer3D lights it).
check_colours() {
	"$CONVERT" "$1" -alpha off -depth 8 -format %c histogram:info:- |
		awk -v expect="$EXPECT_COLOURS" -v tol="$COLOUR_TOLERANCE" -v min="$MIN_PIXELS" \
			-v shaded="${SHADED:-0}" '
		function hex(s) { return index("0123456789abcdef", tolower(substr(s, 1, 1))) * 16 + index("0123456789abcdef", tolower(substr(s, 2, 1))) - 17 }
		function far(a, b) { return a - b > tol || b - a > tol }
		function near_colour(i, k) {
			k = 1
			if (shaded && r[i] + g[i] + b[i] > 0) {
				k = (c[1] + c[2] + c[3]) / (r[i] + g[i] + b[i])
				if (k < 0.6 || k > 1) k = 1
			}
			return !far(c[1], k * r[i]) && !far(c[2], k * g[i]) && !far(c[3], k * b[i])
		}
		BEGIN {
			n = split(expect, names, " ")
			for (i = 1; i <= n; i++) {
				split(names[i], kv, "=")
				label[i] = kv[1]; code[i] = kv[2]
				r[i] = hex(substr(kv[2], 1, 2)); g[i] = hex(substr(kv[2], 3, 2)); b[i] = hex(substr(kv[2], 5, 2))
			}
		}
		{
			count = $1 + 0
			rgb = $2; gsub(/[()]/, "", rgb); split(rgb, c, ",")
			total += count
			if (count > top) top = count
			for (i = 1; i <= n; i++)
				if (near_colour(i)) near[i] += count
		}
		END {
			good = total > 0 && top < 0.95 * total
			printf "  %d pixels, the most common colour %.1f%%\n", total, total ? 100 * top / total : 0
			for (i = 1; i <= n; i++) {
				printf "  %s %s: %d pixels\n", label[i], code[i], near[i]
				if (near[i] < min) good = 0
			}
			exit !good
		}'
}

# shoot ID PNG: a screenshot of the window once it has settled: two in a row
# with the same pixels (a window just moved or sized is drawn anew a moment
# later; a GL view draws some time after it shows up), or the last one after
# 30 s. False if the window cannot be read (off the screen, or gone).
shoot() {
	local id=$1 png=$2 previous='' current deadline=$((SECONDS + 30))
	while :; do
		"$IMPORT" -window "$id" "$png" 2>/dev/null || return 1
		current=$("$IDENTIFY" -format '%#' "$png")
		[ "$current" != "$previous" ] || return 0
		[ $SECONDS -lt $deadline ] || return 0
		previous=$current
		sleep 0.5
	done
}

# shoot_until_good ID PNG SECONDS X Y W H: screenshots the window until its
# pixels pass, and keeps the last screenshot as PNG. A program may size its
# window again after it was placed (SceneViewer3D did once, on a busy
# machine, shrinking the map below the minimum counts): before each
# screenshot the window is put back at X Y W H.
shoot_until_good() {
	local id=$1 png=$2 deadline=$((SECONDS + $3)) report=''
	while :; do
		[ "$(geometry "$id")" = "$6x$7+$4+$5" ] || place "$id" "$4" "$5" "$6" "$7"
		shoot "$id" "$png" && report=$(check_colours "$png") && break
		[ $SECONDS -lt $deadline ] || { echo "$report" >&2; fail "$(basename "$png"): the expected colours did not show up within $3 s (the window: $(geometry "$id"), the picture: $("$IDENTIFY" -format %wx%h "$png"))"; }
		sleep 1
	done
	echo "$report"
	ok "$(basename "$png") shows the expected colours"
}

start_viewer() {
	local log=$1
	shift
	"$@" </dev/null >"$log" 2>&1 &
	started+=("$!")
	viewer_pid=$!
}

end_viewer() {
	stop_process "$viewer_pid"
	unset 'started[-1]'
}

# The main window, once up, at a fixed place and size.
main_window() {
	local id
	id=$(window_id "$MAIN_WINDOW" 90) || { show_log "$1"; fail "RawLogViewer's main window never showed up"; }
	grep -qF "$(basename "$plugin")" "/proc/$viewer_pid/maps" || fail "the plugin is not loaded in RawLogViewer"
	place "$id" 0 0 "$MAIN_WIDTH" "$MAIN_HEIGHT"
	echo "$id"
}

# The text of the dialog's options box, through the clipboard: a click in it,
# ctrl+a, ctrl+c.
copy_options() {
	click "$dialog" 900 150
	xdotool windowfocus "$dialog" key ctrl+a key ctrl+c
}

# Pastes the .ini over the options box, then reads the box back until it holds
# exactly the .ini. The paste is asynchronous (RawLogViewer asks xclip for the
# text): a read-back that overtook it, or a lost keystroke, is retried.
paste_options() {
	local deadline=$((SECONDS + 120)) xclip_pid attempt=0 wait_copy
	while :; do
		attempt=$((attempt + 1))
		# xclip -quiet stays in the foreground, serving the clipboard, until
		# another client owns it: here, RawLogViewer's ctrl+c.
		xclip -selection clipboard -quiet -i "$ini" >"$scratch/xclip.log" 2>&1 &
		xclip_pid=$!
		started+=("$xclip_pid")
		until timeout 5 xclip -selection clipboard -o 2>/dev/null | cmp -s - "$ini"; do
			[ $SECONDS -lt $deadline ] || fail "xclip does not serve the .ini"
			sleep 0.2
		done
		click "$dialog" 900 150
		xdotool windowfocus "$dialog" key ctrl+a key ctrl+v
		sleep 1
		copy_options
		wait_copy=$((SECONDS + 10))
		until timeout 5 xclip -selection clipboard -o 2>/dev/null >"$scratch/options.txt" &&
			cmp -s "$scratch/options.txt" "$ini"; do
			[ $SECONDS -lt $wait_copy ] && sleep 0.5 && continue
			break
		done
		stop_process "$xclip_pid"
		unset 'started[-1]'
		cmp -s "$scratch/options.txt" "$ini" && break
		[ $SECONDS -lt $deadline ] || fail "the options box does not hold the .ini after $attempt pastes (it holds $scratch/options.txt)"
	done
	ok "the options box holds $(basename "$ini") (pasted $attempt time(s), read back)"
}

# 1. The Raw-map dialog on the rawlog with odometry.
echo "== RawLogViewer: Raw-map dialog on $(basename "$odometry_rawlog")"
start_viewer "$scratch/rawmap.log" "$viewer" -l "$plugin" "$odometry_rawlog"
main=$(main_window "$scratch/rawmap.log")
# The rawlog loads from a timer once the window is up; pressed before that,
# the Raw-map button only says "Rawlog is empty": that box is closed and the
# button pressed again.
deadline=$((SECONDS + 120))
until dialog=$(window_id "$RAWMAP_DIALOG" 5); do
	[ $SECONDS -lt $deadline ] || { show_log "$scratch/rawmap.log"; fail "the Raw-map button opened no dialog"; }
	if empty=$(window_id "$EMPTY_RAWLOG" 0); then
		xdotool windowfocus "$empty" key Return
	else
		click "$main" 225 61
	fi
done
place "$dialog" 0 0 1250 950
paste_options
click "$dialog" 134 191
# "Preview map in 3D" stays disabled until the map is built, and the progress
# window blocks the dialog meanwhile: the button is pressed until the preview
# opens.
deadline=$((SECONDS + 240))
until preview=$(window_id "$PREVIEW" 3); do
	[ $SECONDS -lt $deadline ] || { show_log "$scratch/rawmap.log"; fail "no map preview within 240 s of \"Map from odometry\""; }
	window_exists "$PROGRESS" || click "$dialog" 304 277
done
place "$preview" 1280 0 1100 850
shoot "$dialog" "$scratch/rawmap_dialog.png" || fail "cannot screenshot the Raw-map dialog"
shoot_until_good "$preview" "$scratch/rawmap_preview.png" 60 1280 0 1100 850
end_viewer

# 2. The main window on the rawlog holding the map.
echo "== RawLogViewer: main window on $(basename "$map_rawlog")"
start_viewer "$scratch/main.log" "$viewer" -l "$plugin" "$map_rawlog"
main=$(main_window "$scratch/main.log")
# Selecting an entry shows it in the 3-D view, a GL window of its own inside
# the main one. The tree fills once the rawlog has loaded: the map's entry,
# the first, is selected until one of the main window's child windows shows
# the map's colours, by a click on its row and, every other try, from the
# keyboard (the tree's first row, then the next one), in case the row is not
# where it was found to be.
deadline=$((SECONDS + 120)) report='' try=0
until [ -s "$scratch/main_window_map.png" ]; do
	if [ $SECONDS -ge $deadline ]; then
		echo "$report" >&2
		shoot "$main" "$scratch/main_window_failed.png" || true
		show_log "$scratch/main.log"
		fail "no child window of RawLogViewer's shows the map after selecting its entry (see main_window_failed.png)"
	fi
	# RawLogViewer may size its window again once the rawlog has loaded
	# (seen under load): put it back first.
	[ "$(geometry "$main")" = "${MAIN_WIDTH}x${MAIN_HEIGHT}+0+0" ] ||
		place "$main" 0 0 "$MAIN_WIDTH" "$MAIN_HEIGHT"
	click "$main" 204 122
	try=$((try + 1))
	[ $((try % 2)) -eq 0 ] && xdotool windowfocus "$main" key Home key Down
	sleep 1
	for child in $(xwininfo -id "$main" -children | awk '$1 ~ /^0x/ { print $1 }'); do
		xwininfo -id "$child" | grep -qF "Map State: IsViewable" || continue
		if shoot "$child" "$scratch/child.png" && report=$(check_colours "$scratch/child.png"); then
			mv "$scratch/child.png" "$scratch/main_window_map.png"
			break
		fi
	done
done
echo "$report"
ok "main_window_map.png (the main window's 3-D view) shows the expected colours"
shoot "$main" "$scratch/main_window.png" || fail "cannot screenshot the main window"
end_viewer

# 3. SceneViewer3D on the scene file.
if [ -z "$scene" ]; then
	echo "SKIPPED: SceneViewer3D (no scene file given)"
	exit 0
fi
echo "== SceneViewer3D on $(basename "$scene")"
start_viewer "$scratch/sceneviewer.log" "$scene_viewer" "$scene"
id=$(window_id "$SCENE_VIEWER [$(basename "$scene")]" 90) ||
	{ show_log "$scratch/sceneviewer.log"; fail "SceneViewer3D's window never showed up"; }
SHADED=1 shoot_until_good "$id" "$scratch/sceneviewer.png" 60 0 0 1000 800
end_viewer
