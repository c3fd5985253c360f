#!/usr/bin/env bash
# Set-up + build + the whole default test suite (what CI runs), then the input readers under
# AddressSanitizer and UndefinedBehaviorSanitizer: the parsers see every user's input and
# are built in seconds; the whole suite under sanitizers (bash scripts/sanitize.sh, ~10 min of
# build and 7 min of tests on 2 cores) is run before each release instead (docs/reliability.md).
#
#   bash scripts/test.sh          the default suite (every label but `long`), CI
#   bash scripts/test.sh --long   the long tier: the tests labelled `long` (fine meshes, TEAM 20
#                                 at every excitation, the compensator's FE sweep, the thesis's
#                                 coil-pitch study) and `magfem validate --tier full`, then a
#                                 summary; about 50 min of tests + the full validation on 2 cores (docs/development.md)
set -euo pipefail
cd "$(dirname "$0")/.."

long=0
case "${1:-}" in
  "") ;;
  --long) long=1 ;;
  *) echo "test.sh: unknown option '$1' (use no option, or --long)" >&2; exit 2 ;;
esac

bash scripts/install_deps.sh
bash scripts/build.sh

if ((long == 0)); then
  ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600 -LE long
  bash scripts/sanitize.sh --parsers
  exit 0
fi

# The long tier: one test at a time (each uses every core), each with its own timeout (the
# test property TIMEOUT, tests/CMakeLists.txt). Both halves run even if the first fails (with
# pipefail, `| tee ... || rc=$?` keeps the command's exit code), and
# the summary says which failed; the exit code is non-zero if either did.
out="build/long_tier"
rm -rf "$out"
mkdir -p "$out"
start=$(date +%s)
ctest_rc=0
ctest --test-dir build --output-on-failure -L long --output-junit "$PWD/$out/ctest.xml" \
  2>&1 | tee "$out/ctest.log" || ctest_rc=$?
mid=$(date +%s)
validate_rc=0
build/magfem validate --tier full --out "$out/validate" 2>&1 | tee "$out/validate.log" ||
  validate_rc=$?
end=$(date +%s)

echo
echo "== long tier summary (commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)) =="
grep -E "tests passed|tests failed" "$out/ctest.log" | tail -1 | sed 's/^/ctest -L long: /'
grep -E "^[[:space:]]*[0-9]+ - .*\((Failed|Timeout|SEGFAULT|Exception|Not Run)" "$out/ctest.log" |
  sed 's/^/  failed: /' || true
printf '  %d s\n' $((mid - start))
grep -E "entries in .* s \(" "$out/validate.log" | tail -1 | sed 's/^/magfem validate --tier full: /'
printf '  %d s; report %s/validate\n' $((end - mid)) "$out"
printf 'long tier: %d s in all; ctest exit %d, validate exit %d\n' $((end - start)) "$ctest_rc" \
  "$validate_rc"
((ctest_rc == 0 && validate_rc == 0))
