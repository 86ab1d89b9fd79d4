#!/usr/bin/env bash
# Skeleton-driven reconstruction through meshlabserver and the shipped script: a torus
# scan with 20% of its ring missing, reconstructed with its ring skeleton (a closed
# genus-1 surface) and with the ring cut across the gap (genus 0); the one-shot
# scan_to_surface.mlx; a skeleton without radii is refused with the reason in the log
# and no file.
# usage: meshlabserver_reconstruct_test.sh MESHLABSERVER SCRIPT WORKDIR
set -euo pipefail
MESHLABSERVER="$1"; SCRIPT="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"

/usr/bin/python3 "$HERE/make_ring.py" 0.3 --torus --gap 0.2  # torus.ply, ring.ply, ring_cut.ply

# Writes surface_<skeleton>.off and checks it: closed, 2-manifold, one component, the genus.
reconstruct() {
  local skeleton="$1" genus="$2"
  xvfb-run -a "$MESHLABSERVER" -i torus.ply "$skeleton.ply" -s "$SCRIPT" -o "surface_$skeleton.off" \
    >"$skeleton.log" 2>&1 || { cat "$skeleton.log"; echo "FAIL: meshlabserver with $skeleton"; exit 1; }
  grep -q "result: 1 component, genus $genus, closed 2-manifold" "$skeleton.log" \
    || { cat "$skeleton.log"; echo "FAIL: the log does not report genus $genus"; exit 1; }
  /usr/bin/python3 - "surface_$skeleton.off" "$genus" <<'PY'
import sys
from collections import Counter
words = open(sys.argv[1]).read().split()
assert words[0] == "OFF", words[0]
nv, nf = int(words[1]), int(words[2])
faces = words[4 + 3 * nv:]
uses = Counter()
for f in range(nf):
    count, *corners = map(int, faces[4 * f:4 * f + 4])
    assert count == 3
    for a, b in zip(corners, corners[1:] + corners[:1]):
        uses[min(a, b), max(a, b)] += 1
assert set(uses.values()) == {2}, "not closed or not 2-manifold: " + str(Counter(uses.values()))
genus = (2 - (nv - len(uses) + nf)) // 2
assert genus == int(sys.argv[2]), f"genus {genus}, expected {sys.argv[2]}"
print(f"{sys.argv[1]}: {nv} vertices, {nf} triangles, closed, genus {genus}: OK")
PY
}
reconstruct ring 1       # the skeleton's loop bridges the missing band
reconstruct ring_cut 0   # cut where the data is missing: the band stays open

# From the scan to its surface in one script: its own skeleton (a cut ring: the data has a
# gap) saved next to it, and a closed genus-0 surface as the current layer.
xvfb-run -a "$MESHLABSERVER" -i torus.ply -s "$(dirname "$SCRIPT")/scan_to_surface.mlx" -o surface_own.off \
  >own.log 2>&1 || { cat own.log; echo "FAIL: meshlabserver with scan_to_surface.mlx"; exit 1; }
[ -s torus_skeleton.ply ] || { cat own.log; echo "FAIL: the one-shot script did not save the skeleton"; exit 1; }
grep -q "result: 1 component, genus 0, closed 2-manifold" own.log \
  || { cat own.log; echo "FAIL: the one-shot script's surface is not closed and of genus 0"; exit 1; }
[ -s surface_own.off ] || { echo "FAIL: the one-shot script's surface was not saved"; exit 1; }

# A skeleton file without radii (quality 0): refused, the reason logged, nothing written.
sed -e 's/ 0\.3$/ 0/' ring.ply > flat.ply
xvfb-run -a "$MESHLABSERVER" -i torus.ply flat.ply -s "$SCRIPT" -o surface_flat.off >flat.log 2>&1 || true
grep -q "12 of 12 skeleton nodes have no radius" flat.log \
  || { cat flat.log; echo "FAIL: the refusal does not explain itself"; exit 1; }
[ ! -e surface_flat.off ] || { echo "FAIL: a refused reconstruction still wrote a file"; exit 1; }
echo "meshlabserver reconstruction: OK"
