#!/usr/bin/env bash
# The whole test suite, stage by stage:
#   1. installs what is missing, builds build/ and runs every test there with CTest (unit
#      tests, the plugin loaded from its .so, meshlabserver and the GUI under Xvfb);
#   2. builds the library, the CLI and the unit tests with AddressSanitizer and
#      UndefinedBehaviorSanitizer (leaks included) in build-sanitize/, a build that starts
#      in the background with 1's tests, and runs them again there: any sanitizer report
#      fails the test that triggered it;
#   3. makes the Debian packages and checks them on a clean Debian of this release
#      (scripts/make_packages.sh, scripts/test_packages.sh);
#   4. builds and tests the plugins against MeshLab 2022.02 and 2025.07 (meshlab-run, the GUI
#      under Xvfb, the per-user install) in Debian trixie and sid environments
#      (scripts/test_newer_meshlab.sh); on Debian 12 the 2022.02 build is not made, because
#   5. runs the README's two commands on Debian 13, whose own MeshLab is 2022.02, in a clean
#      clone of the last commit (scripts/test_debian13_native.sh), and checks the Debian 13
#      packages there.
# The Debian environments of 3-5 (scripts/meshlab_env.sh, scripts/debian_minbase.sh: a few
# minutes and up to 2 GB each, cached in /var/cache/pcskeleton) are made from Debian's
# archive by a background job that starts with 1's tests (run one at a time, they leave a
# core mostly idle); each of 3-5 waits for that job. At the end it prints how long each
# stage took.
# CTest arguments ("-R io", ...) apply to every run; PCSKELETON_SANITIZE=0 skips 2,
# PCSKELETON_PACKAGES=0 skips 3, PCSKELETON_NEWER_MESHLAB=0 skips 4 and 5.
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
  stop_sanitize_build
  stop_environments
  stage_seconds+=($((SECONDS - stage_start)))
  echo "== Time per stage (seconds)"
  for i in "${!stage_titles[@]}"; do printf '%6d  %s\n' "${stage_seconds[$i]}" "${stage_titles[$i]}"; done
  printf '%6d  in all\n' "$SECONDS"
  return $status
}
trap stage_summary EXIT

