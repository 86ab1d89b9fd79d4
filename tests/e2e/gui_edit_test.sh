#!/usr/bin/env bash
# GUI test of the Edit Skeleton tool: the build tree's MeshLab under Xvfb, driven by real
# mouse and keyboard events (xdotool). It opens a torus cloud and a 12-node ring skeleton,
# starts the tool from the Edit menu, finds the nodes on screen by their colour, deletes
# one, merges two, moves two and undoes the last move, enlarges a radius, shows the
# radius field, saves the layer with Export
# Skeleton and checks the saved graph node by node. Screenshots are kept in WORKDIR.
# usage: gui_edit_test.sh PREFIX WORKDIR [MESHLAB_VERSION]   (2020.09 by default; 2022.02, 2025.07)
set -euo pipefail
PREFIX="$1"; WORK="$2"; VERSION="${3:-2020.09}"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if [ -z "${PCSKELETON_IN_XVFB:-}" ]; then
  # A fixed screen size: the menu positions below depend on it.
  PCSKELETON_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x900x24" "$0" "$@"
fi

rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"
export XDG_CONFIG_HOME="$WORK/config"  # no saved window layout from an earlier run
PY=/usr/bin/python3
NODES="$PY $HERE/find_nodes.py"
source "$HERE/gui_lib.sh"
# Screen position of the ring node at `angle` degrees, from the last screenshot.
node_at() { $NODES "$SHOT" position "$1"; }
nodes_on_screen() { SEEN="$($NODES "$SHOT" count)"; [ "$SEEN" = "$1 $2" ]; }
expect_nodes() {  # yellow, red, screenshot name
  wait_screen 20 "$3" "expected $1 unselected and $2 selected nodes on screen" nodes_on_screen "$1" "$2"
}

# Where things are in a 1280x900 MeshLab window at the top left, read off screenshots of
# each version: Filters, Filters > Point Set, Export Skeleton in it, and the tool panel's
# "Reconstruct from skeleton" button.
case "$VERSION" in
  2020.*) FILTERS=(120 10); POINT_SET=(160 386); EXPORT_ITEM=(640 512); RECONSTRUCT_BUTTON=(1074 326) ;;
  2022.*|2025.*) FILTERS=(116 9); POINT_SET=(150 355); EXPORT_ITEM=(634 493); RECONSTRUCT_BUTTON=(1082 293) ;;
  *) echo "FAIL: no screen positions for MeshLab $VERSION"; exit 1 ;;
esac

$PY "$HERE/make_ring.py" 0.25 --torus  # a torus cloud and its centre circle, 12 nodes

"$PREFIX/bin/meshlab" "$WORK/torus.ply" "$WORK/ring.ply" >"$WORK/meshlab.log" 2>&1 &
MESHLAB_PID=$!
trap 'kill $MESHLAB_PID 2>/dev/null || true' EXIT
wait_window "MeshLab 20" 30
WINDOW="$(xdotool search --onlyvisible --name "MeshLab 20" | head -1)"
place_window "$WINDOW" 1280 900

# Edit Skeleton (the ring is the current layer): the menu's last entry, as edit plugins are
# listed by file name; 2020.09 has it higher up.
if [[ "$VERSION" == 2020.* ]]; then
  open_menu 74 10 128 434  # Edit
  shot edit-menu
  click 128 434 0
else
  open_menu 74 10 74 40    # Edit
  shot edit-menu
  xdotool key Up Return
fi
expect_nodes 12 0 tool-started

# Hovering: the panel names the branch of the node under the cursor (below its buttons), and
# no longer once the cursor leaves it for the empty middle of the ring.
NOHOVER="$SHOT"
panel_text_changed() {  # yes|no: the panel's text below the buttons differs from before the hover
  $PY - "$NOHOVER" "$SHOT" "$1" <<'PY'
import sys
from PIL import Image, ImageChops
before, now = (Image.open(p).convert("RGB").crop((865, 340, 1280, 600)) for p in sys.argv[1:3])
changed = ImageChops.difference(before, now).getbbox() is not None
sys.exit(0 if changed == (sys.argv[3] == "yes") else 1)
PY
}
read -r x y <<<"$(node_at 0)"
xdotool mousemove "$x" "$y"
wait_screen 20 hovering "the panel does not name the branch under the cursor" panel_text_changed yes
read -r cx cy < "$WORK/ring_centre.txt"
xdotool mousemove "${cx%.*}" "${cy%.*}"
wait_screen 20 hover-left "the panel still names a branch with no node under the cursor" panel_text_changed no

read -r x y <<<"$(node_at 0)"
click "$x" "$y"
expect_nodes 11 1 node-selected
xdotool key Delete
expect_nodes 11 0 node-deleted

