#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang in build-fuzz/ and runs each reader's
# fuzzer for SECONDS (default 60) and the restore() fuzzer for RESTORE_SECONDS (default
# SECONDS). New corpus entries go to build-fuzz/corpus/<target>; the committed seeds in
# tests/fuzz/corpus/<target> are only read. Crash inputs land in build-fuzz/crashes/<target>/.
# Exits non-zero if any fuzzer crashed.
#
# Budget with the defaults, 10 minutes on 2 cores: 5 x 60 s of fuzzing, and the build from
# scratch (resharp, io and sim with clang; the restore() fuzzer adds sim and one CGAL file),
# measured at 13 minutes with the cores shared by three other builds (load 8; not yet measured
# on an idle machine). The restore() fuzzer ran 0.4 cases a second under that load (each
# restores a damaged part of 2.6k to 6k triangles under ASan and checks it, CGAL included).
#
# Usage: scripts/fuzz.sh [SECONDS] [RESTORE_SECONDS]
set -euo pipefail

seconds=${1:-60}
restore_seconds=${2:-$seconds}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
targets=(stl obj ply off restore)

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ -DRESHARP_BUILD_FUZZERS=ON \
    -DRESHARP_BUILD_TESTS=OFF -DRESHARP_BUILD_BENCHMARKS=OFF -DRESHARP_BUILD_VIEWER=OFF \
    -DRESHARP_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build" -j2 --target "${targets[@]/#/resharp_fuzz_}"

failed=()
for target in "${targets[@]}"; do
    corpus=$build/corpus/$target
    crashes=$build/crashes/$target
    mkdir -p "$corpus" "$crashes"
    budget=$seconds
    timeout=10  # seconds per input before libFuzzer calls it a hang
    if [[ $target == restore ]]; then
        # A case took up to 17 s under ASan with the cores shared (load 8).
        budget=$restore_seconds
        timeout=60
    fi
    echo "fuzz.sh: $target for ${budget}s"
    set +e
    "$build/tests/fuzz/resharp_fuzz_$target" -max_total_time="$budget" -timeout="$timeout" \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$crashes/" \
        "$corpus" "$root/tests/fuzz/corpus/$target" >"$build/fuzz_$target.log" 2>&1
    status=$?
    set -e
    grep -E "stat::number_of_executed_units|stat::new_units_added|^SUMMARY" \
        "$build/fuzz_$target.log" || true
    if [[ $status -ne 0 ]]; then
        failed+=("$target")
        echo "fuzz.sh: $target FAILED (status $status); see $build/fuzz_$target.log and $crashes"
    fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
    echo "fuzz.sh: crashes in: ${failed[*]}"
    exit 1
fi
echo "fuzz.sh: no crashes"
