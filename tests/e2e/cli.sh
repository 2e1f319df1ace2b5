#!/usr/bin/env bash
# End-to-end: the real binary's command line: --info, --palette-info, exit codes for bad
# arguments (2) and failed loads (1), and --help.
set -u
viewer="$1"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {  # expect STATUS DESCRIPTION -- command...
  local want="$1" what="$2"; shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" != "$want" ]; then echo "FAIL: $what: exit $got, expected $want"; cat "$tmp/err"; fail=1; fi
}
expect 0 "--help" -- "$viewer" --help
grep -q -- "--palette" "$tmp/out" || { echo "FAIL: --help does not list --palette"; fail=1; }

expect 0 "--info bunny" -- "$viewer" --info "$src/models/bunny.obj"
grep -q '"triangles":3674' "$tmp/out" || { echo "FAIL: --info output: $(cat "$tmp/out")"; fail=1; }
[ "$(wc -l < "$tmp/out")" = 1 ] || { echo "FAIL: --info is not one line"; fail=1; }
printf 'v 0 0 0\nv 1 0 0\n' > "$tmp/points.obj"
expect 1 "--info on a file with no faces" -- "$viewer" --info "$tmp/points.obj"
grep -q "no faces" "$tmp/err" || { echo "FAIL: reason missing: $(cat "$tmp/err")"; fail=1; }
expect 1 "--info on a missing file" -- "$viewer" --info "$tmp/none.obj"
# A failed load is said once, with what did not load.
expect 1 "a model with no faces" -- "$viewer" --headless --size 32x32 "$tmp/points.obj"
[ "$(grep -c "no faces" "$tmp/err")" = 1 ] && grep -q "model not loaded" "$tmp/err" || { echo "FAIL: a failed load is not said once: $(cat "$tmp/err")"; fail=1; }

expect 0 "--palette-info" -- "$viewer" --palette-info "$src/palettes/crosshatch/crosshatch.palette"
grep -q '"monotonic":true' "$tmp/out" || { echo "FAIL: --palette-info output"; fail=1; }
printf 'missing.png\n' > "$tmp/bad.palette"
expect 1 "--palette-info on a broken palette" -- "$viewer" --palette-info "$tmp/bad.palette"
grep -q "line 1" "$tmp/err" || { echo "FAIL: palette error does not name the line"; fail=1; }

expect 2 "unknown path" -- "$viewer" --headless --path sideways
expect 2 "negative size" -- "$viewer" --headless --size -5x10
expect 2 "non-finite scale" -- "$viewer" --headless --range-scale nan
expect 2 "zero scale" -- "$viewer" --headless --range-scale 0
expect 2 "missing model" -- "$viewer" --headless "$tmp/nope.obj"
expect 2 "missing palette" -- "$viewer" --headless --palette "$tmp/nope.palette"
expect 2 "bad light" -- "$viewer" --headless --light 1,2
expect 2 "unknown option" -- "$viewer" --frobnicate
[ "$(wc -l < "$tmp/err")" -le 1 ] || { echo "FAIL: bad arguments print more than one line"; fail=1; }
expect 1 "model that fails to load" -- "$viewer" --headless "$tmp/points.obj"
expect 1 "palette that fails to load" -- "$viewer" --headless --palette "$tmp/bad.palette"

