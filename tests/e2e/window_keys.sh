#!/usr/bin/env bash
# End-to-end: the real viewer in a window under Xvfb, driven with xdotool. Hides the overlay
# (F1), takes screenshots (F12) and checks that each action changes the image as it should:
# palette switch, match mode, path, light movement; that an unchanged scene gives the same
# image twice; that Esc closes the viewer with exit status 0; and that space plays and pauses
# an animated scene. Then the file commands: F12 numbers its files after those already in the
# folder (a second run overwrites nothing), Ctrl+O opens a typed path (a broken file keeps the
# scene and says why, on stderr and in the window's message bar; a palette and a glTF scene
# open), Ctrl+S saves the look under a typed name and never replaces a file without a
# confirmation, Ctrl+E exports a picture and a turntable and cancels on Esc.
set -u
viewer="$1"
src=$(cd "$(dirname "$0")/../.." && pwd)
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 1024x768x24" bash "$0" "$@"; fi
tmp=$(mktemp -d); trap 'kill $pid 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp"
. "$src/tests/e2e/window_session.sh"
start_viewer "$tmp/log" --size 480x360
n=0
pic() { printf "npr-screenshot-%04d.png" "$1"; }
shot() {  # presses F12 and waits for the next numbered screenshot
  n=$((n + 1))
  xdotool key --clearmodifiers F12
  for _ in $(seq 100); do [ -s "$(pic $n)" ] && sleep 0.3 && return 0; sleep 0.1; done
  echo "FAIL: screenshot $n was not written"; cat "$tmp/log"; exit 1
}
same() { idiff -q -fail 0 "$1" "$2" >/dev/null 2>&1; }
fail=0
check_changed() {  # check_changed WHAT: the newest screenshot differs from the previous one
  if same "$(pic $((n - 1)))" "$(pic $n)"; then echo "FAIL: $1 did not change the image"; fail=1; fi
}
sleep 1
xdotool key --clearmodifiers F1   # hide the overlay: its timings change every frame
sleep 0.5
shot; shot
same "$(pic 1)" "$(pic 2)" || { echo "FAIL: an unchanged scene rendered differently"; fail=1; }
xdotool key --clearmodifiers 2; sleep 0.5; shot; check_changed "palette 2"
xdotool key --clearmodifiers 1; sleep 0.5; shot
same "$(pic 2)" "$(pic $n)" || { echo "FAIL: palette 1 did not restore the first image"; fail=1; }
xdotool key --clearmodifiers m; sleep 0.5; shot; check_changed "match mode"
xdotool key --clearmodifiers p; sleep 0.5; shot; check_changed "render path"
xdotool key --clearmodifiers a a a a a; sleep 0.5; shot; check_changed "moving the light"
xdotool key --clearmodifiers b; sleep 0.5; shot; check_changed "split view"
xdotool key --clearmodifiers Escape
for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then echo "FAIL: Esc did not close the viewer"; fail=1; else
  wait $pid; status=$?
  [ $status = 0 ] || { echo "FAIL: exit status $status"; cat "$tmp/log"; fail=1; }
fi
grep -q "OpenGL error" "$tmp/log" && { echo "FAIL: GL errors"; cat "$tmp/log"; fail=1; }

# An animated scene opens playing; space pauses and plays it: still while paused, moving while
# it plays. --paused opens it paused.
mkdir "$tmp/animated" && cd "$tmp/animated" && n=0
start_viewer "$tmp/log2" --size 480x360 "$src/models/pendulum.gltf"
sleep 1
xdotool key --clearmodifiers F1; sleep 0.5
shot; shot; check_changed "an animated file opened (it plays)"
xdotool key --clearmodifiers space; sleep 0.3
shot; shot
same "$(pic $((n - 1)))" "$(pic $n)" || { echo "FAIL: space did not pause the animation"; fail=1; }
xdotool key --clearmodifiers space; sleep 0.3
shot; shot; check_changed "playing again (space)"
xdotool key --clearmodifiers Escape
for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
kill -0 $pid 2>/dev/null && { echo "FAIL: Esc did not close the animated viewer"; fail=1; }
grep -q "OpenGL error" "$tmp/log2" && { echo "FAIL: GL errors (animated)"; cat "$tmp/log2"; fail=1; }

