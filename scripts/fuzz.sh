#!/usr/bin/env bash
# `make fuzz`: libFuzzer (clang, ASan + UBSan) on the readers of untrusted input, the scene
# JSON reader, the glTF importer and the JSON reader of scripts, lessons and settings
# (tests/fuzz/fuzz_*.cpp), FUZZ_SECONDS each (default 60), starting from
# the seed corpus in tests/fuzz/corpus (kept in the repository) plus what earlier runs
# found (BUILD_FUZZ/corpus, default build-fuzz). A finding (crash, sanitizer report, leak,
# timeout, out of memory, an exception other than InputError) fails the run and leaves its
# input in BUILD_FUZZ/findings. Then the corpus is replayed with source-based coverage and
# the line coverage of the readers printed (docs/reliability.md); FUZZ_COVERAGE=0 skips
# that (ctest Fuzz.Bounded).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_FUZZ:-build-fuzz}
seconds=${FUZZ_SECONDS:-60}
jobs=${JOBS:-$(nproc)}
configure() {
  cmake -S . -B "$1" -DPENUMBRA_FUZZ=ON "${@:2}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_COMPILER=clang++ >/dev/null
  cmake --build "$1" -j "$jobs" >/dev/null
}
configure "$build"
mkdir -p "$build/findings"
status=0
harnesses=${FUZZ_HARNESSES:-scene_json gltf script lesson settings}
for harness in $harnesses; do
  mkdir -p "$build/corpus/$harness"
  echo "fuzz_$harness: ${seconds} s"
  if ! "$build/fuzz_$harness" "$build/corpus/$harness" "tests/fuzz/corpus/$harness" \
       -dict=tests/fuzz/json.dict -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -max_len=65536 -artifact_prefix="$build/findings/$harness-" -print_final_stats=1 \
       >"$build/fuzz_$harness.log" 2>&1; then
    status=1
    grep -E "ERROR|SUMMARY|==[0-9]+==" "$build/fuzz_$harness.log" | head -20 || true
    echo "fuzz_$harness: FINDING (input in $build/findings, log in $build/fuzz_$harness.log)"
  fi
  grep -E "^#[0-9]+[[:space:]]+DONE|stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz_$harness.log" || true
done
# Line coverage of the readers over the corpus (when llvm-cov is installed).
if [ "${FUZZ_COVERAGE:-1}" != 0 ] && command -v llvm-profdata-14 >/dev/null &&
   command -v llvm-cov-14 >/dev/null; then
  configure "$build/coverage" -DPENUMBRA_FUZZ_COVERAGE=ON
  for harness in $harnesses; do
    LLVM_PROFILE_FILE="$build/coverage/$harness.profraw" "$build/coverage/fuzz_$harness" -runs=0 \
      "$build/corpus/$harness" "tests/fuzz/corpus/$harness" >/dev/null 2>&1 || true
    llvm-profdata-14 merge -sparse "$build/coverage/$harness.profraw" -o "$build/coverage/$harness.profdata"
    echo "line coverage, corpus of fuzz_$harness:"
    llvm-cov-14 report "$build/coverage/fuzz_$harness" -instr-profile="$build/coverage/$harness.profdata" \
      app/scene/scene_file.cpp app/scene/scene_gltf.cpp app/scene/gltf_file_access.cpp app/scene/gltf_declared.cpp app/scene/gltf_animation.cpp app/scene/animation.cpp app/scene/scene.cpp \
      app/base/json_input.cpp app/io/output_path.cpp | sed -n '1,2p;/scene_/p;/gltf_/p;/animation/p;/json_input/p;/output_path/p;/TOTAL/p'
  done
fi
exit $status
