#!/usr/bin/env bash
# Installs what is missing (scripts/setup.sh), then configures and builds into build/.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$ROOT/scripts/setup.sh"
# The Python module and the tests are required here (setup.sh installed what they need):
# elsewhere they are left out when their packages are missing, with a line saying which.
cmake -S "$ROOT" -B "$ROOT/build" -DCMAKE_BUILD_TYPE=Release -DPCSKELETON_BUILD_PYTHON=ON -DPCSKELETON_BUILD_TESTS=ON >/dev/null
cmake --build "$ROOT/build" -j"$(nproc)"
