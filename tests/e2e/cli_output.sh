#!/usr/bin/env bash
# End-to-end: the real binary's outputs and looks: pattern scale, the palette maker, contact
# sheets, turntables, posters, style presets, the seeds' styles and the first run (split from
# cli.sh so the two run side by side).
set -u
viewer="$1"; src="$2"
source "$(dirname "$0")/expect.sh"
expect 0 "plain" -- "$viewer" --headless --size 96x96 --light 1,3,1 --screenshot "$tmp/plain.png"

# Pattern scale, the palette maker and contact sheets.
expect 0 "--pattern-scale 2" -- "$viewer" --headless --size 96x96 --light 1,3,1 --pattern-scale 2 --screenshot "$tmp/scaled.png"
cmp -s "$tmp/plain.png" "$tmp/scaled.png" && { echo "FAIL: --pattern-scale changes nothing"; fail=1; }
expect 2 "--pattern-scale 0" -- "$viewer" --headless --pattern-scale 0
expect 2 "--pattern-scale 100" -- "$viewer" --headless --pattern-scale 100
for path in pixel stencil; do
  expect 0 "--pattern object --path $path" -- "$viewer" --headless --size 96x96 --light 1,3,1 --pattern object --path $path --screenshot "$tmp/object-$path.png"
done
cmp -s "$tmp/plain.png" "$tmp/object-pixel.png" && { echo "FAIL: --pattern object changes nothing"; fail=1; }
expect 2 "unknown --pattern" -- "$viewer" --headless --pattern glued
grep -q "object" "$tmp/err" || { echo "FAIL: --pattern error does not offer object: $(cat "$tmp/err")"; fail=1; }
"$viewer" --headless --size 64x64 --screenshot "$tmp/source.png" 2>/dev/null
expect 0 "--make-palette --ladder darken" -- "$viewer" --make-palette "$tmp/source.png" --ladder darken --levels 5 --out "$tmp/made"
grep -q '"evenly_spaced"' "$tmp/out" || { echo "FAIL: --make-palette prints no palette report"; fail=1; }
expect 0 "the made palette renders" -- "$viewer" --headless --size 64x64 --palette "$tmp/made" --screenshot "$tmp/made.png"
expect 1 "--make-palette into a folder that is not empty" -- "$viewer" --make-palette "$tmp/source.png" --ladder blur --out "$tmp/made"
grep -q "not empty" "$tmp/err" || { echo "FAIL: no reason for the refused folder: $(cat "$tmp/err")"; fail=1; }
expect 1 "--make-palette from a missing image" -- "$viewer" --make-palette "$tmp/none.png" --ladder blur --out "$tmp/none"
[ -e "$tmp/none" ] && { echo "FAIL: a failed --make-palette left a folder"; fail=1; }
expect 2 "--make-palette --levels 0" -- "$viewer" --make-palette "$tmp/source.png" --ladder blur --levels 0 --out "$tmp/l0"
expect 2 "--make-palette --levels 1000" -- "$viewer" --make-palette "$tmp/source.png" --ladder blur --levels 1000 --out "$tmp/l1000"
expect 2 "--make-palette without --out" -- "$viewer" --make-palette "$tmp/source.png" --ladder blur
expect 2 "--make-palette with an unknown ladder" -- "$viewer" --make-palette "$tmp/source.png" --ladder melt --out "$tmp/melt"
expect 2 "--ladder without --make-palette" -- "$viewer" --ladder blur
expect 0 "--palette-sheet" -- "$viewer" --palette-sheet "$tmp/sheets" --palette "$tmp/made" --palette "$src/palettes/stipple"
[ -s "$tmp/sheets/made.png" ] && [ -s "$tmp/sheets/stipple.png" ] || { echo "FAIL: --palette-sheet wrote $(ls "$tmp/sheets")"; fail=1; }
ls -a "$tmp" | grep -q partial && { echo "FAIL: --make-palette left a partial folder"; fail=1; }

# Turntables: N frames of one orbit and an animated GIF of N subimages; progress redrawn on a
# terminal, plain lines in a pipe.
expect 0 "--turntable 36" -- "$viewer" --turntable 36 --size 64x48 --save-frames "$tmp/turn"
[ "$(ls "$tmp/turn"/frame-*.png | wc -l)" = 36 ] || { echo "FAIL: --turntable 36 wrote $(ls "$tmp/turn" | wc -l) files"; fail=1; }
oiiotool --info "$tmp/turn/turntable.gif" | grep -q "36 subimages" || { echo "FAIL: the GIF: $(oiiotool --info "$tmp/turn/turntable.gif")"; fail=1; }
cmp -s "$tmp/turn/frame-0000.png" "$tmp/turn/frame-0001.png" && { echo "FAIL: the turntable does not turn"; fail=1; }
grep -q $'\r' "$tmp/err" && { echo "FAIL: a redrawn progress line in a pipe"; fail=1; }
grep -q "rendering 36 frames: 100%" "$tmp/err" || { echo "FAIL: no plain progress lines in a pipe"; fail=1; }
script -qec "'$viewer' --turntable 4 --size 32x24 --save-frames '$tmp/turn4'" /dev/null > "$tmp/pty" 2>&1
grep -q $'\r'"rendering 4 frames:" "$tmp/pty" || { echo "FAIL: no progress line on a terminal: $(cat -v "$tmp/pty" | head -3)"; fail=1; }
expect 2 "--turntable 1" -- "$viewer" --turntable 1
expect 2 "--turntable with --animate" -- "$viewer" --turntable 10 --animate orbit:1

