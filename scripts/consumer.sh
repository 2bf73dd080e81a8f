#!/usr/bin/env bash
# The consumer lane: installs resharp from BUILD_DIR (default: build, configured by build.sh if it
# is not yet) into a temporary prefix, configures and builds tests/consumer against it with
# find_package(resharp CONFIG REQUIRED), and runs it. Nothing outside the temporary folder is
# written but the build folder.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
TARGETS="resharp resharp_io resharp_cli" BUILD_DIR=$build_dir bash scripts/build.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S tests/consumer -B "$work/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >/dev/null
# The package must come from the prefix just installed, not from a build tree or the system.
found=$(sed -n 's/^resharp_DIR:PATH=//p' "$work/build/CMakeCache.txt")
if [[ "$found" != "$work/prefix/"* ]]; then
    echo "consumer: resharp was found in '$found', not in the installed prefix" >&2
    exit 1
fi
cmake --build "$work/build" --parallel "$(nproc)"
"$work/build/resharp_consumer"
