#!/usr/bin/env bash
# Installs the dependencies, builds, and runs the whole test suite with CTest.
#   scripts/test.sh             Release build in build/
#   scripts/test.sh --sanitize  AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

if [[ "${1:-}" == "--sanitize" ]]; then
    export BUILD_DIR=build-asan BUILD_TYPE=RelWithDebInfo
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
    bash scripts/build.sh -DRESHARP_SANITIZE=ON -DRESHARP_BUILD_BENCHMARKS=OFF
else
    export BUILD_DIR=build
    bash scripts/build.sh
fi
ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$(nproc)"