# Materials: --info reports them; --materials and --palette-for are checked; a palette for a
# material the model does not have is a note naming its materials, not a failure.
printf 'newmtl red\nKd 1 0 0\nmap_Kd gone.png\nnewmtl blue\nKd 0 0 1\n' > "$tmp/two.mtl"
printf 'mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\n' > "$tmp/two.obj"
expect 0 "--info with materials" -- "$viewer" --info "$tmp/two.obj"
grep -q '"materials":2' "$tmp/out" || { echo "FAIL: --info materials: $(cat "$tmp/out")"; fail=1; }
grep -q '"textures_missing":\[".*gone.png"\]' "$tmp/out" || { echo "FAIL: --info missing texture: $(cat "$tmp/out")"; fail=1; }
expect 2 "bad --materials" -- "$viewer" --headless --materials maybe
expect 2 "--palette-for without =" -- "$viewer" --headless --palette-for red
expect 2 "--palette-for missing file" -- "$viewer" --headless --palette-for "red=$tmp/nope.palette"
expect 0 "--palette-for" -- "$viewer" --headless "$tmp/two.obj" --size 64x64 --palette-for "blue=$src/palettes/wood/wood.palette" \
  --palette-for "green=$src/palettes/wood/wood.palette" --screenshot "$tmp/two.png"
grep -q "no material named 'green'.*(its materials: red, blue)" "$tmp/err" || { echo "FAIL: unknown material note: $(cat "$tmp/err")"; fail=1; }
[ -s "$tmp/two.png" ] || { echo "FAIL: no screenshot with --palette-for"; fail=1; }
expect 0 "--materials off" -- "$viewer" --headless "$tmp/two.obj" --size 64x64 --materials off

# Scripted camera motion and frame sequences: one file per frame, and consecutive frames differ.
expect 0 "--animate --save-frames" -- "$viewer" --headless --size 96x72 --frames 3 --animate orbit:5,zoom:1.05 --save-frames "$tmp/frames"
[ "$(ls "$tmp/frames" | tr '\n' ' ')" = "frame-0000.png frame-0001.png frame-0002.png " ] || { echo "FAIL: frames written: $(ls "$tmp/frames")"; fail=1; }
cmp -s "$tmp/frames/frame-0000.png" "$tmp/frames/frame-0001.png" && { echo "FAIL: --animate did not move the camera"; fail=1; }
expect 2 "bad --animate" -- "$viewer" --headless --animate orbit:fast
expect 2 "--save-frames into a file" -- "$viewer" --headless --save-frames "$tmp/two.obj"

# Hatching orientation: each source renders and turns the strokes (the image differs from
# none); the palette report has each entry's direction; bad values are refused.
expect 0 "--palette-info orientation" -- "$viewer" --palette-info "$src/palettes/hatch/hatch.palette"
grep -q '"orientation_degrees":' "$tmp/out" && grep -q '"oriented":true' "$tmp/out" || { echo "FAIL: --palette-info has no orientation: $(cat "$tmp/out")"; fail=1; }
for o in none curvature light 30; do
  expect 0 "--orient $o" -- "$viewer" --headless --size 96x96 --palette "$src/palettes/hatch/hatch.palette" --orient $o --orient-bins 6 --screenshot "$tmp/orient-$o.png"
done
for o in curvature light 30; do
  cmp -s "$tmp/orient-none.png" "$tmp/orient-$o.png" && { echo "FAIL: --orient $o draws the same as none"; fail=1; }
done
expect 2 "bad --orient" -- "$viewer" --headless --orient sideways
expect 2 "--orient nan" -- "$viewer" --headless --orient nan
expect 2 "--orient-bins 1" -- "$viewer" --headless --orient curvature --orient-bins 1
expect 2 "--orient-bins 65" -- "$viewer" --headless --orient curvature --orient-bins 65