# Posters: 2x2 tiles equal one frame of the same size (patterns, lines and image edges continue
# across the seams); beyond the GL limit the still tiles itself.
for p in pixel stencil; do
  expect 0 "one frame ($p)" -- "$viewer" --headless --size 320x240 --path $p --lines silhouette,crease,image --screenshot "$tmp/one-$p.png"
  expect 0 "2x2 tiles ($p)" -- "$viewer" --headless --size 320x240 --path $p --lines silhouette,crease,image --tile 160 --screenshot "$tmp/tiled-$p.png"
  oiiotool "$tmp/one-$p.png" "$tmp/tiled-$p.png" --fail 0.02 --failpercent 0.1 --diff > "$tmp/diff" \
    || { echo "FAIL: $p: the tiled poster differs from one frame: $(grep -E 'Mean|pixels' "$tmp/diff" | head -2)"; fail=1; }
done
expect 0 "a poster wider than the GL allows" -- "$viewer" --headless --size 17000x200 --camera 30,20,0.6 --screenshot "$tmp/poster.png"
oiiotool --info "$tmp/poster.png" | grep -q "17000 x  200" || { echo "FAIL: poster size: $(oiiotool --info "$tmp/poster.png")"; fail=1; }
expect 1 "a tiled poster with frames" -- "$viewer" --headless --size 320x240 --tile 160 --frames 3 --screenshot "$tmp/x.png"
expect 2 "--tile 10" -- "$viewer" --headless --tile 10

# Style presets: a shipped style changes the look; options beside it win; a bad one says why.
expect 0 "--style technical" -- "$viewer" --headless --size 96x96 --light 1,3,1 --style technical --screenshot "$tmp/technical.png"
cmp -s "$tmp/plain.png" "$tmp/technical.png" && { echo "FAIL: --style changes nothing"; fail=1; }
expect 0 "--style technical --palette crosshatch" -- "$viewer" --headless --size 96x96 --light 1,3,1 --style technical --palette "$src/palettes/crosshatch" --screenshot "$tmp/technical-cross.png"
cmp -s "$tmp/technical.png" "$tmp/technical-cross.png" && { echo "FAIL: --palette beside --style does not win"; fail=1; }
printf 'path pixel
glow 3
' > "$tmp/bad.style"
expect 1 "a bad style file" -- "$viewer" --headless --style "$tmp/bad.style"
grep -q "bad.style line 2" "$tmp/err" || { echo "FAIL: the bad style's line is not named: $(cat "$tmp/err")"; fail=1; }
expect 1 "a style that does not exist" -- "$viewer" --headless --style nosuchstyle

# The seeds' styles: hardware outlines, the charcoal rim and tone, painterly strokes; bad
# values are refused with the option named.
expect 0 "--lines hardware" -- "$viewer" --headless --size 96x96 --light 1,3,1 --lines hardware --screenshot "$tmp/hardware.png"
cmp -s "$tmp/plain.png" "$tmp/hardware.png" && { echo "FAIL: --lines hardware changes nothing"; fail=1; }
expect 0 "--outline offset" -- "$viewer" --headless --size 96x96 --light 1,3,1 --lines hardware --outline offset --outline-offset 0.05 --screenshot "$tmp/offset.png"
cmp -s "$tmp/hardware.png" "$tmp/offset.png" && { echo "FAIL: --outline offset draws as fatten"; fail=1; }
expect 2 "unknown --outline" -- "$viewer" --headless --lines hardware --outline wobbly
grep -q -- "--outline" "$tmp/err" || { echo "FAIL: --outline error: $(cat "$tmp/err")"; fail=1; }
expect 2 "--outline-offset out of range" -- "$viewer" --headless --outline-offset 0.9
expect 0 "--tone charcoal --lines rim" -- "$viewer" --headless --size 96x96 --tone charcoal --lines rim --screenshot "$tmp/rim.png"
expect 0 "--strokes" -- "$viewer" --headless --size 96x96 --light 1,3,1 --strokes --stroke-size 12x5 --stroke-density 800 --screenshot "$tmp/strokes.png"
cmp -s "$tmp/plain.png" "$tmp/strokes.png" && { echo "FAIL: --strokes changes nothing"; fail=1; }
expect 2 "bad --stroke-size" -- "$viewer" --headless --strokes --stroke-size 12
grep -q -- "--stroke-size" "$tmp/err" || { echo "FAIL: --stroke-size error: $(cat "$tmp/err")"; fail=1; }
expect 2 "bad --stroke-density" -- "$viewer" --headless --strokes --stroke-density 0
expect 2 "bad --stroke-budget" -- "$viewer" --headless --strokes --stroke-budget -1
expect 0 "--style painterly" -- "$viewer" --headless --size 96x96 --style painterly --screenshot "$tmp/painterly.png"

# The first run on a machine without a display (.ci/setup run): files it names, exit 0.
(unset DISPLAY WAYLAND_DISPLAY; bash "$src/.ci/first_run.sh" "$viewer" "$tmp/first") > "$tmp/first.log" 2>&1 \
  || { echo "FAIL: first run: $(tail -3 "$tmp/first.log")"; fail=1; }
for f in still.png turntable/turntable.gif turntable/frame-0035.png; do
  [ -s "$tmp/first/$f" ] || { echo "FAIL: first run did not write $f"; fail=1; }
done
grep -q "$tmp/first" "$tmp/first.log" || { echo "FAIL: first run does not name its folder"; fail=1; }
grep -q "bash .ci/setup run" "$tmp/first.log" || { echo "FAIL: first run does not say how to open the window"; fail=1; }

[ $fail = 0 ] && echo "cli_output: all checks passed"
exit $fail
