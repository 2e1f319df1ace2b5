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

[ $fail = 0 ] && echo "cli: all checks passed"
exit $fail
