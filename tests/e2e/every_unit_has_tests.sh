#!/usr/bin/env bash
# Every unit of the library (each .cpp under vcg_ext/pcskeleton/<stage>/) has its test file,
# tests/unit/<stage>/<unit>_test.cpp, and every such file is built into the unit tests.
# usage: every_unit_has_tests.sh LIBRARY_DIR TESTS_DIR
set -euo pipefail
library="$1/pcskeleton"
tests="$2"
missing=0
while IFS= read -r source; do
  unit="${source#"$library"/}"
  unit="${unit%.cpp}"
  if [ ! -f "$tests/unit/${unit}_test.cpp" ]; then
    echo "no test file for the unit $unit: expected tests/unit/${unit}_test.cpp"
    missing=1
  elif ! grep -q "unit/${unit}_test.cpp" "$tests/CMakeLists.txt"; then
    echo "tests/unit/${unit}_test.cpp is not built: add it to tests/CMakeLists.txt"
    missing=1
  fi
done < <(find "$library" -name '*.cpp' | sort)
[ "$missing" -eq 0 ] && echo "every unit of the library has a test file"
exit "$missing"