# Ground plane and shadows: each changes the frame (the ground appears; the shadow darkens it).
expect 0 "plain" -- "$viewer" --headless --size 96x96 --light 1,3,1 --screenshot "$tmp/plain.png"
expect 0 "--ground" -- "$viewer" --headless --size 96x96 --light 1,3,1 --ground --screenshot "$tmp/ground.png"
expect 0 "--ground --shadows" -- "$viewer" --headless --size 96x96 --light 1,3,1 --ground --shadows --screenshot "$tmp/shadows.png"
cmp -s "$tmp/plain.png" "$tmp/ground.png" && { echo "FAIL: --ground draws nothing"; fail=1; }
cmp -s "$tmp/ground.png" "$tmp/shadows.png" && { echo "FAIL: --shadows changes nothing"; fail=1; }
expect 0 "--occlusion" -- "$viewer" --headless --size 96x96 --light 1,3,1 --occlusion --occlusion-strength 0.8 --screenshot "$tmp/occlusion.png"
cmp -s "$tmp/plain.png" "$tmp/occlusion.png" && { echo "FAIL: --occlusion changes nothing"; fail=1; }
expect 0 "--triangle-lighting gpu" -- "$viewer" --headless --size 96x96 --light 1,3,1 --path triangle --triangle-lighting gpu --screenshot "$tmp/tri-gpu.png"
expect 0 "--triangle-lighting cpu" -- "$viewer" --headless --size 96x96 --light 1,3,1 --path triangle --triangle-lighting cpu --screenshot "$tmp/tri-cpu.png"
expect 2 "bad --triangle-lighting" -- "$viewer" --headless --triangle-lighting quantum
expect 2 "--occlusion-strength 2" -- "$viewer" --headless --occlusion --occlusion-strength 2
expect 2 "--occlusion-strength nan" -- "$viewer" --headless --occlusion --occlusion-strength nan
expect 0 "--occlusion-method screen" -- "$viewer" --headless --size 96x96 --light 1,3,1 --ground --occlusion --occlusion-method screen --screenshot "$tmp/ssao.png"
cmp -s "$tmp/ground.png" "$tmp/ssao.png" && { echo "FAIL: screen-space occlusion changes nothing"; fail=1; }
expect 2 "bad --occlusion-method" -- "$viewer" --headless --occlusion --occlusion-method raytraced
grep -q "use baked or screen" "$tmp/err" || { echo "FAIL: message: $(cat "$tmp/err")"; fail=1; }
# Control-image palettes: drawn where shadows fall (the frame changes); a missing file is a bad
# argument; one whose parameter is off is a note saying what to turn on, not a failure.
expect 0 "--shadow-palette" -- "$viewer" --headless --size 96x96 --light 1,3,1 --ground --shadows \
  --shadow-palette "$src/palettes/stipple/stipple.palette" --screenshot "$tmp/shadow-palette.png"
cmp -s "$tmp/shadows.png" "$tmp/shadow-palette.png" && { echo "FAIL: --shadow-palette changes nothing"; fail=1; }
expect 2 "--shadow-palette missing file" -- "$viewer" --headless --shadow-palette "$tmp/nope.palette"
grep -q -- "--shadow-palette: no palette named '.*nope.palette'" "$tmp/err" || { echo "FAIL: message: $(cat "$tmp/err")"; fail=1; }
expect 1 "--occlusion-palette broken" -- "$viewer" --headless --occlusion --occlusion-palette "$tmp/bad.palette"
grep -q "occlusion palette not loaded.*line 1" "$tmp/err" || { echo "FAIL: message: $(cat "$tmp/err")"; fail=1; }
expect 0 "--occlusion-palette without --occlusion" -- "$viewer" --headless --size 32x32 --occlusion-palette "$src/palettes/stipple/stipple.palette"
grep -q "turn occlusion on" "$tmp/err" || { echo "FAIL: no note for an idle occlusion palette: $(cat "$tmp/err")"; fail=1; }

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

