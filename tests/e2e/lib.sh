# Helpers of the end-to-end tests (sourced by the test scripts).
#
# Stock MRPT programs wait for a key after an error and may open windows:
# every one runs with stdin from /dev/null, under a timeout, its output kept
# in a log that is printed when something fails.

set -euo pipefail

# The real ImageMagick, whatever else is on PATH.
IDENTIFY=/usr/bin/identify

fail() {
	echo "FAILED: $*" >&2
	exit 1
}

ok() {
	echo "ok: $*"
}

# stop_process PID: ends a process this script started, and reaps it.
stop_process() {
	local pid=$1 deadline=$((SECONDS + 10))
	kill "$pid" 2>/dev/null || return 0
	# A child that has ended stays a zombie until waited for: wait for that
	# state, not for the pid to vanish.
	while [ $SECONDS -lt $deadline ] && [[ "$(ps -o stat= -p "$pid" 2>/dev/null)" != Z* ]]; do
		sleep 0.2
	done
	kill -KILL "$pid" 2>/dev/null || true
	wait "$pid" 2>/dev/null || true
}

# start_xvfb DIR GEOMETRY: a virtual display of its own. Xvfb picks a free
# number itself (-displayfd) and writes it once it accepts clients, so that
# two displays started at once never take the same number (xvfb-run -a picks
# one from the lock files first, and may lose that race). Exports DISPLAY and
# sets XVFB_PID, which the caller ends with stop_process; its log is
# DIR/xvfb.log.
start_xvfb() {
	local dir=$1 geometry=$2 deadline=$((SECONDS + 60))
	command -v Xvfb >/dev/null || fail "Xvfb is missing: install xvfb"
	: >"$dir/display"
	Xvfb -displayfd 3 -screen 0 "$geometry" -nolisten tcp 3>"$dir/display" >"$dir/xvfb.log" 2>&1 &
	XVFB_PID=$!
	until [ -s "$dir/display" ]; do
		kill -0 "$XVFB_PID" 2>/dev/null || { show_log "$dir/xvfb.log"; fail "Xvfb ended"; }
		[ $SECONDS -lt $deadline ] || { stop_process "$XVFB_PID"; fail "Xvfb did not start within 60 s"; }
		sleep 0.2
	done
	DISPLAY=:$(head -n 1 "$dir/display")
	export DISPLAY
}

# Prints a log file's last lines to stderr.
show_log() {
	echo "---- last lines of $1 ----" >&2
	tail -n 40 "$1" >&2 || true
	echo "----" >&2
}

# run_stock LOG SECONDS PRELOAD COMMAND...: runs COMMAND with the plugin
# preloaded (PRELOAD empty: without it) and fails unless it exits with 0.
# The preload goes to the program only, not to `timeout`.
run_stock() {
	local log=$1 seconds=$2 preload=$3
	shift 3
	local start=$SECONDS status=0
	if [ -n "$preload" ]; then
		timeout "$seconds" env LD_PRELOAD="$preload" "$@" </dev/null >"$log" 2>&1 || status=$?
	else
		timeout "$seconds" "$@" </dev/null >"$log" 2>&1 || status=$?
	fi
	local name
	name=$(basename "$1")
	if [ "$status" -ne 0 ]; then
		show_log "$log"
		if [ "$status" -eq 124 ]; then
			fail "$name timed out after ${seconds}s"
		fi
		fail "$name exited with $status (log: $log)"
	fi
	ok "$name ran in $((SECONDS - start))s"
}

