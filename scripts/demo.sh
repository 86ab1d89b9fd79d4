#!/usr/bin/env bash
# The main job on a real model: the curve skeleton of the "elephant" shipped in Debian's
# libcgal-demo (its vertices taken as a point cloud, faces ignored), computed by MeshLab's
# own meshlabserver with our plugin and the shipped script; then a picture of the input,
# the contracted points and the skeleton.
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
ORIGINAL="$OUT/${NAME}_input.ply"
CONTRACTED="$OUT/${NAME}_contracted.ply"
SEGMENTS="$OUT/${NAME}_segments.ply"
SKELETON="$OUT/${NAME}_skeleton.ply"
PICTURE="$OUT/${NAME}_skeleton.png"
LOG="$OUT/${NAME}_meshlabserver.log"

# The shipped script, with the contracted layer kept for the picture and the skeleton
# written into out/demo (the script alone writes it next to the input, never replacing a
# file; the demo replaces its own previous results).
SCRIPT="$OUT/${NAME}_pipeline.mlx"
sed -e 's/name="addContractedLayer" value="false"/name="addContractedLayer" value="true"/' \
    -e "s|name=\"fileName\" value=\"\"|name=\"fileName\" value=\"$SKELETON\"|" \
    -e 's/name="overwrite" value="false"/name="overwrite" value="true"/' \
  "$ROOT/filter_pcskeleton/scripts/compute_curve_skeleton.mlx" >"$SCRIPT"

echo "Computing the curve skeleton of $INPUT with meshlabserver (build/meshlab) ..."
# meshlabserver needs an X server with GLX even for CPU filters, hence xvfb-run.
(cd "$OUT" && xvfb-run -a "$ROOT/build/meshlab/bin/meshlabserver" -i "$INPUT" \
  -o "$ORIGINAL" -l 0 -m sa -o "$CONTRACTED" -l 1 -m sa -o "$SEGMENTS" -l 2 -m vc sa \
  -s "$SCRIPT" >"$LOG" 2>&1) || { cat "$LOG" >&2; echo "meshlabserver failed (log: $LOG)" >&2; exit 1; }
sed -n 's/^LOG: [0-9]* /  /p' "$LOG"  # the filters' log lines

/usr/bin/python3 "$ROOT/scripts/render_points.py" "$PICTURE" \
  "Curve skeleton by Laplacian contraction (Cao et al. 2010) of $NAME" \
  "$ORIGINAL:input" "$CONTRACTED:contracted" "$SKELETON:skeleton"

echo
echo "Skeleton (PLY with edges and radius): $SKELETON"
echo "Points coloured by node:              $SEGMENTS"
echo "Contracted points:                    $CONTRACTED"
echo "Picture:                              $PICTURE"
echo "meshlabserver log:                    $LOG"