# The Debian environments of the stages after the sanitizer run, made by one background job
# that those stages wait for. It starts with the main build's tests, which run one at a time
# and leave a core mostly idle, and runs at a lower priority, so that the sanitizer build
# keeps the cores where the job is not done by then. Its own process group: a failed run
# stops it. Only where no password is asked (as root, or with sudo that needs none);
# elsewhere each stage makes its own.
environments_pid="" environments_log=""
start_environments() {  # "minbase SUITE" and "meshlab VERSION" words
  [ $# -gt 0 ] || return 0
  [ ${#SUDO[@]} -eq 0 ] || sudo -n true 2>/dev/null || return 0
  environments_log="$(mktemp)"
  set -m
  "${SUDO[@]}" nice -n 10 bash -euo pipefail -c '
    root="$1"; shift
    while [ $# -gt 0 ]; do
      case "$1" in
        minbase) bash "$root/scripts/debian_minbase.sh" "$2" ;;
        meshlab) bash "$root/scripts/meshlab_env.sh" "$2" ;;
      esac >/dev/null
      shift 2
    done
    echo "[environments] ready in $SECONDS s"' _ "$ROOT" "$@" >"$environments_log" 2>&1 &
  environments_pid=$!
  set +m
}
wait_environments() {
  [ -n "$environments_pid" ] || return 0
  local waited=$SECONDS status=0
  wait "$environments_pid" || status=$?
  environments_pid=""
  if [ $status -ne 0 ]; then
    tail -40 "$environments_log"; rm -f "$environments_log"
    echo "FAIL: making the Debian environments (exit status $status)"; exit 1
  fi
  grep -E '^\[(meshlab_env|debian_minbase|environments)\]' "$environments_log" || true
  rm -f "$environments_log"
  echo "The Debian environments were made in the background; this run waited $((SECONDS - waited)) s for them"
}
stop_environments() {
  [ -n "$environments_pid" ] || return 0
  "${SUDO[@]}" kill -- -"$environments_pid" 2>/dev/null || true
  wait "$environments_pid" 2>/dev/null || true
  rm -f "$environments_log"
}

# The sanitizer build of stage 2 starts with the main build's tests, at the lowest priority:
# they run one at a time, and the build takes what they leave of the cores (as the
# environments' job does, at a higher priority than the build). When they are done it gets
# the usual priority back where renice may raise it (as root). Its own process group: a
# failed run stops it.
sanitize_pid="" sanitize_log=""
start_sanitize_build() {
  [ "${PCSKELETON_SANITIZE:-1}" != 0 ] || return 0
  cmake -S "$ROOT" -B "$ROOT/build-sanitize" -DCMAKE_BUILD_TYPE=Release -DPCSKELETON_SANITIZE=ON \
    -DPCSKELETON_BUILD_PLUGINS=OFF -DPCSKELETON_BUILD_BENCH=OFF -DPCSKELETON_BUILD_PYTHON=OFF >/dev/null
  sanitize_log="$(mktemp)"
  set -m
  nice -n 19 cmake --build "$ROOT/build-sanitize" -j"$(nproc)" >"$sanitize_log" 2>&1 &
  sanitize_pid=$!
  set +m
}
finish_sanitize_build() {
  local status=0
  renice -n 0 -g "$sanitize_pid" >/dev/null 2>&1 || true
  wait "$sanitize_pid" || status=$?
  sanitize_pid=""
  cat "$sanitize_log"; rm -f "$sanitize_log"
  [ $status -eq 0 ] || { echo "FAIL: the sanitizer build (exit status $status)"; exit 1; }
}
stop_sanitize_build() {
  [ -n "$sanitize_pid" ] || return 0
  kill -- -"$sanitize_pid" 2>/dev/null || true
  wait "$sanitize_pid" 2>/dev/null || true
  rm -f "$sanitize_log"
}

stage "Setup and the main build (build/)"
bash "$ROOT/scripts/build.sh"

# What the runs in Debian environments below test: the Debian packages on a clean Debian of
# this release; the plugins against each newer MeshLab; on Debian 12, the README's two
# commands on Debian 13, whose own MeshLab is 2022.02 (its test suite holds the tests of the
# MeshLab 2022.02 build, which is therefore not made a second time).
packages=0 newer_meshlab=() debian13=0 environments=()
if [ "${PCSKELETON_PACKAGES:-1}" != 0 ]; then
  packages=1
  environments+=(minbase "$(. /etc/os-release && echo "$VERSION_CODENAME")")
fi
if [ "${PCSKELETON_NEWER_MESHLAB:-1}" != 0 ]; then
  main_version="$(cut -c1-4 "$ROOT/deps/meshlab-src/ML_VERSION")"  # the build above: 2020 or 2022
  for version in 2022 2025; do
    [ "$version" != "$main_version" ] || continue
    [ "$version:$main_version" != 2022:2020 ] || continue
    newer_meshlab+=("$version")
    environments+=(meshlab "$version")
  done
  if [ "$main_version" = 2020 ]; then
    debian13=1
    environments+=(meshlab 2022 minbase trixie)
  fi
fi
start_environments "${environments[@]}"

stage "The main build's tests"
start_sanitize_build
(cd "$ROOT/build" && ctest --output-on-failure -j1 "$@")

if [ "${PCSKELETON_SANITIZE:-1}" != 0 ]; then
  stage "The library, CLI and unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/)"
  finish_sanitize_build
  # Two at a time: no GUI here, and the instrumented tests leave a core idle between
  # their parallel parts (the e2e timeouts of this build allow for the sharing).
  (cd "$ROOT/build-sanitize" && ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1" \
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" ctest --output-on-failure -j2 "$@")
fi

if [ $packages = 1 ]; then
  stage "The Debian packages (build-deb/), installed and used on a clean Debian"
  wait_environments
  bash "$ROOT/scripts/make_packages.sh" "$ROOT/build-deb/debs"
  "${SUDO[@]}" bash "$ROOT/scripts/test_packages.sh" "$ROOT/build-deb/debs"
fi
for version in "${newer_meshlab[@]}"; do
  stage "The plugins in MeshLab $version (build-$version/)"
  wait_environments
  "${SUDO[@]}" bash "$ROOT/scripts/test_newer_meshlab.sh" "$version" "$@"
done
if [ $debian13 = 1 ]; then
  stage "The README's two commands on Debian 13 (MeshLab 2022.02), in a clean clone"
  wait_environments
  "${SUDO[@]}" bash "$ROOT/scripts/test_debian13_native.sh" "$@"
fi
