#!/usr/bin/env bash
# Runs every test program of a build tree's tests/ (the CPU and GL tiers) whole, each once with
# all its tests in one process, JOBS at a time, and prints a failing program's output. CI's
# sanitizer stage uses it instead of ctest: under ASan a test process takes about 0.8 s to
# start, and ctest's one process per test (289 of them) spent most of the stage starting them.
# Usage: tests/run_test_binaries.sh BUILD_DIR [JOBS]
set -uo pipefail
dir="$(cd "$1" && pwd)"; jobs="${2:-$(nproc)}"
mapfile -t programs < <(find "$dir/tests" -maxdepth 1 -type f -name 'test_*' -perm -u+x | sort)
# The longest programs under ASan start first (9-28 s each on two cores), so that no core is left
# running one of them alone at the end; the order of the others does not matter.
long=(test_gl_shadows test_gl_render test_gl_scene test_gl_style_legibility test_gl_viewer_state test_drawn_palettes)
ordered=()
for name in "${long[@]}"; do [ -x "$dir/tests/$name" ] && ordered+=("$dir/tests/$name"); done
for p in "${programs[@]}"; do [[ " ${long[*]} " == *" $(basename "$p") "* ]] || ordered+=("$p"); done
programs=("${ordered[@]}")
# Every npr_test() of tests/CMakeLists.txt: a missing program is a failure, not a skip.
expected=$(grep -c '^npr_test(' "$(dirname "$0")/CMakeLists.txt")
if [ "${#programs[@]}" -ne "$expected" ]; then
  echo "run_test_binaries: ${#programs[@]} test programs in $dir/tests, tests/CMakeLists.txt declares $expected"
  exit 1
fi
logs=$(mktemp -d); trap 'rm -rf "$logs"' EXIT
export logs
# ctest runs them in the tree's tests/ folder; so does this.
cd "$dir/tests"
printf '%s\n' "${programs[@]}" | xargs -P "$jobs" -I{} bash -c '
  name=$(basename "$1"); start=$SECONDS
  if "$1" --gtest_brief=1 >"$logs/$name.log" 2>&1; then
    echo "passed $name ($(grep -m1 -oE "[0-9]+ tests? from [0-9]+ test suites? ran" "$logs/$name.log"), $((SECONDS - start)) s)"
  else
    echo "FAILED $name"; cat "$logs/$name.log"; exit 1
  fi' _ {}
status=$?
[ $status -eq 0 ] && echo "run_test_binaries: all ${#programs[@]} test programs passed" || echo "run_test_binaries: a test program failed"
exit $([ $status -eq 0 ] && echo 0 || echo 1)
