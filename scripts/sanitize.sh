#!/usr/bin/env bash
# Builds magfem with AddressSanitizer + UndefinedBehaviorSanitizer into ./build-sanitize and
# runs tests under them; any report (memory error, leak, undefined behaviour) fails the run.
#   scripts/sanitize.sh            all targets; the unit and example tests (ctest -L)
#   scripts/sanitize.sh --parsers  only the input readers (core, materials, casefile) and their
#                                  tests: no CGAL/TetGen/VTK code, small enough for CI
# Extra arguments after the mode go to ctest (full mode), e.g. -R test_cli_cli.
# Reports from third-party code are suppressed in tests/sanitize/*.supp, each with its reason.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=full
if [[ ${1:-} == --parsers ]]; then
  mode=parsers
  shift
fi
supp=$PWD/tests/sanitize
# fast_unwind_on_malloc=0: full allocation stacks through libraries built without frame
# pointers (Open MPI), so that tests/sanitize/lsan.supp can name the function that leaks.
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:fast_unwind_on_malloc=0:abort_on_error=0:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
# -O1 keeps the run fast enough and the stack traces exact; asserts (no NDEBUG) stay on.
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g1" \
  -DMAGFEM_SANITIZE=address,undefined >/dev/null
start=$SECONDS
if [[ $mode == parsers ]]; then
  tests=(tests/core/test_core tests/materials/test_materials tests/casefile/test_case_reader
         tests/fuzz/test_fuzz_regressions)
  targets=()
  for t in "${tests[@]}"; do targets+=("$(basename "$t")"); done
  cmake --build build-sanitize -j"$(nproc)" --target "${targets[@]}"
  echo "sanitize: built in $((SECONDS - start)) s"
  for t in "${tests[@]}"; do
    (cd build-sanitize && "./$t" --gtest_brief=1)
  done
else
  cmake --build build-sanitize -j"$(nproc)"
  echo "sanitize: built in $((SECONDS - start)) s"
  ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)" --timeout 1800 -L 'unit|example' "$@"
fi
echo "sanitize: $mode done in $((SECONDS - start)) s, no sanitizer report"
