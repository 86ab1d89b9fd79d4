#!/usr/bin/env bash
# The C++ package: `cmake --install BUILD --component dev` into a scratch prefix, then a
# user's project (tests/package) finds it with find_package(pcskeleton), builds against
# its headers and library alone (not the source tree) and gets a torus's one cycle and the
# version from the installed <pcskeleton/version.h>.
# usage: cmake_package_test.sh BUILD_DIR SOURCE_DIR WORKDIR VERSION
set -euo pipefail
BUILD="$1"; SRC="$2"; WORK="$3"; VERSION="$4"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK"; mkdir -p "$WORK"
cmake --install "$BUILD" --prefix "$WORK/prefix" --component dev >"$WORK/install.log"
for f in include/pcskeleton/curve_skeleton.h lib/cmake/pcskeleton/pcskeletonConfig.cmake; do
  [ -f "$WORK/prefix/$f" ] || fail "$f is not installed"
done
[ -n "$(find "$WORK/prefix" -name 'libpcskeleton.a')" ] || fail "libpcskeleton.a is not installed"
# Nothing but the package's own files: no CGAL, CHOLMOD or vcglib header among them.
if grep -rlE '#include *[<"](CGAL|vcg)/|cholmod' "$WORK/prefix/include"; then fail "a private dependency in the public headers"; fi
cmake -S "$SRC/tests/package" -B "$WORK/consumer" -DCMAKE_PREFIX_PATH="$WORK/prefix" -DCMAKE_BUILD_TYPE=Release \
  >"$WORK/configure.log" 2>&1 || { cat "$WORK/configure.log"; fail "find_package(pcskeleton) failed"; }
cmake --build "$WORK/consumer" >"$WORK/build.log" 2>&1 || { cat "$WORK/build.log"; fail "the user's program did not build"; }
# It was built from the installed headers, not from the source tree.
grep -rq "$SRC/vcg_ext" "$WORK/consumer/CMakeFiles" && fail "the user's program saw the source tree"
out="$("$WORK/consumer/torus_skeleton")"
[ "$out" = "pcskeleton $VERSION: cycles 1" ] || fail "the program said '$out', not 'pcskeleton $VERSION: cycles 1'"
# A version the package does not have is refused.
cat >"$WORK/wrong_version.cmake" <<CMAKE
set(CMAKE_PREFIX_PATH "$WORK/prefix")
find_package(pcskeleton 9.0 CONFIG QUIET)
if(pcskeleton_FOUND)
  message(FATAL_ERROR "version 9.0 was accepted")
endif()
CMAKE
cmake -P "$WORK/wrong_version.cmake" || fail "a wrong version was accepted"
echo "cmake package: OK"
