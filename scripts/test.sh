#!/usr/bin/env bash
# Builds and runs every test: the whole suite under AddressSanitizer + UndefinedBehaviorSanitizer
# (the `asan` preset), including a few-seconds fuzz smoke run per file format.
# Game data: $NPRQ_DATA (default ../shared/data); tests fail loudly if it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Warnings are errors here, so the suite never passes on a build that warns.
cmake --preset asan -DNQ_WERROR=ON
cmake --build --preset asan -j "$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
ctest --preset asan -j "$(nproc)"
