#!/usr/bin/env bash
# Whole process, file to a 1280x720 PNG: npr-viewer headless against f3d (under Xvfb, as a
# user without a GPU runs it), interleaved rounds, medians; and --version alone (start-up:
# loading the shared libraries). Caches: the mesh cache and Mesa's shader cache warm after the
# first round (the first round's figures are printed apart as "cold").
# Usage: first_frame.sh VIEWER [ROUNDS=5] [MODEL...]   (default models: the bunny and the Khronos engine)
# EMPTY_CACHES=1: every run of either program gets a fresh, empty XDG_CACHE_HOME (no mesh cache,
# no Mesa shader cache: the first run after installing, every time).
set -u
viewer="$1"; rounds="${2:-5}"; shift 2 || shift $#
src=$(cd "$(dirname "$0")/../.." && pwd)
models=("$@")
[ ${#models[@]} -gt 0 ] || models=("$src/models/bunny.obj" /usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb)
command -v f3d >/dev/null || { echo "first_frame: f3d is not installed (apt install f3d)"; exit 1; }
tmp=$(mktemp -d); trap 'kill $xvfb 2>/dev/null; rm -rf "$tmp"' EXIT
Xvfb :77 -screen 0 1920x1080x24 >/dev/null 2>&1 & xvfb=$!; sleep 1
seconds() {
  local s e
  if [ -n "${EMPTY_CACHES:-}" ]; then rm -rf "$tmp/cache"; mkdir -p "$tmp/cache"; export XDG_CACHE_HOME="$tmp/cache"; fi
  s=$(date +%s%N); "$@" >/dev/null 2>&1; e=$(date +%s%N); echo $(( (e - s) / 1000000 ))
}
median() { tr ' ' '\n' | grep -v '^$' | sort -n | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
echo "| file | npr-viewer ms (median of $rounds) | f3d ms | ratio | npr cold | f3d cold |"
echo "|---|---|---|---|---|---|"
for m in "${models[@]}"; do
  npr=""; f3d=""; nprCold=""; f3dCold=""
  for r in $(seq 0 "$rounds"); do
    a=$(seconds "$viewer" --headless --size 1280x720 --screenshot "$tmp/npr.png" "$m")
    b=$(seconds env DISPLAY=:77 f3d --resolution 1280,720 --output "$tmp/f3d.png" "$m")
    if [ "$r" = 0 ]; then nprCold=$a; f3dCold=$b; else npr="$npr $a"; f3d="$f3d $b"; fi
  done
  n=$(echo "$npr" | median); f=$(echo "$f3d" | median)
  echo "| $(basename "$m") | $n | $f | $(awk -v a="$n" -v b="$f" 'BEGIN { printf "%.2f", a / b }') | $nprCold | $f3dCold |"
done
v=""; fv=""
for r in $(seq "$rounds"); do v="$v $(seconds "$viewer" --version)"; fv="$fv $(seconds f3d --version)"; done
echo "| --version | $(echo "$v" | median) | $(echo "$fv" | median) | | | |"
