#!/usr/bin/env bash
# The main job on a real model: contracts the vertices of the "elephant" shipped in
# Debian's libcgal-demo (taken as a point cloud, faces ignored) with MeshLab's own
# meshlabserver and our plugin, then renders a picture of input and result.
# Usage: scripts/demo.sh [INPUT_FILE]   (any point cloud or mesh MeshLab reads)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/out/demo"

bash "$ROOT/scripts/build.sh" >/dev/null 2>&1 || bash "$ROOT/scripts/build.sh"  # quiet unless it fails
mkdir -p "$OUT"
if [ $# -ge 1 ]; then
  INPUT="$(realpath "$1")"
else
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$OUT" data/meshes/elephant.off
  INPUT="$OUT/data/meshes/elephant.off"
fi
NAME="$(basename "${INPUT%.*}")"
RESULT="$OUT/${NAME}_contracted.ply"
ORIGINAL="$OUT/${NAME}_input.ply"
PICTURE="$OUT/${NAME}_contraction.png"
LOG="$OUT/${NAME}_meshlabserver.log"

echo "Contracting $INPUT with meshlabserver (build/meshlab) ..."
# meshlabserver needs an X server with GLX even for CPU filters, hence xvfb-run.
xvfb-run -a "$ROOT/build/meshlab/bin/meshlabserver" -i "$INPUT" \
  -o "$ORIGINAL" -l 0 -m sa -o "$RESULT" -l x -m sa \
  -s "$ROOT/filter_pcskeleton/scripts/contract_point_cloud.mlx" >"$LOG" 2>&1 || {
  cat "$LOG" >&2; echo "meshlabserver failed (log: $LOG)" >&2; exit 1; }
sed -n 's/^LOG: [0-9]* /  /p' "$LOG"  # the filter's log lines

/usr/bin/python3 "$ROOT/scripts/render_points.py" "$PICTURE" \
  "Laplacian contraction (Cao et al. 2010) of $NAME" "$ORIGINAL:input" "$RESULT:contracted"

echo
echo "Input points:      $ORIGINAL"
echo "Contracted points: $RESULT"
echo "Picture:           $PICTURE"
echo "meshlabserver log: $LOG"
