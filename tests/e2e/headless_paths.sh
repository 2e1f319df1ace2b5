#!/usr/bin/env bash
# End-to-end: `--headless --frames 3 --screenshot` for every path, every match mode; the
# images exist, have the requested size, and differ between paths that should differ.
set -u
viewer="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
# The user-selectable paths, from the binary's own path table.
paths=$("$viewer" --list-paths | awk -F'\t' '$2 == "user" { print $1 }')
for needed in stencil triangle pixel smooth reference; do  # the comparisons below use these
  echo "$paths" | grep -qx "$needed" || { echo "FAIL: --list-paths lacks $needed: $paths"; fail=1; }
done
for path in $paths; do
  for match in colors intensity order; do
    if ! "$viewer" --headless --frames 3 --size 200x150 --path $path --match $match --screenshot "$tmp/$path-$match.png" 2>"$tmp/err"; then
      echo "FAIL: $path/$match: $(cat "$tmp/err")"; fail=1; continue
    fi
    info=$(oiiotool --info "$tmp/$path-$match.png")
    echo "$info" | grep -q "200 x  150" || { echo "FAIL: $path/$match size: $info"; fail=1; }
  done
done
# Other formats through OpenImageIO.
"$viewer" --headless --frames 1 --size 64x64 --screenshot "$tmp/shot.tga" 2>/dev/null && [ -s "$tmp/shot.tga" ] || { echo "FAIL: TGA screenshot"; fail=1; }
"$viewer" --headless --frames 1 --size 64x64 --screenshot "$tmp/shot.exr" 2>/dev/null && [ -s "$tmp/shot.exr" ] || { echo "FAIL: EXR screenshot"; fail=1; }
# The reference render and the palette render differ; pixel and smooth differ.
differs() { ! idiff -q -fail 0.004 "$1" "$2" >/dev/null 2>&1; }
differs "$tmp/pixel-intensity.png" "$tmp/reference-intensity.png" || { echo "FAIL: pixel equals reference"; fail=1; }
differs "$tmp/pixel-intensity.png" "$tmp/smooth-intensity.png" || { echo "FAIL: pixel equals smooth"; fail=1; }
# stencil and triangle draw the same image.
idiff -q -fail 0.004 -failpercent 0.1 "$tmp/stencil-intensity.png" "$tmp/triangle-intensity.png" >/dev/null || { echo "FAIL: stencil != triangle"; fail=1; }
[ $fail = 0 ] && echo "headless paths: all checks passed"
exit $fail
