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
# last commit (scripts/test_debian13_native.sh); that run's own MeshLab is 2022.02 and its
# test suite holds the tests of the MeshLab 2022.02 build, which is therefore not made a
# second time. At the end it prints how long each stage took. CTest arguments ("-R io", ...) apply to
# every run; PCSKELETON_NEWER_MESHLAB=0 skips the newer MeshLab versions and Debian 13,
# PCSKELETON_SANITIZE=0 the sanitizer run. After the main build's tests it makes the Debian
# packages and checks them on a clean Debian of this release (scripts/make_packages.sh,
# scripts/test_packages.sh); PCSKELETON_PACKAGES=0 skips that.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "$(id -u)" -eq 0 ]; then SUDO=(); else SUDO=(sudo); fi  # chroots, mounts, debootstrap

# "== title" for each stage, and the seconds each took, listed at the end (also on failure).
stage_titles=() stage_seconds=() stage_start=$SECONDS
stage() {
  [ ${#stage_titles[@]} -eq 0 ] || stage_seconds+=($((SECONDS - stage_start)))
  stage_titles+=("$1") stage_start=$SECONDS
  echo "== $1"
}
stage_summary() {
  local status=$? i
  stage_seconds+=($((SECONDS - stage_start)))
  echo "== Time per stage (seconds)"
  for i in "${!stage_titles[@]}"; do printf '%6d  %s\n' "${stage_seconds[$i]}" "${stage_titles[$i]}"; done
  printf '%6d  in all\n' "$SECONDS"
  return $status
}
trap stage_summary EXIT

stage "Setup and the main build (build/)"
bash "$ROOT/scripts/build.sh"
stage "The main build's tests"
(cd "$ROOT/build" && ctest --output-on-failure -j1 "$@")

if [ "${PCSKELETON_PACKAGES:-1}" != 0 ]; then
  stage "The Debian packages (build-deb/), installed and used on a clean Debian"
  bash "$ROOT/scripts/make_packages.sh" "$ROOT/build-deb/debs"
  "${SUDO[@]}" bash "$ROOT/scripts/test_packages.sh" "$ROOT/build-deb/debs"
fi

if [ "${PCSKELETON_NEWER_MESHLAB:-1}" != 0 ]; then
  main_version="$(cut -c1-4 "$ROOT/deps/meshlab-src/ML_VERSION")"  # the build above: 2020 or 2022
  for version in 2022 2025; do
    [ "$version" != "$main_version" ] || continue
    # On Debian 12 the Debian 13 run below builds against MeshLab 2022.02 and runs its tests.
    [ "$version:$main_version" != 2022:2020 ] || continue
    stage "The plugins in MeshLab $version (build-$version/)"
    "${SUDO[@]}" bash "$ROOT/scripts/test_newer_meshlab.sh" "$version" "$@"
  done
  if [ "$main_version" = 2020 ]; then
    stage "The README's two commands on Debian 13 (MeshLab 2022.02), in a clean clone"
    "${SUDO[@]}" bash "$ROOT/scripts/test_debian13_native.sh" "$@"
  fi
fi

if [ "${PCSKELETON_SANITIZE:-1}" != 0 ]; then
  stage "The library, CLI and unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/)"
  cmake -S "$ROOT" -B "$ROOT/build-sanitize" -DCMAKE_BUILD_TYPE=Release -DPCSKELETON_SANITIZE=ON \
    -DPCSKELETON_BUILD_PLUGINS=OFF -DPCSKELETON_BUILD_BENCH=OFF -DPCSKELETON_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$ROOT/build-sanitize" -j"$(nproc)"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  # Two at a time: no GUI here, and the instrumented tests leave a core idle between
  # their parallel parts (the e2e timeouts of this build allow for the sharing).
  (cd "$ROOT/build-sanitize" && ctest --output-on-failure -j2 "$@")
fi
