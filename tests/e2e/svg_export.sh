#!/usr/bin/env bash
# End-to-end: --svg. The file parses as XML, is SVG 1.1 with one group per line kind (suggestive
# contours among them), and its
# lines, rasterised by rsvg-convert, coincide with the raster lines within a pixel (drawn over a
# plain white palette so only the lines show), on the bunny and the teapot; a glTF file's own
# points and lines are written where the frame draws them.
set -u
viewer="$1"; overlap="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
oiiotool --pattern constant:color=1,1,1 4x4 3 -o "$tmp/white.png"
printf 'white.png\nbackground #FFFFFF\n' > "$tmp/white.palette"
src="$(cd "$(dirname "$0")/../.." && pwd)"
for model in bunny teapot; do
  args=("$src/models/$model.obj" --headless --size 480x360 --palette "$tmp/white.palette" --lines silhouette,boundary,suggestive)
  if ! "$viewer" "${args[@]}" --screenshot "$tmp/$model.png" --svg "$tmp/$model.svg" 2>"$tmp/err"; then
    echo "FAIL: $model: --svg: $(cat "$tmp/err")"; fail=1; continue
  fi
  grep -Eq "wrote .*$model.svg: [1-9][0-9]* paths, [0-9]+ px of lines" "$tmp/err" || { echo "FAIL: no path count in the log: $(cat "$tmp/err")"; fail=1; }
  python3 - "$tmp/$model.svg" <<'PY' || fail=1
import sys, xml.dom.minidom
doc = xml.dom.minidom.parse(sys.argv[1])
svg = doc.documentElement
assert svg.tagName == "svg" and svg.getAttribute("version") == "1.1", "not SVG 1.1"
assert svg.getAttribute("width") == "480" and svg.getAttribute("height") == "360", "canvas is not the frame"
groups = [g.getAttribute("id") for g in svg.getElementsByTagName("g")]
assert "silhouettes" in groups, groups
assert "suggestive-contours" in groups, groups
assert len(svg.getElementsByTagName("polyline")) > 0, "no polylines"
PY
  rsvg-convert -b white "$tmp/$model.svg" -o "$tmp/$model-svg.png" || { echo "FAIL: rsvg-convert cannot draw $model.svg"; fail=1; continue; }
  "$overlap" "$tmp/$model.png" "$tmp/$model-svg.png" 1 0.9 || { echo "FAIL: $model: the SVG's lines and the raster lines do not coincide"; fail=1; }
done
# Intersection lines: a box and a bar through it, in one OBJ file; the SVG's group
# "intersections" coincides with the raster's.
{
  printf 'o box\n'
  for z in -1 1; do for y in -1 1; do for x in -1 1; do echo "v $x $y $z"; done; done; done
  printf 'f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n'
  printf 'o bar\n'
  for z in -0.4 0.4; do for y in -0.4 0.4; do for x in 0 2; do echo "v $x $y $z"; done; done; done
  printf 'f 9 11 12 10\nf 13 14 16 15\nf 9 10 14 13\nf 11 15 16 12\nf 9 13 15 11\nf 10 12 16 14\n'
} > "$tmp/crossing.obj"
if "$viewer" "$tmp/crossing.obj" --headless --size 480x360 --palette "$tmp/white.palette" --lines intersection \
    --screenshot "$tmp/crossing.png" --svg "$tmp/crossing.svg" 2>"$tmp/err"; then
  grep -q '<g id="intersections"' "$tmp/crossing.svg" || { echo "FAIL: no intersections group in the SVG"; fail=1; }
  rsvg-convert -b white "$tmp/crossing.svg" -o "$tmp/crossing-svg.png" &&
    "$overlap" "$tmp/crossing.png" "$tmp/crossing-svg.png" 1 0.9 || { echo "FAIL: the SVG's intersection lines and the raster's do not coincide"; fail=1; }
else
  echo "FAIL: --lines intersection --svg: $(cat "$tmp/err")"; fail=1
fi
# --svg-fill: the palette's regions filled with its textures; rasterised, the SVG is the frame
# (at most 5% of the pixels differ by more than 0.1; lines off, so only the fills compare), on
# the per-pixel path and on the triangle path at pattern scale 2.
for args in "--path pixel" "--path triangle --pattern-scale 2"; do
  # shellcheck disable=SC2086
  if "$viewer" "$src/models/bunny.obj" --headless --size 320x240 $args --svg "$tmp/fill.svg" --svg-fill --screenshot "$tmp/fill.png" 2>"$tmp/err"; then
    grep -Eq "[1-9][0-9]* palette regions in [1-9][0-9]* outlines" "$tmp/err" || { echo "FAIL: --svg-fill ($args) reports no regions: $(cat "$tmp/err")"; fail=1; }
    rsvg-convert "$tmp/fill.svg" -o "$tmp/fill-svg.png" &&
      oiiotool --fail 0.1 --failpercent 5 "$tmp/fill.png" --ch R,G,B "$tmp/fill-svg.png" --ch R,G,B --diff >"$tmp/diff" 2>&1 ||
      { echo "FAIL: --svg-fill ($args): the rasterised SVG is not the frame: $(grep -E 'over' "$tmp/diff" | tail -1)"; fail=1; }
  else
    echo "FAIL: --svg-fill ($args): $(cat "$tmp/err")"; fail=1
  fi
