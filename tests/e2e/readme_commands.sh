#!/usr/bin/env bash
# End-to-end: every npr-viewer command in the README's code blocks runs, as written, on the
# shipped files, so a stale example fails CI. Each runs in a scratch folder holding links to
# models/ and palettes/ (the README's paths are the source tree's), with /tmp/ in its output
# paths moved into the scratch folder. Sizes become 96x64 to keep the tier fast, and commands
# that open a window run headless (the window's own tests drive it); nothing else changes.
# Usage: readme_commands.sh VIEWER SOURCE_DIR
set -u
viewer="$1"; src="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
ln -s "$src/models" "$tmp/models"; ln -s "$src/palettes" "$tmp/palettes"
fail=0; ran=0
touch "$tmp/start"
# The README's indented code lines that run the viewer, continuation lines joined.
mapfile -t commands < <(awk '
  /^    / { line = substr($0, 5); if (held != "") { line = held " " line; held = "" }
           if (line ~ /\\$/) { held = substr(line, 1, length(line) - 1); next }
           if (line ~ /^(NPR_[A-Z_]+=[^ ]+ )*npr-viewer /) print line; next }
  { held = "" }' "$src/README.md")
[ ${#commands[@]} -ge 20 ] || { echo "FAIL: found only ${#commands[@]} commands in the README"; fail=1; }
headless_options='--headless|--turntable|--video|--frame-range|--make-palette|--palette-sheet|--palette-info|--gl-info|--info|--benchmark|--settings-reference|--style-sheet|--version|--help'
for cmd in "${commands[@]}"; do
  run="${cmd%%  #*}"                                  # the comment after the command
  run="${run//\/tmp\//$tmp/}"                          # outputs into the scratch folder
  run=$(sed -E 's/--size [0-9]+x[0-9]+/--size 96x64/' <<<"$run")
  grep -qE -- "--size " <<<"$run" || run="$run --size 96x64"
  grep -qE -- "($headless_options)( |$)" <<<"$run" || run="$run --headless"
  run=$(sed -E "s#(^|[ ])npr-viewer #\\1'$viewer' #" <<<"$run")
  ran=$((ran + 1))
  if ! (cd "$tmp" && eval "$run") >"$tmp/out" 2>"$tmp/err"; then
    echo "FAIL: README: $cmd"; tail -3 "$tmp/err"; fail=1
  fi
done
# Nothing was written beside the links: every output went where the README said.
[ "$(find -L "$src/models" "$src/palettes" -newer "$tmp/start" -type f 2>/dev/null | head -1)" = "" ] || { echo "FAIL: an example wrote into the source tree"; fail=1; }
echo "readme: $ran commands run"
exit $fail
