#!/usr/bin/env bash
# End-to-end: the window on a screen of content scale 2 (Xft.dpi 192, as a desktop at 200%
# sets it). The window, the overlay's font, its widgets and its panel are twice their size at
# scale 1, so the panel is laid out as at scale 1 (where no label runs past its edge) instead
# of holding twice the text in the old width; no GL error. Usage: window_scale.sh VIEWER
set -u
viewer="$1"
here="$(cd "$(dirname "$0")" && pwd)"
# Always an X server of its own, even where DISPLAY is set: the test changes the server's
# resource database (a desktop's own Xft.dpi must not be touched). -noreset: the server keeps
# that database after the client that set it left.
if [ -z "${NPR_OWN_XVFB:-}" ]; then NPR_OWN_XVFB=1 exec xvfb-run -a -s "-noreset -screen 0 1600x1000x24" bash "$0" "$@"; fi
tmp=$(mktemp -d); trap 'kill $pid 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp"
. "$here/window_session.sh"
fail=0
shoot() {  # shoot DPI NAME: the viewer at that DPI; Shift+F12 (the whole window) into NAME
  /usr/bin/python3 -c "
from Xlib import display, Xatom
d = display.Display(); r = d.screen().root
r.change_property(d.intern_atom('RESOURCE_MANAGER'), Xatom.STRING, 8, b'Xft.dpi:\t$1\n'); d.sync()"
  start_viewer "$tmp/log-$1" --size 640x360
  sleep 2
  xdotool key --clearmodifiers shift+F12
  for _ in $(seq 100); do [ -s npr-screenshot-0001.png ] && break; sleep 0.1; done
  sleep 0.3
  [ -s npr-screenshot-0001.png ] || { echo "FAIL: no screenshot at $1 dpi"; cat "$tmp/log-$1"; exit 1; }
  mv npr-screenshot-0001.png "$2"
  xdotool key --clearmodifiers Escape; wait $pid
  grep -q "OpenGL error" "$tmp/log-$1" && { echo "FAIL: GL errors at $1 dpi"; fail=1; }
}
size() { oiiotool --info "$1" | grep -oE '[0-9]+ x +[0-9]+' | tr -d ' '; }
# The panel's width: on the third row of pixels (the title bar, above its text), the run of one
# colour that ends at the window's right edge (its border aside).
panel() {
  oiiotool "$1" --cut "$(size "$1" | cut -dx -f1)x1+0+2" --ch R,G,B -o "$tmp/row.ppm" >/dev/null || return
  /usr/bin/python3 -c "
d = open('$tmp/row.ppm', 'rb').read()
parts = d.split(maxsplit=4); w = int(parts[1]); px = parts[4]
same = lambda a, b: all(abs(px[3 * a + c] - px[3 * b + c]) <= 8 for c in range(3))
end = w - 1
while end > 0 and not same(end, end - 1): end -= 1
start = end
while start > 0 and same(start - 1, end): start -= 1
print(end - start + 1)"
}
shoot 96 one.png
shoot 192 two.png
[ "$(size one.png)" = 640x360 ] || { echo "FAIL: the window at scale 1 is $(size one.png)"; fail=1; }
[ "$(size two.png)" = 1280x720 ] || { echo "FAIL: the window at scale 2 is $(size two.png), not twice 640x360"; fail=1; }
p1=$(panel one.png); p2=$(panel two.png)
echo "window scale: panel $p1 px at scale 1, $p2 px at scale 2"
[ -n "$p1" ] && [ -n "$p2" ] && [ "$p1" -gt 100 ] && [ $((p2 - 2 * p1)) -le 4 ] && [ $((2 * p1 - p2)) -le 4 ] \
  || { echo "FAIL: the panel at scale 2 is not twice its width at scale 1"; fail=1; }
[ $fail = 0 ] && echo "window scale: all checks passed"
exit $fail
