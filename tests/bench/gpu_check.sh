#!/usr/bin/env bash
# The GPU check: what a machine with a GPU measures in under 4 minutes, printed as one table.
#   bash tests/bench/gpu_check.sh [BUILD=build] [FRAMES=30]
# First --gl-info (which device the headless context opened); then, for the bunny and the
# 871K-triangle torus at 1920x1080 and 3840x2160, every user path and the pixel path with
# shadows, occlusion (bake and screen), strokes and the object pattern: the median frame time of
# FRAMES frames of an orbit (npr-viewer --headless, one process per row, so rows are
# independent); then bench_frames' per-triangle lighting on the CPU against the GPU (the choice
# made on llvmpipe) on the torus. Needs the Release build with the benchmarks (the default).
set -u
build="${1:-build}"; frames="${2:-30}"
viewer="$build/app/npr-viewer"
[ -x "$viewer" ] || { echo "gpu_check: no $viewer (build first: cmake -S . -B $build && cmake --build $build)"; exit 2; }
start=$SECONDS
"$viewer" --gl-info || exit 1
echo
echo "| mesh | size | configuration | median ms |"
echo "|---|---|---|---|"
row() {  # row MESH SIZE LABEL ARGS...
  local mesh="$1" size="$2" label="$3"; shift 3
  local out ms
  out=$("$viewer" --headless "$mesh" --size "$size" --frames "$frames" --animate orbit:1 "$@" 2>&1)
  ms=$(printf '%s\n' "$out" | grep -o 'median [0-9.]* ms' | tail -1 | grep -o '[0-9.]*')
  echo "| $(basename "$mesh") | $size | $label | ${ms:-failed: $(printf '%s' "$out" | tail -1)} |"
}
for mesh in models/bunny.obj generated:torus-871k; do
  for size in 1920x1080 3840x2160; do
    for path in stencil triangle vertex pixel smooth reference; do row "$mesh" "$size" "path $path" --path "$path"; done
    row "$mesh" "$size" "pixel + shadows" --path pixel --shadows
    row "$mesh" "$size" "pixel + occlusion (bake)" --path pixel --occlusion
    row "$mesh" "$size" "pixel + occlusion (screen)" --path pixel --occlusion --occlusion-method screen
    row "$mesh" "$size" "pixel + strokes" --path pixel --strokes
    row "$mesh" "$size" "pixel + object pattern" --path pixel --pattern object
  done
done
echo
echo "Per-triangle lighting, CPU (the llvmpipe choice) against GPU, on the torus at 1920x1080:"
if [ -x "$build/tests/bench/bench_frames" ]; then
  "$build/tests/bench/bench_frames" --mesh torus --size 1920x1080 --frames "$frames" --paths stencil,triangle --gpu-triangles 2>&1 | tail -n +1
else
  echo "(no $build/tests/bench/bench_frames: configure with -DNPR_BUILD_BENCHMARKS=ON)"
fi
echo
echo "gpu_check: $((SECONDS - start)) s"
