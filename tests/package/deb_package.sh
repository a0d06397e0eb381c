#!/usr/bin/env bash
# The Debian packages (label package): builds them with scripts/build-deb.sh,
# installs them all into this system with apt-get, then checks, from the
# installed files only, where the library lands and that the programs find
# it, the programs' --help, the consumer project against /usr (as the test
# find_package_consumer does against a scratch prefix) and stock
# observations2map with the installed plugin and .ini (as e2e_observations2map
# does with the build tree's). Then purges every package the install added,
# on failure too, so that the system is left as it was.
#
# Needs root (apt-get). The CTest test runs alone (RUN_SERIAL): while the
# packages are installed no other test runs.
#
# Usage: deb_package.sh <source dir> <work dir> <jobs> <library soname>
#        <installed programs, comma-separated> <datasets dir> [CMAKE_ARGS...]
source "$(dirname "${BASH_SOURCE[0]}")/../e2e/lib.sh"
[ $# -ge 6 ] || fail "usage: $0 <source dir> <work dir> <jobs> <soname> <programs> <datasets dir> [CMAKE_ARGS...]"
source_dir=$1 work=$2 jobs=$3 soname=$4 programs=$5 datasets=$6
shift 6
[ "$(id -u)" -eq 0 ] ||
	fail "needs root: it installs the packages with apt-get and purges them afterwards (ctest -LE package leaves this test out)"
export DEBIAN_FRONTEND=noninteractive

tree=$work/tree
# What was installed before this test installed anything; it exists only
# while the packages may be installed, so that a run that was killed
# before its purge is told from a system where someone installed them.
before=$work/installed-before.txt

installed_packages() {
	dpkg-query -W -f='${db:Status-Status} ${Package}\n' | awk '$1 == "installed" { print $2 }' | sort
}
is_installed() {
	[ "$(dpkg-query -W -f='${db:Status-Status}' "$1" 2>/dev/null)" = installed ]
}

mkdir -p "$work"
start=$SECONDS
JOBS=$jobs bash "$source_dir/scripts/build-deb.sh" "$tree" "$@" >"$work/build-deb.log" 2>&1 ||
	{ show_log "$work/build-deb.log"; fail "scripts/build-deb.sh failed (log: $work/build-deb.log)"; }
debs=("$tree"/packages/*.deb)
packages=()
for deb in "${debs[@]}"; do
	packages+=("$(dpkg-deb -f "$deb" Package)")
done
ok "built ${packages[*]} in $((SECONDS - start))s"

runtime=libmrpt-evidential${soname#libmrpt_evidential.so.}
for expected in "$runtime" libmrpt-evidential-dev mrpt-evidential-tools mrpt-evidential-data mrpt-evidential-doc; do
	[[ " ${packages[*]} " == *" $expected "* ]] || fail "no package $expected among ${packages[*]}"
done
# dpkg-shlibdeps wrote the libraries' dependencies; the tools depend on the
# library of their own version.
tools_depends=$(dpkg-deb -f "$tree"/packages/mrpt-evidential-tools_*.deb Depends)
version=$(dpkg-deb -f "$tree"/packages/mrpt-evidential-tools_*.deb Version)
for expected in "$runtime (= $version)" "libc6 (>=" libmrpt-maps; do
	[[ $tools_depends == *"$expected"* ]] || fail "mrpt-evidential-tools does not depend on $expected: $tools_depends"
done

for package in "${packages[@]}"; do
	if is_installed "$package"; then
		[ -e "$before" ] || fail "$package is already installed, not by this test: purge it first (apt-get purge ${packages[*]})"
		echo "purging ${packages[*]}, left installed by an earlier run of this test that was stopped"
		apt-get purge -y "${packages[@]}" >"$work/purge-leftover.log" 2>&1 ||
			{ show_log "$work/purge-leftover.log"; fail "cannot purge what an earlier run left"; }
		break
	fi
done

# Purges what the install added and checks that none of our files is left.
purge() {
	local status=$? added clean=1
	set +e  # every step runs, whatever failed before
	added=$(comm -13 "$before" <(installed_packages))
	if [ -n "$added" ]; then
		# shellcheck disable=SC2086  # one package name a word
		if apt-get purge -y $added >"$work/purge.log" 2>&1; then
			echo "ok: purged" $added
		else
			show_log "$work/purge.log"
			echo "FAILED: apt-get purge $added" >&2
			clean=0
		fi
	fi
	local path
	for path in /usr/bin/evgrid "$libdir/$soname" "$libdir/cmake/mrpt_evidential" \
		/usr/include/mrpt_evidential /usr/share/mrpt-evidential /usr/share/doc/mrpt-evidential; do
		if [ -e "$path" ]; then
			echo "FAILED: $path is still there after the purge" >&2
			clean=0
		fi
	done
	if [ "$clean" -eq 1 ]; then
		rm -f "$before"
	else
		status=1
	fi
	exit "$status"
}

libdir=/usr/lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)
installed_packages >"$before"
trap purge EXIT
trap 'exit 130' INT TERM
apt-get install -y --no-install-recommends "${debs[@]}" >"$work/install.log" 2>&1 ||
	{ show_log "$work/install.log"; fail "apt-get install of the packages failed (log: $work/install.log)"; }
ok "installed $(comm -13 "$before" <(installed_packages) | tr '\n' ' ')"

# The library, also the plugin, in the multiarch folder, and the programs
# find it there by themselves.
plugin=$libdir/$soname
[ -f "$plugin" ] || fail "the library is not at $plugin"
[ "$(dpkg -S "$plugin" | cut -d: -f1)" = "$runtime" ] || fail "$plugin does not belong to $runtime"
resolved=$(env -u LD_LIBRARY_PATH ldd /usr/bin/evgrid | awk -v lib="$soname" '$1 == lib { print $3 }')
[ "$resolved" -ef "$plugin" ] || fail "/usr/bin/evgrid loads $soname from '${resolved}', not $plugin"
if readelf -d /usr/bin/evgrid | grep -qE 'RPATH|RUNPATH'; then
	fail "/usr/bin/evgrid has an RPATH"
fi
ok "$plugin, found by /usr/bin/evgrid without RPATH or LD_LIBRARY_PATH"

# The documentation, the data, and the link between them.
for path in /usr/share/doc/mrpt-evidential/README.md /usr/share/doc/mrpt-evidential/doc/map.md \
	/usr/share/doc/mrpt-evidential/rawlogs/observations2map.ini /usr/share/mrpt-evidential/rawlogs/room_door_box.rawlog; do
	[ -f "$path" ] || fail "missing: $path"
done
ok "documentation in /usr/share/doc/mrpt-evidential, data in /usr/share/mrpt-evidential/rawlogs"

# The programs and the consumer project, from /usr only.
cmake -DPREFIX=/usr -DINSTALLED_PROGRAMS="$programs" -DCONSUMER_SOURCE_DIR="$source_dir/tests/consumer" \
	-DREADME="$source_dir/README.md" -DWORK_DIR="$work/consumer" \
	-P "$source_dir/tests/consumer/run_consumer.cmake" >"$work/consumer.log" 2>&1 ||
	{ show_log "$work/consumer.log"; fail "the consumer project against /usr failed (log: $work/consumer.log)"; }
ok "$programs --help from /usr/bin; the consumer project built against /usr and ran"

# Stock observations2map with the installed plugin and .ini.
bash "$source_dir/tests/e2e/observations2map.sh" "$plugin" "$(command -v observations2map)" \
	/usr/share/mrpt-evidential/rawlogs "$datasets" "$work/observations2map"
ok "the whole test took $((SECONDS - start))s before the purge"