# The style sheet: every shipped style in one picture of the asked size, each cell its own look.
expect 0 "--style-sheet" -- "$viewer" "$src/models/bunny.obj" --style-sheet "$tmp/styles.png" --size 640x352
styles=$(ls "$src/palettes/styles/"*.style | wc -l)
info=$(oiiotool --info "$tmp/styles.png" 2>/dev/null)
echo "$info" | grep -Eq "640 x +3(4[0-9]|5[0-2])," || { echo "FAIL: --style-sheet size: $info"; fail=1; }
# Columns: round(sqrt(n * 640/352 * 0.75)); the first two cells (charcoal's paper and cel's) differ.
columns=$(python3 -c "import math; print(max(1, min($styles, round(math.sqrt($styles * 640 / 352 * 0.75)))))")
cw=$((640 / columns))
oiiotool "$tmp/styles.png" --cut "${cw}x60+0+20" -o "$tmp/c1.png" && oiiotool "$tmp/styles.png" --cut "${cw}x60+${cw}+20" -o "$tmp/c2.png"
idiff -q "$tmp/c1.png" "$tmp/c2.png" >/dev/null 2>&1 && { echo "FAIL: --style-sheet's first two cells are equal"; fail=1; }
expect 1 "--style-sheet too small" -- "$viewer" --style-sheet "$tmp/tiny.png" --size 64x48
grep -q "cells of" "$tmp/err" || { echo "FAIL: --style-sheet too small gives no reason: $(cat "$tmp/err")"; fail=1; }

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
# A mapped pattern (scaled, through the anchored frame) continues across the seams too.
for p in pixel stencil; do
  expect 0 "one frame, mapped pattern ($p)" -- "$viewer" --headless --size 320x240 --path $p --pattern anchored --pattern-scale 1.5 --screenshot "$tmp/one-mapped-$p.png"
  expect 0 "2x2 tiles, mapped pattern ($p)" -- "$viewer" --headless --size 320x240 --path $p --pattern anchored --pattern-scale 1.5 --tile 160 --screenshot "$tmp/tiled-mapped-$p.png"
  oiiotool "$tmp/one-mapped-$p.png" "$tmp/tiled-mapped-$p.png" --fail 0.02 --failpercent 0.1 --diff > "$tmp/diff" \
    || { echo "FAIL: $p: the tiled poster's mapped pattern differs from one frame: $(grep -E 'Mean|pixels' "$tmp/diff" | head -2)"; fail=1; }
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
expect 2 "a style that does not exist" -- "$viewer" --headless --style nosuchstyle
grep -q "the shipped styles are .*pencil" "$tmp/err" || { echo "FAIL: an unknown style does not list the shipped ones: $(cat "$tmp/err")"; fail=1; }

# Names everywhere, through one resolver: a shipped palette or style by name, a typo answered
# with the closest names (exit 2), counts out of range refused, a saved style naming shipped
# palettes by name.
expect 0 "--palette NAME" -- "$viewer" --headless --size 64x48 --palette wood --screenshot "$tmp/wood.png"
expect 2 "--style with a typo" -- "$viewer" --headless --style pencl
grep -q "did you mean pencil" "$tmp/err" || { echo "FAIL: --style pencl: $(cat "$tmp/err")"; fail=1; }
[ "$(wc -l < "$tmp/err")" = 1 ] || { echo "FAIL: --style pencl says more than one line: $(cat "$tmp/err")"; fail=1; }
expect 2 "--palette with a typo" -- "$viewer" --headless --palette crosshach
grep -q "did you mean crosshatch" "$tmp/err" || { echo "FAIL: --palette crosshach: $(cat "$tmp/err")"; fail=1; }
expect 2 "--object-palette with a typo" -- "$viewer" --headless "$src/models/bunny.obj" --object-palette bunny=wod
grep -q "did you mean wood" "$tmp/err" || { echo "FAIL: --object-palette bunny=wod: $(cat "$tmp/err")"; fail=1; }
expect 2 "--turntable 0" -- "$viewer" --turntable 0
grep -q "2..3600" "$tmp/err" || { echo "FAIL: --turntable 0 does not name the range: $(cat "$tmp/err")"; fail=1; }
expect 2 "--frames 0" -- "$viewer" --headless --frames 0
grep -q "at least 1" "$tmp/err" || { echo "FAIL: --frames 0 does not name the range: $(cat "$tmp/err")"; fail=1; }
NPR_DATA_DIR="$tmp/no-such-folder" "$viewer" --headless --size 32x32 >"$tmp/out" 2>"$tmp/err"; status=$?
[ $status = 2 ] && grep -q "NPR_DATA_DIR" "$tmp/err" || { echo "FAIL: NPR_DATA_DIR naming a missing folder: exit $status, $(cat "$tmp/err")"; fail=1; }
expect 0 "--save-style of shipped palettes" -- "$viewer" --headless --size 32x32 --style illustrated --save-style "$tmp/saved.style"
grep -qx "palette stipple" "$tmp/saved.style" && grep -qx "shadow-palette crosshatch" "$tmp/saved.style" ||
  { echo "FAIL: a saved style names shipped palettes by path: $(grep palette "$tmp/saved.style")"; fail=1; }

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

