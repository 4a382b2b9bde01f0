#!/usr/bin/env bash
# Runs the project's own `make test` (or another target) on a fresh clone inside a
# Debian chroot of another release, as a new user of that release would:
#
#   tools/chroot-test.sh SUITE [MAKE_TARGET]
#
#   SUITE        trixie (FreeCAD 1.0) or sid (FreeCAD 1.1); any suite debootstrap knows works
#   MAKE_TARGET  test (default), demo, ...
#
# The chroot is built once with debootstrap and kept in $FAIRSPLINES_CHROOTS/SUITE
# (default /var/cache/fairsplines/chroots, never inside the repository); the project's
# dependencies are installed there by its own tools/install-deps.sh, which only installs
# what is missing, so a rerun reuses the chroot and costs only the build and the tests.
# What the script mounts it unmounts again, on success, failure or interrupt.
#
# Needs root (debootstrap, chroot, mount). The clone is of HEAD of the repository this
# script lives in (FAIRSPLINES_REV to choose another revision): uncommitted changes
# are not tested, exactly as in CI.
set -euo pipefail

suite=${1:?usage: tools/chroot-test.sh SUITE [MAKE_TARGET]}
target=${2:-test}
repo=$(cd "$(dirname "$0")/.." && pwd)
cache=${FAIRSPLINES_CHROOTS:-/var/cache/fairsplines/chroots}
root=$cache/$suite
rev=${FAIRSPLINES_REV:-HEAD}

[ "$(id -u)" -eq 0 ] || { echo "chroot-test: needs root (debootstrap, chroot, mount)" >&2; exit 2; }

log() { printf 'chroot-test[%s]: %s\n' "$suite" "$*"; }

# The host's own Debian mirror: the first deb822 URIs line or one-line `deb` entry
# that serves the main archive (not -security).
host_mirror() {
  local f
  for f in /etc/apt/sources.list.d/*.sources /etc/apt/sources.list; do
    [ -r "$f" ] || continue
    awk '/^URIs:/ { for (i = 2; i <= NF; i++) print $i }
         /^deb[ \t]/ { for (i = 2; i <= NF; i++) if ($i ~ /^[a-z]+:\/\//) { print $i; break } }' "$f"
  done | grep -v -e security -e '^$' | grep -m1 '/debian/\?$' || true
}

mirror=${FAIRSPLINES_MIRROR:-$(host_mirror)}
[ -n "$mirror" ] || { echo "chroot-test: no Debian mirror found in /etc/apt; set FAIRSPLINES_MIRROR" >&2; exit 2; }

command -v debootstrap >/dev/null || {
  log "installing debootstrap"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null
}

mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -l "${mounted[i]}" 2>/dev/null || true
  done
  mounted=()
}
trap cleanup EXIT
trap 'exit 130' INT TERM

mount_into() { # mount_into SOURCE TARGET_IN_CHROOT
  mkdir -p "$root$2"
  if ! mountpoint -q "$root$2"; then
    mount --bind "$1" "$root$2"
    mounted+=("$root$2")
  fi
}

t0=$SECONDS
if [ ! -e "$root/.fairsplines-bootstrapped" ]; then
  log "debootstrap $suite from $mirror into $root"
  rm -rf "$root.partial"
  mkdir -p "$cache"
  debootstrap --variant=minbase --include=ca-certificates,git,make "$suite" "$root.partial" "$mirror" \
    >"$cache/$suite.debootstrap.log" 2>&1 || {
      tail -n 20 "$cache/$suite.debootstrap.log" >&2
      exit 1
    }
  # The mirror is a frozen snapshot: its Release files are past their Valid-Until.
  printf 'Acquire::Check-Valid-Until "false";\n' >"$root.partial/etc/apt/apt.conf.d/99fairsplines-snapshot"
  # No daemons may start inside the chroot.
  printf '#!/bin/sh\nexit 101\n' >"$root.partial/usr/sbin/policy-rc.d"
  chmod +x "$root.partial/usr/sbin/policy-rc.d"
  rm -rf "$root"
  mv "$root.partial" "$root"
  touch "$root/.fairsplines-bootstrapped"
  log "bootstrapped in $((SECONDS - t0)) s"
fi

mount_into /proc /proc
mount_into /sys /sys
mount_into /dev /dev
mount_into /dev/pts /dev/pts
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true

in_chroot() {
  chroot "$root" /usr/bin/env -i \
    HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 LC_ALL=C.UTF-8 DEBIAN_FRONTEND=noninteractive ${CI:+CI=$CI} \
    "$@"
}

# A fresh clone of the revision under test, made on the host (the chroot cannot see
# the repository) and handed over as a plain directory.
src=/root/fairsplines
rm -rf "$root$src"
git -c advice.detachedHead=false clone -q "$repo" "$root$src"
git -C "$root$src" -c advice.detachedHead=false checkout -q "$(git -C "$repo" rev-parse "$rev")"
log "testing $(git -C "$root$src" log -1 --format='%h %s')"

t1=$SECONDS
in_chroot bash "$src/tools/install-deps.sh"
log "install-deps took $((SECONDS - t1)) s"

freecad_version=$(in_chroot dpkg-query -W -f='${Version}' freecad 2>/dev/null || echo '?')
log "FreeCAD $freecad_version; make $target"
t2=$SECONDS
status=0
in_chroot make -C "$src" "$target" || status=$?
log "make $target exited $status after $((SECONDS - t2)) s (whole run $((SECONDS - t0)) s)"
exit "$status"
