#!/usr/bin/env bash
# The no-root install for MeshLab 2021+: `cmake --install BUILD --component user-plugins`
# into a scratch home puts both plugins in MeshLab's per-user plugin folder and meshlab-run
# in ~/.local/bin; that meshlab-run, outside the build tree, loads Debian's stock plugins
# and ours from the per-user folder and runs the shipped skeleton script.
# usage: user_install_test.sh BUILD_DIR VERSION SCRIPTS_DIR WORKDIR
set -euo pipefail
BUILD="$1"; VERSION="$2"; SCRIPTS="$3"; WORK="$4"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$WORK"; mkdir -p "$WORK/home"; cd "$WORK"
export HOME="$WORK/home"; unset XDG_DATA_HOME
cmake --install "$BUILD" --component user-plugins >install.log 2>&1 || { cat install.log; fail "the install failed"; }
FOLDER="$HOME/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/$VERSION"
for plugin in libfilter_pcskeleton.so libedit_skeleton.so; do
  [ -f "$FOLDER/$plugin" ] || fail "$plugin is not in $FOLDER"
done
RUNNER="$HOME/.local/bin/meshlab-run"
"$RUNNER" --list-plugins >plugins.txt 2>&1 || { cat plugins.txt; fail "meshlab-run --list-plugins failed"; }
grep -q "^FilterPCSkeleton	$FOLDER/libfilter_pcskeleton.so" plugins.txt \
  || { cat plugins.txt; fail "the filter plugin was not loaded from the per-user folder"; }
grep -q "^EditSkeleton	$FOLDER/libedit_skeleton.so" plugins.txt || fail "the editor was not loaded from $FOLDER"
grep -q "^IOBase	/usr/lib/" plugins.txt || { cat plugins.txt; fail "MeshLab's stock plugins were not loaded"; }
tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz data/meshes/double-torus-example.off
"$RUNNER" -i data/meshes/double-torus-example.off -s "$SCRIPTS/compute_curve_skeleton.mlx" >run.log 2>&1 \
  || { cat run.log; fail "the installed meshlab-run failed"; }
/usr/bin/python3 "$HERE/skeleton_graph.py" check data/meshes/double-torus-example_skeleton.ply --cycles 2 --components 1
echo "per-user install for MeshLab $VERSION: OK"
