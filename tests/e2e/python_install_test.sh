#!/usr/bin/env bash
# `cmake --install` puts the Python package where Debian's python3 finds it under the
# prefix (<prefix>/lib/python3.X/dist-packages), and it works from there alone.
# usage: python_install_test.sh BUILD_DIR PYTHON WORKDIR
set -euo pipefail
BUILD="$1"; PYTHON="$2"; WORK="$3"
rm -rf "$WORK"; mkdir -p "$WORK"
# Only the Python part: the plugins would go to MeshLab's own folder whatever the prefix.
cmake --install "$BUILD" --prefix "$WORK/prefix" --component python >/dev/null
site="$(find "$WORK/prefix/lib" -maxdepth 2 -name dist-packages -type d)"
[ -f "$site/pcskeleton/__init__.py" ] || { echo "FAIL: no pcskeleton package under $WORK/prefix/lib"; exit 1; }
# The prefix's dist-packages is the one Debian's python3 searches for its prefix (/usr/local).
expected="$("$PYTHON" -c 'import sys; print("lib/python%d.%d/dist-packages" % sys.version_info[:2])')"
[ "$site" = "$WORK/prefix/$expected" ] || { echo "FAIL: installed in $site, Debian's python3 looks in $expected"; exit 1; }
cd "$WORK"
PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$PYTHON" - <<'PY'
import numpy as np, pcskeleton
assert pcskeleton.__file__.startswith(__import__("os").getcwd()), pcskeleton.__file__
rng = np.random.default_rng(0)
t, u = rng.uniform(0, 2 * np.pi, (2, 3000))
points = np.stack([(1 + 0.25 * np.cos(u)) * np.cos(t), (1 + 0.25 * np.cos(u)) * np.sin(t), 0.25 * np.sin(u)], 1)
assert pcskeleton.skeletonize(points).report["topology"]["cycles"] == 1
PY
echo "python install: OK"
