#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every test with CTest
# (unit tests, the plugin loaded from its .so, meshlabserver and the GUI under Xvfb), then
# builds the library, the CLI and the unit tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (leaks included) in build-sanitize/ and runs them again there:
# any sanitizer report fails the test that triggered it. Between the two, the plugins are
# built and tested against MeshLab 2022.02 and 2025.07 (meshlab-run, the GUI under Xvfb, the
# per-user install) in Debian trixie and sid environments that scripts/meshlab_env.sh makes
# once from Debian's archive (a few minutes, 2 GB each, cached in /var/cache/pcskeleton).
# On Debian 12 it also runs the README's two commands on Debian 13 in a clean clone of the
# last commit (scripts/test_debian13_native.sh). CTest arguments ("-R io", ...) apply to
# every run; PCSKELETON_NEWER_MESHLAB=0 skips the newer MeshLab versions and Debian 13,
# PCSKELETON_SANITIZE=0 the sanitizer run. After the main build's tests it makes the Debian
# packages and checks them on a clean Debian of this release (scripts/make_packages.sh,
# scripts/test_packages.sh); PCSKELETON_PACKAGES=0 skips that.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "$(id -u)" -eq 0 ]; then SUDO=(); else SUDO=(sudo); fi  # chroots, mounts, debootstrap
bash "$ROOT/scripts/build.sh"
(cd "$ROOT/build" && ctest --output-on-failure -j1 "$@")

if [ "${PCSKELETON_PACKAGES:-1}" != 0 ]; then
  echo "== The Debian packages (build-deb/), installed and used on a clean Debian"
  bash "$ROOT/scripts/make_packages.sh" "$ROOT/build-deb/debs"
  "${SUDO[@]}" bash "$ROOT/scripts/test_packages.sh" "$ROOT/build-deb/debs"
fi

if [ "${PCSKELETON_NEWER_MESHLAB:-1}" != 0 ]; then
  main_version="$(cut -c1-4 "$ROOT/deps/meshlab-src/ML_VERSION")"  # the build above: 2020 or 2022
  for version in 2022 2025; do
    [ "$version" != "$main_version" ] || continue
    echo "== The plugins in MeshLab $version (build-$version/)"
    "${SUDO[@]}" bash "$ROOT/scripts/test_newer_meshlab.sh" "$version" "$@"
  done
  if [ "$main_version" = 2020 ]; then
    echo "== The README's two commands on Debian 13 (MeshLab 2022.02), in a clean clone"
    "${SUDO[@]}" bash "$ROOT/scripts/test_debian13_native.sh" "$@"
  fi
fi

if [ "${PCSKELETON_SANITIZE:-1}" != 0 ]; then
  echo "== The same tests under AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/)"
  cmake -S "$ROOT" -B "$ROOT/build-sanitize" -DCMAKE_BUILD_TYPE=Release -DPCSKELETON_SANITIZE=ON \
    -DPCSKELETON_BUILD_PLUGINS=OFF -DPCSKELETON_BUILD_BENCH=OFF -DPCSKELETON_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$ROOT/build-sanitize" -j"$(nproc)"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  (cd "$ROOT/build-sanitize" && ctest --output-on-failure -j1 "$@")
fi
