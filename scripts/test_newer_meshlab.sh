#!/usr/bin/env bash
# Builds the plugins and meshlab-run against a newer MeshLab and runs their end-to-end
# tests there, inside the cached Debian environment of scripts/meshlab_env.sh:
#   scripts/test_newer_meshlab.sh 2022 [ctest arguments]   MeshLab 2022.02 (Debian 13)
#   scripts/test_newer_meshlab.sh 2025 [ctest arguments]   MeshLab 2025.07 (Debian sid)
# The checkout is bind-mounted at the same path inside the environment (with its parent,
# so that ../shared is seen as in the main build); the build goes to build-<version>/.
# Needs root (chroot and mounts); scripts/test.sh runs it for both versions.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VERSION="${1:?usage: $0 2022|2025 [ctest arguments]}"; shift
[ "$(id -u)" -eq 0 ] || { echo "test_newer_meshlab.sh needs root (chroot): run it with sudo" >&2; exit 1; }

CHROOT="$(bash "$ROOT/scripts/meshlab_env.sh" "$VERSION")"
PARENT="$(dirname "$ROOT")"
source "$ROOT/scripts/chroot_mounts.sh"
chroot_mount "$CHROOT" "$PARENT"
trap 'chroot_unmount "$CHROOT" "$PARENT"' EXIT

BUILD="$ROOT/build-$VERSION"
start=$SECONDS
chroot "$CHROOT" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  CCACHE_DIR=/var/cache/ccache bash -euo pipefail -c '
  cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DMESHLAB_SOURCE_DIR=/src/meshlab \
    -DPCSKELETON_BUILD_TESTS=ON -DPCSKELETON_BUILD_BENCH=OFF -DPCSKELETON_BUILD_LIBRARY_TESTS=OFF -DPCSKELETON_BUILD_PYTHON=OFF -Wno-dev >/dev/null
  cmake --build "$2" -j"$(nproc)"
' _ "$ROOT" "$BUILD"
built=$SECONDS
chroot "$CHROOT" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  XDG_DATA_HOME=/tmp/pcskeleton-xdg bash -euo pipefail -c 'cd "$1" && shift && ctest --output-on-failure -j1 "$@"' \
  _ "$BUILD" "$@"
echo "MeshLab $VERSION: build $((built - start)) s, tests $((SECONDS - built)) s"
