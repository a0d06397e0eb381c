#!/usr/bin/env bash
# Builds and tests mrpt-evidential on the other Debian release from this one,
# in a chroot made with debootstrap, as root.
#
#   scripts/other-release.sh [RELEASE] [ROOT] [-- CTEST-ARGS...]
#   scripts/other-release.sh root     # make (or reuse) the root only
#
# RELEASE  the Debian suite to test on (default: trixie on a bookworm host,
#          bookworm on a trixie host); also OTHER_RELEASE in the environment.
# ROOT     where the root lives (default: /var/tmp/mrpt-evidential-RELEASE);
#          also OTHER_RELEASE_ROOT. It is kept and reused on later runs.
# CTEST-ARGS  given to ctest (default: the whole suite, e.g. `-- -L unit`).
#
# The mirror is the host's own: the first Debian archive URI of its apt
# sources (deb822 /etc/apt/sources.list.d/*.sources or one-line sources.list),
# read at run time. Inside the root, the project's scripts/quickstart.sh
# installs the packages and builds a clean copy of HEAD (`git archive`, so
# uncommitted changes are not tested: commit or stash them first; set
# OTHER_RELEASE_TREE=worktree to copy the tracked files as they are on disk).
# The build and its logs stay in ROOT/root/mrpt-evidential/build.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

if [ "$(id -u)" -ne 0 ]; then
  echo "other-release: run as root (debootstrap, chroot and mounts need it)" >&2
  exit 1
fi

host_codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
case "$host_codename" in
  bookworm) default_release=trixie ;;
  trixie) default_release=bookworm ;;
  *) default_release=trixie ;;
esac

root_only=0
if [ "${1:-}" = root ]; then
  root_only=1
  shift
fi
release=${OTHER_RELEASE:-$default_release}
if [ $# -gt 0 ] && [ "$1" != -- ]; then release=$1; shift; fi
root=${OTHER_RELEASE_ROOT:-/var/tmp/mrpt-evidential-$release}
if [ $# -gt 0 ] && [ "$1" != -- ]; then root=$1; shift; fi
[ "${1:-}" = -- ] && shift
ctest_args=("$@")

root=$(realpath -m "$root")
case "$root/" in
  "$here"/*)
    echo "other-release: the root must be outside the project ($root)" >&2
    exit 2
    ;;
esac

# The first Debian archive URI the host's apt is configured with.
host_mirror() {
  local f uri
  shopt -s nullglob
  for f in /etc/apt/sources.list.d/*.sources; do
    # deb822: a stanza's URIs field, skipping the security archive.
    uri=$(awk 'tolower($1) == "uris:" { for (i = 2; i <= NF; i++) print $i }' "$f" |
      grep -v -- '-security' | head -n 1 || true)
    [ -n "$uri" ] && { echo "$uri"; return; }
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    uri=$(awk '$1 == "deb" { for (i = 2; i <= NF; i++) if ($i !~ /^\[/ && $i !~ /\]$/) { print $i; break } }' "$f" |
      grep -v -- '-security' | head -n 1 || true)
    [ -n "$uri" ] && { echo "$uri"; return; }
  done
  shopt -u nullglob
}

make_root() {
  if [ -x "$root/usr/bin/apt-get" ] && [ -f "$root/.mrpt-evidential-root" ]; then
    echo "other-release: reusing the $release root in $root"
    return
  fi
  local mirror
  mirror=$(host_mirror)
  if [ -z "$mirror" ]; then
    echo "other-release: no Debian archive found in the host's apt sources" >&2
    exit 1
  fi
  if ! command -v debootstrap >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends debootstrap
  fi
  echo "other-release: making a $release root in $root from $mirror (takes a while)"
  local start=$SECONDS
  # A half-made root from an interrupted run is started again.
  if [ -d "$root" ] && [ ! -f "$root/.mrpt-evidential-root" ]; then
    rm -rf --one-file-system "$root"
  fi
  mkdir -p "$(dirname "$root")"
  debootstrap --variant=minbase "$release" "$root" "$mirror"
  # The root's own apt sources: the release and its updates from the same mirror.
  rm -f "$root/etc/apt/sources.list"
  cat >"$root/etc/apt/sources.list.d/debian.sources" <<EOF
Types: deb
URIs: $mirror
Suites: $release $release-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  echo "made by scripts/other-release.sh in $((SECONDS - start)) s" >"$root/.mrpt-evidential-root"
  echo "other-release: root made in $((SECONDS - start)) s"
}

mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -l "${mounted[i]}" 2>/dev/null || true
  done
}
mount_in_root() { # mount-args... target
  local target=${*: -1}
  mkdir -p "$target"
  mount "$@"
  mounted+=("$target")
}

make_root
[ "$root_only" = 1 ] && exit 0

trap cleanup EXIT
mount_in_root -t proc proc "$root/proc"
mount_in_root --rbind /sys "$root/sys"
mount_in_root --rbind /dev "$root/dev"
mount_in_root -t tmpfs tmpfs "$root/dev/shm"
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true

# A clean copy of the project.
src=/root/mrpt-evidential
rm -rf "$root$src"
mkdir -p "$root$src"
if [ "${OTHER_RELEASE_TREE:-head}" = worktree ]; then
  (cd "$here" && git ls-files -z --cached --others --exclude-standard | xargs -0 tar -cf - --no-recursion) | tar -xf - -C "$root$src"
else
  git -C "$here" archive --format=tar HEAD | tar -xf - -C "$root$src"
fi
echo "other-release: testing $(git -C "$here" rev-parse --short HEAD) on $release in $root"

jobs=${JOBS:-2}
quoted_args=$(printf ' %q' "${ctest_args[@]}")
[ ${#ctest_args[@]} -eq 0 ] && quoted_args=
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 TERM="${TERM:-dumb}" JOBS="$jobs" /bin/bash -c "
    set -euo pipefail
    cd $src
    bash scripts/quickstart.sh build
    ctest --test-dir build --output-on-failure -j$jobs$quoted_args
  "
