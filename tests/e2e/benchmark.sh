#!/usr/bin/env bash
# End-to-end: a CI-sized run of `--benchmark` (small model, few frames, 256x256). Checks the
# output files exist and parse, every path appears, the accuracy ordering holds (smooth and
# pixel no worse than vertex, vertex no worse than triangle, triangle equal to stencil) and
# no non-finite value was seen. Timings are printed, never asserted.
set -u
viewer="$1"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
"$viewer" --benchmark "$src/models/teapot.obj" --size 256x256 --frames 8 --out "$tmp/out" > "$tmp/stdout" 2> "$tmp/stderr" \
  || { echo "FAIL: benchmark exited $?"; cat "$tmp/stderr"; exit 1; }
cat "$tmp/stdout"
for f in results.csv results.md; do [ -s "$tmp/out/$f" ] || { echo "FAIL: $f missing"; fail=1; }; done
ls "$tmp/out"/plot-*.png >/dev/null 2>&1 || { echo "FAIL: no plot"; fail=1; }
for png in "$tmp"/out/plot-*.png; do oiiotool --info "$png" | grep -q "900 x  600" || { echo "FAIL: $png is not a 900x600 image"; fail=1; }; done
csv="$tmp/out/results.csv"
header=$(head -1 "$csv")
[ "$(echo "$header" | tr ',' '\n' | wc -l)" = 20 ] || { echo "FAIL: unexpected CSV header: $header"; fail=1; }
awk -F, 'NR > 1 && NF != 20 { bad = 1 } END { exit bad }' "$csv" || { echo "FAIL: a CSV row does not have 20 fields"; fail=1; }
# Every path of the binary's path table, internal ones included.
all_paths=$("$viewer" --list-paths | cut -f1)
[ -n "$all_paths" ] || { echo "FAIL: --list-paths printed nothing"; fail=1; }
for path in $all_paths; do
  grep -q ",$path," "$csv" || { echo "FAIL: path $path missing from results.csv"; fail=1; }
done
err() { awk -F, -v p="$1" 'NR > 1 && $4 == p { print $14 }' "$csv"; }   # mean_error
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a <= b + 1e-9) }'; }
le "$(err smooth)" "$(err vertex)" || { echo "FAIL: smooth ($(err smooth)) less accurate than vertex ($(err vertex))"; fail=1; }
le "$(err pixel)" "$(err vertex)" || { echo "FAIL: pixel ($(err pixel)) less accurate than vertex ($(err vertex))"; fail=1; }
le "$(err vertex)" "$(err triangle)" || { echo "FAIL: vertex ($(err vertex)) less accurate than triangle ($(err triangle))"; fail=1; }
[ "$(err triangle)" = "$(err stencil)" ] || { echo "FAIL: triangle ($(err triangle)) and stencil ($(err stencil)) differ"; fail=1; }
awk -F, 'NR > 1 && $20 != 0 { bad = 1 } END { exit bad }' "$csv" || { echo "FAIL: non-finite values seen"; fail=1; }
grep -q "0 lighting recomputations, 0 uploads, 0 shader builds" "$tmp/out/results.md" || { echo "FAIL: static frames did work"; fail=1; }
# With --shadows the reference casts rays toward the light: the smooth path, whose only error is
# rounding, then agrees with it (a reference lit without shadows puts it 0.04 steps off here).
"$viewer" --benchmark "$src/models/teapot.obj" --size 256x256 --frames 6 --shadows --out "$tmp/shadows" > /dev/null 2> "$tmp/stderr" \
  || { echo "FAIL: benchmark --shadows exited $?"; cat "$tmp/stderr"; fail=1; }
smooth=$(awk -F, 'NR > 1 && $4 == "smooth" { print $14 }' "$tmp/shadows/results.csv")
grep -q "teapot.obj +shadows" "$tmp/shadows/results.csv" || { echo "FAIL: the shadowed run is not labelled"; fail=1; }
le "$smooth" 0.02 || { echo "FAIL: smooth path with shadows $smooth steps from the ray-cast reference"; fail=1; }
[ $fail = 0 ] && echo "benchmark: all checks passed"
exit $fail
