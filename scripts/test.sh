#!/usr/bin/env bash
# Set-up + build + the whole test suite (what CI runs), then the input readers under
# AddressSanitizer and UndefinedBehaviorSanitizer: the parsers see every user's input and
# are built in seconds; the whole suite under sanitizers (bash scripts/sanitize.sh, ~10 min of
# build and 7 min of tests on 2 cores) is run before each release instead (README).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
bash scripts/sanitize.sh --parsers
