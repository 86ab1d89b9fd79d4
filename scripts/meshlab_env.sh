#!/usr/bin/env bash
# Creates (once) and caches a Debian environment holding a newer MeshLab, from Debian's
# own archive only, for building and testing the plugins against that MeshLab:
#   scripts/meshlab_env.sh 2022     Debian 13 "trixie": MeshLab 2022.02
#   scripts/meshlab_env.sh 2025     Debian sid:         MeshLab 2025.07
# The environment is a debootstrap chroot in $PCSKELETON_ENV_DIR (default
# /var/cache/pcskeleton) with MeshLab, Xvfb and our build dependencies, plus that
# MeshLab's upstream source tarball unpacked in /src/meshlab (headers and vcglib: Debian
# ships no MeshLab SDK). Idempotent: a second run checks a stamp and returns at once.
# Prints the chroot's path on stdout. Needs root (debootstrap, chroot, mounts); nothing
# stays mounted in it afterwards (scripts/chroot_mounts.sh).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ENV_DIR="${PCSKELETON_ENV_DIR:-/var/cache/pcskeleton}"

log() { printf '[meshlab_env] %s\n' "$*" >&2; }
die() { log "$*"; exit 1; }

case "${1:-}" in
  2022) SUITE=trixie ;;
  2025) SUITE=sid ;;
  *) die "usage: $0 2022|2025   (MeshLab 2022.02 from Debian trixie, 2025.07 from Debian sid)" ;;
esac
[ "$(id -u)" -eq 0 ] || die "needs root: debootstrap and chroot (run it with sudo)"

CHROOT="$ENV_DIR/$SUITE"
STAMP="$CHROOT/.pcskeleton-ready"
# Bump when the package list below changes, so cached environments are refreshed.
ENV_REVISION=4

PACKAGES=(
  build-essential cmake pkg-config ccache dpkg-dev
  qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libglu1-mesa-dev
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev libsuitesparse-dev
  meshlab xvfb xauth xdotool imagemagick python3 python3-numpy python3-matplotlib python3-pil libcgal-demo
  # stock plugins' libraries that are only Recommends: without them MeshLab shows a
  # modal "Error while loading plugins" box
  lib3ds-1-3 libmuparser2v5 libopenctm1 libqhull-r8.0
)
[ "$SUITE" = trixie ] && PACKAGES+=(libxerces-c3.2t64)


source "$ROOT/scripts/chroot_mounts.sh"

in_chroot() { chroot "$CHROOT" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
  DEBIAN_FRONTEND=noninteractive LANG=C.UTF-8 "$@"; }

if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$ENV_REVISION" ]; then
  echo "$CHROOT"
  exit 0
fi

command -v debootstrap >/dev/null || { apt-get update -qq; apt-get install -y -qq debootstrap >/dev/null; }
MIRROR="$(debian_mirror)"
mkdir -p "$ENV_DIR"
if [ ! -x "$CHROOT/usr/bin/apt-get" ]; then
  log "creating the Debian $SUITE environment in $CHROOT from $MIRROR (about a minute)"
  rm -rf "$CHROOT.partial"
  debootstrap --variant=minbase "$SUITE" "$CHROOT.partial" "$MIRROR" >&2
  mv "$CHROOT.partial" "$CHROOT"
fi
chroot_mount "$CHROOT"
trap 'chroot_unmount "$CHROOT"' EXIT
cp /etc/resolv.conf "$CHROOT/etc/resolv.conf" 2>/dev/null || true
# deb and deb-src from the same mirror; sid's index may be older than the machine's clock.
cat >"$CHROOT/etc/apt/sources.list.d/debian.sources" <<SRC
Types: deb deb-src
URIs: $MIRROR
Suites: $SUITE
Components: main
Check-Valid-Until: no
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
rm -f "$CHROOT/etc/apt/sources.list"
log "installing MeshLab and the build dependencies in $SUITE (a few minutes)"
in_chroot apt-get update -qq >&2
in_chroot apt-get install -y -qq --no-install-recommends "${PACKAGES[@]}" >&2
if [ ! -f "$CHROOT/src/meshlab/CMakeLists.txt" ] && [ ! -f "$CHROOT/src/meshlab/src/CMakeLists.txt" ]; then
  log "fetching MeshLab's upstream source tarball (headers and vcglib) with apt-get source --tar-only"
  in_chroot sh -c 'mkdir -p /src/fetch && cd /src/fetch && apt-get source --tar-only meshlab' >&2
  tarball="$(ls "$CHROOT"/src/fetch/meshlab_*.orig.tar.* | head -1)"
  rm -rf "$CHROOT/src/meshlab" && mkdir -p "$CHROOT/src/meshlab"
  tar -xf "$tarball" -C "$CHROOT/src/meshlab" --strip-components=1
fi
echo "$ENV_REVISION" >"$STAMP"
log "ready: $CHROOT ($(in_chroot dpkg-query -W -f='${Version}' meshlab))"
echo "$CHROOT"
