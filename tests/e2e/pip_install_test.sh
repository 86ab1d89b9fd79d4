#!/usr/bin/env bash
# pip: `pip install .` from the source tree into a fresh virtual environment, offline with
# Debian's build tools (--no-build-isolation --no-index; numpy from Debian through
# --system-site-packages), then import, a skeleton, `pip uninstall`; and
# `python3 -m build --wheel --no-isolation` makes a wheel that installs the same way.
# setuptools builds in SOURCE/build-python (setup.cfg), beside CMake's build/.
# usage: pip_install_test.sh SOURCE_DIR PYTHON WORKDIR
set -euo pipefail
SRC="$1"; PYTHON="$2"; WORK="$3"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK"; mkdir -p "$WORK"
version="$(sed -n 's/^project(pcskeleton VERSION \([0-9.]*\).*/\1/p' "$SRC/CMakeLists.txt")"
"$PYTHON" -m venv --system-site-packages "$WORK/venv"
VENV_PYTHON="$WORK/venv/bin/python"
unset PYTHONPATH  # the venv alone, not the build tree's module

skeleton_check() {  # the installed module, from the venv's site-packages
  (cd "$WORK" && "$VENV_PYTHON" - "$WORK/venv" "$version" <<'PY'
import sys, numpy as np, pcskeleton
venv, version = sys.argv[1:]
assert pcskeleton.__file__.startswith(venv), f"{pcskeleton.__file__} is not in {venv}"
assert pcskeleton.__version__ == version, (pcskeleton.__version__, version)
t, u = np.random.default_rng(0).uniform(0, 2 * np.pi, (2, 3000))
points = np.stack([(1 + 0.25 * np.cos(u)) * np.cos(t), (1 + 0.25 * np.cos(u)) * np.sin(t), 0.25 * np.sin(u)], 1)
assert pcskeleton.skeletonize(points).report["topology"]["cycles"] == 1
PY
  )
}
# Whether the venv has its own pcskeleton (one installed system-wide may show through).
in_venv() {
  (cd "$WORK" && "$VENV_PYTHON" -c "import sys, pcskeleton; sys.exit(not pcskeleton.__file__.startswith(sys.prefix))" 2>/dev/null)
}

! in_venv || fail "the new venv already has pcskeleton"
(cd "$SRC" && "$VENV_PYTHON" -m pip install --no-build-isolation --no-index . >"$WORK/pip.log" 2>&1) \
  || { tail -40 "$WORK/pip.log"; fail "pip install ."; }
skeleton_check || fail "the module pip installed"
"$VENV_PYTHON" -m pip uninstall -y pcskeleton >"$WORK/uninstall.log" 2>&1 || { cat "$WORK/uninstall.log"; fail "pip uninstall"; }
! in_venv || fail "pcskeleton is still in the venv after pip uninstall"
[ -z "$(find "$WORK/venv" -path '*site-packages/pcskeleton*' -print -quit)" ] || fail "pip uninstall left files behind"

(cd "$SRC" && "$VENV_PYTHON" -m build --wheel --no-isolation --outdir "$WORK/wheels" . >"$WORK/wheel.log" 2>&1) \
  || { tail -40 "$WORK/wheel.log"; fail "python3 -m build --wheel"; }
wheel="$(ls "$WORK"/wheels/pcskeleton-"$version"-*.whl)" || fail "no wheel of version $version"
"$VENV_PYTHON" -m pip install --no-index "$wheel" >"$WORK/pip_wheel.log" 2>&1 || { cat "$WORK/pip_wheel.log"; fail "pip install the wheel"; }
skeleton_check || fail "the module installed from the wheel"
echo "pip install, uninstall and wheel: OK"