# Scenes: several files at once, glTF nodes as objects, each object's own palette, the file's
# camera; bad scene arguments are refused by name.
G=/usr/share/assimp/models/glTF2
expect 0 "--info on a glTF scene and an OBJ" -- "$viewer" --info "$G/2CylinderEngine-glTF-Binary/2CylinderEngine.glb" "$src/models/bunny.obj"
[ "$(wc -l < "$tmp/out")" = 2 ] || { echo "FAIL: --info of two files is not two lines"; fail=1; }
head -1 "$tmp/out" | grep -q '"objects":\[{"name":' || { echo "FAIL: --info lists no objects: $(head -c 300 "$tmp/out")"; fail=1; }
expect 0 "--info --split-objects" -- "$viewer" --info --split-objects /usr/share/assimp/models/OBJ/spider.obj
grep -q '"name":"Bein1Li"' "$tmp/out" || { echo "FAIL: --split-objects does not list the spider's legs: $(head -c 300 "$tmp/out")"; fail=1; }
expect 0 "--info cameras" -- "$viewer" --info "$G/cameras/Cameras.gltf"
grep -q '"cameras":\[{"name":"camera 0","type":"perspective"' "$tmp/out" || { echo "FAIL: --info cameras: $(cat "$tmp/out")"; fail=1; }
expect 0 "two files, each object its own palette" -- "$viewer" --headless --size 160x96 "$src/models/bunny.obj" "$src/models/teapot.obj" --layout row --screenshot "$tmp/row.png"
expect 0 "--object-palette" -- "$viewer" --headless --size 160x96 "$src/models/bunny.obj" "$src/models/teapot.obj" --layout row --object-palette teapot=wood --screenshot "$tmp/row-wood.png"
cmp -s "$tmp/row.png" "$tmp/row-wood.png" && { echo "FAIL: --object-palette changes nothing"; fail=1; }
expect 0 "--object-palette by number" -- "$viewer" --headless --size 160x96 "$src/models/bunny.obj" "$src/models/teapot.obj" --layout row --object-palette 2=wood --screenshot "$tmp/row-wood2.png"
cmp -s "$tmp/row-wood.png" "$tmp/row-wood2.png" || { echo "FAIL: --object-palette 2 is not the teapot"; fail=1; }
expect 1 "--object-palette of no such object" -- "$viewer" --headless --size 64x64 "$src/models/bunny.obj" --object-palette kettle=wood
grep -q "no object named 'kettle'.*its objects: bunny" "$tmp/err" || { echo "FAIL: unknown object message: $(cat "$tmp/err")"; fail=1; }
# A palette with rows by detail: each object's --object-detail picks its row.
printf 'axis detail\nrow\n%s\n%s\nrow\n%s\n%s\n' "$src/palettes/cel/tone00.png" "$src/palettes/cel/tone03.png" "$src/palettes/wood/wood00.png" "$src/palettes/wood/wood29.png" > "$tmp/detail.palette"
expect 0 "a detail palette" -- "$viewer" --headless --size 160x96 "$src/models/bunny.obj" "$src/models/teapot.obj" --layout row --palette "$tmp/detail.palette" --screenshot "$tmp/detail0.png"
expect 0 "--object-detail" -- "$viewer" --headless --size 160x96 "$src/models/bunny.obj" "$src/models/teapot.obj" --layout row --palette "$tmp/detail.palette" --object-detail teapot=1 --screenshot "$tmp/detail1.png"
cmp -s "$tmp/detail0.png" "$tmp/detail1.png" && { echo "FAIL: --object-detail changes nothing"; fail=1; }
expect 2 "--object-detail out of range" -- "$viewer" --headless "$src/models/bunny.obj" --object-detail bunny=2
grep -q -- "--object-detail must be OBJECT=VALUE with VALUE in \[0, 1\], got 'bunny=2'" "$tmp/err" || { echo "FAIL: --object-detail message: $(cat "$tmp/err")"; fail=1; }
expect 1 "--object-detail of no such object" -- "$viewer" --headless --size 64x64 "$src/models/bunny.obj" --object-detail kettle=0.5
grep -q "no object named 'kettle'" "$tmp/err" || { echo "FAIL: --object-detail unknown object: $(cat "$tmp/err")"; fail=1; }
# ... and each material's --material-detail the row of its faces (the spider's body here).
expect 0 "a detail palette on the spider" -- "$viewer" --headless --size 160x96 /usr/share/assimp/models/OBJ/spider.obj --materials on --palette "$tmp/detail.palette" --screenshot "$tmp/mdetail0.png"
expect 0 "--material-detail" -- "$viewer" --headless --size 160x96 /usr/share/assimp/models/OBJ/spider.obj --materials on --palette "$tmp/detail.palette" --material-detail Skin=1 --screenshot "$tmp/mdetail1.png"
cmp -s "$tmp/mdetail0.png" "$tmp/mdetail1.png" && { echo "FAIL: --material-detail changes nothing"; fail=1; }
expect 2 "--material-detail out of range" -- "$viewer" --headless "$src/models/bunny.obj" --material-detail Skin=-1
grep -q -- "--material-detail must be MATERIAL=VALUE with VALUE in \[0, 1\], got 'Skin=-1'" "$tmp/err" || { echo "FAIL: --material-detail message: $(cat "$tmp/err")"; fail=1; }
expect 0 "--material-detail of no such material" -- "$viewer" --headless --size 64x64 /usr/share/assimp/models/OBJ/spider.obj --material-detail Kettle=0.5 --screenshot "$tmp/mdetail2.png"
grep -q "no material named 'Kettle' in .* for its detail" "$tmp/err" || { echo "FAIL: --material-detail unknown material: $(cat "$tmp/err")"; fail=1; }
expect 2 "bad --layout" -- "$viewer" --headless --layout diagonal
grep -q -- "--layout must be file, row or grid" "$tmp/err" || { echo "FAIL: --layout message: $(cat "$tmp/err")"; fail=1; }
expect 0 "--camera-from-file" -- "$viewer" --headless --size 96x96 "$G/cameras/Cameras.gltf" --camera-from-file 2 --screenshot "$tmp/ortho.png"
expect 1 "--camera-from-file past the file's cameras" -- "$viewer" --headless --size 64x64 "$src/models/bunny.obj" --camera-from-file 3
grep -q "no camera 3 in bunny.obj (it has none)" "$tmp/err" || { echo "FAIL: camera message: $(cat "$tmp/err")"; fail=1; }
expect 2 "--camera-from-file with --turntable" -- "$viewer" --headless "$G/cameras/Cameras.gltf" --camera-from-file 1 --turntable 4

