#!/usr/bin/env bash
# End-to-end, in CI only (it installs into the system): builds the .deb from BUILD (CPack),
# installs it with dpkg, renders one frame with the installed /usr/bin/npr-viewer from a
# scratch folder on its installed data, then removes the package again.
set -u
build=$(cd "$1" && pwd)
sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
(cd "$build" && rm -f npr-viewer_*.deb && cpack -G DEB >"$tmp/cpack.log" 2>&1) || { echo "FAIL: cpack"; cat "$tmp/cpack.log"; exit 1; }
deb=$(ls "$build"/npr-viewer_*.deb)
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KB; depends: $(dpkg-deb -f "$deb" Depends)"
$sudo_cmd dpkg -i "$deb" >"$tmp/dpkg.log" 2>&1 || { echo "FAIL: dpkg -i"; cat "$tmp/dpkg.log"; exit 1; }
fail=0
cd "$tmp" || exit 1
if ! env -u NPR_DATA_DIR /usr/bin/npr-viewer --headless --style woodcut --size 160x120 --screenshot "$tmp/deb.png" >"$tmp/run.log" 2>&1 || [ ! -s "$tmp/deb.png" ]; then
  echo "FAIL: the installed package does not render"; cat "$tmp/run.log"; fail=1
fi
# The modules (/usr/lib/npr-viewer): OpenImageIO for a TGA; their libraries among the Depends.
if ! env -u NPR_DATA_DIR /usr/bin/npr-viewer --headless --size 64x48 --screenshot "$tmp/deb.tga" >"$tmp/run.log" 2>&1 || [ ! -s "$tmp/deb.tga" ]; then
  echo "FAIL: the installed package cannot write a TGA through its OpenImageIO module"; cat "$tmp/run.log"; fail=1
fi
for dep in libopenimageio libavcodec; do
  dpkg-deb -f "$deb" Depends | grep -q "$dep" || { echo "FAIL: the package does not depend on $dep (its modules link it)"; fail=1; }
done
env -u NPR_DATA_DIR /usr/bin/npr-viewer --version | grep -qx "data: /usr/share/npr-viewer" || { echo "FAIL: the package's viewer does not use /usr/share/npr-viewer"; fail=1; }
[ -f /usr/share/man/man1/npr-viewer.1.gz ] || [ -f /usr/share/man/man1/npr-viewer.1 ] || { echo "FAIL: no manual page installed"; fail=1; }
$sudo_cmd dpkg -r npr-viewer >/dev/null 2>&1 || { echo "FAIL: dpkg -r"; fail=1; }
[ $fail -eq 0 ] && echo "package: installed, rendered, removed"
exit $fail
