#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every test with CTest
# (unit tests, the plugin loaded from its .so, meshlabserver and the GUI under Xvfb).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$ROOT/scripts/build.sh"
cd "$ROOT/build"
ctest --output-on-failure -j1 "$@"
