#!/usr/bin/env bash
# The skeleton scripts through meshlabserver (the build tree's MeshLab prefix) on real
# models from Debian's libcgal-demo with known topology, the written files re-read by
# MeshLab itself and by an independent reader; the paper's 9-handle torus when ../shared
# is present.
# usage: meshlabserver_skeleton_test.sh MESHLABSERVER SCRIPTS_DIR WORKDIR
set -euo pipefail
MESHLABSERVER="$1"; SCRIPTS="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
PAPER_INPUTS="$HERE/../../../shared/data/paper-inputs"
GRAPH="/usr/bin/python3 $HERE/skeleton_graph.py"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"

server() {  # log name, then meshlabserver arguments
  local log="$1"; shift
  xvfb-run -a "$MESHLABSERVER" "$@" >"$log" 2>&1 || { cat "$log"; echo "FAIL: meshlabserver $*"; exit 1; }
}

tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz data/meshes/double-torus-example.off data/meshes/knot.off

# The whole pipeline, one script: a double torus has two independent cycles. The skeleton
# is written next to the input, named after it; a second run takes the next free name.
mkdir -p double && cp data/meshes/double-torus-example.off double/
(cd double && server run.log -i double-torus-example.off -s "$SCRIPTS/compute_curve_skeleton.mlx")
grep -q "Skeleton 'double-torus-example skeleton', quality report" double/run.log \
  && grep -q "Skeleton: .*2 cycles" double/run.log && grep -q "Contraction: .*converged" double/run.log \
  || { cat double/run.log; echo "FAIL: the log has no quality report with 2 cycles and converged"; exit 1; }
$GRAPH check double/double-torus-example_skeleton.ply --cycles 2 --components 1
cp double/double-torus-example_skeleton.ply first_run.ply
(cd double && server run2.log -i double-torus-example.off -s "$SCRIPTS/compute_curve_skeleton.mlx")
cmp -s first_run.ply double/double-torus-example_skeleton.ply \
  || { echo "FAIL: a second run replaced the first run's skeleton"; exit 1; }
$GRAPH same double/double-torus-example_skeleton.ply double/double-torus-example_skeleton_1.ply
[[ "$(ls double)" != *partial* ]] || { echo "FAIL: a temporary file was left behind"; exit 1; }

# MeshLab reads the PLY back with its edges: exporting the re-opened file gives the same graph.
cat > reexport.mlx <<'MLX'
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Export Skeleton (PLY with edges, OBJ, CG)">
  <Param type="RichSaveFile" name="fileName" value="reopened.cg" ext="Skeleton (*.ply *.obj *.cg)"/>
  <Param type="RichBool" name="overwrite" value="false"/>
 </filter>
</FilterScript>
MLX
(cd double && server reopen.log -i double-torus-example_skeleton.ply -s ../reexport.mlx)
$GRAPH same double/double-torus-example_skeleton.ply double/reopened.cg

# A script naming the open file as its output is refused, even with 'overwrite'; the
# file is left as it was.
sed -e 's/value="reopened.cg"/value="double-torus-example_skeleton.ply"/' \
    -e 's/name="overwrite" value="false"/name="overwrite" value="true"/' reexport.mlx >clobber.mlx
(cd double && xvfb-run -a "$MESHLABSERVER" -i double-torus-example_skeleton.ply -s ../clobber.mlx >clobber.log 2>&1 || true)
grep -q "it is the file of the open layer" double/clobber.log \
  || { cat double/clobber.log; echo "FAIL: writing over the open file was not refused"; exit 1; }
cmp -s first_run.ply double/double-torus-example_skeleton.ply || { echo "FAIL: the open file was overwritten"; exit 1; }

# The branches script: the knot is one branch that closes its loop, logged and written.
mkdir -p branches && cp data/meshes/knot.off branches/
(cd branches && server run.log -i knot.off -s "$SCRIPTS/measure_branches.mlx")
grep -q "Branches of 'knot skeleton' (up axis +Z): 1 branch (order 1: 1)" branches/run.log \
  && grep -q "branch 0: order 1, from the root, .*closes a loop" branches/run.log \
  || { cat branches/run.log; echo "FAIL: the log does not give the knot's one branch closing its loop"; exit 1; }
[ "$(wc -l <branches/branches.csv)" = 2 ] && grep -q "^branch,parent,order," <<<"$(head -1 branches/branches.csv)" \
  || { cat branches/branches.csv; echo "FAIL: branches.csv is not a header and one branch"; exit 1; }
(cd branches && xvfb-run -a "$MESHLABSERVER" -i knot.off -s "$SCRIPTS/measure_branches.mlx" >again.log 2>&1 || true)
grep -q "exists already" branches/again.log || { cat branches/again.log; echo "FAIL: branches.csv was replaced"; exit 1; }

# Contraction and thinning as two filters: a knot is one loop without tips.
mkdir -p knot && cp data/meshes/knot.off knot/
(cd knot && server run.log -i knot.off -s "$SCRIPTS/contract_then_thin.mlx")
$GRAPH check knot/knot_skeleton.obj --cycles 1 --tips 0 --components 1
$GRAPH same knot/knot_skeleton.obj knot/knot_skeleton.cg

# A point layer is not a skeleton: the export refuses it and writes nothing.
(cd knot && xvfb-run -a "$MESHLABSERVER" -i knot.off -s ../reexport.mlx >refused.log 2>&1 || true)
[ ! -e knot/reopened.cg ] || { echo "FAIL: a point cloud was exported as a skeleton"; exit 1; }

if [ -f "$PAPER_INPUTS/9HandleTorus.off" ]; then
  # A copy: the skeleton is written next to its input, and ../shared is not ours to write.
  mkdir -p handles && cp "$PAPER_INPUTS/9HandleTorus.off" handles/
  (cd handles && server run.log -i 9HandleTorus.off -s "$SCRIPTS/compute_curve_skeleton.mlx")
  $GRAPH check handles/9HandleTorus_skeleton.ply --cycles 9 --components 1
else
  echo "SKIP paper input: $PAPER_INPUTS not present (it is only beside the developers' checkout)"
fi
echo "meshlabserver skeleton end-to-end: OK"