# run_stock_without_plugin LOG SECONDS MAPCLASS COMMAND...: runs COMMAND,
# whose .ini names MAPCLASS, without the plugin. MRPT before 2.11.3 skips a
# map class nobody registered: COMMAND must exit with 0. Since, the map list
# is rejected: COMMAND must fail with MRPT's error naming MAPCLASS.
# E2E_MRPT_COMPAT (tests/e2e/mrpt_compat.cpp) tells which MRPT this is.
# Prints the ok line: what MRPT did.
run_stock_without_plugin() {
	local log=$1 seconds=$2 class=$3
	shift 3
	local expected status=0 name
	name=$(basename "$1")
	expected=$("${E2E_MRPT_COMPAT:?E2E_MRPT_COMPAT is not set (tests/e2e/CMakeLists.txt sets it)}")
	case "$expected" in
	"unknown-maps: skipped")
		run_stock "$log" "$seconds" "" "$@"
		;;
	"unknown-maps: rejected")
		timeout "$seconds" "$@" </dev/null >"$log" 2>&1 || status=$?
		[ "$status" -ne 124 ] || { show_log "$log"; fail "$name timed out after ${seconds}s"; }
		[ "$status" -ne 0 ] || { show_log "$log"; fail "$name exited with 0 on an .ini naming the unregistered $class"; }
		grep -qF "there is no such registered CMetricMap class '$class'" "$log" ||
			{ show_log "$log"; fail "$name did not stop on the unregistered map class $class"; }
		ok "$name stopped on the unregistered map class $class (exit $status)"
		;;
	*) fail "E2E_MRPT_COMPAT printed '$expected'" ;;
	esac
}

# help_has PROGRAM TEXT...: fails unless PROGRAM --help mentions every TEXT.
# The help is read whole first: grep -q on a pipe stops reading early, and
# under pipefail the program's next write then fails with SIGPIPE.
help_has() {
	local program=$1 help text
	shift
	help=$("$program" --help) || fail "$program --help exited with $?"
	for text in "$@"; do
		grep -qF -- "$text" <<<"$help" || fail "$(basename "$program") --help does not mention $text"
	done
}

# The one file matching a glob pattern, or a failure.
only_file() {
	local matches=()
	local f IFS=  # expand the pattern's wildcards, not its spaces
	for f in $1; do
		[ -e "$f" ] && matches+=("$f")
	done
	[ "${#matches[@]}" -eq 1 ] || fail "expected one file matching $1, found ${#matches[@]}"
	echo "${matches[0]}"
}

# check_evidential_files PREFIX MIN_FREE MIN_OCCUPIED: the files that
# saveMetricMapRepresentationToFile writes for an evidential map exist, its
# counts of free and occupied cells reach the minimums, the counts add up to
# the grid, and every picture has one pixel per cell above its legend strip.
check_evidential_files() {
	local prefix=$1 min_free=$2 min_occupied=$3
	local info=${prefix}_info.txt suffix
	for suffix in _map.png _evidential.png _betp.png _conflict.png _motion.png _info.txt .evgrid .3Dscene; do
		[ -s "$prefix$suffix" ] || fail "missing or empty: $prefix$suffix"
	done
	local size counts
	size=$(sed -n 's/^cells: \([0-9]*\) x \([0-9]*\) .*/\1 \2/p' "$info")
	counts=$(sed -n 's/^cells by decision: free \([0-9]*\), occupied \([0-9]*\), unknown \([0-9]*\), conflict \([0-9]*\)$/\1 \2 \3 \4/p' "$info")
	[ -n "$size" ] && [ -n "$counts" ] || fail "cannot read the geometry and counts of $info"
	local sx sy free occupied unknown conflict
	read -r sx sy <<<"$size"
	read -r free occupied unknown conflict <<<"$counts"
	echo "evidential map $sx x $sy cells: free $free, occupied $occupied, unknown $unknown, conflict $conflict"
	[ $((free + occupied + unknown + conflict)) -eq $((sx * sy)) ] ||
		fail "the counts of $info do not add up to $sx x $sy cells"
	[ "$free" -ge "$min_free" ] || fail "free cells: $free < $min_free"
	[ "$occupied" -ge "$min_occupied" ] || fail "occupied cells: $occupied < $min_occupied"
	local picture w h
	for suffix in _map.png _evidential.png _betp.png _conflict.png _motion.png; do
		picture=$prefix$suffix
		read -r w h <<<"$("$IDENTIFY" -format '%w %h' "$picture")" || fail "identify cannot read $picture"
		[ "$w" -eq "$((sx > 320 ? sx : 320))" ] && [ "$h" -gt "$sy" ] ||
			fail "$picture is $w x $h pixels, the map $sx x $sy cells above a legend"
	done
	ok "evidential files of $(basename "$prefix"): counts and picture sizes match"
}
