#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan, UBSan) in build-fuzz/ and runs them, JOBS at a
# time. Two modes:
#   tests/fuzz/run.sh --ci [NAME...]     what CI runs, the same every time: each harness replays
#                                        its regressions (tests/fuzz/regressions/NAME) and then
#                                        runs a fixed number of inputs (RUNS below) from seed 1
#                                        on a fresh copy of its committed corpus. A submission
#                                        never passes or fails on chance.
#   tests/fuzz/run.sh SECONDS [NAME...]  a campaign: a random seed, SECONDS per harness, on the
#                                        corpus kept in build-fuzz/corpus/NAME between campaigns
#                                        (tests/fuzz/run.sh 3600: one hour each).
# Exits 1 when any harness finds a crash, leak, hang or sanitizer report; the reproducer is left
# in build-fuzz/findings/NAME/ (add it to tests/fuzz/regressions/NAME once fixed). Merge a
# campaign's new inputs into the committed corpus with
#   build-fuzz/tests/fuzz/fuzz_NAME -merge=1 tests/fuzz/corpus/NAME build-fuzz/corpus/NAME
# FUZZ_TIMEOUT (seconds, default 10) is per input and counts wall time.
set -uo pipefail
cd "$(dirname "$0")/../.."
mode=campaign; seconds=30
if [ "${1:-}" = "--ci" ]; then mode=ci; shift
elif [ $# -gt 0 ]; then seconds="$1"; shift; fi
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(obj mtl ply off stl om gltf palette image)
# CI's inputs per harness: about 1 s each on this 2-core machine (the OM harness forks a
# reader per input, the image ones decode whole images). Exploration is the campaigns' job.
declare -A RUNS=([gltf]=1250 [obj]=12500 [mtl]=20000 [ply]=50000 [off]=40000 [stl]=12500 [om]=20 [palette]=1250 [image]=300)
jobs="${FUZZ_JOBS:-$(nproc)}"
build="${FUZZ_BUILD_DIR:-build-fuzz}"
# A unity build with line tables only (-g1, all a report needs): 52 s instead of 62 on two cores.
CC=clang CXX=clang++ cmake -S . -B "$build" -DNPR_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=gold \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" >/dev/null || exit 1
cmake --build "$build" -j"$(nproc)" >/dev/null || { echo "fuzz: build failed"; exit 1; }

# Reports name their frames with llvm-symbolizer (package llvm-14); lsan.supp also matches
# without names, by module.
if [ -z "${ASAN_SYMBOLIZER_PATH:-}" ]; then
  for s in "$(command -v llvm-symbolizer)" /usr/lib/llvm-14/bin/llvm-symbolizer; do
    [ -n "$s" ] && [ -x "$s" ] && { export ASAN_SYMBOLIZER_PATH="$s"; break; }
  done
fi

run_harness() {  # run_harness NAME LOG ARGS...: the harness under the sanitizers' options
  local name="$1" log="$2"; shift 2
  local dict=(); [ -f tests/fuzz/dict/"$name".dict ] && dict=(-dict=tests/fuzz/dict/"$name".dict)
  # The one known leak is inside OpenImageIO (lsan.supp); matching it needs full stacks, which
  # cost speed, so only the harnesses that read images pay for them (glTF decodes its images:
  # a campaign found the leak there with a fast, cut stack that no suppression matched).
  local unwind=1; case "$name" in image|palette|gltf) unwind=0 ;; esac
  # rss_limit: no input may grow the process past 2 GiB; timeout: none may take 10 s.
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
    LSAN_OPTIONS=suppressions=tests/fuzz/lsan.supp:fast_unwind_on_malloc=$unwind \
    "$build/tests/fuzz/fuzz_$name" "${dict[@]}" -timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$build/findings/$name/" "$@" >"$log" 2>&1
}

finding() {  # finding NAME LOG WHAT
  echo "fuzz_$1: FINDING $3 (log: $2, input in $build/findings/$1/)"
  grep -m3 -E 'ERROR|runtime error|SUMMARY' "$2"
  return 1
}

run_one() {
  local name="$1" corpus
  mkdir -p "$build/findings/$name"
  if [ "$mode" = ci ]; then
    local regressions=(tests/fuzz/regressions/"$name"/*)
    if [ -e "${regressions[0]}" ]; then
      run_harness "$name" "$build/fuzz_$name.regressions.log" "${regressions[@]}" ||
        finding "$name" "$build/fuzz_$name.regressions.log" "replaying tests/fuzz/regressions/$name" || return 1
    fi
    corpus="$build/ci-corpus/$name"
    rm -rf "$corpus"
  else
    corpus="$build/corpus/$name"
  fi
  mkdir -p "$corpus"
  cp -n tests/fuzz/corpus/"$name"/* "$corpus"/ 2>/dev/null
  local limit=(-max_total_time="$seconds")
  # -reload=0: the corpus is not re-read every second, which made runs of one seed differ.
  [ "$mode" = ci ] && limit=(-seed=1 -reload=0 -runs="${RUNS[$name]}")
  local log="$build/fuzz_$name.log"
  run_harness "$name" "$log" "${limit[@]}" -print_final_stats=1 "$corpus"
  local status=$?
  local execs cov
  # (the OM harness's child processes print their own statistics too: the parent's come last)
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | tail -1 | grep -o '[0-9]*$')
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
  [ $status -eq 0 ] || { finding "$name" "$log" "after ${execs:-?} executions"; return 1; }
  local what="${seconds} s"
  if [ "$mode" = ci ]; then what="seed 1"; [ -d tests/fuzz/regressions/"$name" ] && what="regressions replayed, $what"; fi
  echo "fuzz_$name: $what, ${execs:-?} executions, coverage ${cov:-?} edges, corpus $(ls "$corpus" | wc -l) inputs, no finding"
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
