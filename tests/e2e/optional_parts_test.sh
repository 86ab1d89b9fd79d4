#!/usr/bin/env bash
# The optional parts (the Python module, the test suites) are left out, one line each saying
# what to install, when what they need is missing; asked for explicitly, the error stays.
# "Missing" is CMake's CMAKE_DISABLE_FIND_PACKAGE_<package>, as on a machine without
# python3-dev or libgtest-dev. Configures only (a few seconds each).
# usage: optional_parts_test.sh SOURCE_DIR MESHLAB_SOURCE_DIR WORKDIR
set -euo pipefail
SOURCE="$1"; MESHLAB="$2"; WORK="$3"
rm -rf "$WORK"; mkdir -p "$WORK"
fail() { echo "FAIL: $*"; exit 1; }
configure() {  # build-dir, extra options...
  local dir="$WORK/$1"; shift
  cmake -S "$SOURCE" -B "$dir" -DMESHLAB_SOURCE_DIR="$MESHLAB" -DPCSKELETON_BUILD_PLUGINS=OFF \
    -DPCSKELETON_BUILD_BENCH=OFF -DCMAKE_DISABLE_FIND_PACKAGE_Python3=TRUE -DCMAKE_DISABLE_FIND_PACKAGE_GTest=TRUE "$@" \
    >"$dir.log" 2>&1
}

configure auto || { cat "$WORK/auto.log"; fail "the configuration without Python and GoogleTest failed"; }
grep -qx -- "-- pcskeleton: the Python module left out: install python3-dev and pybind11-dev (Debian), or -DPCSKELETON_BUILD_PYTHON=ON to require it" "$WORK/auto.log" \
  || { cat "$WORK/auto.log"; fail "no line saying the Python module was left out and what to install"; }
grep -qx -- "-- pcskeleton: the test suites left out: install libgtest-dev (Debian), or -DPCSKELETON_BUILD_TESTS=ON to require it" "$WORK/auto.log" \
  || { cat "$WORK/auto.log"; fail "no line saying the tests were left out and what to install"; }
! grep -q "pcskeleton_python\|_pcskeleton" "$WORK/auto/Makefile" "$WORK/auto/CMakeFiles/Makefile2" \
  || fail "the Python module is still built"
[ ! -e "$WORK/auto/CTestTestfile.cmake" ] || fail "the tests are still configured"

for part in PYTHON TESTS; do
  if configure "required_$part" -DPCSKELETON_BUILD_$part=ON; then
    fail "-DPCSKELETON_BUILD_$part=ON configured without what it needs"
  fi
  package=$([ $part = PYTHON ] && echo Python3 || echo GTest)
  grep -q "$package" "$WORK/required_$part.log" || { cat "$WORK/required_$part.log"; fail "the error does not name $package"; }
done
echo "optional parts: OK"
