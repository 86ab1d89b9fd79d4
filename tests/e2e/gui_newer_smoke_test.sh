#!/usr/bin/env bash
# GUI smoke test for MeshLab 2022.02 / 2025.07: the build tree's MeshLab under Xvfb,
# driven by real mouse and keyboard events (xdotool). MeshLab starts with our plugins and
# no plugin error dialog; Filters > Point Set > Compute Curve Skeleton runs from its dialog
# and adds the skeleton layers; Edit > Edit Skeleton starts on the new skeleton and draws
# its nodes (found on screen by their colour). Screenshots are kept in WORKDIR.
# usage: gui_newer_smoke_test.sh PREFIX VERSION WORKDIR
set -euo pipefail
PREFIX="$1"; VERSION="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if [ -z "${PCSKELETON_IN_XVFB:-}" ]; then
  # A fixed screen size: the menu positions below depend on it.
  PCSKELETON_IN_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi

# Menu positions in a 1280x1000 MeshLab window at the top left, read off screenshots:
# Filters, Filters > Point Set, and Compute Curve Skeleton in that submenu (the same in
# 2022.02 and 2025.07).
case "$VERSION" in
  2022.*|2025.*) FILTERS=(116 9); POINT_SET=(150 355); SKELETON_ITEM=(656 401) ;;
  *) echo "FAIL: no menu positions for MeshLab $VERSION"; exit 1 ;;
esac
EDIT_MENU=(72 9)

rm -rf "$WORK"; mkdir -p "$WORK"; cd "$WORK"
# A fresh MeshLab configuration every time: saved window layouts would move the widgets.
export XDG_CONFIG_HOME="$WORK/config" XDG_DATA_HOME="$WORK/data-home"
tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz data/meshes/elephant.off
source "$HERE/gui_lib.sh"

"$PREFIX/bin/meshlab" "$WORK/data/meshes/elephant.off" >"$WORK/meshlab.log" 2>&1 &
MESHLAB_PID=$!
trap 'kill $MESHLAB_PID 2>/dev/null || true' EXIT
wait_window "MeshLab $VERSION" 30
WINDOW="$(xdotool search --onlyvisible --name "MeshLab $VERSION" | head -1)"
place_window "$WINDOW" 1280 1000
wait_screen_still opened 30
# Any other window now would be an error box (e.g. "Error while loading plugins").
others="$(xdotool search --onlyvisible --name '.' getwindowname %@ 2>/dev/null | grep -v "^MeshLab $VERSION" || true)"
[ -z "$others" ] || fail "MeshLab opened with another window: $others"

open_menu "${FILTERS[@]}" "${POINT_SET[@]}"
open_menu "${POINT_SET[@]}" "${SKELETON_ITEM[@]}"
shot point-set-menu
click "${SKELETON_ITEM[@]}" 0
wait_window "Compute Curve Skeleton" 10
shot skeleton-dialog
dialog_buttons "Compute Curve Skeleton"
# The dialog fits a 1024-pixel-high screen with room for a title bar and a panel. Qt
# shrinks a taller dialog to the screen (its last fields cut off), so a height at the
# screen's is a dialog that does not fit.
echo "the skeleton dialog: ${DIALOG_WIDTH}x${DIALOG_HEIGHT}"
[ "$DIALOG_HEIGHT" -le 960 ] || fail "the skeleton dialog is $DIALOG_HEIGHT pixels high: it does not fit a 1024-pixel screen"
click "${APPLY[@]}" 6
shot skeleton-applied
click "${CLOSE[@]}"

open_menu "${EDIT_MENU[@]}" "${EDIT_MENU[0]}" 40
shot edit-menu
xdotool key Up Return   # the last entry: Edit Skeleton (plugins are listed by file name)
skeleton_on_screen() {
  read -r yellow red <<<"$(/usr/bin/python3 "$HERE/find_nodes.py" "$SHOT" count)"
  SEEN="$yellow nodes, $red selected"
  [ "$yellow" -ge 20 ] && [ "$red" -eq 0 ]
}
wait_screen 30 edit-skeleton "the Edit Skeleton tool does not show the elephant's skeleton (20 or more nodes, none selected)" \
  skeleton_on_screen
echo "GUI smoke test, MeshLab $VERSION: OK ($yellow nodes on screen; screenshots in $WORK)"
