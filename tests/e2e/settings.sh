#!/usr/bin/env bash
# End-to-end: the settings table as users meet it. docs/settings.md is what the table gives
# (--settings-reference); --help offers every setting; a look given on the command line and
# kept with --save-style comes back whole from --style, as the same picture.
set -u
viewer="$1"
root="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
"$viewer" --settings-reference > "$tmp/settings.md" || { echo "FAIL: --settings-reference"; fail=1; }
if ! diff -u "$root/docs/settings.md" "$tmp/settings.md" > "$tmp/diff"; then
  echo "FAIL: docs/settings.md is not current: regenerate it with npr-viewer --settings-reference > docs/settings.md"; head -20 "$tmp/diff"; fail=1
fi
"$viewer" --help > "$tmp/help"
for key in $(grep -o '^| `[a-z-]*`' "$tmp/settings.md" | tr -d '|` '); do
  grep -q "^  --$key\b\|^  --$key," "$tmp/help" || grep -q "^| \`$key\` (style only)" "$tmp/settings.md" || { echo "FAIL: --help lacks --$key"; fail=1; }
done
look=(--path stencil --orient curvature --orient-bins 16 --pattern object --pattern-scale 1.5 --lines silhouette,crease --line-width 3
      --shadows --ground --light 1,3,1 --tone gooch --tone-blue 0.7)
"$viewer" --headless --size 96x96 "${look[@]}" --palette "$root/palettes/hatch" --screenshot "$tmp/given.png" --save-style "$tmp/a.style" 2>"$tmp/err" \
  || { echo "FAIL: --save-style: $(cat "$tmp/err")"; fail=1; }
"$viewer" --headless --size 96x96 --style "$tmp/a.style" --screenshot "$tmp/styled.png" --save-style "$tmp/b.style" 2>"$tmp/err" \
  || { echo "FAIL: --style of a saved style: $(cat "$tmp/err")"; fail=1; }
diff <(grep -v '^name ' "$tmp/a.style") <(grep -v '^name ' "$tmp/b.style") > "$tmp/diff" || { echo "FAIL: the saved style does not save back the same:"; cat "$tmp/diff"; fail=1; }
for expected in "path stencil" "orient-bins 16" "pattern object" "lines silhouette,crease" "tone-blue 0.7" "light 1,3,1"; do
  grep -qx "$expected" "$tmp/a.style" || { echo "FAIL: the saved style lacks '$expected'"; fail=1; }
done
cmp -s "$tmp/given.png" "$tmp/styled.png" || { echo "FAIL: the saved style draws another picture than the options it saved"; fail=1; }
# A value out of range names the option and what it takes.
"$viewer" --headless --orient-bins 65 2>"$tmp/err"; [ $? = 2 ] || { echo "FAIL: --orient-bins 65 accepted"; fail=1; }
grep -q -- "--orient-bins '65': use an integer in 2..64" "$tmp/err" || { echo "FAIL: message: $(cat "$tmp/err")"; fail=1; }
[ $fail = 0 ] && echo "settings: reference current, every option offered, saved looks round-trip"
exit $fail
