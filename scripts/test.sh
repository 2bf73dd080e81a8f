#!/usr/bin/env bash
# Installs the dependencies, builds, and runs the whole test suite with CTest.
#   scripts/test.sh             Release build in build/
#   scripts/test.sh --sanitize  Debug build (assertions on, every stage's invariants checked) with
#                               AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

if [[ "${1:-}" == "--sanitize" ]]; then
    # Debug keeps NDEBUG off, so RESHARP_ASSERT and the expensive tier both run; -O1 keeps the
    # simulations in the tests within CI's time.
    export BUILD_DIR=build-asan BUILD_TYPE=Debug
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
    bash scripts/build.sh -DRESHARP_SANITIZE=ON -DRESHARP_EXPENSIVE_ASSERTS=ON \
        -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DRESHARP_BUILD_BENCHMARKS=OFF -DRESHARP_BUILD_VIEWER=OFF
else
    export BUILD_DIR=build
    bash scripts/build.sh
fi
ctest --test-dir "$BUILD_DIR" --output-on-failure --parallel "$(nproc)"
