#!/usr/bin/env bash
# The main job on a real model: the curve skeleton of the "elephant" shipped in Debian's
# libcgal-demo (its vertices taken as a point cloud, faces ignored), computed by MeshLab's
# own meshlabserver with our plugin and the shipped script (MeshLab 2022+, which has no
# meshlabserver: our meshlab-run); then a picture of the input, the contracted points and
# the skeleton.
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
if [ -x "$ROOT/build/meshlab/bin/meshlabserver" ]; then
  # meshlabserver needs an X server with GLX even for CPU filters, hence xvfb-run.
  RUNNER=(xvfb-run -a "$ROOT/build/meshlab/bin/meshlabserver"); RUNNER_NAME=meshlabserver
else
  RUNNER=("$ROOT/build/meshlab/bin/meshlab-run"); RUNNER_NAME=meshlab-run
fi
LOG="$OUT/${NAME}_$RUNNER_NAME.log"

# The shipped script, with the contracted layer kept for the picture and the skeleton
# written into out/demo (the script alone writes it next to the input, never replacing a
# file; the demo replaces its own previous results).
SCRIPT="$OUT/${NAME}_pipeline.mlx"
sed -e 's/name="addContractedLayer" value="false"/name="addContractedLayer" value="true"/' \
    -e "s|name=\"fileName\" value=\"\"|name=\"fileName\" value=\"$SKELETON\"|" \
    -e 's/name="overwrite" value="false"/name="overwrite" value="true"/' \
  "$ROOT/filter_pcskeleton/scripts/compute_curve_skeleton.mlx" >"$SCRIPT"

echo "Computing the curve skeleton of $INPUT with $RUNNER_NAME (build/meshlab) ..."
(cd "$OUT" && "${RUNNER[@]}" -i "$INPUT" \
  -o "$ORIGINAL" -l 0 -m sa -o "$CONTRACTED" -l 1 -m sa -o "$SEGMENTS" -l 2 -m vc sa \
  -s "$SCRIPT" >"$LOG" 2>&1) || { cat "$LOG" >&2; echo "$RUNNER_NAME failed (log: $LOG)" >&2; exit 1; }
# The filters' log lines: meshlabserver marks them LOG:, meshlab-run prints them as they are.
if [ "$RUNNER_NAME" = meshlabserver ]; then
  sed -n 's/^LOG: [0-9]* /  /p' "$LOG"
else
  grep -vE '^(Mesh .* loaded|Starting script|filter: |Layer .* saved to| +[0-9]+% )' "$LOG" | sed 's/^/  /'
fi

/usr/bin/python3 "$ROOT/scripts/render_points.py" "$PICTURE" \
  "Curve skeleton by Laplacian contraction (Cao et al. 2010) of $NAME" \
  "$ORIGINAL:input" "$CONTRACTED:contracted" "$SKELETON:skeleton"

echo
echo "Skeleton (PLY with edges and radius): $SKELETON"
echo "Points coloured by node:              $SEGMENTS"
echo "Contracted points:                    $CONTRACTED"
echo "Picture:                              $PICTURE"
printf '%-38s%s\n' "$RUNNER_NAME log:" "$LOG"
