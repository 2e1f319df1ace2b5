#!/usr/bin/env bash
# What `bash .ci/setup run` does on a machine without a display: renders the default scene (or
# the model and palette given) headless, a still and a short turntable, into a folder it names,
# and says how to open the window where there is a screen.
# Usage: first_run.sh VIEWER OUTDIR [viewer arguments...]
set -u
viewer="$1"; out="$2"; shift 2
mkdir -p "$out" || { echo "first run: cannot create $out" >&2; exit 1; }
echo "No display here: rendering headless instead."
"$viewer" --headless --size 1280x720 --screenshot "$out/still.png" "$@" || exit $?
"$viewer" --turntable 36 --size 480x360 --save-frames "$out/turntable" "$@" || exit $?
cat <<MSG

Wrote $out/still.png (1280x720) and $out/turntable/ (36 frames and turntable.gif, one orbit).
On a machine with a screen, 'bash .ci/setup run [MODEL] [--palette FILE]' opens the viewer's
window (F1 shows the overlay, H the key bindings). Here, 'xvfb-run -a $viewer' runs the window
invisibly, and '$viewer --headless --screenshot FILE' renders any scene.
MSG
