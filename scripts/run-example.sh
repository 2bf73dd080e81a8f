#!/usr/bin/env bash
# Installs the dependencies, builds resharp, and restores the shipped example mesh, printing
# the summary. The restored mesh and its segmentation land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
BUILD_DIR=build bash scripts/build.sh
mkdir -p out
./build/resharp restore examples/bracket.stl -o out/bracket-restored.stl \
    --report out/bracket-report.json --segments out/bracket-segments.ply
echo "Restored mesh: out/bracket-restored.stl; detected segments: out/bracket-segments.ply"
