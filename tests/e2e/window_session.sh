# Sourced by the window tests: starts the viewer in a window under the current DISPLAY and
# waits for it. start_viewer LOG ARGS...: sets $pid and $wid, or fails the test naming LOG.
start_viewer() {
  local log="$1"; shift
  # Recent files go to the test's own folder, not the user's.
  XDG_STATE_HOME="${tmp:-/tmp}/state" "$viewer" "$@" >"$log" 2>&1 &
  pid=$!
  wid=$(timeout 30 xdotool search --sync --name '^npr-viewer$' | head -1)
  [ -n "$wid" ] || { echo "FAIL: no viewer window ($*)"; cat "$log"; exit 1; }
  xdotool windowfocus --sync "$wid" 2>/dev/null || true
}