done
# A set coloured by tone: its lines in groups by palette entry, each in that entry's average
# colour (the wood palette's browns), none in the kinds' black; a tapered set as filled outlines.
if "$viewer" "$src/models/bunny.obj" --headless --size 320x240 --palette "$src/palettes/wood" --line-set "silhouette width=3 colour=tone" \
     --line-set "crease width=4 taper=20 colour=0,0,0" --crease-angle 40 --svg "$tmp/tone.svg" 2>"$tmp/err"; then
  toned=$(grep -c '<g id="set1-silhouettes-tone-[0-9a-f]*" fill="none" stroke="#' "$tmp/tone.svg")
  [ "$toned" -ge 2 ] || { echo "FAIL: colour=tone: $toned groups by entry (expected several)"; fail=1; }
  grep -q '<g id="set1-silhouettes" ' "$tmp/tone.svg" && { echo "FAIL: colour=tone: a group in the kind's colour"; fail=1; }
  grep -q '<g id="set2-creases" fill="#000000" stroke="none"' "$tmp/tone.svg" || { echo "FAIL: a tapered set is not written as filled outlines"; fail=1; }
else
  echo "FAIL: colour=tone --svg: $(cat "$tmp/err")"; fail=1
fi
# A file's own points and lines (glTF POINTS and LINE_STRIP): a quad with 16 points in front of
# it and 16 behind, and a strip from front to back. The SVG has the 16 visible dots as circles of
# the drawn diameter and the strip's visible part as a polyline; rasterised, both coincide with
# the frame's (drawn over the white palette, so only the marks show).
python3 - "$tmp/marks.gltf" <<'PY'
import base64, json, struct, sys
# A quad at z=0 facing +z; 16 points in front of it (z=0.4) and 16 behind (z=-0.4), all inside
# its outline; a line strip from front to back.
quad = [(-1,-1,0),(1,-1,0),(1,1,0),(-1,1,0)]
front = [(-0.6+0.4*i, -0.6+0.4*j, 0.4) for i in range(4) for j in range(4)]
back = [(x, y, -0.4) for x, y, _ in front]
strip = [(-0.8,-0.8,0.4),(0.8,-0.8,0.4),(0.8,0.8,-0.4),(-0.8,0.8,-0.4)]
pts = quad + front + back + strip
pos = b"".join(struct.pack("<3f", *p) for p in pts)
idx = struct.pack("<6H", 0,1,2, 0,2,3) + b"\0\0"
buf = pos + idx
n = len(pts)
lo = [min(p[k] for p in pts) for k in range(3)]; hi = [max(p[k] for p in pts) for k in range(3)]
doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)}, {"buffer": 0, "byteOffset": len(pos), "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1,-1,0], "max": [1,1,0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
    {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 32, "type": "VEC3", "min": [-0.6,-0.6,-0.4], "max": [0.6,0.6,0.4]},
    {"bufferView": 0, "byteOffset": 48 + 32*12, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.8,-0.8,-0.4], "max": [0.8,0.8,0.4]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4},
                             {"attributes": {"POSITION": 2}, "mode": 0},
                             {"attributes": {"POSITION": 3}, "mode": 3}]}]}
json.dump(doc, open(sys.argv[1], "w"))
PY
if "$viewer" "$tmp/marks.gltf" --headless --size 480x360 --palette "$tmp/white.palette" --line-width 2 \
     --screenshot "$tmp/marks.png" --svg "$tmp/marks.svg" 2>"$tmp/err"; then
  dots=$(grep -c '<circle [^>]* r="2.50"/>' "$tmp/marks.svg")
  [ "$dots" = 16 ] || { echo "FAIL: marks: $dots dots of 5 px in the SVG (expected the 16 in front)"; fail=1; }
  grep -q '<g id="marks" fill="none"' "$tmp/marks.svg" || { echo "FAIL: marks: no group of the file's lines"; fail=1; }
  rsvg-convert -b white "$tmp/marks.svg" -o "$tmp/marks-svg.png" &&
    "$overlap" "$tmp/marks.png" "$tmp/marks-svg.png" 1 0.95 || { echo "FAIL: the SVG's points and lines and the frame's do not coincide"; fail=1; }
else
  echo "FAIL: points and lines --svg: $(cat "$tmp/err")"; fail=1
fi
# With the frame embedded underneath, and a refusal without lines.
"$viewer" --headless --size 96x72 --lines silhouette --svg "$tmp/raster.svg" --svg-raster 2>/dev/null
grep -q 'data:image/png;base64,' "$tmp/raster.svg" || { echo "FAIL: --svg-raster embeds no image"; fail=1; }
"$viewer" --headless --size 96x72 --lines none --svg "$tmp/none.svg" 2>"$tmp/err" && { echo "FAIL: --svg without lines succeeded"; fail=1; }
grep -q "lines" "$tmp/err" || { echo "FAIL: --svg without lines gives no reason"; fail=1; }
[ $fail = 0 ] && echo "svg: all checks passed"
exit $fail
