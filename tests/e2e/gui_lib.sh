# Shared by the GUI tests (sourced): screenshots, failing with one, and waiting for the
# state a test checks (a window, the window's place, a file, what the screen shows) by
# polling it until a timeout, never by a fixed delay and a guess. Expects WORK (the
# screenshot folder) to be set.
step=0
shot() { step=$((step + 1)); SHOT="$WORK/$(printf '%02d' $step)-$1.png"; import -window root "$SHOT"; }
fail() { shot failure; echo "FAIL: $*"; echo "screenshots: $WORK"; exit 1; }

# Runs the command every 0.3 s until it succeeds; fails with the description after SECONDS
# (and with SEEN, which a check may set to what it saw last).
wait_until() {  # seconds, description, command...
  local seconds="$1" what="$2"; shift 2
  local deadline=$((SECONDS + seconds))
  SEEN=""
  until "$@"; do
    [ $SECONDS -lt $deadline ] || fail "$what (after waiting $seconds s${SEEN:+; last seen: $SEEN})"
    sleep 0.3
  done
}
window_shown() { xdotool search --onlyvisible --name "$1" >/dev/null 2>&1; }
wait_window() {  # name, seconds
  wait_until "$2" "no window named '$1'" window_shown "$1"
}
# Takes a screenshot named NAME and runs the check on it ($SHOT), until the check passes.
wait_screen() {  # seconds, name, description, check command...
  local seconds="$1" name="$2" what="$3"; shift 3
  screen_shows() { shot "$name"; "$@"; }
  wait_until "$seconds" "$what" screen_shows "$@"
}
# The screen has finished drawing once two screenshots in a row have the same pixels.
screen_still() {
  local previous="${SHOT:-}"
  shot "$1"
  [ -n "$previous" ] && /usr/bin/python3 -c "
import sys
from PIL import Image, ImageChops
a, b = (Image.open(p).convert('RGB') for p in sys.argv[1:3])
sys.exit(0 if a.size == b.size and ImageChops.difference(a, b).getbbox() is None else 1)" "$previous" "$SHOT"
}
wait_screen_still() {  # name, seconds
  wait_until "$2" "the screen kept changing" screen_still "$1"
}
# A file is complete once it exists and its size stays the same over two polls (MeshLab's
# own writers write in place).
file_written() {
  local size; size="$(stat -c %s "$1" 2>/dev/null || echo 0)"
  [ "$size" -gt 0 ] && [ "$size" = "${LAST_SIZE:-}" ] && return 0
  LAST_SIZE="$size"; return 1
}
wait_file() {  # path, seconds, description
  LAST_SIZE=""
  wait_until "$2" "$3" file_written "$1"
}
# Moves and sizes the window until it stays where asked (MeshLab sets its own geometry
# once after it shows).
window_placed() {  # window, width, height
  xdotool windowmove "$1" 0 0 windowsize "$1" "$2" "$3"
  local X Y WIDTH HEIGHT SCREEN WINDOW
  eval "$(xdotool getwindowgeometry --shell "$1" | tr -d ' ')"
  if [ "$X $Y $WIDTH $HEIGHT" = "0 0 $2 $3" ]; then PLACED_POLLS=$((PLACED_POLLS + 1)); else PLACED_POLLS=0; fi
  [ "$PLACED_POLLS" -ge 4 ]
}
place_window() {  # window, width, height
  PLACED_POLLS=0
  wait_until 30 "the window did not stay at 0,0 with size $2x$3" window_placed "$@"
}
click() { xdotool mousemove "$1" "$2" click 1; sleep "${3:-0.8}"; }
# A menu covers the point once a visible window of MeshLab's (MESHLAB_PID) other than its
# main window ("MeshLab 20..."), a menu or a submenu, lies over it: a click there then
# reaches the menu, not what was under it when it was still closing or not yet open.
menu_covers() {  # x, y
  local id X Y WIDTH HEIGHT SCREEN WINDOW
  for id in $(xdotool search --maxdepth 1 --onlyvisible --pid "$MESHLAB_PID" 2>/dev/null); do
    WIDTH=""
    case "$(xdotool getwindowname "$id" 2>/dev/null)" in "MeshLab 20"*) continue ;; esac
    eval "$(xdotool getwindowgeometry --shell "$id" 2>/dev/null | tr -d ' ')"
    [ -n "$WIDTH" ] || continue
    if [ "$1" -ge "$X" ] && [ "$1" -lt $((X + WIDTH)) ] && [ "$2" -ge "$Y" ] && [ "$2" -lt $((Y + HEIGHT)) ]; then
      return 0
    fi
  done
  return 1
}
# Clicks a menu (x, y: the menu bar's entry, or a submenu's entry in an open menu) and waits
# until what it opens covers the next entry to click (next x, next y).
open_menu() {  # x, y, next x, next y
  xdotool mousemove "$1" "$2" click 1
  wait_until 20 "no menu opened over $3,$4 after a click at $1,$2" menu_covers "$3" "$4"
}
# A filter dialog's bottom row, from the window's geometry (a new parameter or a longer
# description moves it): sets APPLY and CLOSE (Close at a quarter of its width, Apply at
# three quarters) and DIALOG_WIDTH, DIALOG_HEIGHT.
dialog_buttons() {  # window name
  local X Y WIDTH HEIGHT SCREEN WINDOW
  eval "$(xdotool search --onlyvisible --name "$1" getwindowgeometry --shell | tr -d ' ')"
  APPLY=($((X + WIDTH * 3 / 4)) $((Y + HEIGHT - 21)))
  CLOSE=($((X + WIDTH / 4)) $((Y + HEIGHT - 21)))
  DIALOG_WIDTH=$WIDTH; DIALOG_HEIGHT=$HEIGHT
}
