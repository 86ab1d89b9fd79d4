#!/usr/bin/env bash
# The README's two commands on Debian 13 "trixie", whose own MeshLab is 2022.02: a clean
# clone of this checkout inside the trixie environment of scripts/meshlab_env.sh runs
# scripts/demo.sh, then scripts/test.sh: there without the nested newer-MeshLab runs and
# the packages' clean-system check, which need chroots of their own, and without the
# sanitizer pass, which the Debian 12 run makes on the same code (here it would build
# and run everything a second time). Then it makes the Debian 13 packages in the clone and
# checks them on a clean Debian 13 (scripts/test_packages.sh). Needs root;
# scripts/test.sh runs it on bookworm.
# usage: scripts/test_debian13_native.sh [ctest arguments]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ "$(id -u)" -eq 0 ] || { echo "test_debian13_native.sh needs root (chroot): run it with sudo" >&2; exit 1; }

CHROOT="$(bash "$ROOT/scripts/meshlab_env.sh" 2022)"
CLONE=/tmp/pcskeleton-native
rm -rf "$CHROOT$CLONE"
git clone -q "$ROOT" "$CHROOT$CLONE"
# ../shared beside the clone, as beside the checkout, when the developers' data is there.
if [ -d "$ROOT/../shared" ]; then
  mkdir -p "$CHROOT/tmp/shared"
  SHARED=("$(cd "$ROOT/../shared" && pwd)")
else
  SHARED=()
fi
source "$ROOT/scripts/chroot_mounts.sh"
chroot_mount "$CHROOT"
[ ${#SHARED[@]} -eq 0 ] || { mountpoint -q "$CHROOT/tmp/shared" || mount --bind "${SHARED[0]}" "$CHROOT/tmp/shared"; }
trap 'mountpoint -q "$CHROOT/tmp/shared" && umount "$CHROOT/tmp/shared"; chroot_unmount "$CHROOT"' EXIT

start=$SECONDS
chroot "$CHROOT" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  CCACHE_DIR=/var/cache/ccache PCSKELETON_NEWER_MESHLAB=0 PCSKELETON_SANITIZE=0 PCSKELETON_PACKAGES=0 bash -euo pipefail -c '
  cd "$1"; shift
  scripts/demo.sh
  grep -q "MeshLab 2022.02" build/CMakeCache.txt 2>/dev/null || grep -q "2022.02" deps/meshlab-src/ML_VERSION
  scripts/test.sh "$@"
  scripts/make_packages.sh build-deb/debs
' _ "$CLONE" "$@"
echo "Debian 13 (MeshLab 2022.02), the README's two commands and the packages: $((SECONDS - start)) s"
# The Debian 13 packages made there, on a clean Debian 13 (from here: it needs a chroot).
chroot_unmount "$CHROOT"
bash "$ROOT/scripts/test_packages.sh" "$CHROOT$CLONE/build-deb/debs" trixie
