#!/usr/bin/env bash
# The scriptable skeleton repairs through meshlabserver: the shipped example script on a
# ring skeleton whose every step has a known answer, and a refusal that leaves no file.
# usage: meshlabserver_edit_test.sh MESHLABSERVER SCRIPTS_DIR WORKDIR
set -euo pipefail
MESHLABSERVER="$1"; SCRIPTS="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
GRAPH="/usr/bin/python3 $HERE/skeleton_graph.py"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"

/usr/bin/python3 "$HERE/make_ring.py" 0.1  # 12 nodes on the unit circle, radius 0.1
$GRAPH check ring.ply --cycles 1 --tips 0

xvfb-run -a "$MESHLABSERVER" -i ring.ply -s "$SCRIPTS/repair_skeleton_example.mlx" >run.log 2>&1 \
  || { cat run.log; echo "FAIL: meshlabserver"; exit 1; }
# Cut (12 -> 11 nodes, 2 tips), closed again (1 cycle), three top nodes merged (9 nodes).
grep -q "delete 1 node; now 11 nodes, 10 edges, 1 component, 0 cycles, 2 tips" run.log \
  || { cat run.log; echo "FAIL: the log does not show the cut"; exit 1; }
# Written next to the input under the next free name: ring.ply itself is never replaced.
$GRAPH check ring.ply --cycles 1 --tips 0 --min-nodes 12
$GRAPH check ring_1.ply --cycles 1 --tips 0 --components 1 --min-nodes 9
/usr/bin/python3 - <<'PY'
import math
lines = open("ring_1.ply").read().splitlines()
start = lines.index("end_header") + 1
count = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
nodes = [[float(x) for x in l.split()] for l in lines[start:start + count]]
assert count == 9, f"{count} nodes, expected 9"
assert not any(x > 0.9 for x, *_ in nodes), "the node at +x was not deleted"
top = [n for n in nodes if n[1] > 0.8]
assert len(top) == 1 and abs(top[0][0]) < 1e-4 and abs(top[0][1] - (1 + math.sqrt(3)) / 3) < 1e-4, top
left = [n for n in nodes if n[0] < -0.9]
assert len(left) == 1 and abs(left[0][4] - 0.5) < 1e-6 and abs(left[0][3] - 0.5) < 1e-6, left
others = [n for n in nodes if n not in left and n not in top]
assert all(abs(n[4] - 0.1) < 1e-6 for n in others), "a radius changed that should not have"
print("repaired ring: OK")
PY

# Connecting needs exactly two selected nodes: with three the script stops, no file written.
sed -e 's/(x &gt; 0.8)/(x \&gt; 0.4)/' "$SCRIPTS/repair_skeleton_example.mlx" > refused.mlx
mkdir -p refused && cp ring.ply refused/
(cd refused && xvfb-run -a "$MESHLABSERVER" -i ring.ply -s ../refused.mlx >run.log 2>&1 || true)
grep -q "select exactly two nodes (4 selected)" refused/run.log \
  || { cat refused/run.log; echo "FAIL: the refusal does not explain itself"; exit 1; }
[ "$(ls refused)" = "$(printf 'ring.ply\nrun.log')" ] || { echo "FAIL: a refused script still wrote its result"; exit 1; }
echo "meshlabserver skeleton editing: OK"