# The file commands, in the first run's folder (its screenshots are there).
cd "$tmp"
first=$(md5sum "$(pic 1)")
n=$(ls npr-screenshot-*.png | wc -l)
start_viewer "$tmp/log3" --size 480x360
sleep 1
xdotool key --clearmodifiers F1; sleep 0.5
shot
[ "$(md5sum "$(pic 1)")" = "$first" ] || { echo "FAIL: a second run's F12 replaced the first run's picture"; fail=1; }
printf 'v 0 0 0\nf 1 2 3\n' > broken.obj
xdotool key --clearmodifiers ctrl+o; sleep 0.5
xdotool type --delay 20 "$tmp/broken.obj"; xdotool key --clearmodifiers Return; sleep 1
grep -q "broken.obj" "$tmp/log3" || { echo "FAIL: a broken file opened with Ctrl+O gave no reason"; cat "$tmp/log3"; fail=1; }
xdotool key --clearmodifiers F1; sleep 0.3; xdotool key --clearmodifiers F1; sleep 0.3   # the bar stays: only the scene is compared
shot
same "$(pic $((n - 1)))" "$(pic $n)" || { echo "FAIL: a failed open changed the scene"; fail=1; }
# The reason shows in the window too: a red bar across the top of the scene (Shift+F12 shoots
# the whole window; the file is moved aside so the scene shots keep their numbers).
n=$((n + 1)); xdotool key --clearmodifiers shift+F12
for _ in $(seq 100); do [ -s "$(pic $n)" ] && sleep 0.3 && break; sleep 0.1; done
mv "$(pic $n)" bar.png 2>/dev/null; n=$((n - 1))
oiiotool bar.png --cut 480x40+0+0 --ch R,G,B -o bar.ppm >/dev/null 2>&1
red=$(/usr/bin/python3 -c "
d = open('bar.ppm', 'rb').read(); px = d.split(maxsplit=4)[4]
print(sum(1 for i in range(0, len(px) - 2, 3) if px[i] > 80 and px[i] > 2.5 * px[i + 1] and px[i] > 2.5 * px[i + 2]))" 2>/dev/null)
[ "${red:-0}" -gt 1000 ] || { echo "FAIL: no message bar in the window after a failed open (${red:-no} red pixels at its top)"; fail=1; }
xdotool key --clearmodifiers ctrl+o; sleep 0.5
xdotool type --delay 20 "$src/palettes/stipple"; xdotool key --clearmodifiers Return; sleep 1
shot; check_changed "opening a palette with Ctrl+O"
grep -q "palettes/stipple" "$tmp/state/npr-viewer/recent-files" 2>/dev/null || { echo "FAIL: the opened palette is not kept in the recent files"; fail=1; }
grep -q "broken.obj" "$tmp/state/npr-viewer/recent-files" 2>/dev/null && { echo "FAIL: a file that failed to open was kept as recent"; fail=1; }
xdotool key --clearmodifiers ctrl+o; sleep 0.5
xdotool type --delay 20 "$src/models/pendulum.gltf"; xdotool key --clearmodifiers Return; sleep 1.5
shot; check_changed "opening a glTF scene with Ctrl+O"
grep -q "pendulum.gltf" "$tmp/state/npr-viewer/recent-files" 2>/dev/null || { echo "FAIL: the glTF opened with Ctrl+O is not among the recent files"; fail=1; }
xdotool key --clearmodifiers ctrl+s; sleep 0.5
xdotool key --clearmodifiers ctrl+a; xdotool type --delay 20 "Kept look"; xdotool key --clearmodifiers Return; sleep 1
[ -s kept-look.style ] || { echo "FAIL: Ctrl+S did not write kept-look.style"; cat "$tmp/log3"; fail=1; }
saved=$(md5sum kept-look.style 2>/dev/null)
xdotool key --clearmodifiers m; sleep 0.3
xdotool key --clearmodifiers ctrl+s; sleep 0.5
xdotool key --clearmodifiers ctrl+a; xdotool type --delay 20 "Kept look"; xdotool key --clearmodifiers Return; sleep 1
[ "$(md5sum kept-look.style 2>/dev/null)" = "$saved" ] || { echo "FAIL: Ctrl+S replaced an existing style without a confirmation"; fail=1; }
xdotool key --clearmodifiers Escape; sleep 0.3   # closes the dialog, not the viewer
kill -0 $pid 2>/dev/null || { echo "FAIL: Esc in a dialog closed the viewer"; fail=1; }
# Ctrl+E: a picture at the typed name, a turntable whose extension makes it a GIF of 120 frames
# (the default), and an export cancelled with Esc leaves nothing, the viewer still open.
export_as() {  # export_as PATH: Ctrl+E, the path typed over the suggested one, Enter
  xdotool key --clearmodifiers ctrl+e; sleep 0.5
  xdotool key --clearmodifiers ctrl+a; xdotool type --delay 20 "$1"; xdotool key --clearmodifiers Return
}
export_as "$tmp/picture.png"; sleep 1.5
[ -s "$tmp/picture.png" ] || { echo "FAIL: Ctrl+E did not write picture.png"; cat "$tmp/log3"; fail=1; }
export_as "$tmp/spin.gif"
for _ in $(seq 120); do [ -e "$tmp/spin.gif" ] && break; sleep 0.25; done
oiiotool --info "$tmp/spin.gif" 2>/dev/null | grep -q "120 subimages" || { echo "FAIL: Ctrl+E's turntable: $(oiiotool --info "$tmp/spin.gif" 2>&1)"; cat "$tmp/log3"; fail=1; }
export_as "$tmp/stopped.gif"; sleep 0.8
xdotool key --clearmodifiers Escape; sleep 0.8   # cancels the export, not the viewer
ls -a "$tmp" | grep -q "stopped" && { echo "FAIL: a cancelled export left $(ls -a "$tmp" | grep stopped)"; fail=1; }
grep -q "export cancelled" "$tmp/log3" || { echo "FAIL: the cancel is not said"; fail=1; }
kill -0 $pid 2>/dev/null || { echo "FAIL: Esc during an export closed the viewer"; fail=1; }
xdotool key --clearmodifiers Escape
for _ in $(seq 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
grep -q "OpenGL error" "$tmp/log3" && { echo "FAIL: GL errors (file commands)"; cat "$tmp/log3"; fail=1; }
[ $fail = 0 ] && echo "window: all checks passed ($n screenshots)"
exit $fail
