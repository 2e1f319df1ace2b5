#!/usr/bin/env bash
# End-to-end: text from files and paths never reaches the terminal raw. Each parser gets a file
# whose content (and whose name) holds ESC sequences, BEL, CR, NUL and invalid UTF-8; the real
# binary's stdout and stderr (--info's JSON included) must then hold no control byte but line
# breaks and only valid UTF-8, while the message still names the file.
set -u
viewer="$1"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
bad=$'\e]0;pwned\a\e[2J\r\xff\xc3'  # title change, bell, clear screen, CR, invalid UTF-8
word=$'\e]0;pwned\a\e[2J\xff\xc3'   # the same without the CR, where a reader quotes one token
check() {  # check WHAT [any]: the last run's output is safe to print and (unless `any`) shows the escaped text
  python3 - "$tmp/out" "$tmp/err" "$1" "${2:-}" <<'PY' || fail=1
import sys
what = sys.argv[3]
text = open(sys.argv[1], 'rb').read() + open(sys.argv[2], 'rb').read()
bad = [b for b in set(text) if (b < 0x20 and b != 0x0a) or b == 0x7f]
try:
    text.decode('utf-8')
    utf8 = True
except UnicodeDecodeError:
    utf8 = False
if bad or not utf8:
    print(f"FAIL: {what}: raw bytes reach the terminal: control {sorted(bad)}, valid UTF-8 {utf8}: {text[:300]!r}")
    sys.exit(1)
if sys.argv[4] != 'any' and b'\\x1b' not in text:
    print(f"FAIL: {what}: the message does not show the escaped text: {text[:300]!r}")
    sys.exit(1)
PY
}
run() { "$@" >"$tmp/out" 2>"$tmp/err"; }

# Content: statements, names and keys each reader quotes in a warning or an error.
printf 'mtllib %s.mtl\nusemtl %s\n%s unknown\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 %s\n' "$bad" "$bad" "$bad" "$bad" > "$tmp/content.obj"
run "$viewer" --info "$tmp/content.obj"; check "OBJ statements, mtllib and usemtl names (--info JSON)"
printf 'newmtl m\nKd 1 0 0\nmap_Kd %s.png\n' "$word" > "$tmp/lib.mtl"
printf 'mtllib lib.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$tmp/uses-mtl.obj"
run "$viewer" --info "$tmp/uses-mtl.obj"; check "an MTL texture name"
printf 'ply\nformat %s 1.0\nend_header\n' "$bad" > "$tmp/format.ply"
run "$viewer" --info "$tmp/format.ply"; check "PLY format"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty %s x\nend_header\n' "$bad" > "$tmp/type.ply"
run "$viewer" --info "$tmp/type.ply"; check "PLY property type"
printf 'ply\nformat ascii 1.0\nkeyword %s\nend_header\n' "$word" > "$tmp/line.ply"
run "$viewer" --info "$tmp/line.ply"; check "PLY header line"
printf '%sOFF\n3 1 0\n' "$word" > "$tmp/variant.off"
run "$viewer" --info "$tmp/variant.off"; check "OFF variant"
printf '{"asset":{"version":"2.0"},"extensionsRequired":["\\u001b]0;pwned\\u0007\\u009b2J"]}' > "$tmp/extension.gltf"
run "$viewer" --info "$tmp/extension.gltf"; check "a glTF extension name"
printf '%s' "$bad" > "$tmp/garbage.glb"
run "$viewer" --info "$tmp/garbage.glb"; check "glTF bytes the loader quotes" any
printf '%s\n' "$bad" > "$tmp/entry.palette"
run "$viewer" --palette-info "$tmp/entry.palette"; check "palette entry"
printf 'match %s\n' "$bad" > "$tmp/match.palette"
run "$viewer" --palette-info "$tmp/match.palette"; check "palette match mode"
printf '%s on\n' "$bad" > "$tmp/key.style"
run "$viewer" --headless --style "$tmp/key.style" --size 32x32; check "style key"
# Names: a file whose name carries the sequence, for each format the gate or a reader refuses.
for ext in obj ply off stl om gltf glb palette; do
  name="$tmp/name$bad.$ext"
  printf 'garbage\n' > "$name"
  if [ "$ext" = palette ]; then run "$viewer" --palette-info "$name"; else run "$viewer" --info "$name"; fi
  check "a .$ext file's name"
done
run "$viewer" --headless --size 32x32 --save-frames "/proc/$bad"; check "a folder name on the command line"
run "$viewer" --gl-info --gpu "$bad"; check "a --gpu name"
exit $fail
