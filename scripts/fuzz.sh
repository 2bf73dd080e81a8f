#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang in build-fuzz/ and runs each reader's
# fuzzer for SECONDS (default 60). New corpus entries go to build-fuzz/corpus/<format>; the
# committed seeds in tests/fuzz/corpus/<format> are only read. Crash inputs land in
# build-fuzz/crashes/<format>/. Exits non-zero if any fuzzer crashed.
#
# Usage: scripts/fuzz.sh [SECONDS]
set -euo pipefail

seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
formats=(stl obj ply off)

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ -DRESHARP_BUILD_FUZZERS=ON \
    -DRESHARP_BUILD_TESTS=OFF -DRESHARP_BUILD_BENCHMARKS=OFF -DRESHARP_BUILD_VIEWER=OFF \
    -DRESHARP_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build" -j2 --target "${formats[@]/#/resharp_fuzz_}"

failed=()
for format in "${formats[@]}"; do
    corpus=$build/corpus/$format
    crashes=$build/crashes/$format
    mkdir -p "$corpus" "$crashes"
    echo "fuzz.sh: $format for ${seconds}s"
    set +e
    "$build/tests/fuzz/resharp_fuzz_$format" -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$crashes/" \
        "$corpus" "$root/tests/fuzz/corpus/$format" >"$build/fuzz_$format.log" 2>&1
    status=$?
    set -e
    grep -E "stat::number_of_executed_units|stat::new_units_added|^SUMMARY" \
        "$build/fuzz_$format.log" || true
    if [[ $status -ne 0 ]]; then
        failed+=("$format")
        echo "fuzz.sh: $format FAILED (status $status); see $build/fuzz_$format.log and $crashes"
    fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
    echo "fuzz.sh: crashes in: ${failed[*]}"
    exit 1
fi
echo "fuzz.sh: no crashes"
