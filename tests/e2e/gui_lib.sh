# Shared by the GUI tests (sourced): screenshots, failing with one, waiting for windows,
# clicking. Expects WORK (the screenshot folder) to be set.
step=0
shot() { step=$((step + 1)); SHOT="$WORK/$(printf '%02d' $step)-$1.png"; import -window root "$SHOT"; }
fail() { shot failure; echo "FAIL: $*"; echo "screenshots: $WORK"; exit 1; }
wait_window() {  # name, seconds
  local deadline=$((SECONDS + $2))
  until xdotool search --onlyvisible --name "$1" >/dev/null 2>&1; do
    [ $SECONDS -lt $deadline ] || fail "no window named '$1' after $2 s"
    sleep 0.3
  done
}
click() { xdotool mousemove "$1" "$2" click 1; sleep "${3:-0.8}"; }