# Animation: the scene's clock moves the animated objects in headless sequences (1/--fps per
# frame), --animation none holds the rest pose, --time poses a still; bad values are refused.
P="$src/models/pendulum.gltf"
expect 0 "--info animations" -- "$viewer" --info "$P"
grep -q '"animations":\[{"name":"swing and bounce","start":0,"end":2,"channels":3}\]' "$tmp/out" || { echo "FAIL: --info animations: $(tail -c 200 "$tmp/out")"; fail=1; }
expect 0 "an animated sequence" -- "$viewer" --headless --size 96x72 "$P" --frames 3 --fps 4 --save-frames "$tmp/anim"
cmp -s "$tmp/anim/frame-0000.png" "$tmp/anim/frame-0001.png" && { echo "FAIL: an animated scene does not move between frames"; fail=1; }
expect 0 "--animation none" -- "$viewer" --headless --size 96x72 "$P" --frames 2 --animation none --save-frames "$tmp/rest"
cmp -s "$tmp/rest/frame-0000.png" "$tmp/rest/frame-0001.png" || { echo "FAIL: --animation none moves"; fail=1; }
expect 0 "--time" -- "$viewer" --headless --size 96x72 "$P" --time 0.25 --screenshot "$tmp/quarter.png"
cmp -s "$tmp/quarter.png" "$tmp/anim/frame-0001.png" || { echo "FAIL: --time 0.25 is not the sequence's second frame at --fps 4"; fail=1; }
# A skinned mesh moves in every path, with no GL error (the run fails on one).
for path in stencil triangle vertex pixel smooth; do
  expect 0 "skinned, $path" -- "$viewer" --headless --size 96x96 "$src/models/bending_tube.gltf" --path $path --pattern object --lines silhouette \
    --frames 2 --fps 2 --save-frames "$tmp/tube-$path"
  cmp -s "$tmp/tube-$path/frame-0000.png" "$tmp/tube-$path/frame-0001.png" && { echo "FAIL: the skinned tube does not bend ($path)"; fail=1; }