read -r x y <<<"$(node_at 90)"; click "$x" "$y" 0.5
read -r x y <<<"$(node_at 120)"
xdotool keydown shift mousemove "$x" "$y" click 1 keyup shift
expect_nodes 9 2 two-selected
xdotool key m
expect_nodes 9 1 merged

drag() {  # from x y, by dx dy pixels, in steps as a hand would
  xdotool mousemove "$1" "$2" mousedown 1
  for i in 1 2 3 4 5; do xdotool mousemove $(($1 + $3 * i / 5)) $(($2 + $4 * i / 5)); sleep 0.1; done
  xdotool mouseup 1; sleep 0.8
}
read -r x y <<<"$(node_at 180)"; drag "$x" "$y" -60 0      # the node at -x, outwards
shot moved-left
read -r x y <<<"$(node_at 270)"; drag "$x" "$y" 0 60       # the node at -y, outwards
shot moved-down
xdotool key ctrl+z; sleep 0.8                               # undo the second move only
shot undone
xdotool key plus; sleep 0.8                                 # the -y node, still selected: radius x 1.1
xdotool key r
wait_screen_still radius-field 20  # the view before the reconstruction, fully drawn
BEFORE="$SHOT"

# Reconstruct from skeleton (the panel's button): a surface layer appears in the view,
# once the reconstruction is done and drawn (polled: it takes seconds, more on a busy machine).
surface_in_view() {
  SEEN="$($PY - "$BEFORE" "$SHOT" <<'PY'
import sys
from PIL import Image, ImageChops
before, after = (Image.open(p).convert("RGB").crop((0, 75, 860, 775)) for p in sys.argv[1:3])
changed = sum(1 for value in ImageChops.difference(before, after).convert("L").getdata() if value > 40)
share = changed / (860 * 700)
print(f"{share:.1%} of the view's pixels changed")
sys.exit(0 if share > 0.05 else 1)
PY
)"
}
click "${RECONSTRUCT_BUTTON[@]}" 0
wait_screen 120 reconstructed "no reconstructed surface appeared in the view" surface_in_view

# Save the layer: Filters > Point Set > Export Skeleton, with its default file name.
open_menu "${FILTERS[@]}" "${POINT_SET[@]}"
open_menu "${POINT_SET[@]}" "${EXPORT_ITEM[@]}"
click "${EXPORT_ITEM[@]}" 0
wait_window "Export Skeleton" 10
shot export-dialog
dialog_buttons "Export Skeleton"
click "${APPLY[@]}" 2
click "${CLOSE[@]}"
SAVED="$WORK/ring_1.ply"  # the default never replaces the file the skeleton came from
wait_file "$SAVED" 20 "the edited skeleton was not saved to $SAVED"
cmp -s "$SAVED" ring.ply && fail "the saved skeleton is the original"

$PY "$HERE/skeleton_graph.py" check "$SAVED" --cycles 0 --tips 2 --components 1
$PY - "$SAVED" <<'PY' || fail "the saved skeleton is not the edited one"
import math, sys
lines = open(sys.argv[1]).read().splitlines()
start = lines.index("end_header") + 1
count = next(int(l.split()[2]) for l in lines if l.startswith("element vertex"))
rows = [[float(x) for x in l.split()] for l in lines[start:start + count]]
nodes = [tuple(r[:3]) for r in rows]
radius = {tuple(r[:3]): r[4] for r in rows}  # x y z quality radius
def near(p, q, tolerance=1e-3):
    return math.dist(p, q) < tolerance
expected_fixed = [(math.cos(math.radians(a)), math.sin(math.radians(a)), 0) for a in (30, 60, 150, 210, 240, 270, 300, 330)]
problems = []
if count != 10:
    problems.append(f"{count} nodes, expected 10 (12, one deleted, two merged)")
if any(near(n, (1, 0, 0)) for n in nodes):
    problems.append("the deleted node at +x is still there")
merged = (math.cos(math.radians(90)) / 2 + math.cos(math.radians(120)) / 2, (1 + math.sin(math.radians(120))) / 2, 0)
if not any(near(n, merged) for n in nodes):
    problems.append(f"no merged node at {merged}")
for p in expected_fixed:  # includes 270: its move was undone
    if not any(near(n, p) for n in nodes):
        problems.append(f"node {p} moved or vanished")
for n in nodes:
    wanted = 0.275 if near(n, (0, -1, 0)) else 0.25
    if abs(radius[n] - wanted) > 1e-5:
        problems.append(f"node {n} has radius {radius[n]}, expected {wanted}")
left = [n for n in nodes if n[0] < -1.05 and abs(n[1]) < 0.05 and abs(n[2]) < 1e-3]
if len(left) != 1:
    problems.append("the node at -x was not moved outwards in the screen plane")
print("\n".join(problems) or f"saved skeleton: {count} nodes as edited; node at -x now at x = {left[0][0]:.3f}")
sys.exit(1 if problems else 0)
PY
echo "GUI skeleton editing: OK (screenshots in $WORK)"
