#!/usr/bin/env bash
# MeshLab 2021+'s own plugin manager (through meshlab-run) loads our two plugins from the
# build tree's MeshLab prefix: no version or precision refusal, no load error, and the
# runner itself was built for the MeshLab version the tree says; Help > Plugin Info's vendor
# column gives our version.
# usage: plugins_load_test.sh MESHLAB_RUN VERSION PCSKELETON_VERSION
set -euo pipefail
RUNNER="$1"; VERSION="$2"; OURS="$3"
fail() { echo "FAIL: $*"; exit 1; }
grep -qx "meshlab-run for MeshLab $VERSION" <<<"$("$RUNNER" --version)" || fail "meshlab-run is not built for MeshLab $VERSION"
out="$("$RUNNER" --list-plugins 2>&1)" || { echo "$out"; fail "meshlab-run --list-plugins failed"; }
for plugin in FilterPCSkeleton EditSkeleton; do
  grep -q "^$plugin	.*/plugins/lib" <<<"$out" || { echo "$out"; fail "$plugin was not loaded"; }
  grep -q "^$plugin	.*	pcskeleton $OURS\$" <<<"$out" || { echo "$out"; fail "$plugin's vendor is not pcskeleton $OURS"; }
done
ours_lines="$(grep -i skeleton <<<"$out" || true)"
! grep -qi "unable\|error\|version\|precision" <<<"$ours_lines" \
  || { echo "$out"; fail "MeshLab reported a problem with our plugins"; }
stock="$(grep -c '/plugins/lib' <<<"$out")"
[ "$stock" -gt 20 ] || { echo "$out"; fail "only $stock plugins loaded: MeshLab's stock plugins are missing"; }
echo "MeshLab $VERSION loads both plugins ($stock plugins in all): OK"
