#!/usr/bin/env bash
# End-to-end: the real binary's command line: --info, --palette-info, exit codes for bad
# arguments (2) and failed loads (1), and --help.
set -u
viewer="$1"; src="$2"
source "$(dirname "$0")/expect.sh"
expect 0 "--help" -- "$viewer" --help
grep -q -- "--palette" "$tmp/out" || { echo "FAIL: --help does not list --palette"; fail=1; }

expect 0 "--info bunny" -- "$viewer" --info "$src/models/bunny.obj"
grep -q '"triangles":3674' "$tmp/out" || { echo "FAIL: --info output: $(cat "$tmp/out")"; fail=1; }
[ "$(wc -l < "$tmp/out")" = 1 ] || { echo "FAIL: --info is not one line"; fail=1; }
printf 'v 0 0 0\nv 1 0 0\n' > "$tmp/points.obj"
expect 1 "--info on a file with no faces" -- "$viewer" --info "$tmp/points.obj"
grep -q "no faces" "$tmp/err" || { echo "FAIL: reason missing: $(cat "$tmp/err")"; fail=1; }
expect 1 "--info on a missing file" -- "$viewer" --info "$tmp/none.obj"

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
grep -q -- "--shadow-palette: palette file '.*nope.palette' does not exist" "$tmp/err" || { echo "FAIL: message: $(cat "$tmp/err")"; fail=1; }
expect 1 "--occlusion-palette broken" -- "$viewer" --headless --occlusion --occlusion-palette "$tmp/bad.palette"
grep -q "occlusion palette not loaded.*line 1" "$tmp/err" || { echo "FAIL: message: $(cat "$tmp/err")"; fail=1; }
expect 0 "--occlusion-palette without --occlusion" -- "$viewer" --headless --size 32x32 --occlusion-palette "$src/palettes/stipple/stipple.palette"
grep -q "turn occlusion on" "$tmp/err" || { echo "FAIL: no note for an idle occlusion palette: $(cat "$tmp/err")"; fail=1; }

[ $fail = 0 ] && echo "cli: all checks passed"
exit $fail
