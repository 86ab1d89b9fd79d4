#!/usr/bin/env bash
# The Debian packages of this tree for this machine's Debian and MeshLab, by one command:
# configures build-deb/ for /usr (the library, the CLI, the Python module and the plugins;
# no tests or benchmarks), builds it, and has CPack make the four packages
# (cmake/DebianPackages.cmake) into OUT (default: packages/), then checks them with
# lintian when it is installed. Run scripts/setup.sh first (scripts/build.sh does).
# usage: scripts/make_packages.sh [OUT]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$(mkdir -p "${1:-$ROOT/packages}" && cd "${1:-$ROOT/packages}" && pwd)"
BUILD="$ROOT/build-deb"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr \
  -DPCSKELETON_BUILD_TESTS=OFF -DPCSKELETON_BUILD_BENCH=OFF -DPCSKELETON_BUILD_PYTHON=ON \
  -DPCSKELETON_PYTHON_INSTALL_DIR=lib/python3/dist-packages/pcskeleton >/dev/null
cmake --build "$BUILD" -j"$(nproc)"
rm -rf "$BUILD/packages"
(cd "$BUILD" && cpack -G DEB >cpack.log 2>&1) || { cat "$BUILD/cpack.log"; exit 1; }
rm -f "$OUT"/*.deb
cp "$BUILD"/packages/*.deb "$OUT"/
if command -v lintian >/dev/null; then
  # Errors fail; warnings are printed (a package built outside Debian's archive has some).
  lintian --fail-on error --suppress-tags-from-file "$ROOT/packaging/lintian-overrides" "$OUT"/*.deb
fi
ls -1 "$OUT"/*.deb
