#!/usr/bin/env bash
# The first run of a new user, in a throwaway copy of a FreeCAD 1.x chroot:
#
#   tools/first-run-test.sh SUITE [present|absent]
#
#   SUITE    trixie (FreeCAD 1.0) or sid (FreeCAD 1.1): a chroot made by tools/chroot-test.sh
#   present  the build tools are there: the dialog builds the kernel, the workbench works after
#   absent   cmake, g++ and Eigen's headers are removed (in the copy): the dialog lists them
#
# The chroot in $FAIRSPLINES_CHROOTS/SUITE is not modified: an overlay (its upper layer in a
# temporary folder) takes every write, and is thrown away at the end. A clone of HEAD (or
# FAIRSPLINES_REV) is placed where the Addon Manager puts an add-on (FreeCAD's user Mod
# folder, versioned on 1.1), with nothing built; FreeCAD's GUI runs under Xvfb with
# tools/first_run_driver.py, which presses the dialog's buttons. The driver's result.json and
# screenshots land in out/first-run/SUITE-MODE/. FAIRSPLINES_BUILD_JOBS (default 1) sets
# the build's parallel jobs. Needs root (mount, chroot).
set -euo pipefail

suite=${1:?usage: tools/first-run-test.sh SUITE [present|absent]}
mode=${2:-present}
repo=$(cd "$(dirname "$0")/.." && pwd)
lower=${FAIRSPLINES_CHROOTS:-/var/cache/fairsplines/chroots}/$suite
rev=${FAIRSPLINES_REV:-HEAD}
out=$repo/out/first-run/$suite-$mode
[ "$(id -u)" -eq 0 ] || { echo "first-run-test: needs root (mount, chroot)" >&2; exit 2; }
[ -e "$lower/.fairsplines-bootstrapped" ] || { echo "first-run-test: no chroot $lower (make test-freecad-1.x makes it)" >&2; exit 2; }

log() { printf 'first-run[%s/%s]: %s\n' "$suite" "$mode" "$*"; }
tmp=$(mktemp -d /tmp/fairsplines-first-run.XXXXXX)
root=$tmp/merged
mkdir -p "$tmp/upper" "$tmp/work" "$root"
mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2>/dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
mount -t overlay overlay -o "lowerdir=$lower,upperdir=$tmp/upper,workdir=$tmp/work" "$root"
mounted+=("$root")
for m in /proc /sys /dev /dev/pts; do
  mount --bind "$m" "$root$m"
  mounted+=("$root$m")
done

in_chroot() {
  chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 LC_ALL=C.UTF-8 QTWEBENGINE_DISABLE_SANDBOX=1 "$@"
}

# A new user: no FreeCAD settings, no add-on, no earlier build (CI's clone in /root stays below).
rm -rf "$root/root/.local/share/FreeCAD" "$root/root/.config/FreeCAD" "$root/root/fairsplines"
data=$(in_chroot freecadcmd -c 'import FreeCAD; print("DATA=" + FreeCAD.getUserAppDataDir())' 2>/dev/null |
  sed -n 's/^DATA=//p' | tail -1)
[ -n "$data" ] || { echo "first-run-test: FreeCAD's user data folder not found" >&2; exit 1; }
mod=${data%/}/Mod/FairSplines
git -c advice.detachedHead=false clone -q "$repo" "$root$mod"
git -C "$root$mod" -c advice.detachedHead=false checkout -q "$(git -C "$repo" rev-parse "$rev")"
log "FreeCAD $(in_chroot dpkg-query -W -f='${Version}' freecad), add-on at $mod ($(git -C "$root$mod" log -1 --format=%h))"

if [ "$mode" = absent ]; then
  rm -f "$root"/usr/bin/cmake "$root"/usr/bin/g++* "$root"/usr/bin/c++ "$root"/usr/bin/x86_64-linux-gnu-g++*
  rm -rf "$root/usr/include/eigen3"
  log "removed cmake, g++ and Eigen's headers (in the overlay only)"
fi

cp "$repo/tools/first_run_driver.py" "$root/tmp/first_run_driver.py"
t0=$SECONDS
status=0
in_chroot env FAIRSPLINES_BUILD_JOBS="${FAIRSPLINES_BUILD_JOBS:-1}" FAIRSPLINES_FIRST_RUN_OUT=/tmp/first-run \
  timeout 5400 xvfb-run -a -s "-screen 0 1280x1024x24" freecad /tmp/first_run_driver.py \
  >"$tmp/freecad.log" 2>&1 || status=$?
log "FreeCAD ran $((SECONDS - t0)) s (exit $status)"
rm -rf "$out"
mkdir -p "$out"
cp -r "$root/tmp/first-run/." "$out/" 2>/dev/null || true
cp "$tmp/freecad.log" "$out/"
find "$root${data%/}/FairSplines" -maxdepth 1 -name '*.log' -exec cp {} "$out/" \; 2>/dev/null || true
[ -f "$out/result.json" ] || { echo "first-run-test: the driver wrote no result" >&2; tail -n 30 "$out/freecad.log" >&2; exit 1; }
cat "$out/result.json"
# present: the dialog built the kernel and the workbench fits a curve; absent: the dialog
# listed the missing tools and offered no build.
if [ "$mode" = present ]; then
  grep -q '"built": true' "$out/result.json" && grep -q '"fit"' "$out/result.json"
else
  grep -q '"build_enabled": false' "$out/result.json" && grep -q 'missing: CMake' "$out/result.json" &&
    grep -q 'missing: Eigen' "$out/result.json"
fi
log "passed; results in $out"
