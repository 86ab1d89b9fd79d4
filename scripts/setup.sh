#!/usr/bin/env bash
# Installs everything pcskeleton needs on Debian 12 "bookworm" or 13 "trixie", from Debian's
# packages only:
#   - build tools and libraries (Qt5, Eigen, CGAL, SuiteSparse, GoogleTest),
#   - the release's MeshLab itself (2020.09 on bookworm, 2022.02 on trixie: its binaries and
#     libmeshlab-common.so),
#   - that MeshLab's plugin headers and vcglib, from Debian's own source package, unpacked
#     into deps/meshlab-src (Debian ships no MeshLab SDK package); the build reads the
#     version there and builds the plugins for it,
#   - what the tests and the demo run with (Xvfb, xdotool, ImageMagick, matplotlib,
#     libcgal-demo's real models),
#   - the Python module's build and tests (python3-dev, pybind11, pytest, networkx, Open3D).
# Idempotent: a second run checks and returns in a second or two.
# Runs as root (CI) or as a user with sudo.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SDK_DIR="$ROOT/deps/meshlab-src"

PACKAGES=(
  build-essential cmake pkg-config ccache
  qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libglu1-mesa-dev
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libsuitesparse-dev libopenblas0-pthread libgtest-dev
  meshlab dpkg-dev help2man lintian
  xvfb xauth xdotool imagemagick python3 python3-matplotlib python3-pil python3-numpy
  python3-dev pybind11-dev python3-pytest python3-networkx python3-open3d
  python3-distributed python3-venv python3-pip python3-build python3-setuptools python3-wheel
  libcgal-demo
  locales
)

# What MeshLab 2022's stock plugins need but Debian only recommends: without them MeshLab
# opens with a modal "Error while loading plugins" box.
CODENAME="$(. /etc/os-release && echo "${VERSION_CODENAME:-}")"
case "$CODENAME" in
  bookworm) ;;
  trixie) PACKAGES+=(lib3ds-1-3 libmuparser2v5 libopenctm1 libqhull-r8.0 libxerces-c3.2t64) ;;
  *) printf '[setup] this is Debian "%s": pcskeleton is set up for bookworm (12) and trixie (13)\n' \
       "${CODENAME:-unknown}" >&2 ;;
esac

if [ "$(id -u)" -eq 0 ]; then SUDO=(); else SUDO=(sudo); fi

log() { printf '[setup] %s\n' "$*" >&2; }

missing_packages() {
  local p
  for p in "${PACKAGES[@]}"; do
    [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" == *"install ok installed"* ]] || echo "$p"
  done
}

source_is_known() {
  grep -q '^Package: meshlab' <<<"$(apt-cache showsrc meshlab 2>/dev/null)"
}

deb_src_configured() {
  grep -rhsqE '^(deb-src[[:space:]]|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/
}

# Adds deb-src entries mirroring the machine's own 'deb' entries of its release, so the
# source package comes from the same archive the binaries came from.
add_deb_src() {
  local out=/etc/apt/sources.list.d/pcskeleton-src.sources
  local tmp
  tmp="$(mktemp)"
  # deb822 files: copy each stanza that serves this release's 'main', as deb-src.
  local f
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -e "$f" ] || continue
    [ "$f" = "$out" ] && continue
    awk -v codename="$CODENAME" 'BEGIN{RS=""; ORS="\n\n"}
         /Types:[^\n]*deb/ && $0 ~ "Suites:[^\n]*" codename && /Components:[^\n]*main/ {
           gsub(/Types:[^\n]*/, "Types: deb-src"); print }' "$f" >>"$tmp"
  done
  # one-line files
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -e "$f" ] || continue
    grep -E "^deb[[:space:]].*[[:space:]]$CODENAME[[:space:]].*main" "$f" \
      | sed -E 's/^deb([[:space:]])/deb-src\1/' \
      | awk '{print "Types: deb-src\nURIs: " $2 "\nSuites: " $3 "\nComponents: main\n"}' >>"$tmp" || true
  done
  if ! grep -q 'URIs:' "$tmp"; then
    rm -f "$tmp"
    log "no Debian $CODENAME 'deb' entry found in /etc/apt: cannot add a matching deb-src entry"
    exit 1
  fi
  "${SUDO[@]}" install -m 0644 "$tmp" "$out"
  rm -f "$tmp"
  log "added $out"
}

missing="$(missing_packages | tr '\n' ' ')"
if [ -n "${missing// /}" ]; then
  log "installing: $missing"
  "${SUDO[@]}" apt-get update -qq
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

# The installed MeshLab's version, e.g. 2022.02 for 2022.02+dfsg1-1, and the version of
# the headers in deps/meshlab-src: they must match (MeshLab 2021+ refuses other plugins).
version="$(dpkg-query -W -f='${Version}' meshlab)"
upstream="${version%%+*}"; upstream="${upstream#*:}"
if [ "$(cat "$SDK_DIR/ML_VERSION" 2>/dev/null)" != "$upstream" ]; then
  if ! source_is_known; then
    deb_src_configured || add_deb_src
    "${SUDO[@]}" apt-get update -qq
  fi
  log "fetching MeshLab's source package (meshlab=$version) for its plugin headers"
  work="$(mktemp -d "$ROOT/deps.tmp.XXXXXX")"
  case "$upstream" in
    2020.*)  # the whole source package: vcglib comes as a second upstream tarball
      (cd "$work" && apt-get source -qq "meshlab=$version" >/dev/null 2>&1) || {
        rm -rf "$work"; log "apt-get source meshlab=$version failed"; exit 1; }
      unpacked=("$work"/meshlab-*/) ;;
    *)  # the mirror has only the upstream tarball of 2022.02 (no .dsc); it holds vcglib
      (cd "$work" && apt-get source -qq --tar-only "meshlab=$version" >/dev/null 2>&1) || {
        rm -rf "$work"; log "apt-get source --tar-only meshlab=$version failed"; exit 1; }
      mkdir "$work/tree" && tar -xf "$work"/meshlab_*.orig.tar.* -C "$work/tree" --strip-components=1
      unpacked=("$work/tree") ;;
  esac
  mkdir -p "$ROOT/deps"
  rm -rf "$SDK_DIR"
  mv "${unpacked[0]}" "$SDK_DIR"
  rm -rf "$work"
fi

log "ready: MeshLab $upstream's plugin headers in ${SDK_DIR#"$ROOT"/}, packages installed"
