#!/usr/bin/env bash
# GUI smoke test: the build tree's MeshLab, under Xvfb, driven by real mouse and keyboard
# events (xdotool). It opens a model, finds our filters in Filters > Point Set, applies
# them from their dialogs (contraction; the whole skeleton pipeline; the skeleton export),
# exports the new layers and checks them against meshlabserver's results.
# Screenshots of every step are kept in WORKDIR as artifacts.
# usage: gui_smoke_test.sh PREFIX MLX WORKDIR
set -euo pipefail
PREFIX="$1"; MLX="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if [ -z "${PCSKELETON_IN_XVFB:-}" ]; then
  # A fixed screen size: the menu and dialog positions below depend on it.
  PCSKELETON_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi

rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"
# A fresh MeshLab configuration every time: saved window layouts would move the widgets.
export XDG_CONFIG_HOME="$WORK/config"
tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz data/meshes/elephant.off
INPUT="$WORK/data/meshes/elephant.off"
source "$HERE/gui_lib.sh"

"$PREFIX/bin/meshlab" "$INPUT" >"$WORK/meshlab.log" 2>&1 &
MESHLAB_PID=$!
trap 'kill $MESHLAB_PID 2>/dev/null || true' EXIT
wait_window "MeshLab 20" 30
wait_screen_still opened 30

open_menu 120 10 160 386    # Filters
open_menu 160 386 640 486   # Point Set
shot point-set-menu
click 640 486 0       # Contract Point Cloud (Laplacian)
wait_window "Contract Point Cloud \(Laplacian\)" 10
shot filter-dialog
dialog_buttons "Contract Point Cloud"
click "${APPLY[@]}" 4
click "${CLOSE[@]}"
click 472 114         # hide the input layer, to see the result
click 540 145         # make the contracted layer current
shot contracted-layer

xdotool key ctrl+shift+e   # File > Export Mesh As...
wait_window "Save .*contracted.* Layer" 10
xdotool type --delay 15 "$WORK/gui_contracted.ply"
xdotool key Return
wait_window "Choose Saving Options" 10
shot saving-options
click 39 279          # untick "Binary encoding"
click 549 378 0       # OK
wait_file "$WORK/gui_contracted.ply" 30 "the exported layer was not written"

# The same filter through meshlabserver gives the reference for the GUI's result.
xvfb-run -a "$PREFIX/bin/meshlabserver" -i "$INPUT" -o "$WORK/input.ply" -l 0 -m sa \
  -o "$WORK/script_contracted.ply" -l x -m sa -s "$MLX" >"$WORK/meshlabserver.log" 2>&1 \
  || fail "meshlabserver failed"
/usr/bin/python3 "$HERE/check_contracted.py" "$WORK/input.ply" "$WORK/gui_contracted.ply"
/usr/bin/python3 -c "
import sys
sys.path.insert(0, '$HERE/../../scripts')
import numpy as np
from render_points import read_points
gui, script = read_points('$WORK/gui_contracted.ply'), read_points('$WORK/script_contracted.ply')
difference = np.abs(gui - script).max() if gui.shape == script.shape else float('inf')
print(f'GUI vs meshlabserver: largest coordinate difference {difference:.3g}')
sys.exit(0 if difference < 1e-5 else 1)
" || fail "the GUI's layer differs from meshlabserver's"

# The whole pipeline from the menu, then the skeleton exported with its edges.
click 540 114         # make the input layer current
open_menu 120 10 160 386    # Filters
open_menu 160 386 640 436   # Point Set
click 640 436 0       # Compute Curve Skeleton (Laplacian Contraction)
wait_window "Compute Curve Skeleton" 10
shot skeleton-dialog
dialog_buttons "Compute Curve Skeleton"
# The dialog fits a 1024-pixel-high screen with room for a title bar and a panel. Qt
# shrinks a taller dialog to the screen (its last fields cut off), so a height at the
# screen's is a dialog that does not fit.
echo "the skeleton dialog: ${DIALOG_WIDTH}x${DIALOG_HEIGHT}"
[ "$DIALOG_HEIGHT" -le 960 ] || fail "the skeleton dialog is $DIALOG_HEIGHT pixels high: it does not fit a 1024-pixel screen"
click "${APPLY[@]}" 5
click "${CLOSE[@]}"
shot skeleton-layer
open_menu 120 10 160 386    # Filters
open_menu 160 386 640 536   # Point Set
click 640 536 0       # Export Skeleton (PLY with edges, OBJ, CG)
wait_window "Export Skeleton" 10
shot export-dialog
dialog_buttons "Export Skeleton"
click "${APPLY[@]}" 2  # the default file is next to the input, named after the layer
click "${CLOSE[@]}"
GUI_SKELETON="$WORK/data/meshes/elephant_skeleton.ply"
wait_file "$GUI_SKELETON" 30 "Export Skeleton did not write $GUI_SKELETON"
shot skeleton-exported

# meshlabserver's run of the shipped pipeline script gives the same graph, written next to
# the input under the next free name (the GUI's file is kept).
mkdir -p "$WORK/server" && (cd "$WORK/server" && xvfb-run -a "$PREFIX/bin/meshlabserver" -i "$INPUT" \
  -s "$(dirname "$MLX")/compute_curve_skeleton.mlx" >meshlabserver.log 2>&1) || fail "meshlabserver failed"
/usr/bin/python3 "$HERE/skeleton_graph.py" check "$GUI_SKELETON" --max-cycles 3 --components 1 --min-tips 6 \
  || fail "the GUI's skeleton has the wrong topology"
/usr/bin/python3 "$HERE/skeleton_graph.py" same "$GUI_SKELETON" "$WORK/data/meshes/elephant_skeleton_1.ply" \
  || fail "the GUI's skeleton differs from meshlabserver's"
echo "GUI smoke test: OK (screenshots in $WORK)"