done
# The Khronos skin and morph samples Debian ships play (their frames differ).
for sample in simple_skin/simple_skin.gltf glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf; do
  name=$(basename "$sample" .gltf)
  expect 0 "plays $name" -- "$viewer" --headless --size 96x96 "$G/$sample" --frames 2 --fps 1 --save-frames "$tmp/k-$name"
  cmp -s "$tmp/k-$name/frame-0000.png" "$tmp/k-$name/frame-0001.png" && { echo "FAIL: $name does not move"; fail=1; }
done
expect 0 "--svg of a pose" -- "$viewer" --headless --size 96x96 "$src/models/bending_tube.gltf" --time 1 --lines silhouette --svg "$tmp/bent.svg"
expect 0 "--svg at rest" -- "$viewer" --headless --size 96x96 "$src/models/bending_tube.gltf" --time 0 --lines silhouette --svg "$tmp/straight.svg"
cmp -s "$tmp/bent.svg" "$tmp/straight.svg" && { echo "FAIL: the SVG does not show the pose"; fail=1; }
expect 1 "--animation of no such animation" -- "$viewer" --headless --size 64x64 "$P" --animation walk
grep -q "no animation named 'walk' (the scene's: swing and bounce" "$tmp/err" || { echo "FAIL: --animation message: $(cat "$tmp/err")"; fail=1; }
expect 2 "negative --time" -- "$viewer" --headless "$P" --time -1
expect 2 "zero --fps" -- "$viewer" --headless "$P" --fps 0

# The first run on a machine without a display (.ci/setup run): files it names, exit 0.
(unset DISPLAY WAYLAND_DISPLAY; bash "$src/.ci/first_run.sh" "$viewer" "$tmp/first") > "$tmp/first.log" 2>&1 \
  || { echo "FAIL: first run: $(tail -3 "$tmp/first.log")"; fail=1; }
for f in still.png turntable/turntable.gif turntable/frame-0035.png; do
  [ -s "$tmp/first/$f" ] || { echo "FAIL: first run did not write $f"; fail=1; }
done
grep -q "$tmp/first" "$tmp/first.log" || { echo "FAIL: first run does not name its folder"; fail=1; }
grep -q "bash .ci/setup run" "$tmp/first.log" || { echo "FAIL: first run does not say how to open the window"; fail=1; }

[ $fail = 0 ] && echo "cli: all checks passed"
exit $fail
