#!/usr/bin/env bash
# Configures and builds resharp into BUILD_DIR (default: build). Extra arguments go to CMake.
# TARGETS (space-separated) builds only those targets, e.g. TARGETS=resharp_cli for the binary.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
    cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" "$@"
else
    cmake -S . -B "$build_dir" "$@" >/dev/null
fi
targets=()
for target in ${TARGETS:-}; do targets+=(--target "$target"); done
cmake --build "$build_dir" --parallel "$(nproc)" "${targets[@]}"
