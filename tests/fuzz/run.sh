#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan, UBSan) in build-fuzz/ and runs each for SECONDS
# on a scratch copy of its committed corpus (tests/fuzz/corpus/NAME), JOBS at a time. Exits 1
# when any harness finds a crash, leak, hang or sanitizer report; the reproducer is left in
# build-fuzz/findings/NAME/. Used by CI for a short run; for a long campaign:
#   tests/fuzz/run.sh 3600            # one hour per harness
#   tests/fuzz/run.sh 600 obj ply     # ten minutes each, two harnesses
# New inputs that reached new code stay in build-fuzz/corpus/NAME: merge them into the
# committed corpus with `build-fuzz/tests/fuzz/fuzz_NAME -merge=1 tests/fuzz/corpus/NAME build-fuzz/corpus/NAME`.
# FUZZ_TIMEOUT (seconds, default 10) is per input and counts wall time: raise it when the
# machine is busy with other work, or a starved harness reports a false timeout.
set -uo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-30}"; shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(obj mtl ply off stl om palette image)
jobs="${FUZZ_JOBS:-$(nproc)}"
build="${FUZZ_BUILD_DIR:-build-fuzz}"
CC=clang CXX=clang++ cmake -S . -B "$build" -DNPR_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null || exit 1
cmake --build "$build" -j"$(nproc)" >/dev/null || { echo "fuzz: build failed"; exit 1; }

run_one() {
  local name="$1" corpus="$build/corpus/$1" findings="$build/findings/$1"
  mkdir -p "$corpus" "$findings"
  cp -n tests/fuzz/corpus/"$name"/* "$corpus"/ 2>/dev/null
  local dict=(); [ -f tests/fuzz/dict/"$name".dict ] && dict=(-dict=tests/fuzz/dict/"$name".dict)
  # The one known leak is inside OpenImageIO (lsan.supp); matching it needs full stacks, which
  # cost speed, so only the harnesses that read images pay for them.
  local unwind=1; case "$name" in image|palette) unwind=0 ;; esac
  # rss_limit: no input may grow the process past 2 GiB; timeout: none may take 10 s.
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
    LSAN_OPTIONS=suppressions=tests/fuzz/lsan.supp:fast_unwind_on_malloc=$unwind \
    "$build/tests/fuzz/fuzz_$name" "${dict[@]}" -max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" >"$build/fuzz_$name.log" 2>&1
  local status=$?
  local execs cov
  # (the OM harness's child processes print their own statistics too: the parent's come last)
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz_$name.log" | tail -1 | grep -o '[0-9]*$')
  cov=$(grep -o 'cov: [0-9]*' "$build/fuzz_$name.log" | tail -1 | grep -o '[0-9]*')
  if [ $status -ne 0 ]; then
    echo "fuzz_$name: FINDING after ${execs:-?} executions (log: $build/fuzz_$name.log, input in $findings/)"
    grep -m3 -E 'ERROR|runtime error|SUMMARY' "$build/fuzz_$name.log"
    return 1
  fi
  echo "fuzz_$name: ${seconds} s, ${execs:-?} executions, coverage ${cov:-?} edges, corpus $(ls "$corpus" | wc -l) inputs, no finding"
}

fail=0
pids=()
for name in "${harnesses[@]}"; do
  [ -x "$build/tests/fuzz/fuzz_$name" ] || { echo "fuzz: no harness '$name'"; fail=1; continue; }
  run_one "$name" & pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then wait "${pids[0]}" || fail=1; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || fail=1; done
exit $fail
