#!/usr/bin/env bash
# The GPU check: what a machine with a GPU measures in under 4 minutes, printed as one table.
#   bash tests/bench/gpu_check.sh [BUILD=build] [FRAMES=30] [IMAGES]
# First --gl-info (which device the headless context opened); then, for the bunny and the
# 871K-triangle torus at 1920x1080 and 3840x2160, every user path and the pixel path with
# shadows, occlusion (bake and screen), strokes and the object pattern: the median frame time of
# FRAMES frames of an orbit (npr-viewer --headless, one process per row, so rows are
# independent); then bench_frames' per-triangle lighting on the CPU against the GPU (the choice
# made on llvmpipe) on the torus; the turn's placement forced into the mesh pass and into the
# resolve pass on the bunny and the torus (the density threshold chosen on llvmpipe); a skinned
# and a morphing torus against it still (bench_animation); scenes of many objects against one
# mesh, with the GL calls each frame sends (bench_scene). With IMAGES, the bunny in every path
# and every shipped style is also saved there as PNGs, with any GL error failing the run, to be
# compared with the same pictures from llvmpipe. Needs the Release build with the benchmarks
# (the default).
set -u
build="${1:-build}"; frames="${2:-30}"; images="${3:-}"
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
echo "The turn's placement (bench_frames --turn-placements) at 1920x1080, the hatch palette's 10 entries:"
if [ -x "$build/tests/bench/bench_frames" ]; then
  for mesh in bunny torus; do
    "$build/tests/bench/bench_frames" --mesh "$mesh" --size 1920x1080 --frames "$frames" --entries 10 --paths triangle,pixel,smooth --turn-placements 2>&1 | grep -E "^\| $mesh .*orient"
  done
fi
echo
echo "A deforming torus against it still (bench_animation) at 1920x1080:"
[ -x "$build/tests/bench/bench_animation" ] && "$build/tests/bench/bench_animation" --size 1920x1080 --frames "$frames" 2>&1
echo
echo "A scene of 1, 16 and 256 objects against one merged mesh (bench_scene) at 1920x1080:"
[ -x "$build/tests/bench/bench_scene" ] && "$build/tests/bench/bench_scene" --size 1920x1080 --frames "$frames" 2>&1
if [ -n "$images" ]; then
  mkdir -p "$images"
  fails=0
  for path in stencil triangle vertex pixel smooth reference; do
    "$viewer" --headless models/bunny.obj --size 800x600 --frames 1 --path "$path" --screenshot "$images/path-$path.png" > /dev/null 2>&1 || { echo "image: path $path failed"; fails=$((fails + 1)); }
  done
  for style in palettes/styles/*.style; do
    name=$(basename "$style" .style)
    "$viewer" --headless models/bunny.obj --size 800x600 --frames 1 --style "$name" --screenshot "$images/style-$name.png" > /dev/null 2>&1 || { echo "image: style $name failed"; fails=$((fails + 1)); }
  done
  "$viewer" --headless models/pendulum.gltf --size 800x600 --frames 1 --time 0.5 --shadows --screenshot "$images/scene-pendulum.png" > /dev/null 2>&1 || { echo "image: pendulum failed"; fails=$((fails + 1)); }
  echo "images: $(ls "$images" | wc -l) saved in $images, $fails failed"
fi
echo
echo "gpu_check: $((SECONDS - start)) s"
