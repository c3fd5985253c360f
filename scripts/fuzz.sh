#!/usr/bin/env bash
# Builds the libFuzzer targets (clang-14, ASan + UBSan) into ./build-fuzz and runs each for
# SECONDS (default 60), one after the other, niced, one job each.
#   scripts/fuzz.sh [SECONDS] [TARGET...]   targets: case_reader material_parser probe_csv
# Seeds: tests/fuzz/corpus/<target>/ (read only); new inputs go to build-fuzz/corpus/<target>/;
# a crash, hang (> 60 s per input) or sanitizer report leaves its input in
# build-fuzz/artifacts/<target>/ and fails the run. Once fixed, the input goes to
# tests/fuzz/regressions/<target>/, which the default suite replays (test_fuzz_regressions).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(case_reader material_parser probe_csv)
CXX=${CXX:-clang++-14} cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Fuzz \
  -DCMAKE_CXX_FLAGS_FUZZ="-O1 -g1" -DMAGFEM_SANITIZE=address,undefined -DMAGFEM_FUZZ=ON >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]/#/fuzz_}"
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
status=0
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t"
  dict=()
  [[ $t == probe_csv ]] || dict=(-dict=tests/fuzz/yaml.dict) # the case-file vocabulary
  echo "fuzz: $t for $seconds s"
  # -rss_limit_mb: a case file must not make the reader allocate gigabytes either. -timeout is
  # generous: niced on a busy machine a 0.1 s input once stalled past 10 s (not reproducible).
  nice -n 15 "build-fuzz/tests/fuzz/fuzz_$t" "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" \
    -max_total_time="$seconds" -timeout=60 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" "${dict[@]}" || status=1
done
exit $status
