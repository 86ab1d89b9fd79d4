#!/usr/bin/env bash
# Regenerates the troubleshooting pictures of docs/quality-and-troubleshooting.md (docs/troubleshooting/*.png): typical
# failures on the robustness suite's cases, and the parameter that fixes each. Needs a
# build (scripts/build.sh). Usage: bash scripts/troubleshooting_pictures.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BENCH="$ROOT/build/bench/bench_robustness"
PCSKELETON="$ROOT/build/cli/pcskeleton"
RENDER="/usr/bin/python3 $ROOT/scripts/render_points.py"
PICTURES="$ROOT/docs/troubleshooting"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
mkdir -p "$PICTURES"
cd "$WORK"

# picture NAME TITLE SHAPE CONDITION "LABEL|OPTIONS" "LABEL|OPTIONS"
# (VIEW=ELEVATION,AZIMUTH before it: another viewpoint than render_points.py's)
picture() {
  local name="$1" title="$2" shape="$3" condition="$4"
  shift 4
  "$BENCH" --write "$shape" "$condition" "$name.xyz"
  local panels=("$name.xyz:input ($condition)")
  local i=0
  for run in "$@"; do
    local label="${run%%|*}" options="${run#*|}"
    # shellcheck disable=SC2086
    "$PCSKELETON" "$name.xyz" -o "$name-$i.ply" --quiet $options
    panels+=("$name-$i.ply:$label")
    i=$((i + 1))
  done
  $RENDER ${VIEW:+--view "$VIEW"} "$PICTURES/$name.png" "$title" "${panels[@]}"
  echo "wrote $PICTURES/$name.png"
}

picture short-limbs "Limbs end short of the shape: tip extension (on by default)" \
  "tree" "clean" "--no-extend-tips|--no-extend-tips" "default|"
picture not-converged "Contraction stopped early: raise --iterations" \
  "ring" "clean" "--iterations 1|--iterations 1" "default|"
picture spacing-too-large "Node spacing too large merges loops: lower --radius" \
  "genus 2 (figure eight)" "clean" "--radius 0.3|--radius 0.3" "default (0.02)|"
picture outliers "Outliers make false loops; outlier detection (on by default) sets them aside" \
  "Y branch" "outliers 1%" "--paper|--paper" "default|"
VIEW=90,-90 picture one-view-recentring "One-view scan: the paper's nodes hug the visible wall; re-centring (on by default) moves them to the axis" \
  "ring" "scan 1 view" "--paper|--paper" "--no-recentre|--no-recentre" "default|"
picture one-view-gaps "One-view scan: hidden stretches leave the skeleton in pieces; gap bridging (on by default) joins them" \
  "elephant (libcgal-demo)" "scan 1 view" "--gap-limit 0|--gap-limit 0" "default|"
picture one-view-thin-legs "One-view scan: a thin leg hidden where it meets a thick body is joined across the gap to the body's wall" \
  "thin legs, thick body" "1 view, side" "--gap-limit 0|--gap-limit 0" "default|"
# Seen as the scanner saw it (from (1, 0.3, -0.55)): the arm in front of the body.
VIEW=28,-163 picture one-view-shadow "One-view scan: an arm in front of the body leaves a shadow that contracts to a false loop; refinement (on by default) opens it" \
  "figure, arms close" "1 view, side" "--min-hole 0|--min-hole 0" "default|"
VIEW=90,-90 picture loops-over-data "Loops round points, not holes: refinement (on by default) opens them; --min-hole 0 keeps them" \
  "genus 2 (figure eight)" "outliers 5%" "--min-hole 0|--min-hole 0" "default|"

# The paper's corn scan (tests/data/scans), seen from the side: the skeleton stays on the
# curled leaves. BEFORE=/path/to/an/older/pcskeleton adds that build's skeleton as a panel
# (docs/troubleshooting/leaves.png has the one of a699d79, before the neighbour test).
corn="$ROOT/tests/data/scans/corn_v12108.ply"
PYTHONPATH="$ROOT/build/python" /usr/bin/python3 -c \
  "import pcskeleton, sys; pcskeleton.write_points(pcskeleton.read_points(sys.argv[1]), 'corn.xyz')" "$corn"
panels=("corn.xyz:input (the paper's corn scan)")
if [ -n "${BEFORE:-}" ]; then
  "$BEFORE" "$corn" -o corn-before.ply --quiet
  panels+=("corn-before.ply:before")
fi
"$PCSKELETON" "$corn" -o corn-default.ply --quiet
panels+=("corn-default.ply:default")
$RENDER --view 10,0 "$PICTURES/leaves.png" \
  "A curled leaf is not a tube: re-centring leaves the nodes on the leaves" "${panels[@]}"
echo "wrote $PICTURES/leaves.png"
